// The reflection's coarser mesh (docs/knobs.md#level-of-detail: a 100k-triangle model's reflection within 1.25× of the
// scene pass): vertex clustering and the grid chosen for a size on screen.
import { beforeEach, describe, expect, it } from 'vitest';
import { clusterMesh, meshExtent } from '../../src/scene/geometry/cluster';
import { gaussianMesh } from '../../src/scene/geometry/gaussian';
import { boxMesh } from '../../src/scene/geometry/box';
import { flatMesh } from '../../src/scene/geometry/flat';
import { pixelsPerUnit, reflectionGrid, REFLECTION_CELL_PX, REFLECTION_GRIDS } from '../../src/frame/reflection-lod';
import type { MeshData } from '../../src/scene/geometry/mesh-data';

const v3 = (a: Float32Array, i: number) => [a[3 * i], a[3 * i + 1], a[3 * i + 2]];
const sub = (a: number[], b: number[]) => a.map((x, i) => x - b[i]);
const cross = (a: number[], b: number[]) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

function faceNormal(m: MeshData, t: number): number[] {
  const [a, b, c] = [0, 1, 2].map((k) => v3(m.positions, m.indices[3 * t + k]));
  return cross(sub(b, a), sub(c, a));
}

describe('clusterMesh', () => {
  let fine: ReturnType<typeof gaussianMesh>;
  beforeEach(() => { fine = gaussianMesh(225); });

  it('cuts a 100k-triangle Gaussian to 2–3·G² triangles on a G grid (its slopes add cells in y)', () => {
    const coarse = clusterMesh(fine, 64);
    const triangles = coarse.indices.length / 3;
    expect(fine.indices.length / 3).toBe(100_352);
    expect(triangles).toBeGreaterThan(2 * 60 * 60);
    expect(triangles).toBeLessThan(3 * 64 * 64);
    expect(coarse.positions.length / 3).toBeLessThan(triangles);
  });

  it('keeps every vertex within one cell of the surface and every normal unit and close to the surface normal', () => {
    const coarse = clusterMesh(fine, 32);
    const cell = 4 / 32;
    for (let v = 0; v < coarse.positions.length / 3; v++) {
      const [x, y, z] = v3(coarse.positions, v);
      expect(Math.abs(x)).toBeLessThanOrEqual(2);
      expect(Math.abs(y - Math.exp(-x * x - z * z))).toBeLessThan(cell);
      const n = v3(coarse.normals, v);
      expect(Math.hypot(n[0], n[1], n[2])).toBeCloseTo(1, 5);
      const gx = 2 * x * Math.exp(-x * x - z * z), gz = 2 * z * Math.exp(-x * x - z * z);
      const exact = [gx, 1, gz].map((c) => c / Math.hypot(gx, 1, gz));
      expect(dot(n, exact)).toBeGreaterThan(Math.cos((15 * Math.PI) / 180));
    }
  });

  it('keeps the winding: every coarse face still faces up (+Y) like the fine surface', () => {
    const coarse = clusterMesh(fine, 64);
    for (let t = 0; t < coarse.indices.length / 3; t++) expect(faceNormal(coarse, t)[1]).toBeGreaterThan(0);
  });

  it('keeps no triangle with a repeated corner and no triangle twice (a transparent reflection would blend it twice)', () => {
    const coarse = clusterMesh(fine, 16);
    const seen = new Set<string>();
    for (let t = 0; t < coarse.indices.length / 3; t++) {
      const [a, b, c] = [0, 1, 2].map((k) => coarse.indices[3 * t + k]);
      expect(a !== b && b !== c && a !== c).toBe(true);
      const r = [a, b, c], s = r.indexOf(Math.min(a, b, c));
      const key = [r[s], r[(s + 1) % 3], r[(s + 2) % 3]].join();
      expect(seen.has(key)).toBe(false);
      seen.add(key);
    }
  });

  it('leaves a mesh already coarser than the grid alone (a box on a 64 grid: 12 triangles in, 12 out)', () => {
    const box = boxMesh(1);
    const coarse = clusterMesh(box, 64);
    expect(coarse.indices.length).toBe(box.indices.length);
  });

  it('returns degenerate input unchanged: a single point, an empty mesh, a flat (per-face) mesh', () => {
    const empty: MeshData = { positions: new Float32Array(0), normals: new Float32Array(0), uvs: new Float32Array(0), indices: new Uint16Array(0) };
    expect(clusterMesh(empty, 16)).toBe(empty);
    const flat = flatMesh(gaussianMesh(8));
    expect(clusterMesh(flat, 4)).toBe(flat);
    expect(meshExtent(new Float32Array([1, 2, 3]))).toBe(0);
  });
});

describe('reflectionGrid', () => {
  it('chooses the coarsest grid whose cells span at most REFLECTION_CELL_PX pixels', () => {
    // Extent 4 at 43.8 px per unit: 175 px, 43.8 cells of 4 px → the 64 grid.
    expect(reflectionGrid(4, 43.8)).toBe(64);
    for (const ppu of [1, 5, 20, 43.8, 100, 250]) {
      const g = reflectionGrid(4, ppu);
      expect((4 / g) * ppu).toBeLessThanOrEqual(REFLECTION_CELL_PX);
      const i = REFLECTION_GRIDS.indexOf(g);
      if (i > 0) expect((4 / REFLECTION_GRIDS[i - 1]) * ppu).toBeGreaterThan(REFLECTION_CELL_PX);
    }
  });

  it('draws the full mesh when the finest grid is too coarse, or the size is not finite', () => {
    expect(reflectionGrid(4, 1000)).toBe(0);
    expect(reflectionGrid(4, Infinity)).toBe(0);
    expect(reflectionGrid(4, NaN)).toBe(0);
    expect(reflectionGrid(0, 10)).toBe(0);
  });

  it('pixelsPerUnit: a unit at distance d under a 60° field of view over 360 px', () => {
    expect(pixelsPerUnit(360, 60, 1)).toBeCloseTo(360 / (2 * Math.tan(Math.PI / 6)), 9);
    expect(pixelsPerUnit(360, 60, 2)).toBeCloseTo(pixelsPerUnit(360, 60, 1) / 2, 9);
  });
});
