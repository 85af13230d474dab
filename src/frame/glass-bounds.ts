// Where the glass lands on screen: its rectangle clipped to the view frustum in clip space
// (Sutherland–Hodgman, float64), as a pixel bounding box and an area. The reflection pass is
// skipped when the area is nil (off screen or edge-on) and scissored to the box otherwise.
import type { Vec3 } from '../scene/scene';

export interface ScreenRect {
  /** Pixel bounds, origin bottom-left, x0 ≤ x < x1. Empty when x1 ≤ x0 or y1 ≤ y0. */
  x0: number;
  y0: number;
  x1: number;
  y1: number;
  /** Projected area in square pixels. */
  area: number;
}

const MAX = 4 + 6; // a quadrilateral clipped by six planes has at most 10 vertices
let a = new Float64Array(MAX * 4);
let b = new Float64Array(MAX * 4);
const SIGNS = [1, -1];

/** Clips the polygon in `src` (n vertices, xyzw) by the plane dot(k, v) ≥ 0 into `dst`. */
function clip(src: Float64Array, n: number, dst: Float64Array, axis: number, sign: number): number {
  let m = 0;
  for (let i = 0; i < n; i++) {
    const j = (i + 1) % n;
    const di = src[i * 4 + 3] + sign * src[i * 4 + axis];
    const dj = src[j * 4 + 3] + sign * src[j * 4 + axis];
    // Stryker disable next-line EqualityOperator: k = 4 writes the next vertex's x, written after it or never read
    if (di >= 0) { for (let k = 0; k < 4; k++) dst[m * 4 + k] = src[i * 4 + k]; m++; }
    if ((di >= 0) !== (dj >= 0)) {
      const t = di / (di - dj);
      // Stryker disable next-line EqualityOperator: as above
      for (let k = 0; k < 4; k++) dst[m * 4 + k] = src[i * 4 + k] + t * (src[j * 4 + k] - src[i * 4 + k]);
      m++;
    }
  }
  return m;
}

/**
 * `viewProjectionRelative` maps eye-relative world points to clip space (float64);
 * `eye` is the camera position, `corners` the glass's. Writes its screen rectangle into `out`.
 */
export function glassScreenRect(
  viewProjectionRelative: Float64Array, eye: Float64Array, width: number, height: number, out: ScreenRect,
  corners: readonly Vec3[],
): ScreenRect {
  const m = viewProjectionRelative;
  for (let i = 0; i < 4; i++) {
    const c = corners[i];
    const x = c[0] - eye[0], y = c[1] - eye[1], z = c[2] - eye[2];
    // Stryker disable next-line EqualityOperator: r = 4 writes the next corner's x, written after it (the fifth slot is never read)
    for (let r = 0; r < 4; r++) a[i * 4 + r] = m[r] * x + m[4 + r] * y + m[8 + r] * z + m[12 + r];
  }
  let n = 4;
  // Stryker disable next-line EqualityOperator: a fourth axis (w ≥ 0, w ≥ w) cuts nothing |z| ≤ w kept
  for (let axis = 0; axis < 3; axis++) {
    for (const sign of SIGNS) {
      n = clip(a, n, b, axis, sign);
      [a, b] = [b, a];
      // Stryker disable next-line ConditionalExpression: an empty polygon clips to empty
      if (n === 0) break;
    }
  }
  out.x0 = out.y0 = Infinity;
  out.x1 = out.y1 = -Infinity;
  out.area = 0;
  if (n < 3) { out.x0 = out.y0 = out.x1 = out.y1 = 0; return out; }
  let twice = 0;
  let px0 = 0, py0 = 0, pxPrev = 0, pyPrev = 0;
  for (let i = 0; i < n; i++) {
    const w = a[i * 4 + 3];
    const px = (a[i * 4] / w * 0.5 + 0.5) * width;
    const py = (a[i * 4 + 1] / w * 0.5 + 0.5) * height;
    // Stryker disable next-line EqualityOperator: a tie assigns the same value
    if (px < out.x0) out.x0 = px;
    // Stryker disable next-line EqualityOperator: a tie assigns the same value
    if (px > out.x1) out.x1 = px;
    // Stryker disable next-line EqualityOperator: a tie assigns the same value
    if (py < out.y0) out.y0 = py;
    // Stryker disable next-line EqualityOperator: a tie assigns the same value
    if (py > out.y1) out.y1 = py;
    if (i === 0) { px0 = px; py0 = py; } else twice += pxPrev * py - px * pyPrev;
    pxPrev = px; pyPrev = py;
  }
  twice += pxPrev * py0 - px0 * pyPrev;
  out.area = Math.abs(twice) / 2;
  out.x0 = Math.max(0, Math.floor(out.x0));
  out.y0 = Math.max(0, Math.floor(out.y0));
  out.x1 = Math.min(width, Math.ceil(out.x1));
  out.y1 = Math.min(height, Math.ceil(out.y1));
  return out;
}
