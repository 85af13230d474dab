// glTF buffers and buffer views (src/loaders/gltf/buffers.ts, docs/gltf.md#buffers): which URIs the
// caller fetches, the bytes of the BIN chunk, of data: URIs and of fetched files, each too-short
// source named in its error, and a view's range and stride checked against its buffer.
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { GltfFile } from '../../src/loaders/gltf/fields';
import { bufferView, externalBuffers, resolveBuffers } from '../../src/loaders/gltf/buffers';

const file = (json: Record<string, unknown>) => new GltfFile('m.gltf', json);
const bytes = (...b: number[]) => new Uint8Array(b);

/** The path and message of the LoadError `read` throws. */
function refusal(read: () => unknown): { path: string | undefined; message: string } {
  try {
    read();
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    return { path: (e as LoadError).path, message: (e as LoadError).detail.message };
  }
  throw new Error('read without an error');
}

describe('external buffers', () => {
  it('lists only buffers with a uri that is not a data: URI, by index, the uri as written', () => {
    const f = file({
      buffers: [
        { byteLength: 4 }, { byteLength: 4, uri: 'data:application/octet-stream;base64,AAAAAA==' },
        { byteLength: 4, uri: 'DATA:application/octet-stream;base64,AAAAAA==' }, { byteLength: 4, uri: 'parts/a%20b.bin' },
        // A relative path with "data:" in a later segment is a file, not a data: URI.
        { byteLength: 4, uri: 'parts/data:1.bin' },
      ],
    });
    expect(externalBuffers(f)).toEqual([{ index: 3, uri: 'parts/a%20b.bin' }, { index: 4, uri: 'parts/data:1.bin' }]);
    expect(externalBuffers(file({ buffers: [{ byteLength: 4 }] }))).toEqual([]);
    expect(externalBuffers(file({}))).toEqual([]);
  });

  it('refuses a buffer that is not an object, or a uri that is not a string, by its path', () => {
    expect(refusal(() => externalBuffers(file({ buffers: [5] })))).toEqual({ path: 'buffers[0]', message: 'buffers[0] is not an object' });
    expect(refusal(() => externalBuffers(file({ buffers: [{ byteLength: 1 }, { byteLength: 1, uri: 3 }] })))).toEqual({
      path: 'buffers[1].uri', message: 'buffers[1].uri is 3, not a string',
    });
  });
});

describe('resolved buffers', () => {
  it('takes buffers[0] without a uri from the BIN chunk, cut to its byteLength', () => {
    const [b] = resolveBuffers(file({ buffers: [{ byteLength: 3 }] }), bytes(1, 2, 3, 4), new Map());
    expect(Array.from(b)).toEqual([1, 2, 3]);
  });

  it('refuses a buffer without a uri where there is no BIN chunk, or that is not buffers[0]', () => {
    expect(refusal(() => resolveBuffers(file({ buffers: [{ byteLength: 4 }] }), null, new Map()))).toEqual({
      path: 'buffers[0]', message: 'buffers[0] has no uri and the file has no BIN chunk for it',
    });
    const two = file({ buffers: [{ byteLength: 4 }, { byteLength: 4 }] });
    expect(refusal(() => resolveBuffers(two, bytes(1, 2, 3, 4), new Map()))).toEqual({
      path: 'buffers[1]', message: 'buffers[1] has no uri and the file has no BIN chunk for it',
    });
  });

  it('names the source that is shorter than the byteLength declared: the BIN chunk, a data: URI, a fetched file', () => {
    expect(refusal(() => resolveBuffers(file({ buffers: [{ byteLength: 8 }] }), bytes(1, 2, 3, 4), new Map()))).toEqual({
      path: 'buffers[0].byteLength', message: 'buffers[0] declares 8 bytes, the BIN chunk has 4',
    });
    const data = file({ buffers: [{ byteLength: 8, uri: 'data:application/octet-stream;base64,AQID' }] });
    expect(refusal(() => resolveBuffers(data, null, new Map()))).toEqual({
      path: 'buffers[0].byteLength', message: 'buffers[0] declares 8 bytes, its data: URI has 3',
    });
    const ext = file({ buffers: [{ byteLength: 8, uri: 'a.bin' }] });
    expect(refusal(() => resolveBuffers(ext, null, new Map([[0, bytes(1, 2)]])))).toEqual({
      path: 'buffers[0].byteLength', message: 'buffers[0] declares 8 bytes, "a.bin" has 2',
    });
    expect(refusal(() => resolveBuffers(ext, null, new Map()))).toEqual({ path: 'buffers[0].uri', message: 'buffers[0]: "a.bin" was not loaded' });
  });

  it('reads a fetched file whose path has "data:" in a later segment as a file', () => {
    const f = file({ buffers: [{ byteLength: 2, uri: 'parts/data:1.bin' }] });
    expect(Array.from(resolveBuffers(f, null, new Map([[0, bytes(9, 8, 7)]]))[0])).toEqual([9, 8]);
  });

  it('decodes base64 data: URIs, whitespace and all, and refuses one that is not base64', () => {
    const uri = 'data:application/octet-stream;base64,AQID\n BAUG';
    expect(Array.from(resolveBuffers(file({ buffers: [{ byteLength: 6, uri }] }), null, new Map())[0])).toEqual([1, 2, 3, 4, 5, 6]);
    for (const bad of ['data:application/octet-stream,AQID', 'data:application/octet-stream;base64=no,AQID', 'data:;base64']) {
      expect(refusal(() => resolveBuffers(file({ buffers: [{ byteLength: 1, uri: bad }] }), null, new Map())), bad).toEqual({
        path: 'buffers[0].uri', message: 'buffers[0].uri is a data: URI that is not base64',
      });
    }
    const broken = file({ buffers: [{ byteLength: 1, uri: 'data:application/octet-stream;base64,A' }] });
    expect(refusal(() => resolveBuffers(broken, null, new Map()))).toEqual({ path: 'buffers[0].uri', message: 'buffers[0].uri: its base64 does not decode' });
  });
});

describe('buffer views', () => {
  const buffers = [new Uint8Array(16).map((_, i) => i)];
  const view = (v: Record<string, unknown>) => bufferView(file({ bufferViews: [v] }), buffers, 0, 'accessors[0].bufferView');

  it('reads a view\'s range of its buffer, with its stride', () => {
    expect(view({ buffer: 0, byteOffset: 4, byteLength: 8 })).toEqual({ bytes: buffers[0].subarray(4, 12), stride: undefined });
    expect(Array.from(view({ buffer: 0, byteOffset: 12, byteLength: 4 }).bytes)).toEqual([12, 13, 14, 15]);
    expect(view({ buffer: 0, byteLength: 16, byteStride: 4 }).stride).toBe(4);
    expect(view({ buffer: 0, byteLength: 16, byteStride: 252 }).stride).toBe(252);
  });

  it('refuses a view of a buffer that does not exist, or past the end of its buffer, with the bytes it names', () => {
    expect(refusal(() => view({ buffer: 1, byteLength: 4 }))).toEqual({ path: 'bufferViews[0].buffer', message: 'buffers[1] does not exist (buffers has 1)' });
    expect(refusal(() => view({ buffer: 0, byteOffset: 10, byteLength: 8 }))).toEqual({
      path: 'bufferViews[0]', message: 'bufferViews[0] (bytes 10 to 18) runs past the end of buffers[0] (16 bytes)',
    });
  });

  it('refuses a stride outside [4, 252]', () => {
    for (const byteStride of [3, 253]) {
      expect(refusal(() => view({ buffer: 0, byteLength: 16, byteStride }))).toEqual({
        path: 'bufferViews[0].byteStride', message: `bufferViews[0].byteStride is ${byteStride}, outside [4, 252]`,
      });
    }
  });
});

describe('meshopt fallback buffers', () => {
  const fallback = (more: Record<string, unknown> = {}) => ({ byteLength: 4, extensions: { EXT_meshopt_compression: { fallback: true } }, ...more });
  const data = 'data:application/octet-stream;base64,AQIDBA==';

  it('is never fetched; its extension, when not an object, is named by the buffer\'s path', () => {
    expect(externalBuffers(file({ buffers: [fallback({ uri: 'f.bin' }), { byteLength: 4, uri: 'g.bin' }] }))).toEqual([{ index: 1, uri: 'g.bin' }]);
    expect(refusal(() => externalBuffers(file({ buffers: [{ byteLength: 4, uri: 'g.bin' }, { byteLength: 4, uri: 'f.bin', extensions: 3 }] })))).toEqual({
      path: 'buffers[1].extensions', message: 'buffers[1].extensions is not an object',
    });
  });

  it('is read where its bytes are at hand (the BIN chunk for buffers[0], a data: URI, a fetched file), else empty, never an error', () => {
    const bin = bytes(1, 2, 3, 4);
    expect(resolveBuffers(file({ buffers: [fallback()] }), bin, new Map())).toEqual([bin]);
    expect(resolveBuffers(file({ buffers: [fallback()] }), null, new Map())).toEqual([bytes()]);
    // Without a uri, only buffers[0] may take the BIN chunk.
    expect(resolveBuffers(file({ buffers: [{ byteLength: 4 }, fallback()] }), bin, new Map())).toEqual([bin, bytes()]);
    expect(resolveBuffers(file({ buffers: [fallback({ uri: data })] }), null, new Map())).toEqual([bin]);
    expect(resolveBuffers(file({ buffers: [fallback({ uri: 'f.bin' })] }), null, new Map([[0, bin]]))).toEqual([bin]);
    expect(resolveBuffers(file({ buffers: [fallback({ uri: 'f.bin' })] }), bin, new Map())).toEqual([bytes()]);
    // "data:" later in a path is a file name, not a data: URI: not at hand unless fetched.
    expect(resolveBuffers(file({ buffers: [fallback({ uri: 'parts/data:1.bin' })] }), null, new Map())).toEqual([bytes()]);
  });

  it('a view decoded from meshopt reads the decoded bytes, cut to the view\'s byteLength', () => {
    const f = file({ bufferViews: [{ buffer: 0, byteLength: 3, byteStride: 4 }] });
    f.decodedViews = new Map([[0, bytes(9, 8, 7, 6, 5)]]);
    expect(bufferView(f, [], 0, 'x')).toEqual({ bytes: bytes(9, 8, 7), stride: 4 });
    f.decodedViews = new Map([[0, bytes(9, 8)]]);
    expect(bufferView(f, [], 0, 'x')).toEqual({ bytes: bytes(9, 8), stride: 4 });
  });
});
