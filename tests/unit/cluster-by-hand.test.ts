// Vertex clustering (src/scene/geometry/cluster.ts) on a mesh small enough to do by hand: which
// vertices share a cell, their means (position, normal, UV), the normal of a cell whose normals
// cancel, and which triangles survive the merge in which winding.
import { describe, expect, it } from 'vitest';
import { clusterMesh, meshExtent } from '../../src/scene/geometry/cluster';
import type { MeshData } from '../../src/scene/geometry/mesh-data';
import { expectClose } from './helpers/math';

// Six vertices in the box x ∈ [0, 2], y ∈ [0, 1.5], z = 0, moved by O: the largest side is 2,
// so grid 2 gives cells of 1 (a vertex on the far face, x = 2, gets a cell of its own, number 2).
const O = [10, -3, 5];
const LOCAL = [
  [0, 0, 0], //    v0: cell (0, 0) → cluster 0
  [0.5, 0.5, 0], // v1: cell (0, 0) → cluster 0
  [1.5, 0, 0], //  v2: cell (1, 0) → cluster 1
  [2, 0, 0], //    v3: cell (2, 0) → cluster 2 (the far face)
  [0, 1.5, 0], //  v4: cell (0, 1) → cluster 3
  [1.2, 0.5, 0], // v5: cell (1, 0) → cluster 1
];
const NORMALS = [[0, 0, 1], [0, 0, -1], [1, 0, 0], [0, 0, 2], [0, 1, 0], [0, 1, 0]];
const UVS = [[0, 0], [1, 0.5], [0.2, 0.4], [0.9, 0.1], [0.5, 0.5], [0.6, 0]];
const TRIANGLES = [
  [0, 1, 2], // clusters (0, 0, 1): two corners merge → dropped
  [0, 2, 4], // (0, 1, 3) → kept
  [5, 4, 1], // (1, 3, 0) → the same triangle, same winding, starting elsewhere → dropped
  [2, 3, 4], // (1, 2, 3) → kept
  [4, 3, 2], // (3, 2, 1) → the other winding: kept, as (1, 3, 2)
  [3, 4, 0], // (2, 3, 0) → kept, as (0, 2, 3)
  [4, 0, 2], // (3, 0, 1) → (0, 1, 3) again → dropped
  [1, 2, 0], // (0, 1, 0): first and last merge → dropped
  [2, 0, 1], // (1, 0, 0): last two merge → dropped
];

function mesh(): MeshData {
  return {
    positions: new Float32Array(LOCAL.flatMap((p) => p.map((x, i) => x + O[i]))),
    normals: new Float32Array(NORMALS.flat()),
    uvs: new Float32Array(UVS.flat()),
    // Two loose indices at the end (not a triangle): ignored.
    indices: new Uint16Array([...TRIANGLES.flat(), 3, 4]),
  };
}

describe('clusterMesh by hand', () => {
  it('merges each cell\'s vertices to their mean position and UV, in order of first appearance', () => {
    const out = clusterMesh(mesh(), 2);
    const at = (p: number[]) => p.map((x, i) => x + O[i]);
    expectClose(Array.from(out.positions), [
      ...at([0.25, 0.25, 0]), ...at([1.35, 0.25, 0]), ...at([2, 0, 0]), ...at([0, 1.5, 0]),
    ], 1e-5);
    expectClose(Array.from(out.uvs), [0.5, 0.25, 0.4, 0.2, 0.9, 0.1, 0.5, 0.5], 1e-6);
  });

  it('normals: the normalized mean; where they cancel, the first vertex\'s own', () => {
    const out = clusterMesh(mesh(), 2);
    const s = Math.SQRT1_2;
    expectClose(Array.from(out.normals), [0, 0, 1, s, s, 0, 0, 0, 1, 0, 1, 0], 1e-6);
    // The cancelling cell again, its first vertex's normal not unit: normalized too.
    const m = mesh();
    m.normals.set([0, 0, 3, 0, 0, -3], 0);
    expectClose(Array.from(clusterMesh(m, 2).normals.slice(0, 3)), [0, 0, 1], 1e-6);
    // And a first vertex with no normal at all: zero, not NaN.
    m.normals.set([0, 0, 0, 0, 0, 0], 0);
    expect(Array.from(clusterMesh(m, 2).normals.slice(0, 3))).toEqual([0, 0, 0]);
  });

  it('keeps each surviving triangle once, winding kept, starting at its smallest index', () => {
    const out = clusterMesh(mesh(), 2);
    expect(Array.from(out.indices)).toEqual([0, 1, 3, 1, 2, 3, 1, 3, 2, 0, 2, 3]);
    expect(out.indices).toBeInstanceOf(Uint16Array);
  });

  it('grid 1 puts cell boundaries at the box\'s far faces only: v3 (x = 2) and v4 (y = 1.5)... v4 falls in cell 0', () => {
    // Cells of 2: x = 2 is the far face (cell 1); y = 1.5 is inside cell 0.
    const out = clusterMesh(mesh(), 1);
    expect(out.positions.length / 3).toBe(2);
    // Cluster 0: v0, v1, v2, v4, v5; cluster 1: v3 alone.
    const mean = [0, 1, 2, 4, 5].map((v) => LOCAL[v]).reduce((a, p) => a.map((x, i) => x + p[i] / 5), [0, 0, 0]);
    expectClose(Array.from(out.positions.slice(0, 3)), mean.map((x, i) => x + O[i]), 1e-5);
    expect(out.indices.length).toBe(0);
  });

  it('leaves alone what it cannot cluster: no extent, a grid below 1, a flat mesh', () => {
    const point: MeshData = { positions: new Float32Array([1, 2, 3]), normals: new Float32Array(3), uvs: new Float32Array(2), indices: new Uint16Array(0) };
    expect(clusterMesh(point, 4)).toBe(point);
    const m = mesh();
    expect(clusterMesh(m, 0.5)).toBe(m);
    expect(clusterMesh(m, NaN)).toBe(m);
    expect(clusterMesh(m, 1)).not.toBe(m);
  });
});

describe('meshExtent', () => {
  it('is the largest side of the box, whichever axis it lies on and wherever the extremes come', () => {
    // x: 1..4 (3), y: 0..7 (7), z: −1..3.5 (4.5); the first point is no extreme.
    const pts = [2, 3, 0, 1, 0, 3.5, 4, 7, -1, 3, 2, 1];
    expect(meshExtent(new Float32Array(pts))).toBe(7);
    // The same points with the axes turned: the 7 on x, then on z.
    const turn = (p: number[], order: number[]) => p.flatMap((_, i) => (i % 3 === 0 ? order.map((k) => p[i + k]) : []));
    expect(meshExtent(new Float32Array(turn(pts, [1, 2, 0])))).toBe(7);
    expect(meshExtent(new Float32Array(turn(pts, [2, 0, 1])))).toBe(7);
    expect(meshExtent(new Float32Array(turn(pts, [0, 2, 1])))).toBe(7);
    // x alone: 1..4 when the others are flat.
    expect(meshExtent(new Float32Array([2, 0, 0, 1, 0, 0, 4, 0, 0, 3, 0, 0]))).toBe(3);
    expect(meshExtent(new Float32Array([0, 2, 0, 0, 1, 0, 0, 4, 0, 0, 3, 0]))).toBe(3);
    expect(meshExtent(new Float32Array([0, 0, 2, 0, 0, 1, 0, 0, 4, 0, 0, 3]))).toBe(3);
  });

  it('is 0 for no vertex or one', () => {
    expect(meshExtent(new Float32Array(0))).toBe(0);
    expect(meshExtent(new Float32Array([5, 6, 7]))).toBe(0);
  });
});
