// The Gaussian surface and truly per-face flat meshes (docs/scene-model.md#built-in-shapes, docs/scene-model.md#shading-modes).
import { beforeEach, describe, expect, it } from 'vitest';
import { gaussianHeight, gaussianMesh } from '../../src/scene/geometry/gaussian';
import { flatMesh } from '../../src/scene/geometry/flat';
import { sphereMesh } from '../../src/scene/geometry/sphere';
import type { MeshData } from '../../src/scene/geometry/mesh-data';

const v3 = (a: Float32Array, i: number) => [a[3 * i], a[3 * i + 1], a[3 * i + 2]];
const sub = (a: number[], b: number[]) => a.map((x, i) => x - b[i]);
const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: number[], b: number[]) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

/** Unnormalised face normal of triangle t, from its corners in index order. */
function faceNormal(m: MeshData, t: number): number[] {
  const [a, b, c] = [0, 1, 2].map((k) => v3(m.positions, m.indices[3 * t + k]));
  return cross(sub(b, a), sub(c, a));
}

describe('gaussianMesh', () => {
  it('has N² vertices and 2(N − 1)² triangles, corners exactly on ±2', () => {
    const m = gaussianMesh(40);
    expect(m.positions.length / 3).toBe(1600);
    expect(m.indices.length / 3).toBe(2 * 39 * 39);
    expect(v3(m.positions, 0)).toEqual([-2, Math.fround(gaussianHeight(-2, -2)), -2]);
    expect(v3(m.positions, 1599).map((x) => Math.fround(x))).toEqual([2, Math.fround(Math.exp(-8)), 2]);
  });

  it('lies on y = e^(−x²)·e^(−z²), peak 1 at the origin (odd N puts a vertex there)', () => {
    const m = gaussianMesh(41);
    for (let v = 0; v < 41 * 41; v++) {
      const [x, y, z] = v3(m.positions, v);
      expect(Math.abs(y - Math.exp(-x * x) * Math.exp(-z * z))).toBeLessThan(1e-7);
    }
    expect(v3(m.positions, 20 * 41 + 20)).toEqual([0, 1, 0]);
  });

  it('normals are the surface normal: unit, and orthogonal to the surface tangents by finite differences', () => {
    const m = gaussianMesh(33);
    const h = 1e-4;
    for (const v of [0, 100, 16 * 33 + 10, 500, 1088]) {
      const [x, , z] = v3(m.positions, v);
      const n = v3(m.normals, v);
      expect(Math.abs(Math.hypot(n[0], n[1], n[2]) - 1)).toBeLessThan(1e-6);
      const tx = [2 * h, gaussianHeight(x + h, z) - gaussianHeight(x - h, z), 0];
      const tz = [0, gaussianHeight(x, z + h) - gaussianHeight(x, z - h), 2 * h];
      expect(Math.abs(dot(n, tx)) / (2 * h)).toBeLessThan(1e-5);
      expect(Math.abs(dot(n, tz)) / (2 * h)).toBeLessThan(1e-5);
      expect(n[1]).toBeGreaterThan(0);
    }
  });

  it('triangles wind counter-clockwise seen from +Y (face normals agree with the vertex normals)', () => {
    const m = gaussianMesh(12);
    for (let t = 0; t < m.indices.length / 3; t++) expect(faceNormal(m, t)[1]).toBeGreaterThan(0);
  });

  it('UVs span [0, 1]² with u along x and v along z', () => {
    const m = gaussianMesh(5);
    expect([m.uvs[0], m.uvs[1]]).toEqual([0, 0]);
    expect([m.uvs[2 * 4], m.uvs[2 * 4 + 1]]).toEqual([1, 0]);
    expect([m.uvs[2 * 20], m.uvs[2 * 20 + 1]]).toEqual([0, 1]);
  });

  it('clamps the resolution to 2..1024 and switches to 32-bit indices from 65,536 vertices', () => {
    expect(gaussianMesh(1).positions.length / 3).toBe(4);
    expect(gaussianMesh(5000).positions.length / 3).toBe(1024 * 1024);
    expect(gaussianMesh(255).indices).toBeInstanceOf(Uint16Array); // 65,025 vertices
    // 256² = 65,536: the last index, 65,535, is WebGL2's fixed primitive-restart index for
    // 16-bit indices, so it needs 32 bits.
    const big = gaussianMesh(256);
    expect(big.indices).toBeInstanceOf(Uint32Array);
    expect(Math.max(...big.indices.subarray(big.indices.length - 3))).toBe(256 * 256 - 1);
  });
});

describe('flatMesh', () => {
  let sphere: ReturnType<typeof sphereMesh>, flat: ReturnType<typeof flatMesh>;
  beforeEach(() => {
    sphere = sphereMesh(0.75, 16);
    flat = flatMesh(sphere);
  });

  it('keeps every triangle and corner position, each triangle with three vertices of its own', () => {
    expect(flat.indices.length).toBe(sphere.indices.length);
    for (let v = 0; v < flat.indices.length; v++) {
      expect(flat.indices[v]).toBe(v);
      expect(v3(flat.positions, v)).toEqual(v3(sphere.positions, sphere.indices[v]));
    }
  });

  it('gives the three vertices of a triangle one unit face normal, orthogonal to its edges and outward', () => {
    for (let t = 0; t < flat.indices.length / 3; t++) {
      const [n0, n1, n2] = [0, 1, 2].map((k) => v3(flat.normals, 3 * t + k));
      expect(n1).toEqual(n0);
      expect(n2).toEqual(n0);
      expect(Math.abs(Math.hypot(n0[0], n0[1], n0[2]) - 1)).toBeLessThan(1e-6);
      const [a, b, c] = [0, 1, 2].map((k) => v3(flat.positions, 3 * t + k));
      expect(Math.abs(dot(n0, sub(b, a)))).toBeLessThan(1e-6);
      expect(Math.abs(dot(n0, sub(c, a)))).toBeLessThan(1e-6);
      expect(dot(n0, a), 'outward on a sphere centred at the origin').toBeGreaterThan(0);
    }
  });

  it('gives the three vertices of a triangle its centroid', () => {
    for (let t = 0; t < flat.indices.length / 3; t++) {
      const [a, b, c] = [0, 1, 2].map((k) => v3(flat.positions, 3 * t + k));
      const want = [0, 1, 2].map((i) => (a[i] + b[i] + c[i]) / 3);
      for (let k = 0; k < 3; k++) {
        v3(flat.centroids!, 3 * t + k).forEach((x, i) => expect(Math.abs(x - want[i])).toBeLessThan(1e-6));
      }
    }
  });

  it('turns the face normal to agree with the corners\u2019 normals whatever the winding', () => {
    const tri: MeshData = {
      positions: new Float32Array([0, 0, 0, 1, 0, 0, 0, 1, 0]),
      normals: new Float32Array([0, 0, -1, 0, 0, -1, 0, 0, -1]), // counter-clockwise from +Z, normals towards −Z
      uvs: new Float32Array(6), indices: new Uint16Array([0, 1, 2]),
    };
    expect(v3(flatMesh(tri).normals, 0).map((x) => x + 0)).toEqual([0, 0, -1]);
  });

  it('a degenerate triangle takes the mean of its corners\u2019 normals instead of NaN', () => {
    const tri: MeshData = {
      positions: new Float32Array([0, 1, 0, 0, 1, 0, 0, 1, 0]),
      normals: new Float32Array([0, 1, 0, 0, 1, 0, 0, 1, 0]),
      uvs: new Float32Array(6), indices: new Uint16Array([0, 1, 2]),
    };
    expect(v3(flatMesh(tri).normals, 0)).toEqual([0, 1, 0]);
  });
});
