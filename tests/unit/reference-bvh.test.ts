// The reference's BVH on small meshes (src/reference/bvh.ts): its layout checked node by node (tight bounds, leaves that
// cover every slot once, children where the layout says, edges in slot order), splits where the surface area heuristic
// must split, and nearest hits worked out by hand (ties, edges, tMin exclusive, tMax inclusive, parallel rays).
import { describe, expect, it } from 'vitest';
import { Bvh, BvhHit } from '../../src/reference/bvh';

/** A triangle (x0, y0) … in the plane z, as 9 numbers. */
const tri = (z: number, a: [number, number], b: [number, number], c: [number, number]) => [a[0], a[1], z, b[0], b[1], z, c[0], c[1], z];

/** A mesh from triangles given as 9 numbers each (no shared vertices). */
function mesh(tris: number[][]): { positions: Float64Array; indices: Uint32Array } {
  return { positions: new Float64Array(tris.flat()), indices: Uint32Array.from({ length: tris.length * 3 }, (_, i) => i) };
}

/** Every node's layout, checked: returns the leaves' sizes and the tree's depth. */
function checkLayout(bvh: Bvh, positions: ArrayLike<number>, indices: ArrayLike<number>): { leaves: number[]; depth: number } {
  const count = Math.floor(indices.length / 3);
  expect([...bvh.order].sort((a, b) => a - b)).toEqual([...Array(count).keys()]);
  for (let s = 0; s < count; s++) {
    const f = bvh.order[s];
    for (let k = 0; k < 3; k++) {
      const v = (c: number) => positions[indices[3 * f + c] * 3 + k];
      expect(bvh.edges[s * 9 + k]).toBe(v(0));
      expect(bvh.edges[s * 9 + 3 + k]).toBe(v(1) - v(0));
      expect(bvh.edges[s * 9 + 6 + k]).toBe(v(2) - v(0));
    }
  }
  const covered = new Array(count).fill(0);
  const leaves: number[] = [];
  let visited = 0, maxDepth = 0;
  /** The node's triangle slots, with its bounds checked as exactly their union. */
  const visit = (node: number, depth: number): number[] => {
    visited++;
    maxDepth = Math.max(maxDepth, depth);
    const first = bvh.nodes[2 * node], n = bvh.nodes[2 * node + 1];
    let slots: number[];
    if (n > 0) {
      slots = Array.from({ length: n }, (_, i) => first + i);
      leaves.push(n);
    } else {
      expect(first).toBeGreaterThan(node + 1);
      slots = [...visit(node + 1, depth + 1), ...visit(first, depth + 1)];
    }
    const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
    for (const s of slots) {
      const f = bvh.order[s];
      for (let c = 0; c < 3; c++) for (let k = 0; k < 3; k++) {
        const x = positions[indices[3 * f + c] * 3 + k];
        lo[k] = Math.min(lo[k], x);
        hi[k] = Math.max(hi[k], x);
      }
    }
    expect([...bvh.bounds.subarray(node * 6, node * 6 + 6)], `node ${node}`).toEqual([...lo, ...hi]);
    return slots;
  };
  for (const s of visit(0, 1)) covered[s]++;
  expect(covered.every((c) => c === 1)).toBe(true);
  expect(visited).toBe(bvh.nodeCount);
  expect(bvh.nodes.length).toBe(2 * bvh.nodeCount);
  expect(bvh.bounds.length).toBe(6 * bvh.nodeCount);
  expect(bvh.depth).toBe(maxDepth);
  return { leaves, depth: maxDepth };
}

/** A grid of n × n small triangles over [0, n)², two per cell, in z = 0. */
function grid(n: number) {
  const tris: number[][] = [];
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
    tris.push(tri(0, [i, j], [i + 1, j], [i + 1, j + 1]), tri(0, [i, j], [i + 1, j + 1], [i, j + 1]));
  }
  return mesh(tris);
}

describe('Bvh: layout', () => {
  it('no triangles: one empty leaf with inverted bounds', () => {
    const bvh = new Bvh([], []);
    expect([bvh.nodeCount, bvh.depth, bvh.order.length, bvh.edges.length]).toEqual([1, 0, 0, 0]);
    expect([...bvh.nodes]).toEqual([0, 0]);
    expect([...bvh.bounds]).toEqual([Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity]);
    const hit = new BvhHit();
    expect(bvh.intersect(0, 0, 1, 0, 0, -1, -Infinity, Infinity, hit)).toBe(false);
    expect(bvh.intersect(0.3, 0.2, 1, 0.1, 0.2, -1, -Infinity, Infinity, hit)).toBe(false);
  });

  it('up to four triangles: one leaf', () => {
    const m = mesh([tri(0, [0, 0], [1, 0], [0, 1]), tri(1, [2, 0], [3, 0], [2, 1]), tri(-1, [0, 2], [1, 2], [0, 3]), tri(2, [5, 5], [6, 5], [5, 6])]);
    const bvh = new Bvh(m.positions, m.indices);
    expect([bvh.nodeCount, bvh.depth]).toEqual([1, 1]);
    expect([...bvh.nodes]).toEqual([0, 4]);
    expect([...bvh.order]).toEqual([0, 1, 2, 3]);
    expect([...bvh.bounds]).toEqual([0, 0, -1, 6, 6, 2]);
    checkLayout(bvh, m.positions, m.indices);
  });

  it('a trailing partial triangle is ignored; shared vertices are read through the indices', () => {
    const positions = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0];
    const indices = [3, 2, 1, 0, 1, 2, 3];
    const bvh = new Bvh(positions, indices);
    expect(bvh.order.length).toBe(2);
    checkLayout(bvh, positions, indices.slice(0, 6));
    // Slot 0 is triangle 0: v0 = vertex 3, e1 = vertex 2 − vertex 3, e2 = vertex 1 − vertex 3.
    expect([...bvh.edges.subarray(0, 9)]).toEqual([1, 1, 0, -1, 0, 0, 0, -1, 0]);
  });

  it('two clusters of four far apart: split between them, one leaf each', () => {
    const near = [0, 1, 2, 3].map((k) => tri(0, [k * 0.1, 0], [k * 0.1 + 0.5, 0], [k * 0.1, 0.5]));
    const far = [0, 1, 2, 3].map((k) => tri(0, [10 + k * 0.1, 0], [10.5 + k * 0.1, 0], [10 + k * 0.1, 0.5]));
    // Interleaved, so the split has to sort them.
    const m = mesh([far[0], near[0], far[1], near[1], far[2], near[2], far[3], near[3]]);
    const bvh = new Bvh(m.positions, m.indices);
    const { leaves, depth } = checkLayout(bvh, m.positions, m.indices);
    expect([bvh.nodeCount, depth, leaves]).toEqual([3, 2, [4, 4]]);
    // The left child (node 1) holds the near cluster (the lower x), the right one (node 2) the far one.
    expect(bvh.nodes[0]).toBe(2);
    expect([...bvh.order.subarray(0, 4)].sort()).toEqual([1, 3, 5, 7]);
    expect([...bvh.bounds.subarray(6, 12)]).toEqual([0, 0, 0, 0.8, 0.5, 0]);
    expect([...bvh.bounds.subarray(12, 18)]).toEqual([10, 0, 0, 10.8, 0.5, 0]);
  });

  it('the cheaper axis wins: clusters apart in x, spread a little in y, are split in x', () => {
    // Each cluster's triangles are 0.3 apart in y as well: splitting in y would mix the clusters (a far worse cost).
    const cluster = (x0: number) => [0, 1, 2, 3].map((k) =>
      tri(0, [x0 + k * 0.1, 0.3 * k], [x0 + 0.5 + k * 0.1, 0.3 * k], [x0 + k * 0.1, 0.5 + 0.3 * k]));
    const near = cluster(0), far = cluster(10);
    const m = mesh([far[0], near[0], far[1], near[1], far[2], near[2], far[3], near[3]]);
    const bvh = new Bvh(m.positions, m.indices);
    expect(checkLayout(bvh, m.positions, m.indices).leaves).toEqual([4, 4]);
    expect([...bvh.order.subarray(0, 4)].sort()).toEqual([1, 3, 5, 7]);
  });

  it('below the root too, a stack is kept whole: two stacks of eight far apart make two leaves of eight', () => {
    const stack = (x0: number) => Array.from({ length: 8 }, (_, k) => tri(0.001 * k, [x0, 0], [x0 + 1, 0], [x0, 1]));
    const m = mesh([...stack(0), ...stack(20)]);
    const bvh = new Bvh(m.positions, m.indices);
    expect(checkLayout(bvh, m.positions, m.indices).leaves).toEqual([8, 8]);
  });

  it('the same along y and along z', () => {
    for (const axis of [1, 2]) {
      const tris: number[][] = [];
      for (const base of [0, 20]) for (let k = 0; k < 4; k++) {
        const p = (a: number, b: number) => {
          const v = [a + k * 0.1, 0, 0];
          v[axis] = base + b;
          return v;
        };
        tris.push([...p(0, 0), ...p(0.5, 0), ...p(0, 0.5)]);
      }
      const m = mesh(tris);
      const bvh = new Bvh(m.positions, m.indices);
      const { leaves } = checkLayout(bvh, m.positions, m.indices);
      expect(leaves, `axis ${axis}`).toEqual([4, 4]);
      expect(bvh.bounds[6 + 3 + axis]).toBe(0.5);
      expect(bvh.bounds[12 + axis]).toBe(20);
    }
  });

  it('a grid: a valid layout whose leaves hold at most four, a few levels deep', () => {
    for (const n of [3, 5]) {
      const m = grid(n);
      const bvh = new Bvh(m.positions, m.indices);
      const { leaves, depth } = checkLayout(bvh, m.positions, m.indices);
      expect(Math.max(...leaves), `${n}×${n}`).toBeLessThanOrEqual(4);
      // About log2(2n²/4) + 1 levels, far fewer than one per triangle.
      expect(depth, `${n}×${n}`).toBeLessThanOrEqual(Math.ceil(Math.log2((2 * n * n) / 4)) + 3);
      expect(depth).toBeGreaterThanOrEqual(Math.ceil(Math.log2((2 * n * n) / 4)) + 1);
    }
  });

  it('a uniform grid of 2^k × 2^k cells is halved all the way down: leaves of two cells, a perfectly balanced tree', () => {
    // 2n² triangles in leaves of 4: n²/2 leaves, n² − 1 nodes, depth log2(n²/2) + 1.
    for (const n of [4, 8, 16]) {
      const m = grid(n);
      const bvh = new Bvh(m.positions, m.indices);
      const { leaves, depth } = checkLayout(bvh, m.positions, m.indices);
      expect([bvh.nodeCount, depth, leaves.length], `${n}×${n}`).toEqual([n * n - 1, Math.log2((n * n) / 2) + 1, (n * n) / 2]);
      expect(leaves.every((l) => l === 4)).toBe(true);
      // Each leaf is two neighbouring cells: its box 2 × 1 or 1 × 2.
      for (let node = 0; node < bvh.nodeCount; node++) {
        if (bvh.nodes[2 * node + 1] === 0) continue;
        const b = bvh.bounds.subarray(node * 6, node * 6 + 6);
        expect([b[3] - b[0], b[4] - b[1]].sort()).toEqual([1, 2]);
      }
    }
  });

  it('triangles whose centres coincide cannot be split: one leaf, however many', () => {
    // Triangle k: (−a, −a, −1), (a, a, 1), (a, −a, 0) with a = 1 + k: its box is centred on the origin.
    const same = mesh(Array.from({ length: 20 }, (_, k) => [-1 - k, -1 - k, -1, 1 + k, 1 + k, 1, 1 + k, -1 - k, 0]));
    const { leaves } = checkLayout(new Bvh(same.positions, same.indices), same.positions, same.indices);
    expect(leaves).toEqual([20]);
  });

  it('sixteen triangles stacked on each other: the heuristic keeps them in one leaf; seventeen are split', () => {
    // Unit triangles at z = 0.001·k: splitting along z saves nothing (every ray through one meets all).
    const stack = (n: number) => mesh(Array.from({ length: n }, (_, k) => tri(0.001 * k, [0, 0], [1, 0], [0, 1])));
    const s16 = stack(16), s17 = stack(17);
    expect(checkLayout(new Bvh(s16.positions, s16.indices), s16.positions, s16.indices).leaves).toEqual([16]);
    expect(checkLayout(new Bvh(s17.positions, s17.indices), s17.positions, s17.indices).leaves.length).toBeGreaterThan(1);
  });
});

describe('Bvh: nearest hit', () => {
  const hitOf = (bvh: Bvh, o: number[], d: number[], tMin = -Infinity, tMax = Infinity) => {
    const hit = new BvhHit();
    return bvh.intersect(o[0], o[1], o[2], d[0], d[1], d[2], tMin, tMax, hit) ? hit : null;
  };

  it('BvhHit starts empty', () => {
    const h = new BvhHit();
    expect([h.t, h.triangle, h.b1, h.b2]).toEqual([Infinity, -1, 0, 0]);
  });

  it('t and the barycentrics of the second and third corners', () => {
    // (0, 0, 0), (4, 0, 0), (0, 2, 0); from (1, 0.5, 3) down: t = 3, b1 = 1/4, b2 = 1/4.
    const m = mesh([tri(0, [0, 0], [4, 0], [0, 2])]);
    const h = hitOf(new Bvh(m.positions, m.indices), [1, 0.5, 3], [0, 0, -1])!;
    expect([h.t, h.triangle, h.b1, h.b2]).toEqual([3, 0, 0.25, 0.25]);
    // A direction of length 2: t halves.
    expect(hitOf(new Bvh(m.positions, m.indices), [1, 0.5, 3], [0, 0, -2])!.t).toBe(1.5);
    // From below, going up: both faces count.
    expect(hitOf(new Bvh(m.positions, m.indices), [1, 0.5, -3], [0, 0, 1])!.t).toBe(3);
  });

  it('edges and corners are inside; a hair outside is not', () => {
    const m = mesh([tri(0, [0, 0], [4, 0], [0, 2])]);
    const bvh = new Bvh(m.positions, m.indices);
    const down = (x: number, y: number) => hitOf(bvh, [x, y, 3], [0, 0, -1]);
    for (const [x, y] of [[0, 0], [4, 0], [0, 2], [2, 0], [0, 1], [2, 1]]) expect(down(x, y), `${x}, ${y}`).not.toBeNull();
    for (const [x, y] of [[-0.001, 1], [2, -0.001], [2.002, 1], [4.001, 0]]) expect(down(x, y), `${x}, ${y}`).toBeNull();
  });

  it('t within (tMin, tMax]: tMin exclusive, tMax inclusive', () => {
    const m = mesh([tri(0, [0, 0], [4, 0], [0, 2])]);
    const bvh = new Bvh(m.positions, m.indices);
    expect(hitOf(bvh, [1, 0.5, 3], [0, 0, -1], 2.999, 3)!.t).toBe(3);
    expect(hitOf(bvh, [1, 0.5, 3], [0, 0, -1], 3, 10)).toBeNull();
    expect(hitOf(bvh, [1, 0.5, 3], [0, 0, -1], 0, 2.999)).toBeNull();
    // Behind the origin: t = −3, found only when tMin allows it.
    expect(hitOf(bvh, [1, 0.5, -3], [0, 0, -1])!.t).toBe(-3);
    expect(hitOf(bvh, [1, 0.5, -3], [0, 0, -1], 0)).toBeNull();
  });

  it('a ray in the triangle\'s plane, or not a number, finds nothing', () => {
    const m = mesh([tri(0, [0, 0], [4, 0], [0, 2])]);
    const bvh = new Bvh(m.positions, m.indices);
    expect(hitOf(bvh, [-1, 0.5, 0], [1, 0, 0])).toBeNull();
    expect(hitOf(bvh, [1, 0.5, 3], [NaN, 0, -1])).toBeNull();
    // Along a slab's face with no motion across it (x = 0 exactly, dx = 0): still found.
    expect(hitOf(bvh, [0, 1, 3], [0, 0, -1])!.t).toBe(3);
    expect(hitOf(bvh, [1, 0, 3], [0, 0, -1])!.t).toBe(3);
  });

  it('the nearest of overlapping triangles, in either leaf, whatever the ray\'s direction', () => {
    // Two clusters of four (x ≈ 0 and x ≈ 10), each a stack at z = 0..3; plus a big triangle at z = −1 under both.
    const tris: number[][] = [];
    for (const x0 of [0, 10]) for (let k = 0; k < 4; k++) tris.push(tri(k, [x0, 0], [x0 + 2, 0], [x0, 2]));
    tris.push(tri(-1, [-5, -5], [20, -5], [-5, 20]));
    const m = mesh(tris);
    const bvh = new Bvh(m.positions, m.indices);
    checkLayout(bvh, m.positions, m.indices);
    // From above: the top of the stack (z = 3) at t = 2; from below: the big one at t = 4, then the bottom of a stack.
    expect(hitOf(bvh, [0.5, 0.5, 5], [0, 0, -1])).toMatchObject({ t: 2, triangle: 3 });
    expect(hitOf(bvh, [10.5, 0.5, 5], [0, 0, -1])).toMatchObject({ t: 2, triangle: 7 });
    expect(hitOf(bvh, [10.5, 0.5, -5], [0, 0, 1])).toMatchObject({ t: 4, triangle: 8 });
    expect(hitOf(bvh, [10.5, 0.5, -5], [0, 0, 1], 4)).toMatchObject({ t: 5, triangle: 4 });
    expect(hitOf(bvh, [0.5, 0.5, -5], [0, 0, 1], 5, 6.5)).toMatchObject({ t: 6, triangle: 1 });
    // Slanted rays across both clusters, each way along x, y and z. The first passes x < 0 above z = 2 and meets the
    // edge x = 0 of the triangle at z = 1 (t = 4.5).
    expect(hitOf(bvh, [-4.5, 0.5, 10], [1, 0, -2])).toMatchObject({ t: 4.5, triangle: 1 });
    expect(hitOf(bvh, [15.5, 0.5, 7], [-1, 0, -1])).toMatchObject({ t: 4, triangle: 7 });
    expect(hitOf(bvh, [10.5, 5.5, 8], [0, -1, -1])).toMatchObject({ t: 5, triangle: 7 });
    expect(hitOf(bvh, [10.5, -4.5, -6], [0, 1, 1])).toMatchObject({ t: 5, triangle: 8 });
    // Between the clusters: only the big triangle.
    expect(hitOf(bvh, [5, 0.5, 5], [0, 0, -1])).toMatchObject({ t: 6, triangle: 8 });
    // Beside everything.
    expect(hitOf(bvh, [30, 30, 5], [0, 0, -1])).toBeNull();
  });

  it('a miss leaves the hit as it was', () => {
    const m = mesh([tri(0, [0, 0], [4, 0], [0, 2])]);
    const bvh = new Bvh(m.positions, m.indices);
    const hit = new BvhHit();
    expect(bvh.intersect(1, 0.5, 3, 0, 0, -1, -Infinity, Infinity, hit)).toBe(true);
    expect(bvh.intersect(9, 9, 3, 0, 0, -1, -Infinity, Infinity, hit)).toBe(false);
    expect([hit.t, hit.triangle, hit.b1, hit.b2]).toEqual([3, 0, 0.25, 0.25]);
  });

  it('random triangles and rays: the same nearest hit as testing every triangle', () => {
    // mulberry32, seeded; Möller–Trumbore written out apart, by Cramer's rule (as tests/unit/bvh.test.ts does).
    let a = 12345;
    const random = () => {
      a = (a + 0x6d2b79f5) | 0;
      let t = Math.imul(a ^ (a >>> 15), 1 | a);
      t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
      return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
    };
    const tris: number[][] = [];
    for (let f = 0; f < 40; f++) {
      const c = [random() * 8 - 4, random() * 8 - 4, random() * 8 - 4];
      tris.push(Array.from({ length: 9 }, (_, i) => c[i % 3] + (random() - 0.5) * 2));
    }
    const m = mesh(tris);
    const bvh = new Bvh(m.positions, m.indices);
    checkLayout(bvh, m.positions, m.indices);
    const det3 = (x: number[], y: number[], z: number[]) =>
      x[0] * (y[1] * z[2] - y[2] * z[1]) - y[0] * (x[1] * z[2] - x[2] * z[1]) + z[0] * (x[1] * y[2] - x[2] * y[1]);
    let hits = 0;
    for (let r = 0; r < 300; r++) {
      const o = [0, 1, 2].map(() => random() * 14 - 7);
      const d = [0, 1, 2].map((k) => random() * 8 - 4 - o[k]);
      const tMin = r % 3 === 0 ? random() * 0.5 : -Infinity;
      let best = Infinity, tri = -1;
      tris.forEach((p, f) => {
        const e1 = [p[3] - p[0], p[4] - p[1], p[5] - p[2]], e2 = [p[6] - p[0], p[7] - p[1], p[8] - p[2]];
        const s0 = [o[0] - p[0], o[1] - p[1], o[2] - p[2]], nd = d.map((x) => -x);
        const det = det3(nd, e1, e2);
        if (det === 0) return;
        const t = det3(s0, e1, e2) / det, u = det3(nd, s0, e2) / det, v = det3(nd, e1, s0) / det;
        if (u >= 0 && v >= 0 && u + v <= 1 && t > tMin && t <= best) { best = t; tri = f; }
      });
      const h = hitOf(bvh, o, d, tMin);
      expect(h !== null, `ray ${r}`).toBe(tri >= 0);
      if (!h) continue;
      hits++;
      expect(Math.abs(h.t - best), `ray ${r}`).toBeLessThan(1e-9 * Math.max(1, best));
      const p = tris[h.triangle];
      for (let k = 0; k < 3; k++) {
        const q = (1 - h.b1 - h.b2) * p[k] + h.b1 * p[3 + k] + h.b2 * p[6 + k];
        expect(Math.abs(q - (o[k] + h.t * d[k])), `ray ${r}`).toBeLessThan(1e-9);
      }
    }
    expect(hits).toBeGreaterThan(40);
  });

  it('every cell of a grid, from above and from below', () => {
    const n = 6, m = grid(n);
    const bvh = new Bvh(m.positions, m.indices);
    for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) {
      // (i + 0.7, j + 0.3) lies in the cell's first triangle (below its diagonal), (i + 0.3, j + 0.7) in the second.
      expect(hitOf(bvh, [i + 0.7, j + 0.3, 2], [0, 0, -1])).toMatchObject({ t: 2, triangle: 2 * (j * n + i) });
      expect(hitOf(bvh, [i + 0.3, j + 0.7, -2], [0, 0, 1])).toMatchObject({ t: 2, triangle: 2 * (j * n + i) + 1 });
    }
  });
});
