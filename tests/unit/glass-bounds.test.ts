// Where the glass lands on screen (src/frame/glass-bounds.ts): its corners through a clip-space
// matrix, clipped to the frustum (Sutherland–Hodgman), as a pixel box (floor/ceil, clamped to the
// canvas) and an area, on matrices simple enough to follow by hand.
import { describe, expect, it } from 'vitest';
import { glassScreenRect, type ScreenRect } from '../../src/frame/glass-bounds';
import type { Vec3 } from '../../src/scene/scene';

const W = 100, H = 50;
const rect = (): ScreenRect => ({ x0: NaN, y0: NaN, x1: NaN, y1: NaN, area: NaN });
/** Column-major 4×4 from its rows. */
const rows = (r: number[][]) => new Float64Array([0, 1, 2, 3].flatMap((c) => r.map((row) => row[c])));
const IDENTITY = rows([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]]);
/** clip = (x, y, z, −z): a camera looking down −Z, NDC x = x/−z. */
const PERSPECTIVE = rows([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, -1, 0]]);
const ORIGIN = new Float64Array(3);
const quad = (x0: number, y0: number, x1: number, y1: number, z = 0): Vec3[] => [[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]];
const screen = (m: Float64Array, corners: Vec3[], eye = ORIGIN) => glassScreenRect(m, eye, W, H, rect(), corners);

describe('glassScreenRect', () => {
  it('a glass inside the view: pixels (x·½ + ½)·W, floor and ceil outwards, its area', () => {
    // NDC x ∈ [−0.5, 0.5] → 25..75; y ∈ [−0.5, 0.5] → 12.5..37.5 → 12..38; area 50 × 25.
    expect(screen(IDENTITY, quad(-0.5, -0.5, 0.5, 0.5))).toEqual({ x0: 25, y0: 12, x1: 75, y1: 38, area: 1250 });
  });

  it('relative to the eye, through every entry of the matrix (scale, translation)', () => {
    // clip x = 2(x − 1) + 0.1, y = 2(y − 1) − 0.2, z = z − 3, w = 1 (the eye at (1, 1, 3)): corners
    // 0.8..1.2 at z = 3 → x ∈ [−0.3, 0.5], y ∈ [−0.6, 0.2], z = 0.
    const m = rows([[2, 0, 0, 0.1], [0, 2, 0, -0.2], [0, 0, 1, 0], [0, 0, 0, 1]]);
    const r = screen(m, quad(0.8, 0.8, 1.2, 1.2, 3), new Float64Array([1, 1, 3]));
    expect({ ...r, area: 0 }).toEqual({ x0: 35, y0: 10, x1: 75, y1: 30, area: 0 });
    expect(r.area).toBeCloseTo(800, 9);
  });

  it('divides by w: the same glass twice as far covers half the width', () => {
    // At z = −2: NDC = x/2 ∈ [−0.5, 0.5]; at z = −4: [−0.25, 0.25] → 37.5..62.5.
    expect(screen(PERSPECTIVE, quad(-1, -1, 1, 1, -2))).toEqual({ x0: 25, y0: 12, x1: 75, y1: 38, area: 1250 });
    const far = screen(PERSPECTIVE, quad(-1, -1, 1, 1, -4));
    expect(far).toEqual({ x0: 37, y0: 18, x1: 63, y1: 32, area: 312.5 });
  });

  it('clips to the frustum: the part on screen only, the box clamped to the canvas', () => {
    // x ∈ [0, 2], y ∈ [0, 2] → clipped to [0, 1]²: 50..100, 25..50.
    expect(screen(IDENTITY, quad(0, 0, 2, 2))).toEqual({ x0: 50, y0: 25, x1: 100, y1: 50, area: 1250 });
    expect(screen(IDENTITY, quad(-2, -2, 0, 0))).toEqual({ x0: 0, y0: 0, x1: 50, y1: 25, area: 1250 });
    // Beyond near or far (|z| > w): nothing.
    expect(screen(IDENTITY, quad(-0.5, -0.5, 0.5, 0.5, 1.5))).toEqual({ x0: 0, y0: 0, x1: 0, y1: 0, area: 0 });
    expect(screen(IDENTITY, quad(-0.5, -0.5, 0.5, 0.5, -1.5))).toEqual({ x0: 0, y0: 0, x1: 0, y1: 0, area: 0 });
    // Off to one side: nothing.
    expect(screen(IDENTITY, quad(2, -0.5, 3, 0.5))).toEqual({ x0: 0, y0: 0, x1: 0, y1: 0, area: 0 });
    expect(screen(IDENTITY, quad(-0.5, -3, 0.5, -2))).toEqual({ x0: 0, y0: 0, x1: 0, y1: 0, area: 0 });
  });

  it('a clipped corner leaves a triangle: (0, 0), (1, 0), (1, 0.5) of a quad reaching x = 2', () => {
    // Only the first corner is inside x ≤ 1: it and the crossings of its two edges remain.
    const r = screen(IDENTITY, [[0, 0, 0], [2, 0, 0], [2, 0.5, 0], [2, 1, 0]]);
    // The edge from (2, 1) back to (0, 0) crosses x = 1 at y = 0.5. Pixels (50, 25), (100, 25),
    // (100, 37.5): half of 50 × 12.5.
    expect(r).toEqual({ x0: 50, y0: 25, x1: 100, y1: 38, area: 312.5 });
  });

  it('an edge-on glass: a line of no area, its box still where the line is', () => {
    const r = screen(IDENTITY, [[-0.5, 0, 0], [0.5, 0, 0], [0.5, 0, 0], [-0.5, 0, 0]]);
    expect(r).toEqual({ x0: 25, y0: 25, x1: 75, y1: 25, area: 0 });
  });

  it('part behind the eye is cut at w = 0, not projected through it', () => {
    // Corners at z = −2 and z = +2 (behind): the part with −z ≥ |x|, |y|, |z| is kept: at z = −1
    // (w = 1) the glass spans x ∈ [−1, 1], reaching the screen's edges in x; y = −1 is the bottom.
    const r = screen(PERSPECTIVE, [[-1, -1, -2], [1, -1, -2], [1, -1, 2], [-1, -1, 2]]);
    expect(r.x0).toBe(0);
    expect(r.x1).toBe(W);
    expect(r.y0).toBe(0);
    expect(r.y1).toBeLessThanOrEqual(13);
    expect(r.area).toBeGreaterThan(0);
    expect(Number.isFinite(r.area)).toBe(true);
  });
});
