// raster.ts's edge functions on the fixed-point grid, with the top-left rule's biases, and a
// row's covered run from them: where e + k·step ≥ 0 can hold along the row, widened by one either
// side (the exact integer test per pixel still decides).

/** Sub-pixel precision of the snapped vertices: 1/256 px, as GPUs commonly use (8 bits). */
export const SUBPIXEL_BITS = 8;
export const SUB = 1 << SUBPIXEL_BITS;
export const HALF = SUB >> 1;

/**
 * Triangle (i, j, k)'s edge functions at the centre of pixel (px, py) and their steps per
 * pixel (exact integers), with the top-left rule's biases, into `e`: row0..2,
 * stepX0..2, stepY0..2, bias0..2. Edge e_v is opposite vertex v: e0 = E(1→2), e1 = E(2→0),
 * e2 = E(0→1); E(a→b)(p) = (bx − ax)(py − ay) − (by − ay)(px − ax), positive inside (area > 0).
 */
export function edgeFunctions(e: Float64Array, fx: Float64Array, fy: Float64Array, i: number, j: number, k: number, px: number, py: number): Float64Array {
  const x0 = fx[i], y0 = fy[i], x1 = fx[j], y1 = fy[j], x2 = fx[k], y2 = fy[k];
  const ax0 = x2 - x1, ay0 = y2 - y1; // edge 1→2
  const ax1 = x0 - x2, ay1 = y0 - y2; // edge 2→0
  const ax2 = x1 - x0, ay2 = y1 - y0; // edge 0→1
  const cx = px * SUB + HALF, cy = py * SUB + HALF;
  e[0] = ax0 * (cy - y1) - ay0 * (cx - x1);
  e[1] = ax1 * (cy - y2) - ay1 * (cx - x2);
  e[2] = ax2 * (cy - y0) - ay2 * (cx - x0);
  e[3] = -ay0 * SUB; e[4] = -ay1 * SUB; e[5] = -ay2 * SUB;
  e[6] = ax0 * SUB; e[7] = ax1 * SUB; e[8] = ax2 * SUB;
  // Top-left rule (y down, interior on the right of each edge as walked): a top edge runs
  // exactly horizontally rightwards, a left edge upwards. Pixels on other edges are left out.
  // Stryker disable next-line EqualityOperator: ax0 = 0 = ay0 is an edge of no length, of a triangle of no area: raster.ts scans none
  e[9] = (ay0 === 0 && ax0 > 0) || ay0 < 0 ? 0 : -1;
  // Stryker disable next-line EqualityOperator: the same for ax1 = 0 = ay1
  e[10] = (ay1 === 0 && ax1 > 0) || ay1 < 0 ? 0 : -1;
  // Stryker disable next-line EqualityOperator: the same for ax2 = 0 = ay2
  e[11] = (ay2 === 0 && ax2 > 0) || ay2 < 0 ? 0 : -1;
  return e;
}

/** First k ≥ 0 (one early) where e + k·step ≥ 0 can hold; a value past any span when it never can. */
export function runStart(e: number, step: number): number {
  // Stryker disable next-line EqualityOperator: at step = 0 (e < 0) it gives ⌈∞⌉ − 1 = ∞, past any span as 1 << 30 is
  if (step > 0) return e >= 0 ? 0 : Math.ceil(-e / step) - 1;
  return e >= 0 ? 0 : 1 << 30;
}

/** Last k (one late) where e + k·step ≥ 0 can hold, capped at `span`; −1 when it never can. */
export function runEnd(e: number, step: number, span: number): number {
  if (step < 0) return e < 0 ? -1 : Math.min(span, Math.floor(e / -step) + 1);
  return e >= 0 || step > 0 ? span : -1;
}
