// The software rasterizer's clip-space tests (src/software/clip.ts), by hand: each plane's
// distance (≥ 0 inside), a vertex's inside bits, the vertex copy, and the band shortcut that
// skips a triangle wholly above or below a band of rows (docs/software-renderer.md).
import { describe, expect, it } from 'vitest';
import { ALL, CLIP_DISTANCE, GUARD, USER, copyVertex, inside, outsideRows, planeDistance } from '../../src/software/clip';

/** One vertex as the rasterizer lays it out: x, y, z, w, the user clip distance. */
const vertex = (x: number, y: number, z: number, w: number, d = 0) => new Float64Array([x, y, z, w, d]);

describe('clip planes as distances, ≥ 0 inside (near, far, the guard band, the user plane)', () => {
  it('gives each plane its distance for a vertex, read at an offset', () => {
    const v = new Float64Array([9, 9, 9, 9, 9, 1, -2, 0.5, 2, -3]); // the vertex at offset 5
    expect([0, 1, 2, 3, 4, 5, 6].map((p) => planeDistance(v, 5, p))).toEqual([
      0.5 + 2, 2 - 0.5, GUARD * 2 + 1, GUARD * 2 - 1, GUARD * 2 - 2, GUARD * 2 + 2, -3,
    ]);
  });

  it('sets a bit per plane the vertex is inside, on the plane counting as inside', () => {
    expect(inside(vertex(0, 0, 0, 1), 0, false)).toBe(ALL);
    // On each plane exactly: still inside every one.
    for (const v of [vertex(4, 0, 0, 1), vertex(-4, 0, 0, 1), vertex(0, 4, 0, 1), vertex(0, -4, 0, 1), vertex(0, 0, 1, 1), vertex(0, 0, -1, 1)]) {
      expect(inside(v, 0, false), [...v].join(' ')).toBe(ALL);
    }
    // Just outside each plane in turn: that plane's bit alone is clear.
    const out: [Float64Array, number][] = [
      [vertex(0, 0, -1.01, 1), 0], [vertex(0, 0, 1.01, 1), 1], [vertex(-4.01, 0, 0, 1), 2], [vertex(4.01, 0, 0, 1), 3],
      [vertex(0, -4.01, 0, 1), 4], [vertex(0, 4.01, 0, 1), 5],
    ];
    for (const [v, plane] of out) expect(inside(v, 0, false), `plane ${plane}`).toBe(ALL & ~(1 << plane));
    // Read at an offset: the vertex after a first one.
    const two = new Float64Array([0, 0, 0, 1, 0, 0, 0, 0, 1, -1]);
    expect(inside(two, 0, true)).toBe(ALL);
    expect(inside(two, 5, true)).toBe(ALL & ~(1 << USER));
  });

  it('reads the user plane only when asked, its distance 0 inside', () => {
    expect(inside(vertex(0, 0, 0, 1, -0.5), 0, false)).toBe(ALL);
    expect(inside(vertex(0, 0, 0, 1, -0.5), 0, true)).toBe(ALL & ~(1 << USER));
    expect(inside(vertex(0, 0, 0, 1, 0), 0, true)).toBe(ALL);
    expect(CLIP_DISTANCE).toBe(4);
  });
});

describe('copyVertex', () => {
  it('copies n values from one offset to another, and no more', () => {
    const src = new Float64Array([1, 2, 3, 4, 5, 6]);
    const dst = new Float64Array(8).fill(-1);
    copyVertex(src, 2, dst, 3, 3);
    expect([...dst]).toEqual([-1, -1, -1, 3, 4, 5, -1, -1]);
  });
});

describe('outsideRows: a triangle wholly above NDC y = hi or below lo, in front of the eye', () => {
  /** Three vertices of (y, w), x = z = 0, at offsets 0, 5, 10. */
  const tri = (...yw: [number, number][]) => new Float64Array(yw.flatMap(([y, w]) => [0, y, 0, w, 0]));
  const test = (t: Float64Array, hi: number, lo: number) => outsideRows(t, 0, 5, 10, hi, lo);

  it('is true when every vertex is above hi, or every one below lo (y compared with hi·w, lo·w)', () => {
    expect(test(tri([1, 2], [1.2, 2], [3, 4]), 0.4, -0.4)).toBe(true); // y/w 0.5, 0.6, 0.75
    expect(test(tri([-1, 2], [-1.2, 2], [-3, 4]), 0.4, -0.4)).toBe(true);
  });

  it('is false when any one vertex reaches the band, from either side, or lies on its edge', () => {
    for (const k of [0, 1, 2]) {
      const above: [number, number][] = [[1, 2], [1.2, 2], [3, 4]];
      above[k] = [0.8 * above[k][1] / 2, above[k][1]]; // y/w 0.4 = hi: on the edge, not above it
      expect(test(tri(...above), 0.4, -0.4), `above, vertex ${k} on hi`).toBe(false);
      const below: [number, number][] = [[-1, 2], [-1.2, 2], [-3, 4]];
      below[k] = [-0.8 * below[k][1] / 2, below[k][1]];
      expect(test(tri(...below), 0.4, -0.4), `below, vertex ${k} on lo`).toBe(false);
    }
    expect(test(tri([1, 2], [-1, 2], [3, 4]), 0.4, -0.4)).toBe(false); // one above, one below: it crosses the band
  });

  it('is false for a triangle with a vertex at or behind the eye (w ≤ 0): clipping decides', () => {
    for (const k of [0, 1, 2]) {
      for (const w of [0, -1]) {
        const t: [number, number][] = [[3, 2], [3, 2], [3, 2]];
        t[k] = [3, w];
        expect(test(tri(...t), 0.4, -0.4), `vertex ${k}, w ${w}`).toBe(false);
      }
    }
  });
});
