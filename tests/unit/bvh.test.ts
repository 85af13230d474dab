// The BVH finds the same nearest hit as testing every triangle, on random rays (seeded).
import { describe, expect, it } from 'vitest';
import { Bvh, BvhHit } from '../../src/reference/bvh';
import { gaussianMesh } from '../../src/scene/geometry/gaussian';

/** mulberry32: a small seeded PRNG, so a failure reproduces. */
function rng(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) | 0;
    let t = Math.imul(a ^ (a >>> 15), 1 | a);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Nearest hit over every triangle, Möller–Trumbore written out independently (Cramer's rule). */
function bruteForce(p: ArrayLike<number>, idx: ArrayLike<number>, o: number[], d: number[], tMin: number, tMax: number): { t: number; tri: number } {
  let best = tMax, tri = -1;
  for (let f = 0; f < idx.length / 3; f++) {
    const a = idx[3 * f] * 3, b = idx[3 * f + 1] * 3, c = idx[3 * f + 2] * 3;
    const e1 = [0, 1, 2].map((k) => p[b + k] - p[a + k]);
    const e2 = [0, 1, 2].map((k) => p[c + k] - p[a + k]);
    const s = [0, 1, 2].map((k) => o[k] - p[a + k]);
    // Solve −d·t + e1·u + e2·v = s.
    const det3 = (x: number[], y: number[], z: number[]): number =>
      x[0] * (y[1] * z[2] - y[2] * z[1]) - y[0] * (x[1] * z[2] - x[2] * z[1]) + z[0] * (x[1] * y[2] - x[2] * y[1]);
    const nd = d.map((x) => -x);
    const det = det3(nd, e1, e2);
    if (det === 0) continue;
    const t = det3(s, e1, e2) / det, u = det3(nd, s, e2) / det, v = det3(nd, e1, s) / det;
    if (u >= 0 && v >= 0 && u + v <= 1 && t > tMin && t <= best) { best = t; tri = f; }
  }
  return { t: best, tri };
}

function check(positions: ArrayLike<number>, indices: ArrayLike<number>, random: () => number, lo: number[], hi: number[], rays: number): void {
  const bvh = new Bvh(positions, indices);
  let hits = 0;
  for (let r = 0; r < rays; r++) {
    const o = [0, 1, 2].map((k) => lo[k] - 1 + random() * (hi[k] - lo[k] + 2));
    const target = [0, 1, 2].map((k) => lo[k] + random() * (hi[k] - lo[k]));
    const d = [0, 1, 2].map((k) => target[k] - o[k]);
    const tMin = random() < 0.3 ? random() * 0.8 : -Infinity;
    const hit = new BvhHit();
    const found = bvh.intersect(o[0], o[1], o[2], d[0], d[1], d[2], tMin, Infinity, hit);
    const expected = bruteForce(positions, indices, o, d, tMin, Infinity);
    expect(found, `ray ${r}`).toBe(expected.tri >= 0);
    if (!found) continue;
    hits++;
    expect(Math.abs(hit.t - expected.t), `ray ${r}: t ${hit.t} vs ${expected.t}`).toBeLessThan(1e-9 * Math.max(1, expected.t));
    // Same triangle, or a neighbour hit at the same t (a shared edge).
    if (hit.triangle !== expected.tri) expect(Math.abs(hit.t - expected.t)).toBeLessThan(1e-12);
    // The barycentrics reproduce the hit point.
    const a = indices[3 * hit.triangle] * 3, b = indices[3 * hit.triangle + 1] * 3, c = indices[3 * hit.triangle + 2] * 3;
    for (let k = 0; k < 3; k++) {
      const q = (1 - hit.b1 - hit.b2) * positions[a + k] + hit.b1 * positions[b + k] + hit.b2 * positions[c + k];
      expect(Math.abs(q - (o[k] + hit.t * d[k]))).toBeLessThan(1e-9);
    }
  }
  expect(hits).toBeGreaterThan(rays / 5);
}

describe('BVH against brute force', () => {
  it('on the Gaussian surface (24×24)', () => {
    const mesh = gaussianMesh(24);
    check(mesh.positions, mesh.indices, rng(1), [-2, 0, -2], [2, 1, 2], 1500);
  });

  it('on a random triangle soup (300 triangles, overlapping, some slivers)', () => {
    const random = rng(7);
    const positions = new Float64Array(900 * 3);
    for (let f = 0; f < 300; f++) {
      const c = [random() * 4 - 2, random() * 4 - 2, random() * 4 - 2];
      const size = random() < 0.1 ? 2 : 0.4;
      for (let v = 0; v < 3; v++) for (let k = 0; k < 3; k++) positions[(f * 3 + v) * 3 + k] = c[k] + (random() - 0.5) * size;
    }
    const indices = Uint32Array.from({ length: 900 }, (_, i) => i);
    check(positions, indices, random, [-2, -2, -2], [2, 2, 2], 1500);
  });

  it('an empty mesh and a one-triangle mesh', () => {
    const hit = new BvhHit();
    expect(new Bvh([], []).intersect(0, 0, 1, 0, 0, -1, -Infinity, Infinity, hit)).toBe(false);
    const one = new Bvh([0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2]);
    expect(one.intersect(0.25, 0.25, 2, 0, 0, -1, -Infinity, Infinity, hit)).toBe(true);
    expect(hit.t).toBe(2);
    expect(one.intersect(0.25, 0.25, 2, 0, 0, -1, 2, Infinity, hit)).toBe(false); // t must exceed tMin
    expect(one.intersect(0.75, 0.75, 2, 0, 0, -1, -Infinity, Infinity, hit)).toBe(false);
  });
});
