// Two small steps of the glTF reader held by hand: primitives merged into one vertex and index
// buffer grouped by material (src/loaders/gltf/merge.ts, docs/gltf.md#primitives), and images as
// references with their names, MIME types and paths (src/loaders/gltf/images.ts, docs/gltf.md#images).
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { GltfFile } from '../../src/loaders/gltf/fields';
import { readImages } from '../../src/loaders/gltf/images';
import { mergePieces } from '../../src/loaders/gltf/merge';
import type { Piece } from '../../src/loaders/gltf/primitives';

const f32 = (...v: number[]) => new Float32Array(v);

/** A piece of `n` vertices whose every value is `tag` (so each piece's values show where they land). */
function piece(n: number, tag: number, material: number | null, indices: number[], extra: Partial<Piece> = {}): Piece {
  const filled = (k: number) => new Float32Array(n * k).fill(tag);
  return { positions: filled(3), normals: filled(3), uv0: null, uv1: null, colors: null, tangents: null, indices: new Uint32Array(indices), material, ...extra };
}

describe('mergePieces', () => {
  it('hands one piece on as it is, without copying its arrays', () => {
    const p = piece(3, 1, 2, [0, 1, 2], { uv0: f32(0, 0, 1, 0, 0, 1) });
    const m = mergePieces([p]);
    expect(m.positions).toBe(p.positions);
    expect(m.uv0).toBe(p.uv0);
    expect(m.indices).toBe(p.indices);
    expect(m.groups).toEqual([{ material: 2, start: 0, count: 3 }]);
  });

  it('concatenates vertices, offsets each piece\'s indices by its first vertex, and groups by material in order of first use', () => {
    const a = piece(3, 1, 5, [0, 1, 2]);
    const b = piece(2, 2, null, [1, 0, 1]);
    const c = piece(1, 3, 5, [0, 0, 0]);
    const m = mergePieces([a, b, c]);
    expect([...m.positions]).toEqual([1, 1, 1, 1, 1, 1, 1, 1, 1, 2, 2, 2, 2, 2, 2, 3, 3, 3]);
    expect([...m.normals]).toEqual([...m.positions]);
    // Material 5 first (a, then c at vertex 5), then the default material (b at vertex 3).
    expect([...m.indices]).toEqual([0, 1, 2, 5, 5, 5, 4, 3, 4]);
    expect(m.groups).toEqual([{ material: 5, start: 0, count: 6 }, { material: null, start: 6, count: 3 }]);
    expect([m.uv0, m.uv1, m.colors, m.tangents]).toEqual([null, null, null, null]);
  });

  it('gives every piece each attribute some piece has: zeros where it lacks UVs or tangents, white where it lacks colours', () => {
    const withAll = { uv0: f32(0.5, 0.25), uv1: f32(0.75, 1), colors: f32(0.1, 0.2, 0.3, 0.4), tangents: f32(1, 0, 0, -1) };
    // The piece that has them starts at vertex 2 (at 1, 2 / at and 2 * at would agree).
    const bare = () => piece(1, 0, 0, [0, 0, 0]);
    const m = mergePieces([bare(), bare(), piece(1, 0, 0, [0, 0, 0], withAll), bare()]);
    expect([...m.uv0!]).toEqual([0, 0, 0, 0, 0.5, 0.25, 0, 0]);
    expect([...m.uv1!]).toEqual([0, 0, 0, 0, 0.75, 1, 0, 0]);
    expect([...m.colors!]).toEqual([1, 1, 1, 1, 1, 1, 1, 1, ...[0.1, 0.2, 0.3, 0.4].map(Math.fround), 1, 1, 1, 1]);
    expect([...m.tangents!]).toEqual([0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 0]);
  });
});

describe('readImages', () => {
  const read = (json: Record<string, unknown>, buffers: Uint8Array[] = []) => {
    const file = new GltfFile('i.gltf', json);
    return { images: readImages(file, buffers), warnings: file.warnings };
  };
  const refusal = (json: Record<string, unknown>) => {
    try {
      read(json);
    } catch (e) {
      expect(e).toBeInstanceOf(LoadError);
      return { path: (e as LoadError).path, message: (e as LoadError).detail.message };
    }
    throw new Error('read without an error');
  };

  it('names an image by its index, and by its name when it has one (quoted, cut at 60 characters)', () => {
    const long = 'x'.repeat(70);
    const { images } = read({ images: [{ uri: 'a b.png' }, { uri: 'c.png', name: 'shoe' }, { uri: 'd.png', name: long }] });
    expect(images).toEqual([
      { kind: 'uri', uri: 'a b.png', name: 'images[0]' },
      { kind: 'uri', uri: 'c.png', name: 'images[1] "shoe"' },
      { kind: 'uri', uri: 'd.png', name: `images[2] "${'x'.repeat(59)}` },
    ]);
  });

  it('reads a buffer view\'s bytes with the MIME type, and warns once, with the path, for a type glTF does not name', () => {
    const buffers = [new Uint8Array([1, 2, 3, 4, 5, 6])];
    const bufferViews = [{ buffer: 0, byteOffset: 2, byteLength: 3 }];
    for (const mimeType of ['image/png', 'image/jpeg', 'image/webp', 'image/ktx2']) {
      const r = read({ images: [{ bufferView: 0, mimeType }], bufferViews }, buffers);
      expect(r.images).toEqual([{ kind: 'bytes', bytes: new Uint8Array([3, 4, 5]), mimeType, name: 'images[0]' }]);
      expect(r.warnings).toEqual([]);
    }
    const odd = read({ images: [{ uri: 'a.png' }, { bufferView: 0, mimeType: 'image/gif' }, { bufferView: 0 }], bufferViews }, buffers);
    expect(odd.images.map((i) => i.kind === 'bytes' && i.mimeType)).toEqual([false, 'image/gif', '']);
    expect(odd.warnings).toEqual([
      { path: 'images[1].mimeType', message: 'images[1].mimeType is "image/gif": read by its content' },
      { path: 'images[2].mimeType', message: 'images[2].mimeType is "": read by its content' },
    ]);
  });

  it('refuses an image with neither a uri nor a buffer view, and names the buffer view it reads', () => {
    expect(refusal({ images: [{ uri: 'a.png' }, { mimeType: 'image/png' }] })).toEqual({ path: 'images[1]', message: 'images[1] has neither a uri nor a bufferView' });
    expect(refusal({ images: [{ bufferView: 2, mimeType: 'image/png' }] })).toEqual({ path: 'images[0].bufferView', message: 'bufferViews[2] does not exist (bufferViews has 0)' });
    expect(refusal({ images: [{ uri: 4 }] })).toEqual({ path: 'images[0].uri', message: 'images[0].uri is 4, not a string' });
  });
});
