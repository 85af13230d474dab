// Box, sphere and glass meshes of the default scene (docs/default-scene.md): winding, normals, UVs, index width.
import { beforeEach, describe, expect, it } from 'vitest';
import { boxMesh } from '../../src/scene/geometry/box';
import { MAX_SEGMENTS, MIN_SEGMENTS, segmentsForScreenRadius, sphereMesh } from '../../src/scene/geometry/sphere';
import { glassMesh } from '../../src/scene/geometry/rectangle';
import { glassFrame } from '../../src/scene/glass-frame';
import { DEFAULT_GLASS } from '../../src/scene/default-scene';
import type { MeshData } from '../../src/scene/geometry/mesh-data';

type V = [number, number, number];
const at = (a: ArrayLike<number>, i: number): V => [a[i * 3], a[i * 3 + 1], a[i * 3 + 2]];
const sub = (a: V, b: V): V => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const cross = (a: V, b: V): V => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const dot = (a: V, b: V) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const len = (a: V) => Math.hypot(a[0], a[1], a[2]);

/** Calls fn with each triangle's vertex indices and its geometric (CCW) normal. */
function eachTriangle(m: MeshData, fn: (i: [number, number, number], n: V) => void): void {
  for (let t = 0; t < m.indices.length; t += 3) {
    const i: [number, number, number] = [m.indices[t], m.indices[t + 1], m.indices[t + 2]];
    const [a, b, c] = i.map((k) => at(m.positions, k));
    fn(i, cross(sub(b, a), sub(c, a)));
  }
}

function expectIndicesInRange(m: MeshData): void {
  const count = m.positions.length / 3;
  expect(m.normals.length).toBe(count * 3);
  expect(m.uvs.length).toBe(count * 2);
  let bad = -1;
  for (const k of m.indices) if (!(k >= 0 && k < count)) bad = k;
  expect(bad, 'an index out of range').toBe(-1);
}

describe('boxMesh', () => {
  // Built in each test (not once per file): mutation testing runs only the tests that ran the code.
  let box: ReturnType<typeof boxMesh>;
  beforeEach(() => { box = boxMesh(1); });

  it('has 24 vertices and 36 indices', () => {
    expect(box.positions.length).toBe(24 * 3);
    expect(box.indices.length).toBe(36);
    expectIndicesInRange(box);
  });

  it('winds every triangle CCW seen from outside, agreeing with its vertex normals', () => {
    eachTriangle(box, (i, g) => {
      expect(len(g)).toBeGreaterThan(0.1);
      for (const k of i) expect(dot(g, at(box.normals, k))).toBeGreaterThan(0);
      const centroid = i.map((k) => at(box.positions, k)).reduce((s, p) => [s[0] + p[0] / 3, s[1] + p[1] / 3, s[2] + p[2] / 3], [0, 0, 0] as V);
      expect(dot(g, centroid)).toBeGreaterThan(0);
    });
  });

  it('puts every vertex on the unit cube surface with axis-aligned unit normals along its face', () => {
    for (let k = 0; k < 24; k++) {
      const p = at(box.positions, k);
      const n = at(box.normals, k);
      expect(len(n)).toBe(1);
      for (const c of p) expect(Math.abs(c)).toBe(0.5);
      expect(dot(p, n)).toBeCloseTo(0.5, 6);
    }
  });

  it('maps each face over [0,1]² with the four corners', () => {
    for (const u of box.uvs) {
      expect(u).toBeGreaterThanOrEqual(0);
      expect(u).toBeLessThanOrEqual(1);
    }
    for (let f = 0; f < 6; f++) {
      const corners = new Set<string>();
      for (let c = 0; c < 4; c++) corners.add(`${box.uvs[(f * 4 + c) * 2]},${box.uvs[(f * 4 + c) * 2 + 1]}`);
      expect([...corners].sort()).toEqual(['0,0', '0,1', '1,0', '1,1']);
    }
  });

  it('scales with the edge', () => {
    const big = boxMesh(2);
    for (const c of big.positions) expect(Math.abs(c)).toBe(1);
  });
});

describe('sphereMesh', () => {
  const r = 0.75;
  let s: ReturnType<typeof sphereMesh>, count: number;
  beforeEach(() => {
    s = sphereMesh(r, 32);
    count = s.positions.length / 3;
  });

  it('puts every vertex at the radius with unit normals along the position', () => {
    expectIndicesInRange(s);
    for (let k = 0; k < count; k++) {
      const p = at(s.positions, k);
      const n = at(s.normals, k);
      expect(Math.abs(len(p) - r)).toBeLessThan(1e-6);
      expect(Math.abs(len(n) - 1)).toBeLessThan(1e-6);
      expect(dot(p, n) / r).toBeCloseTo(1, 6);
    }
  });

  it('has CCW triangles facing outward and none degenerate', () => {
    let triangles = 0;
    eachTriangle(s, (i, g) => {
      triangles++;
      expect(len(g), `triangle ${i}`).toBeGreaterThan(1e-5);
      const c = i.map((k) => at(s.positions, k)).reduce((a, p) => [a[0] + p[0], a[1] + p[1], a[2] + p[2]], [0, 0, 0] as V);
      expect(dot(g, c), `triangle ${i}`).toBeGreaterThan(0);
      expect(new Set(i).size).toBe(3);
    });
    // 32 segments, 16 rings: two triangles per quad except one at each pole row.
    expect(triangles).toBe(32 * 16 * 2 - 2 * 32);
  });

  it('covers the whole sphere: total area close to 4πr²', () => {
    let area = 0;
    eachTriangle(s, (_, g) => { area += len(g) / 2; });
    expect(area).toBeGreaterThan(4 * Math.PI * r * r * 0.98);
    expect(area).toBeLessThan(4 * Math.PI * r * r);
  });

  it('follows u = 0.5 + atan2(n.x, n.z)/2π, v = acos(−n.y)/π away from the seam and poles', () => {
    let checked = 0;
    for (let k = 0; k < count; k++) {
      const [nx, ny, nz] = at(s.normals, k);
      const u = s.uvs[k * 2];
      const v = s.uvs[k * 2 + 1];
      expect(u).toBeGreaterThanOrEqual(0);
      expect(u).toBeLessThanOrEqual(1);
      expect(v).toBeGreaterThanOrEqual(0);
      expect(v).toBeLessThanOrEqual(1);
      if (v < 0.01 || v > 0.99 || u < 0.01 || u > 0.99) continue;
      expect(Math.abs(u - (0.5 + Math.atan2(nx, nz) / (2 * Math.PI))), `u at ${k}`).toBeLessThan(1e-6);
      expect(Math.abs(v - Math.acos(-ny) / Math.PI), `v at ${k}`).toBeLessThan(1e-6);
      checked++;
    }
    expect(checked).toBeGreaterThan(count / 2);
  });

  it('starts v = 0 at the south pole (−Y) and ends v = 1 at the north pole', () => {
    for (let k = 0; k < count; k++) {
      const v = s.uvs[k * 2 + 1];
      if (v === 0) expect(s.normals[k * 3 + 1]).toBeCloseTo(-1, 6);
      if (v === 1) expect(s.normals[k * 3 + 1]).toBeCloseTo(1, 6);
    }
  });

  it('uses Uint16 indices for small spheres and Uint32 at 512 segments', () => {
    expect(s.indices).toBeInstanceOf(Uint16Array);
    const big = sphereMesh(r, 512);
    expect(big.indices).toBeInstanceOf(Uint32Array);
    expect(big.positions.length / 3).toBeGreaterThan(65535);
    expectIndicesInRange(big);
  });

  it('clamps the segment count', () => {
    expect(sphereMesh(1, 1).positions.length / 3).toBe((MIN_SEGMENTS + 1) * (MIN_SEGMENTS / 2 + 1));
    expect(sphereMesh(1, 10000).positions.length / 3).toBe((MAX_SEGMENTS + 1) * (MAX_SEGMENTS / 2 + 1));
  });
});

describe('segmentsForScreenRadius', () => {
  const err = (radius: number, n: number) => radius * (1 - Math.cos(Math.PI / n));

  for (const radius of [10, 50, 200, 800, 3000]) {
    it(`keeps the silhouette error ≤ 0.5 px at radius ${radius} px, and is minimal in steps of 4`, () => {
      const n = segmentsForScreenRadius(radius);
      expect(n % 4).toBe(0);
      expect(n).toBeGreaterThanOrEqual(MIN_SEGMENTS);
      expect(n).toBeLessThanOrEqual(MAX_SEGMENTS);
      if (n < MAX_SEGMENTS) expect(err(radius, n)).toBeLessThanOrEqual(0.5);
      if (n > MIN_SEGMENTS) expect(err(radius, n - 4)).toBeGreaterThan(0.5);
    });
  }

  it('gives 48 at 200 px (π/acos(1 − 0.5/200) ≈ 44.4, rounded up to a multiple of 4)', () => {
    expect(segmentsForScreenRadius(200)).toBe(48);
  });

  it('falls back to the minimum for tiny, zero, negative or NaN radii, and caps huge ones', () => {
    for (const r of [0, 0.5, -3, NaN]) expect(segmentsForScreenRadius(r)).toBe(MIN_SEGMENTS);
    expect(segmentsForScreenRadius(1e7)).toBe(MAX_SEGMENTS);
    expect(segmentsForScreenRadius(Infinity)).toBe(MAX_SEGMENTS);
  });
});

describe('glassMesh', () => {
  let g: ReturnType<typeof glassMesh>;
  beforeEach(() => { g = glassMesh(glassFrame(DEFAULT_GLASS)); });

  it('spans x ∈ [−4, 4], y ∈ [−1, 3] on z = 0 with u = (x+4)/8, v = (y+1)/4', () => {
    expect(g.positions.length).toBe(12);
    expectIndicesInRange(g);
    const corners = new Set<string>();
    for (let k = 0; k < 4; k++) {
      const [x, y, z] = at(g.positions, k);
      corners.add(`${x},${y}`);
      expect(z).toBe(0);
      expect(at(g.normals, k)).toEqual([0, 0, 1]);
      expect(g.uvs[k * 2]).toBeCloseTo((x + 4) / 8, 12);
      expect(g.uvs[k * 2 + 1]).toBeCloseTo((y + 1) / 4, 12);
    }
    expect([...corners].sort()).toEqual(['-4,-1', '-4,3', '4,-1', '4,3']);
  });

  it('has two CCW triangles facing +Z covering 32 square units', () => {
    expect(g.indices.length).toBe(6);
    let area = 0;
    eachTriangle(g, (_, n) => {
      expect(n[2]).toBeGreaterThan(0);
      area += len(n) / 2;
    });
    expect(area).toBeCloseTo(32, 9);
  });
});
