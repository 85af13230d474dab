// GLB and .gltf containers read byte by byte (src/loaders/gltf/container.ts, docs/gltf.md#containers):
// the magic test, each header and chunk length checked with its exact message, unpadded chunks,
// chunks of other types skipped, a BIN chunk taken only as the second chunk, and the JSON's BOM.
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { isGlb, readContainer } from '../../src/loaders/gltf/container';
import { openGltf } from '../../src/loaders/gltf';
import { parse } from './helpers/gltf';

const JSON_TYPE = 0x4e4f534a, BIN_TYPE = 0x004e4942;
const enc = (s: string) => new TextEncoder().encode(s);

/** A GLB of raw chunks (type, data), each padded to 4 bytes unless `unpadded`, with the header's length right. */
function glbOfChunks(chunks: { type: number; data: Uint8Array; unpadded?: boolean }[], version = 2): Uint8Array {
  const parts: number[] = [];
  for (const c of chunks) {
    const pad = c.unpadded ? (4 - (c.data.length % 4)) % 4 : 0;
    const size = c.unpadded ? c.data.length : Math.ceil(c.data.length / 4) * 4;
    const head = new Uint8Array(8);
    new DataView(head.buffer).setUint32(0, size, true);
    new DataView(head.buffer).setUint32(4, c.type, true);
    parts.push(...head, ...c.data, ...new Array(size - c.data.length + pad).fill(0x20));
  }
  const out = new Uint8Array(12 + parts.length);
  const view = new DataView(out.buffer);
  view.setUint32(0, 0x46546c67, true);
  view.setUint32(4, version, true);
  view.setUint32(8, out.length, true);
  out.set(parts, 12);
  return out;
}

/** The LoadError `bytes` are refused with, opened as `url`. */
function refusal(bytes: Uint8Array, url = 'c.glb'): { path: string | undefined; message: string } {
  try {
    openGltf(bytes, url);
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    return { path: (e as LoadError).path, message: (e as LoadError).detail.message };
  }
  throw new Error('opened without an error');
}

const ASSET = '{"asset":{"version":"2.0"}}';
/** Three vertices (float xyz) and one triangle (uint16), 44 bytes. */
const TRIANGLE_BIN = new Uint8Array(44);
new Float32Array(TRIANGLE_BIN.buffer, 0, 9).set([0, 0, 0, 1, 0, 0, 0, 1, 0]);
new Uint16Array(TRIANGLE_BIN.buffer, 36, 3).set([0, 1, 2]);
const TRIANGLE_JSON = {
  asset: { version: '2.0' }, scenes: [{ nodes: [0] }], nodes: [{ mesh: 0 }],
  meshes: [{ primitives: [{ attributes: { POSITION: 0 }, indices: 1 }] }],
  buffers: [{ byteLength: 44 }],
  bufferViews: [{ buffer: 0, byteOffset: 0, byteLength: 36 }, { buffer: 0, byteOffset: 36, byteLength: 6 }],
  accessors: [
    { bufferView: 0, componentType: 5126, count: 3, type: 'VEC3', min: [0, 0, 0], max: [1, 1, 0] },
    { bufferView: 1, componentType: 5123, count: 3, type: 'SCALAR' },
  ],
};

describe('the GLB magic', () => {
  it('takes four bytes "glTF" as a GLB, and fewer than four bytes as text', () => {
    expect(isGlb(enc('glTF'))).toBe(true);
    expect(isGlb(enc('glTF').subarray(0, 3))).toBe(false);
    expect(isGlb(enc('{}'))).toBe(false);
    // Three bytes of text are JSON to parse, never a GLB header to read.
    expect(refusal(enc('[1]'), 'a.gltf')).toEqual({ path: 'JSON', message: 'JSON is not an object' });
    expect(readContainer(enc(ASSET), 'a.gltf')).toEqual({ json: { asset: { version: '2.0' } }, bin: null, glb: false });
  });
});

describe('GLB headers and chunks', () => {
  it('names a header cut short by its size, and a wrong version by its number', () => {
    expect(refusal(enc('glTF'))).toEqual({ path: 'GLB header', message: 'a GLB of 4 bytes: its 12-byte header is cut short' });
    const v1 = glbOfChunks([{ type: JSON_TYPE, data: enc(ASSET) }], 1);
    expect(refusal(v1)).toEqual({ path: 'GLB header', message: 'GLB version 1: only glTF 2.0 is read' });
  });

  it('refuses a GLB of a whole header and no chunk as having no JSON chunk', () => {
    const header = glbOfChunks([]);
    expect(header.length).toBe(12);
    expect(refusal(header)).toEqual({ path: 'GLB header', message: 'the GLB has no JSON chunk' });
  });

  it('names a chunk header cut short, and a chunk longer than the bytes left', () => {
    const glb = glbOfChunks([{ type: JSON_TYPE, data: enc(ASSET) }]);
    // Four bytes after the header: half a chunk header.
    const half = glb.slice(0, 16);
    new DataView(half.buffer).setUint32(8, 16, true);
    expect(refusal(half)).toEqual({ path: 'GLB chunk 0 (byte 12)', message: 'a chunk header runs past the end of the file (16 bytes)' });
    // The JSON chunk declares 28 bytes; 20 are left after its header (byte 20 of 40).
    const cut = glb.slice(0, 40);
    new DataView(cut.buffer).setUint32(8, 40, true);
    expect(refusal(cut)).toEqual({
      path: 'GLB chunk 0 (byte 12)', message: 'the chunk declares 28 bytes, 20 are left in the file: it is truncated',
    });
  });

  it('reads a chunk header that ends exactly at the end of the file (an empty JSON chunk: a JSON error)', () => {
    const empty = glbOfChunks([{ type: JSON_TYPE, data: new Uint8Array(0) }]);
    expect(empty.length).toBe(20);
    expect(refusal(empty)).toMatchObject({ path: 'JSON', message: expect.stringMatching(/^the JSON does not parse \(.+\)$/) });
  });

  it('refuses a first chunk that is not JSON, naming it', () => {
    const glb = glbOfChunks([{ type: BIN_TYPE, data: enc(ASSET) }]);
    expect(refusal(glb)).toEqual({ path: 'GLB chunk 0 (byte 12)', message: 'the first chunk is not JSON' });
  });

  it('reads a chunk whose size is not a multiple of 4, skipping its padding to the next chunk', () => {
    const text = enc(JSON.stringify(TRIANGLE_JSON));
    expect(text.length % 4).not.toBe(0);
    const glb = glbOfChunks([{ type: JSON_TYPE, data: text, unpadded: true }, { type: BIN_TYPE, data: TRIANGLE_BIN }]);
    const c = readContainer(glb, 'c.glb');
    expect(c.glb).toBe(true);
    expect(Array.from(c.bin!)).toEqual(Array.from(TRIANGLE_BIN));
    expect(Array.from(parse(glb).positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
  });

  it('takes only a second chunk of type BIN as the BIN chunk: an unknown chunk is skipped, a later BIN is not read', () => {
    const json = enc(JSON.stringify(TRIANGLE_JSON));
    const unknown = { type: 0x12345678, data: TRIANGLE_BIN };
    const bin = { type: BIN_TYPE, data: TRIANGLE_BIN };
    expect(readContainer(glbOfChunks([{ type: JSON_TYPE, data: json }, unknown]), 'c.glb').bin).toBeNull();
    expect(readContainer(glbOfChunks([{ type: JSON_TYPE, data: json }, unknown, bin]), 'c.glb').bin).toBeNull();
    expect(() => parse(glbOfChunks([{ type: JSON_TYPE, data: json }, unknown, bin]))).toThrow('buffers[0] has no uri and the file has no BIN chunk for it');
    // The same BIN as the second chunk is read, and a third chunk after it (unknown or BIN) is skipped.
    const withBin = readContainer(glbOfChunks([{ type: JSON_TYPE, data: json }, bin, unknown]), 'c.glb');
    expect(withBin.bin?.length).toBe(44);
    const other = new Uint8Array(44).fill(7);
    const twoBins = glbOfChunks([{ type: JSON_TYPE, data: json }, bin, { type: BIN_TYPE, data: other }]);
    expect(Array.from(parse(twoBins).positions)).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
  });
});

describe('the JSON text', () => {
  it('skips one byte-order mark: a second one is text, which JSON refuses', () => {
    const bom = [0xef, 0xbb, 0xbf];
    expect(readContainer(new Uint8Array([...bom, ...enc(ASSET)]), 'a.gltf').json).toEqual({ asset: { version: '2.0' } });
    expect(refusal(new Uint8Array([...bom, ...bom, ...enc(ASSET)]), 'a.gltf')).toMatchObject({
      path: 'JSON', message: expect.stringMatching(/^the JSON does not parse \(.+\)$/),
    });
  });

  it('refuses text that does not parse with JSON.parse\'s reason', () => {
    let reason = '';
    try {
      JSON.parse('{"asset": ');
    } catch (e) {
      reason = (e as Error).message;
    }
    expect(refusal(enc('{"asset": '), 'a.gltf')).toEqual({ path: 'JSON', message: `the JSON does not parse (${reason})` });
  });
});
