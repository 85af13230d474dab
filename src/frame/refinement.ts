// Refinement at rest (docs/refinement.md): a still view of N frames. Frame 1 is the frame as a moving one is drawn (the
// preview); frames 2..N each draw one stratum of the pixel — the grid moved by a sub-pixel offset, textures read over
// the stratum, spheres cut finer — and are averaged in linear light; the picture shown is the preview blended into that
// mean, the mean's share growing to all of it at frame N, when N − 1 strata are the side × side supersampled picture.
// Both renderers read these numbers; they are tied down by hand in tests/unit/refinement.test.ts.
import type { FrameState } from './types';
import { encodesAtEnd } from './linear-light';

/** The most frames at rest the `refine` attribute can ask for. */
export const MAX_REFINEMENT = 1024;

/** The most base-3 digits of a stratum: a grid of 3⁶ = 729 a side, past any MAX_REFINEMENT asks for. */
const MAX_DIGITS = 6;

/**
 * The side of the grid of strata a still view of `frames` frames fills with its `frames` − 1 strata frames: the least
 * power of 3 whose square is at least that (frames 1..2 → 1, 3..10 → 3, 11..82 → 9, 83..730 → 27). Odd, so one stratum is
 * the pixel's centre; side² strata are the side × side supersampled picture.
 */
export function refinementGrid(frames: number): number {
  let side = 1;
  for (let d = 0; d < MAX_DIGITS && side * side < frames - 1; d++) side *= 3;
  return side;
}

const digits = new Uint8Array(MAX_DIGITS);

/**
 * The stratum, on a 3^m-sided grid, of point i (from 0) of Faure's (0, 2)-sequence in base 3, each digit d then taken to
 * (d + 1) mod 3. x's digits are i's base-3 digits, least first (the radical inverse); y's r-th digit is Σⱼ C(j, r)·aⱼ
 * mod 3 (Pascal's triangle mod 3). Every 3^(2m) points from 0 fall one in each cell of the 3^m × 3^m grid (Faure 1982);
 * the same permutation of every digit keeps that, and takes point 0 to the centre cell. Cell indices into `out`.
 */
function faureCell(i: number, m: number, out: Int32Array): void {
  let n = i;
  // Stryker disable next-line EqualityOperator: j = MAX_DIGITS writes past the Uint8Array's end (dropped); no such digit is read
  for (let j = 0; j < MAX_DIGITS; j++) {
    digits[j] = n % 3;
    n = Math.floor(n / 3);
  }
  let x = 0, y = 0;
  for (let r = 0; r < m; r++) {
    let b = 0;
    for (let j = r; j < MAX_DIGITS; j++) b += binomial3(j, r) * digits[j];
    x = 3 * x + ((digits[r] + 1) % 3);
    y = 3 * y + ((b + 1) % 3);
  }
  out[0] = x;
  out[1] = y;
}

/** C(n, k) mod 3 by Lucas's theorem: the product of the digits' C(a, b), each 1 except C(2, 1) = 2 and 0 for b > a. */
export function binomial3(n: number, k: number): number {
  let result = 1;
  while (n > 0 || k > 0) {
    const a = n % 3, b = k % 3;
    if (b > a) return 0;
    if (a === 2 && b === 1) result *= 2;
    n = Math.floor(n / 3);
    k = Math.floor(k / 3);
  }
  return result % 3;
}

const cell = new Int32Array(2);

/**
 * The k-th frame's offset (k from 1) of the pixel grid, in pixels, in a still view of `frames` frames: (0, 0) for the
 * preview (k = 1); for k ≥ 2 the centre of the stratum of the `refinementGrid(frames)`-sided grid that point k − 2 of
 * the sequence falls in, less ½ — side² strata frames are side² distinct strata (past them the sequence starts again),
 * the first the pixel's centre. Written into `out`.
 */
export function refinementOffset(k: number, frames: number, out: Float64Array | number[]): Float64Array | number[] {
  const side = refinementGrid(frames);
  let m = 0;
  for (let s = side; s > 1; s /= 3) m++;
  faureCell(Math.max(0, Math.floor(k) - 2) % (side * side), m, cell);
  out[0] = (cell[0] + 0.5) / side - 0.5;
  out[1] = (cell[1] + 0.5) / side - 0.5;
  return out;
}

/**
 * How much finer than a pixel a frame draws what depends on the grid (docs/refinement.md#footprints): a strata frame
 * reads its textures over 1/side of a pixel and cuts spheres for side samples a pixel, as the supersampled picture does;
 * the preview and any other frame 1.
 */
export const refinementScale = (state: Pick<FrameState, 'colorSpace' | 'view' | 'refinement' | 'refinementFrames'>): number =>
  refines(state) && state.refinement! >= 2 ? refinementGrid(state.refinementFrames ?? 1) : 1;

/**
 * Rough glass's gather in strata frame k (docs/refinement.md#rough-glass): where in each ring's sector its sample lies,
 * (u, v) — u the share of the sector's area inside it, v the turn across it — and the shift of its mip level, −log₂ side,
 * each sample then standing for 1/side² of its sector. The strata are the sequence's, taken in another order
 * (point 7·(k − 2) mod side², a permutation since 7 and side² share no factor), so that the pixel's move and the
 * sample's place do not go together. Any other frame: (½, ½, 0), the gather as it is alone. Written into `out`.
 */
export function gatherJitter(state: Pick<FrameState, 'colorSpace' | 'view' | 'refinement' | 'refinementFrames'>, out: Float64Array | Float32Array): void {
  const side = refinementScale(state);
  if (side === 1) {
    out[0] = out[1] = 0.5;
    out[2] = 0;
    return;
  }
  const frames = state.refinementFrames ?? 1;
  refinementOffset(2 + ((7 * (Math.floor(state.refinement!) - 2)) % (side * side)), frames, gatherOffset);
  out[0] = gatherOffset[0] + 0.5;
  out[1] = gatherOffset[1] + 0.5;
  out[2] = -Math.log2(side);
}

const gatherOffset = new Float64Array(2);

/** The weight of strata frame k (k ≥ 2) in the strata's running mean: 1/(k − 1), so frame 2 starts it. */
export function refinementWeight(k: number): number {
  return k >= 3 ? 1 / (Math.floor(k) - 1) : 1;
}

/**
 * The strata mean's share of the picture shown after frame k of `frames` (the preview's is 1 − it): (k − 1)/(frames − 1),
 * 0 for the preview alone, all of it at the last frame. The mean's noise is let in as it falls.
 */
export function meanShare(k: number, frames: number): number {
  return frames <= 1 || k <= 1 ? 0 : Math.min(1, (Math.floor(k) - 1) / (Math.floor(frames) - 1));
}

/**
 * Whether a frame of `state` is a refinement frame: k ≥ 1, of the final picture, in linear light (with
 * `color-space="none"` there is no linear light to average, and the debug views show one pass as it is).
 */
export const refines = (state: Pick<FrameState, 'colorSpace' | 'view' | 'refinement'>): boolean =>
  (state.refinement ?? 0) >= 1 && state.view === 'final' && encodesAtEnd(state);

/**
 * Moves clip space by `dx`, `dy` pixels of a `width` × `height` frame: the rows of x and y gain the w row times the
 * offset in normalised device units (2·dx / width), so every point lands dx pixels right and dy pixels up, in either
 * projection. `m` is column-major, as gl-matrix keeps it.
 */
export function jitterClip(m: Float64Array, dx: number, dy: number, width: number, height: number): void {
  const ax = (2 * dx) / Math.max(1, width), ay = (2 * dy) / Math.max(1, height);
  // Stryker disable next-line EqualityOperator: c = 16 writes past the Float64Array's end (dropped)
  for (let c = 0; c < 16; c += 4) {
    m[c] += ax * m[c + 3];
    m[c + 1] += ay * m[c + 3];
  }
}
