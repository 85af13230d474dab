// Tangents computed where a normal map needs them (src/loaders/gltf/tangents.ts, docs/gltf.md#tangents),
// against values worked out by hand: a quad in the z = 0 plane under three UV layouts.
import { describe, expect, it } from 'vitest';
import { computeTangents } from '../../src/loaders/gltf/tangents';

/** The unit square (0,0)–(1,1) at z = 0, normal +z, two triangles; `uv(x, y)` gives each corner's UV. */
function quad(uv: (x: number, y: number) => [number, number]): Float32Array {
  const corners = [[0, 0], [1, 0], [1, 1], [0, 1]];
  return computeTangents(
    new Float32Array(corners.flatMap(([x, y]) => [x, y, 0])), new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
    new Float32Array(corners.flatMap(([x, y]) => uv(x, y))), new Uint32Array([0, 1, 2, 0, 2, 3]),
  );
}
const round = (a: Float32Array) => Array.from(a, (x) => Number(x.toFixed(6)) + 0);

describe('computeTangents', () => {
  it('u along +x, v along +y: T = +x, and N × T = +y points along ∂p/∂v: w = +1', () => {
    expect(round(quad((x, y) => [x, y]))).toEqual([1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1]);
  });

  it('v along −y (an image drawn upright: glTF\'s v runs down): T = +x, ∂p/∂v = −y: w = −1', () => {
    expect(round(quad((x, y) => [x, 1 - y]))).toEqual([1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1]);
  });

  it('u along +y, v along +x (UVs turned a quarter): T = +y, N × T = −x against ∂p/∂v = +x: w = −1', () => {
    expect(round(quad((x, y) => [y, x]))).toEqual([0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1]);
  });

  it('gives a vertex of no UV area a unit tangent perpendicular to its normal', () => {
    const t = quad(() => [0.5, 0.5]);
    for (let i = 0; i < 4; i++) {
      const [x, y, z] = t.subarray(4 * i, 4 * i + 3);
      expect(Math.hypot(x, y, z)).toBeCloseTo(1, 6);
      expect(z + 0).toBe(0);
    }
  });

  it('makes a tangent orthogonal to a tilted normal (Gram-Schmidt)', () => {
    // One triangle, normals tilted toward +x by 45°: T = normalize(x̂ − N(N·x̂)) = (1, 0, −1)/√2.
    const s = Math.SQRT1_2;
    const t = computeTangents(new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]), new Float32Array([s, 0, s, s, 0, s, s, 0, s]),
      new Float32Array([0, 0, 1, 0, 0, 1]), new Uint32Array([0, 1, 2]));
    expect(round(t.subarray(0, 4))).toEqual([Number(s.toFixed(6)), 0, -Number(s.toFixed(6)), 1]);
  });
});

describe('tangents in a read model', () => {
  it('computes them for a normal-mapped material without TANGENT, from the UV set its map reads; none without a normal map', async () => {
    const { newDocument, primitive, accessor, glbOf, parse } = await import('./helpers/gltf');
    const { PNG } = await import('pngjs');
    const image = new PNG({ width: 1, height: 1 });
    const png = new Uint8Array(PNG.sync.write(image));
    const { doc, root } = newDocument();
    const mapped = doc.createMaterial('mapped').setNormalTexture(doc.createTexture().setImage(png).setMimeType('image/png'));
    mapped.getNormalTextureInfo()!.setTexCoord(1);
    const square = [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0];
    const extra = () => ({
      NORMAL: accessor(doc, 'VEC3', new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1])),
      // TEXCOORD_0 along +x/+y, TEXCOORD_1 (which the map reads) turned a quarter: T = +y, w = −1.
      TEXCOORD_0: accessor(doc, 'VEC2', new Float32Array([0, 0, 1, 0, 1, 1, 0, 1])),
      TEXCOORD_1: accessor(doc, 'VEC2', new Float32Array([0, 0, 0, 1, 1, 1, 1, 0])),
    });
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, square, [0, 1, 2, 0, 2, 3], extra(), mapped)));
    const r = parse(await glbOf(doc));
    expect(round(r.tangents!)).toEqual([0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1, 0, 1, 0, -1]);
    const { doc: plainDoc, root: plainRoot } = newDocument();
    plainRoot.setMesh(plainDoc.createMesh().addPrimitive(primitive(plainDoc, square, [0, 1, 2, 0, 2, 3])));
    expect(parse(await glbOf(plainDoc)).tangents).toBeNull();
  });
});
