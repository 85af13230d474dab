// The sRGB transfer curve of docs/colour.md#the-transfer-curve (IEC 61966-2-1, piecewise: not a 2.2 power), and the
// colour space a frame is drawn in. shaders/encode.frag and the texture formats of the GL path
// mirror it. Shared by the float64 reference and the software renderer, so comparing those two
// cannot see a fault here: tied down by tests/unit/srgb.test.ts's published values (8-bit
// levels 10, 64, 128, 200 and 255 in linear light, the curve's two segments at their joint).

/** `srgb`: colour data decoded, light mixed linearly, the image encoded once; `none`: values as stored. */
export type ColorSpace = 'srgb' | 'none';
export const COLOR_SPACES: readonly ColorSpace[] = ['srgb', 'none'];

/** Encoded (0..1) → linear light. */
export function srgbToLinear(c: number): number {
  if (c <= 0.04045) return c / 12.92;
  return Math.pow((c + 0.055) / 1.055, 2.4);
}

/** Linear light → encoded, clipped to 0..1 first (no tone mapping). */
export function linearToSrgb(l: number): number {
  // Stryker disable next-line EqualityOperator: l = 0 takes the linear segment below: 12.92·0 = 0
  if (!(l > 0)) return 0; // NaN, negatives and zero
  if (l >= 1) return 1;
  if (l <= 0.0031308) return 12.92 * l;
  return 1.055 * Math.pow(l, 1 / 2.4) - 0.055;
}

/** decode(b / 255) for every 8-bit level b: colour data held in bytes decoded by a lookup. */
export const SRGB_BYTE_TO_LINEAR: Float64Array = /* @__PURE__ */ (() => {
  const t = new Float64Array(256);
  // Stryker disable next-line EqualityOperator: b ≤ 256 also writes t[256], which a Float64Array of 256 drops
  for (let b = 0; b < 256; b++) t[b] = srgbToLinear(b / 255);
  return t;
})();

/**
 * The linear value at which the encoded byte steps from b − 1 to b (b = 1..255), i.e.
 * decode((b − ½) / 255): a byte is the count of thresholds at or below a value, which is
 * round(encode(l)·255) without a pow per pixel (ties, which rounding sends up, included).
 */
const THRESHOLDS: Float64Array = /* @__PURE__ */ (() => {
  const t = new Float64Array(256);
  // Stryker disable next-line UnaryOperator: t[0] is never read (the search's mid is ≥ 1); −∞ documents "at or below"
  t[0] = -Infinity;
  // Stryker disable next-line EqualityOperator: b ≤ 256 also writes t[256], which a Float64Array of 256 drops
  for (let b = 1; b < 256; b++) t[b] = srgbToLinear((b - 0.5) / 255);
  return t;
})();

/** round(linearToSrgb(l)·255) by a binary search over 255 thresholds (8 comparisons). */
export function linearToSrgbByte(l: number): number {
  // Stryker disable next-line ConditionalExpression,EqualityOperator: a shortcut: the search gives 0 for l ≤ 0 and NaN too (t[1] > 0)
  if (!(l > 0)) return 0;
  const t = THRESHOLDS;
  let lo = 0, hi = 255; // t[lo] ≤ l; the answer is in [lo, hi]
  while (lo < hi) {
    const mid = (lo + hi + 1) >> 1;
    if (t[mid] <= l) lo = mid;
    else hi = mid - 1;
  }
  return lo;
}
