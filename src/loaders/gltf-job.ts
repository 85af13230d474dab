// The glTF worker's work as a plain function (testable without a worker): the file's bytes and
// its external buffers in, the model out, with the buffers to transfer rather than copy.
import { LoadError, type LoadErrorDetail } from './load-error';
import { decompressGltf, openGltf, readGltf, type GltfResult } from './gltf';

export interface GltfJobRequest {
  id: number;
  url: string;
  bytes: ArrayBuffer;
  /** buffers[index] fetched by the page. */
  external: [number, ArrayBuffer][];
}

export type GltfJobResponse = { id: number; ok: true; result: GltfResult } | { id: number; ok: false; error: LoadErrorDetail };

export async function runGltfJob(request: GltfJobRequest): Promise<{ response: GltfJobResponse; transfer: ArrayBuffer[] }> {
  try {
    const open = openGltf(new Uint8Array(request.bytes), request.url);
    const external = new Map(request.external.map(([i, b]) => [i, new Uint8Array(b)]));
    await decompressGltf(open, external);
    const result = readGltf(open, external);
    // An embedded image is a view of the whole file: sliced, so that only its bytes cross over.
    result.images = result.images.map((im) => (im.kind === 'bytes' ? { ...im, bytes: im.bytes.slice() } : im));
    const arrays = [result.positions, result.normals, result.uv0, result.uv1, result.colors, result.tangents, result.indices,
      ...result.images.map((im) => (im.kind === 'bytes' ? im.bytes : null))];
    const transfer = [...new Set(arrays.flatMap((a) => (a ? [a.buffer as ArrayBuffer] : [])))];
    return { response: { id: request.id, ok: true, result }, transfer };
  } catch (e) {
    const error: LoadErrorDetail = e instanceof LoadError ? e.detail
      : { type: 'load', url: request.url, message: e instanceof Error ? e.message : String(e) };
    return { response: { id: request.id, ok: false, error }, transfer: [] };
  }
}
