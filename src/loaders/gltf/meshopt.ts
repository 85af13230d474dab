// EXT_meshopt_compression (docs/gltf.md#compression): buffer views whose bytes are meshoptimizer's
// encoding of another buffer's range, decoded by the meshoptimizer package's own decoder (a chunk
// of its own, fetched only by a file that has such a view). The decoded bytes stand in for the
// view; a buffer marked `fallback` holds nothing and is never read.
import { GltfFile, int, object, optionalObject, str, type Obj } from './fields';

export const MESHOPT = 'EXT_meshopt_compression';

/** The part of meshoptimizer's MeshoptDecoder this reader calls. */
export interface MeshoptDecoderLike {
  ready: Promise<void>;
  decodeGltfBuffer(target: Uint8Array, count: number, size: number, source: Uint8Array, mode: string, filter?: string): void;
}

/** Bytes a decoded view may have: beyond, the file is refused before anything is allocated. */
export const MAX_DECODED_BYTES = 1 << 29;

const MODES = new Set(['ATTRIBUTES', 'TRIANGLES', 'INDICES']);
const FILTERS = new Set(['NONE', 'OCTAHEDRAL', 'QUATERNION', 'EXPONENTIAL', 'COLOR']);

/** The views a file compresses with meshopt, by index. */
export function meshoptViews(file: GltfFile): [number, Obj][] {
  const out: [number, Obj][] = [];
  file.list('bufferViews').forEach((v, i) => {
    const ext = optionalObject(file, object(file, v, `bufferViews[${i}]`), 'extensions', `bufferViews[${i}]`);
    const m = ext && optionalObject(file, ext, MESHOPT, `bufferViews[${i}].extensions`);
    if (m) out.push([i, m]);
  });
  return out;
}

/** Whether buffers[index] is a meshopt fallback buffer (its bytes may be absent). */
export function isFallback(file: GltfFile, buffer: Obj, path: string): boolean {
  const ext = optionalObject(file, buffer, 'extensions', path);
  const m = ext && optionalObject(file, ext, MESHOPT, `${path}.extensions`);
  return m?.fallback === true;
}

export async function decodeMeshopt(file: GltfFile, buffers: readonly Uint8Array[], decoder: MeshoptDecoderLike): Promise<Map<number, Uint8Array>> {
  const out = new Map<number, Uint8Array>();
  const views = meshoptViews(file);
  if (views.length === 0) return out;
  await decoder.ready;
  for (const [index, m] of views) {
    const path = `bufferViews[${index}].extensions.${MESHOPT}`;
    const buffer = int(file, m, 'buffer', path);
    if (buffer >= buffers.length) file.fail(`${path}.buffer`, `buffers[${buffer}] does not exist (buffers has ${buffers.length})`);
    const offset = int(file, m, 'byteOffset', path, 0);
    const length = int(file, m, 'byteLength', path);
    if (offset + length > buffers[buffer].length) {
      file.fail(path, `${path} (bytes ${offset} to ${offset + length}) runs past the end of buffers[${buffer}] (${buffers[buffer].length} bytes)`);
    }
    const stride = int(file, m, 'byteStride', path, undefined, 256);
    const count = int(file, m, 'count', path);
    const mode = str(file, m, 'mode', path);
    const filter = str(file, m, 'filter', path, 'NONE');
    if (!MODES.has(mode)) file.fail(`${path}.mode`, `${path}.mode is ${JSON.stringify(mode).slice(0, 30)}, not ATTRIBUTES, TRIANGLES or INDICES`);
    if (!FILTERS.has(filter)) file.fail(`${path}.filter`, `${path}.filter is ${JSON.stringify(filter).slice(0, 30)}, not a meshopt filter`);
    if (count * stride > MAX_DECODED_BYTES) file.fail(path, `${path} decodes to ${count * stride} bytes, above the ${MAX_DECODED_BYTES} read`);
    const target = new Uint8Array(count * stride);
    try {
      decoder.decodeGltfBuffer(target, count, stride, buffers[buffer].subarray(offset, offset + length), mode, filter);
    } catch (e) {
      file.fail(path, `${path} does not decode (${e instanceof Error ? e.message : String(e)})`);
    }
    out.set(index, target);
  }
  return out;
}
