// The polygon triangulator on its own (src/loaders/obj/triangulate.ts): which triangles, in
// which order, for polygons traced by hand through its quad rule and its ear clipping, laid on
// planes facing each axis either way; its fallbacks (a fan) and dropZeroArea's compaction.
import { describe, expect, it } from 'vitest';
import { I32List } from '../../src/loaders/obj/growable';
import { dropZeroArea, triangulate } from '../../src/loaders/obj/triangulate';
import type { V3 } from './helpers/obj';

type P2 = [number, number];

const START = 5;

/**
 * Triangulates `points` as corners START … START + n − 1 and gives the triangles' corners less
 * START. Position 0 is a decoy that the corners before START name; the polygon's positions follow
 * backwards (corner k is position n − k), and no corner follows the polygon's last.
 */
function triangulated(points: V3[]): { clipped: boolean; tris: number[][] } {
  const n = points.length;
  const positions = new Float64Array([7, -9, 11, ...[...points].reverse().flat()]);
  const corners = new Int32Array(START + n);
  for (let k = 0; k < n; k++) corners[START + k] = n - k;
  const out = new I32List(4);
  const clipped = triangulate(positions, corners, START, n, out);
  const tris: number[][] = [];
  for (let t = 0; t < out.length; t += 3) tris.push([0, 1, 2].map((k) => out.data[t + k] - START));
  return { clipped, tris };
}

/**
 * Planes a 2D polygon is laid on, each projecting back (along the normal's largest axis,
 * mirrored when that axis points the negative way) onto the same counter-clockwise polygon.
 */
const LAYOUTS: [string, (p: P2) => V3][] = [
  ['z = 3 facing +z', ([x, y]) => [x, y, 3]],
  ['z = 3 facing -z', ([x, y]) => [-x, y, 3]],
  ['x = 3 facing +x', ([x, y]) => [3, x, y]],
  ['x = 3 facing -x', ([x, y]) => [3, -x, y]],
  ['y = 3 facing +y', ([x, y]) => [y, 3, x]],
  ['y = 3 facing -y', ([x, y]) => [y, 3, -x]],
  // Normal (0, 1, 1): |ny| = |nz|, |nx| = 0, projected onto (z, x) = (5 − y, x), a quarter turn.
  ['tilted facing (0, 1, 1)', ([x, y]) => [x, y, 5 - y]],
];

/** The same polygon moved by (10, 20): no corner at the origin, so sums and differences differ. */
function shifted(p: P2[]): P2[] {
  return p.map(([x, y]) => [x + 10, y + 20]);
}

/** Expects `expected` from `polygon` on every plane of LAYOUTS. */
function expectOnEveryPlane(polygon: P2[], expected: number[][]): void {
  for (const [name, lay] of LAYOUTS) {
    const r = triangulated(shifted(polygon).map(lay));
    expect(r, name).toEqual({ clipped: true, tris: expected });
  }
}

/** Twice the signed area of triangle abc. */
function area2(a: P2, b: P2, c: P2): number {
  return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/**
 * n − 2 triangles, each turning the polygon's way (or, with `flatAllowed`, of no area), whose
 * areas add up to the polygon's.
 */
function expectExactCover(polygon: P2[], twiceArea: number, flatAllowed = false): void {
  for (const [name, lay] of LAYOUTS) {
    const { clipped, tris } = triangulated(shifted(polygon).map(lay));
    expect(clipped).toBe(true);
    expect(tris.length, name).toBe(polygon.length - 2);
    let sum = 0;
    for (const [a, b, c] of tris) {
      const twice = area2(polygon[a], polygon[b], polygon[c]);
      if (flatAllowed) expect(twice, `${name}: triangle ${a} ${b} ${c}`).toBeGreaterThanOrEqual(0);
      else expect(twice, `${name}: triangle ${a} ${b} ${c}`).toBeGreaterThan(0);
      sum += twice;
    }
    expect(sum, name).toBe(twiceArea);
  }
}

describe('triangulate', () => {
  it('keeps a triangle as written', () => {
    expect(triangulated([[0, 0, 0], [1, 0, 0], [0, 1, 0]])).toEqual({ clipped: true, tris: [[0, 1, 2]] });
  });

  it('splits a quad along the diagonal from its reflex corner, else along 0–2', () => {
    // A dart (0,0) (2,1) (4,0) (2,4), counter-clockwise: (2,1) turns right, (2,1)−(0,0) × (4,0)−(2,1) = 2·(−1) − 1·2 = −4.
    // Reflex at 1 or 3: the diagonal 1–3, triangles (1 2 3) and (1 3 0).
    expectOnEveryPlane([[0, 0], [2, 1], [4, 0], [2, 4]], [[1, 2, 3], [1, 3, 0]]);
    expectOnEveryPlane([[4, 0], [2, 4], [0, 0], [2, 1]], [[1, 2, 3], [1, 3, 0]]);
    // Reflex at 0 or 2: the diagonal 0–2.
    expectOnEveryPlane([[2, 1], [4, 0], [2, 4], [0, 0]], [[0, 1, 2], [0, 2, 3]]);
    expectOnEveryPlane([[2, 4], [0, 0], [2, 1], [4, 0]], [[0, 1, 2], [0, 2, 3]]);
  });

  it('splits a quad with a straight corner at 1 or 3 along 0–2, a straight corner being no reflex one', () => {
    // (1,0) between (0,0) and (2,0): no turn; the other corner (1,1) turns left.
    expectOnEveryPlane([[0, 0], [1, 0], [2, 0], [1, 1]], [[0, 1, 2], [0, 2, 3]]);
    expectOnEveryPlane([[2, 0], [1, 1], [0, 0], [1, 0]], [[0, 1, 2], [0, 2, 3]]);
  });

  it('fans a convex polygon from its first corner', () => {
    // Every corner turns left (cross products 4, 4, 5, 4, 5): no reflex corner, a fan is exact.
    expectOnEveryPlane([[0, 0], [2, 0], [3, 2], [1, 3], [-1, 2]], [[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
  });

  it('ear-clips a notched pentagon, skipping the corners whose triangle holds the notch', () => {
    // (0,0) (4,0) (4,4) (2,1) (0,4): the notch 3 = (2,1) is the only reflex corner (cross −12).
    // Corner 0: triangle (4 0 1) holds (2,1) (edge tests 8, 4, 4 ≥ 0); corner 1: (0 1 2) holds it
    // too (4, 8, 4). Corner 2: the notch is its own neighbour c, an ear (1 2 3); then corner 1,
    // now between 0 and 3, an ear (0 1 3), which makes the notch convex (cross of (2,1) and
    // (−2,3) = 8): the last three (4 0 3).
    expectOnEveryPlane([[0, 0], [4, 0], [4, 4], [2, 1], [0, 4]], [[1, 2, 3], [0, 1, 3], [4, 0, 3]]);
  });

  it('counts a straight corner as reflex until clipping its neighbour makes it turn', () => {
    // (0,0) (1,0) (2,0) (2,2) (0,2): corner 1 is straight (cross 0), so not convex. Ear (4 0 1);
    // corner 1, now after 4 = (0,2), turns left ((1,−2) × (1,0) = 2): the list empties at the
    // next ear (3 4 1) and the last three are (2 3 1). Taken as convex, a fan from 0 would
    // start with (0 1 2), a triangle of no area.
    expectOnEveryPlane([[0, 0], [1, 0], [2, 0], [2, 2], [0, 2]], [[4, 0, 1], [3, 4, 1], [2, 3, 1]]);
  });

  it('fans from where it stands once a full lap finds no ear (a polygon touching itself)', () => {
    // (0,4) (0,0) (1,2) (2,0) (0,3): (0,3) lies on the edge from (0,4) to (0,0). Corner 0 is
    // straight, 2, 3, 4 turn right (−4, −1, −2); the one convex corner, 1, holds (0,3) on its
    // triangle's edge. Six steps without an ear (more than the 5 corners left) end at corner 1.
    expectOnEveryPlane([[0, 4], [0, 0], [1, 2], [2, 0], [0, 3]], [[1, 2, 3], [1, 3, 4], [1, 4, 0]]);
  });

  it('fans from corner 0 a polygon whose Newell normal is zero (a figure eight)', () => {
    // Lobes (−2,−1) (−2,1) (0,0), clockwise, and (0,0) (2,−1) (2,1), counter-clockwise, of area
    // 2 each: the normal sums to zero and no plane to project on is known.
    const eight: P2[] = [[-2, -1], [-2, 1], [0, 0], [2, -1], [2, 1], [0, 0]];
    expectOnEveryPlane(eight, [[0, 1, 2], [0, 2, 3], [0, 3, 4], [0, 4, 5]]);
  });

  it('fans from corner 0 a polygon whose Newell normal is not finite', () => {
    // Coordinates of 1e200: the normal's products (1e400) overflow to infinity and beyond.
    const big = ([x, y]: P2): V3 => [x * 1e200, y * 1e200, 3];
    const r = triangulated([[0, 0], [4, 0], [4, 4], [2, 1], [0, 4]].map((p) => big(p as P2)));
    expect(r).toEqual({ clipped: true, tris: [[0, 1, 2], [0, 2, 3], [0, 3, 4]] });
  });

  it('covers exactly an L, a comb, and two squares that share a corner', () => {
    expectExactCover([[2, 0], [2, 1], [1, 1], [1, 2], [0, 2], [0, 0]], 6);
    const comb: P2[] = [[0, 0], [5, 0], [5, 3], [4, 3], [4, 1], [3, 1], [3, 3], [2, 3], [2, 1], [1, 1], [1, 3], [0, 3]];
    // 5 × 1 base and three teeth of 1 × 2: twice (5 + 6) = 22; from every starting corner.
    for (let k = 0; k < comb.length; k++) expectExactCover([...comb.slice(k), ...comb.slice(0, k)], 22);
    // Squares of side 2 meeting at (2,2), which the polygon passes twice (corners 2 and 6): 4
    // triangles cover them, so 2 of the 6 join the two corners at (2,2) and have no area.
    const squares: P2[] = [[0, 0], [2, 0], [2, 2], [4, 2], [4, 4], [2, 4], [2, 2], [0, 2]];
    for (let k = 0; k < squares.length; k++) expectExactCover([...squares.slice(k), ...squares.slice(0, k)], 16, true);
  });

  it('covers exactly polygons whose reflex corners turn convex as their neighbours are clipped', () => {
    // Twice the areas by the shoelace formula, Σ (x_k y_k+1 − x_k+1 y_k):
    // −5 + 12 + 36 − 6 − 3 = 34, and −4 − 8 + 5 − 4 + 32 − 14 = 7 (a notch under the line y = 4).
    expectExactCover([[1, 2], [3, 1], [6, 6], [0, 6], [1, 5]], 34);
    expectExactCover([[3, 4], [4, 4], [5, 3], [5, 4], [6, 4], [1, 6]], 7);
  });

  it('covers exactly polygons with a corner written twice in a row (f … 4 4 …)', () => {
    // One triangle joins the two copies (no area); the rest cover the polygon. Twice the areas:
    // 6 − 12 + 0 + 9 + 8 = 11; 30 + 31 + 0 − 14 + 8 − 24 = 31; −2 − 2 + 3 − 3 + 25 + 0 − 7 = 14;
    // −15 + 0 + 30 + 30 − 6 − 12 = 27; 0 + 0 + 2 − 1 + 26 + 0 = 27; 1 − 4 − 4 + 0 + 19 − 2 = 10.
    expectExactCover([[2, 4], [0, 3], [4, 3], [4, 3], [5, 6]], 11, true);
    expectExactCover([[6, 0], [6, 5], [1, 6], [1, 6], [3, 4], [1, 4]], 31, true);
    expectExactCover([[2, 3], [2, 2], [2, 1], [3, 3], [6, 5], [1, 5], [1, 5]], 14, true);
    expectExactCover([[3, 3], [5, 0], [5, 0], [5, 6], [0, 6], [1, 5]], 27, true);
    expectExactCover([[0, 0], [0, 0], [2, 0], [5, 1], [6, 1], [4, 5]], 27, true);
    expectExactCover([[1, 2], [0, 1], [4, 4], [6, 5], [6, 5], [1, 4]], 10, true);
  });
});

describe('dropZeroArea', () => {
  // Positions: a decoy, then (1,1,1) (2,2,2) (3,3,3) on one line, and (1,2,4) off it.
  const positions = new Float64Array([9, 8, 7, 1, 1, 1, 2, 2, 2, 3, 3, 3, 1, 2, 4]);
  const corners = new Int32Array([0, 1, 2, 3, 4]);

  it('drops the triangles of no area from `first` on, keeping the order of the rest', () => {
    // A full list of 4 triangles: (1 2 3) on the line, before `first`, stays; from 1 on, (1 2 4) and
    // (3 2 4) have area (u = (1,1,1), v = (0,1,3): u × v = (2, −3, 1)), (3 2 1) is on the line.
    const out = new I32List(12);
    for (const t of [[1, 2, 3], [1, 2, 4], [3, 2, 1], [3, 2, 4]]) out.push3(t[0], t[1], t[2]);
    expect(out.data.length).toBe(12);
    expect(dropZeroArea(positions, corners, out, 1)).toBe(2);
    expect([...out.data.subarray(0, out.length)]).toEqual([1, 2, 3, 1, 2, 4, 3, 2, 4]);
  });

  it('drops a triangle of one point twice, and returns 0 when none is left', () => {
    const out = new I32List(6);
    out.push3(1, 1, 4);
    out.push3(4, 2, 4);
    expect(dropZeroArea(positions, corners, out, 0)).toBe(0);
    expect(out.length).toBe(0);
  });
});
