// A glTF file's buffers and buffer views (docs/gltf.md#buffers): the GLB's BIN chunk, data: URIs
// and external files (fetched by the caller, relative to the model's URL). A buffer's declared
// byteLength is compared with the bytes there are before it is used: a 2 GB declaration over a
// 1 kB file is an error, and nothing is allocated for it.
import { GltfFile, int, object, optionalInt, str, type Obj } from './fields';
import { isFallback } from './meshopt';

export interface ExternalBuffer {
  index: number;
  /** As written in the file (percent-encoded, relative): the caller resolves it against the model's URL. */
  uri: string;
}

/** The buffers the caller must fetch: those with a uri that is not a data: URI. */
export function externalBuffers(file: GltfFile): ExternalBuffer[] {
  const out: ExternalBuffer[] = [];
  file.list('buffers').forEach((b, index) => {
    const buffer = object(file, b, `buffers[${index}]`);
    if (buffer.uri === undefined) return;
    const uri = str(file, buffer, 'uri', `buffers[${index}]`);
    // A meshopt fallback holds what the decoder gives: never fetched (docs/gltf.md#compression).
    if (!/^data:/i.test(uri) && !isFallback(file, buffer, `buffers[${index}]`)) out.push({ index, uri });
  });
  return out;
}

/** Each buffer's bytes, exactly its declared byteLength long. */
export function resolveBuffers(file: GltfFile, bin: Uint8Array | null, external: ReadonlyMap<number, Uint8Array>): Uint8Array[] {
  return file.list('buffers').map((b, index) => {
    const path = `buffers[${index}]`;
    const buffer = object(file, b, path);
    const declared = int(file, buffer, 'byteLength', path);
    let bytes: Uint8Array;
    let source: string;
    if (isFallback(file, buffer, path)) {
      // A meshopt fallback is read only where its bytes are at hand; its views are decoded instead.
      const at = buffer.uri === undefined ? index === 0 && bin !== null : /^data:/i.test(String(buffer.uri)) || external.has(index);
      if (!at) return new Uint8Array(0);
    }
    if (buffer.uri === undefined) {
      if (index !== 0 || bin === null) file.fail(path, `${path} has no uri and the file has no BIN chunk for it`);
      bytes = bin;
      source = 'the BIN chunk';
    } else {
      const uri = str(file, buffer, 'uri', path);
      if (/^data:/i.test(uri)) {
        bytes = dataUri(file, uri, `${path}.uri`);
        source = 'its data: URI';
      } else {
        const got = external.get(index);
        if (!got) file.fail(`${path}.uri`, `${path}: ${JSON.stringify(uri)} was not loaded`);
        bytes = got;
        source = JSON.stringify(uri);
      }
    }
    if (bytes.length < declared) {
      file.fail(`${path}.byteLength`, `${path} declares ${declared} bytes, ${source} has ${bytes.length}`);
    }
    return bytes.subarray(0, declared);
  });
}

export interface View {
  bytes: Uint8Array;
  /** Bytes between elements, or undefined for tightly packed. */
  stride: number | undefined;
}

/** bufferViews[index], checked to lie inside its buffer. */
export function bufferView(file: GltfFile, buffers: readonly Uint8Array[], index: number, from: string): View {
  const path = `bufferViews[${index}]`;
  const v: Obj = file.item('bufferViews', index, from);
  const decoded = file.decodedViews.get(index);
  if (decoded) {
    const stride = optionalInt(file, v, 'byteStride', path);
    return { bytes: decoded.subarray(0, Math.min(decoded.length, int(file, v, 'byteLength', path))), stride };
  }
  const buffer = int(file, v, 'buffer', path);
  if (buffer >= buffers.length) file.fail(`${path}.buffer`, `buffers[${buffer}] does not exist (buffers has ${buffers.length})`);
  const offset = int(file, v, 'byteOffset', path, 0);
  const length = int(file, v, 'byteLength', path);
  const size = buffers[buffer].length;
  if (offset + length > size) {
    file.fail(path, `${path} (bytes ${offset} to ${offset + length}) runs past the end of buffers[${buffer}] (${size} bytes)`);
  }
  const stride = optionalInt(file, v, 'byteStride', path);
  // Stryker disable next-line ConditionalExpression: an undefined stride compares false with 4 and with 252: never refused
  if (stride !== undefined && (stride < 4 || stride > 252)) file.fail(`${path}.byteStride`, `${path}.byteStride is ${stride}, outside [4, 252]`);
  return { bytes: buffers[buffer].subarray(offset, offset + length), stride };
}

function dataUri(file: GltfFile, uri: string, path: string): Uint8Array {
  const comma = uri.indexOf(',');
  // Stryker disable next-line ConditionalExpression,EqualityOperator: no comma: refused below whatever the head; after "data:" a comma is never at 0
  const head = uri.slice(0, comma < 0 ? 0 : comma);
  // Stryker disable next-line ConditionalExpression,EqualityOperator: without a comma the head is '', which the ;base64 test refuses too
  if (comma < 0 || !/;base64$/i.test(head)) file.fail(path, `${path} is a data: URI that is not base64`);
  // Stryker disable next-line Regex: removing whitespace one character or one run at a time leaves the same text
  const body = uri.slice(comma + 1).replace(/\s+/g, '');
  let text: string;
  try {
    text = atob(body);
  } catch {
    file.fail(path, `${path}: its base64 does not decode`);
  }
  const out = new Uint8Array(text.length);
  // Stryker disable next-line EqualityOperator: out[text.length] is past the typed array's end, where a write does nothing
  for (let i = 0; i < text.length; i++) out[i] = text.charCodeAt(i);
  return out;
}
