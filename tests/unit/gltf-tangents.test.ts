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
  it('u along +x, v along +y (the image upside down, v running up it): T = +x, N × T = +y along ∂p/∂v: w = −1', () => {
    expect(round(quad((x, y) => [x, y]))).toEqual([1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1, 1, 0, 0, -1]);
  });

  it('v along −y (an image drawn upright: glTF\'s v runs down): T = +x, N × T = +y against ∂p/∂v = −y: w = +1, the bitangent its top', () => {
    expect(round(quad((x, y) => [x, 1 - y]))).toEqual([1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1]);
  });

  it('u along +y, v along +x (UVs turned a quarter): T = +y, N × T = −x against ∂p/∂v = +x: w = +1', () => {
    expect(round(quad((x, y) => [y, x]))).toEqual([0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1]);
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
    // N × T = (0, 2s², 0) = +y, along ∂p/∂v (v runs up the triangle here): w = −1.
    expect(round(t.subarray(0, 4))).toEqual([Number(s.toFixed(6)), 0, -Number(s.toFixed(6)), -1]);
  });

  // An affine map p = p0 + T·(u − u0) + B·(v − v0): every triangle of it has ∂p/∂u = T and ∂p/∂v = B,
  // whatever its corners, so the tangent is T made orthogonal to the vertex's normal, by construction.
  const T = [2, 1, -2], B = [1, 2, 2.5];
  const P0 = [1, 2, 3], UV0 = [0.2, 0.3];
  const at = (u: number, v: number) => [0, 1, 2].map((c) => P0[c] + T[c] * (u - UV0[0]) + B[c] * (v - UV0[1]));
  const cross = (a: number[], b: number[]) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
  const unit = (a: number[]) => a.map((x) => x / Math.hypot(...a));
  const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  /** Vertices at these UVs on the affine map, each with `normal`, and `indices`. */
  function mapped(uvs: number[][], normal: number[], indices: number[]): Float32Array {
    return computeTangents(new Float32Array(uvs.flatMap(([u, v]) => at(u, v))), new Float32Array(uvs.flatMap(() => normal)),
      new Float32Array(uvs.flat()), new Uint32Array(indices));
  }
  const expectTangent = (t: Float32Array, i: number, xyz: number[], w: number) => {
    [...xyz, w].forEach((x, c) => expect(t[4 * i + c], `vertex ${i}, component ${c}`).toBeCloseTo(x, 5));
  };

  it('follows ∂p/∂u on a triangle placed anywhere, of any UV area, its normal tilted off the face', () => {
    // UV area (0.5·0.4 − (−0.2)·0.1) = 0.22; the normal leans off the face's in all three axes.
    const uvs = [UV0, [UV0[0] + 0.5, UV0[1] + 0.1], [UV0[0] - 0.2, UV0[1] + 0.4]];
    const normal = unit(cross(T, B).map((x, c) => x + [3, 4, 2][c]));
    const t = mapped(uvs, normal, [0, 1, 2]);
    const expected = unit(T.map((x, c) => x - normal[c] * dot(normal, T)));
    // (N × T) · B > 0 with N near T × B: w = −1.
    for (let i = 0; i < 3; i++) expectTangent(t, i, expected, -1);
    // Mirrored (the normal turned over): (N × T) · B < 0, w = +1.
    const flipped = normal.map((x) => -x);
    const m = mapped(uvs, flipped, [0, 1, 2]);
    for (let i = 0; i < 3; i++) expectTangent(m, i, unit(T.map((x, c) => x - flipped[c] * dot(flipped, T))), 1);
  });

  it('sums a shared vertex\'s triangles, a triangle of no UV area adding nothing', () => {
    // Vertices 0–3 on the map; triangle (0, 2, 3) is a second one on it, (0, 1, 4) has vertex 4 at vertex 1's UV
    // and place moved: no UV area. Vertex 0 keeps T; vertex 4, with no other triangle, gets the fallback.
    const uvs = [UV0, [0.7, 0.4], [0.1, 0.8], [0.9, 0.9], [0.7, 0.4]];
    const normal = unit(cross(T, B));
    const indices = [0, 1, 2, 0, 2, 3, 0, 1, 4];
    const positions = new Float32Array(uvs.flatMap(([u, v]) => at(u, v)));
    positions.set([9, -4, 7], 12);
    const t = computeTangents(positions, new Float32Array(uvs.flatMap(() => normal)), new Float32Array(uvs.flat()), new Uint32Array(indices));
    for (let i = 0; i < 4; i++) expectTangent(t, i, unit(T), -1);
    // Vertex 4's fallback: N's y is the largest of its components below 0.9, so (0, nz, −ny) made unit; no ∂p/∂v: w = +1.
    expect(Math.abs(normal[0])).toBeLessThan(0.9);
    expectTangent(t, 4, unit([0, normal[2], -normal[1]]), 1);
  });

  it('adds each triangle\'s ∂p/∂u whole, whatever its UV area: a vertex between two slopes takes their sum', () => {
    // Triangle (0, 1, 2) on the map above (UV area 0.22); triangle (0, 3, 4) on a second map through the same
    // corner, p0 + T2·Δu + B2·Δv, of UV area 0.02: vertex 0's tangent is T + T2 made orthogonal to its normal.
    // B2 against B, and the second triangle small: ∂p/∂v summed whole points against B, which a sum weighted by UV area would not.
    const T2 = [-1, 3, 0.5], B2 = B.map((x) => -3 * x);
    const at2 = (du: number, dv: number) => [0, 1, 2].map((c) => P0[c] + T2[c] * du + B2[c] * dv);
    const uvs = [UV0, [UV0[0] + 0.5, UV0[1] + 0.1], [UV0[0] - 0.2, UV0[1] + 0.4], [UV0[0] + 0.1, UV0[1]], [UV0[0], UV0[1] + 0.2]];
    const positions = [at(...(uvs[0] as [number, number])), at(...(uvs[1] as [number, number])), at(...(uvs[2] as [number, number])), at2(0.1, 0), at2(0, 0.2)];
    const normal = unit(cross(T, B));
    const t = computeTangents(new Float32Array(positions.flat()), new Float32Array(uvs.flatMap(() => normal)), new Float32Array(uvs.flat()),
      new Uint32Array([0, 1, 2, 0, 3, 4]));
    const sum = T.map((x, c) => x + T2[c]);
    const t0 = unit(sum.map((x, c) => x - normal[c] * dot(normal, sum)));
    const w0 = -Math.sign(dot(cross(normal, t0), B.map((x, c) => x + B2[c])));
    expect(w0).toBe(1);
    expect(Math.sign(dot(cross(normal, t0), B))).toBe(1);
    expectTangent(t, 0, t0, w0);
    expectTangent(t, 3, unit(T2.map((x, c) => x - normal[c] * dot(normal, T2))), -Math.sign(dot(cross(normal, unit(T2.map((x, c) => x - normal[c] * dot(normal, T2)))), B2)));
  });

  it('signs w by (N × T) · ∂p/∂v with every term of the cross product: N = (0.8, 0, 0.6), T = (0.6, 0, −0.8), ∂p/∂v = +y', () => {
    // N × T = (0, 0.6 · 0.6 + 0.8 · 0.8, 0) = +y along ∂p/∂v: w = −1 (the y term alone decides it).
    const t = computeTangents(new Float32Array([0, 0, 0, 0.6, 0, -0.8, 0, 1, 0]), new Float32Array([0.8, 0, 0.6, 0.8, 0, 0.6, 0.8, 0, 0.6]),
      new Float32Array([0, 0, 1, 0, 0, 1]), new Uint32Array([0, 1, 2]));
    expectTangent(t, 0, [0.6, 0, -0.8], -1);
  });

  it('falls back, without UVs, to (0, nz, −ny) or (−nz, 0, nx) made unit, and to zero for a zero normal', () => {
    const lone = (normal: number[]) => computeTangents(new Float32Array(9), new Float32Array([...normal, ...normal, ...normal]), new Float32Array(6), new Uint32Array([0, 1, 2]));
    expectTangent(lone([0.6, 0, 0.8]), 0, [0, 1, 0], 1); // |nx| < 0.9: (0, 0.8, 0) made unit
    expectTangent(lone([0.96, 0.28, 0]), 0, [0, 0, 1], 1); // |nx| ≥ 0.9: (0, 0, 0.96) made unit
    expectTangent(lone([-0.96, 0, 0.28]), 1, [-0.28, 0, -0.96], 1); // |nx| ≥ 0.9: (−0.28, 0, −0.96), already unit
    expectTangent(lone([0, 0, 0]), 2, [0, 0, 0], 1);
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
      // TEXCOORD_0 along +x/+y, TEXCOORD_1 (which the map reads) turned a quarter: T = +y, w = +1.
      TEXCOORD_0: accessor(doc, 'VEC2', new Float32Array([0, 0, 1, 0, 1, 1, 0, 1])),
      TEXCOORD_1: accessor(doc, 'VEC2', new Float32Array([0, 0, 0, 1, 1, 1, 1, 0])),
    });
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, square, [0, 1, 2, 0, 2, 3], extra(), mapped)));
    const r = parse(await glbOf(doc));
    expect(round(r.tangents!)).toEqual([0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1, 0, 1]);
    const { doc: plainDoc, root: plainRoot } = newDocument();
    plainRoot.setMesh(plainDoc.createMesh().addPrimitive(primitive(plainDoc, square, [0, 1, 2, 0, 2, 3])));
    expect(parse(await glbOf(plainDoc)).tangents).toBeNull();
  });
});
