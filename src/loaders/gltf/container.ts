// A glTF file's container (docs/gltf.md#containers): a GLB (a 12-byte header, a JSON chunk, an
// optional BIN chunk) or a .gltf's JSON text. Every length a header declares is checked against
// the bytes there are before anything is read or allocated: a truncated file is an error naming
// where it ends, never a read past the end.
import { LoadError } from '../load-error';
import { bomOf } from '../decode-text';

/** "glTF", little-endian. */
export const GLB_MAGIC = 0x46546c67;
const CHUNK_JSON = 0x4e4f534a;
const CHUNK_BIN = 0x004e4942;
const HEADER = 12;
const CHUNK_HEADER = 8;

export interface Container {
  /** The parsed JSON, not yet checked to be glTF. */
  json: unknown;
  /** The GLB's BIN chunk (buffers[0] when it has no uri), or null. */
  bin: Uint8Array | null;
  glb: boolean;
}

/** Whether the bytes start as a GLB does (the sniffer's test, docs/gltf.md#containers). */
export function isGlb(bytes: Uint8Array): boolean {
  return bytes.length >= 4 && new DataView(bytes.buffer, bytes.byteOffset, 4).getUint32(0, true) === GLB_MAGIC;
}

export function readContainer(bytes: Uint8Array, url: string): Container {
  return isGlb(bytes) ? readGlb(bytes, url) : { json: parseJson(textOf(bytes), url), bin: null, glb: false };
}

function readGlb(bytes: Uint8Array, url: string): Container {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  if (bytes.length < HEADER) throw new LoadError(url, `a GLB of ${bytes.length} bytes: its 12-byte header is cut short`, 'GLB header');
  const version = view.getUint32(4, true);
  if (version !== 2) throw new LoadError(url, `GLB version ${version}: only glTF 2.0 is read`, 'GLB header');
  const length = view.getUint32(8, true);
  if (length > bytes.length) {
    throw new LoadError(url, `the GLB header declares ${length} bytes, the file has ${bytes.length}: it is truncated`, 'GLB header');
  }
  let json: Uint8Array | null = null;
  let bin: Uint8Array | null = null;
  for (let at = HEADER, n = 0; at < length; n++) {
    const where = `GLB chunk ${n} (byte ${at})`;
    if (at + CHUNK_HEADER > length) throw new LoadError(url, `a chunk header runs past the end of the file (${length} bytes)`, where);
    const size = view.getUint32(at, true);
    const type = view.getUint32(at + 4, true);
    const start = at + CHUNK_HEADER;
    if (size > length - start) {
      throw new LoadError(url, `the chunk declares ${size} bytes, ${length - start} are left in the file: it is truncated`, where);
    }
    const data = bytes.subarray(start, start + size);
    if (n === 0 && type !== CHUNK_JSON) throw new LoadError(url, 'the first chunk is not JSON', where);
    if (n === 0) json = data;
    else if (n === 1 && type === CHUNK_BIN) bin = data;
    // Chunks of other types are skipped, as the specification asks; a second BIN is not glTF 2.0's.
    at = start + size + ((4 - (size % 4)) % 4);
  }
  if (json === null) throw new LoadError(url, 'the GLB has no JSON chunk', 'GLB header');
  return { json: parseJson(textOf(json), url), bin, glb: true };
}

function textOf(bytes: Uint8Array): string {
  const { encoding, skip } = bomOf(bytes);
  return new TextDecoder(encoding, { ignoreBOM: true }).decode(bytes.subarray(skip));
}

function parseJson(text: string, url: string): unknown {
  try {
    return JSON.parse(text);
  } catch (e) {
    const why = e instanceof Error ? e.message : String(e);
    throw new LoadError(url, `the JSON does not parse (${why})`, 'JSON');
  }
}
