// An environment image as the reference's light (docs/pbr.md#the-reference): read by the lookup every renderer's light comes
// from (math/environment-image.ts), and drawn by its own brightness — a texel chosen with probability ∝ the mean luminance of
// the bilinear read over its cell × sin θ (the solid angle a cell of its row spans), a point uniform in it — so that a small
// bright sun is found by a few samples rather than by the lobes' luck. The mean over a cell is ⅛, ¾, ⅛ of the texels before, at
// and after it along each axis: the bilinear read carries a texel's light half a texel into its neighbours, and their cells
// must be drawn for it too. The density in solid angle is the cell's share × texels ÷ (2π² sin θ).
import { imageDirection, imageRadiance, type EnvironmentImage } from '../math/environment-image';
import type { EnvironmentLight } from './pbr-light';

/** The index k with cdf[k] ≤ r < cdf[k + 1] in cdf[lo..hi] (cdf[lo] = 0 ≤ r < cdf[hi]), and where r falls within it (0..1). */
function pick(cdf: Float64Array, lo: number, hi: number, r: number): { k: number; f: number } {
  let a = lo, b = hi;
  while (b - a > 1) {
    const m = (a + b) >> 1;
    // Stryker disable next-line EqualityOperator: r exactly at an entry's start picks the one before at f = 1: the same point
    if (cdf[m] <= r) a = m;
    else b = m;
  }
  const span = cdf[a + 1] - cdf[a];
  // Stryker disable next-line ConditionalExpression,EqualityOperator: the search never ends on an entry of no width (r < its end): span > 0, the ½ is a guard
  return { k: a - lo, f: span > 0 ? (r - cdf[a]) / span : 0.5 };
}

const lights = new WeakMap<EnvironmentImage, EnvironmentLight>();

/** `img` as an environment: its lookup, and drawn by its texels' power where it has any (a black image draws by the lobes alone). */
export function imageLight(img: EnvironmentImage): EnvironmentLight {
  const kept = lights.get(img);
  // Stryker disable next-line ConditionalExpression: made again, the same light (the map saves the time)
  if (kept) return kept;
  const { width: w, height: h, rgb } = img;
  const lum = new Float64Array(w * h);
  // Stryker disable next-line EqualityOperator: k = w·h writes past lum's end: dropped
  for (let k = 0; k < w * h; k++) lum[k] = 0.2126 * rgb[3 * k] + 0.7152 * rgb[3 * k + 1] + 0.0722 * rgb[3 * k + 2];
  // Across (wrapping), then down (held at the first and last rows), as the read does.
  const across = new Float64Array(w * h);
  // Stryker disable next-line EqualityOperator: j = h writes past across's end: dropped
  for (let j = 0; j < h; j++) {
    // Stryker disable next-line EqualityOperator,ArithmeticOperator: i = w writes the next row's first (written again with it) or past the end; × 8 for ÷ 8 scales every cell alike
    for (let i = 0; i < w; i++) across[j * w + i] = (lum[j * w + ((i + w - 1) % w)] + 6 * lum[j * w + i] + lum[j * w + ((i + 1) % w)]) / 8;
  }
  // Row j's column CDF in rows[j(w + 1) ..], unnormalised; the rows' CDF by their sums.
  const rows = new Float64Array(h * (w + 1)), marginal = new Float64Array(h + 1);
  // Stryker disable next-line EqualityOperator: j = h writes past rows' and marginal's ends: dropped
  for (let j = 0; j < h; j++) {
    const sin = Math.sin((Math.PI * (j + 0.5)) / h), o = j * (w + 1), up = Math.max(0, j - 1) * w, down = Math.min(h - 1, j + 1) * w;
    for (let i = 0; i < w; i++) {
      // Stryker disable next-line ArithmeticOperator: × 8 for ÷ 8 scales every cell alike: the shares are the same
      const cell = (across[up + i] + 6 * across[j * w + i] + across[down + i]) / 8;
      rows[o + i + 1] = rows[o + i] + cell * sin;
    }
    marginal[j + 1] = marginal[j] + rows[o + w];
  }
  const total = marginal[h];
  const light: EnvironmentLight = { radiance: imageRadiance(img) };
  if (total > 0) {
    light.lights = {
      draw(out, u, v) {
        const row = pick(marginal, 0, h, v * total), o = row.k * (w + 1);
        const col = pick(rows, o, o + w, u * rows[o + w]);
        imageDirection(out, (col.k + col.f) / w, (row.k + row.f) / h);
      },
      density(x, y, z) {
        const sin = Math.sqrt(Math.max(0, 1 - y * y));
        if (sin === 0) return 0;
        // Stryker disable next-line EqualityOperator,ConditionalExpression,UnaryOperator: |y| ≥ 1 gives sin θ = 0, returned above: the clamps never act here
        const u = 0.5 + Math.atan2(z, x) / (2 * Math.PI), v = Math.acos(y < -1 ? -1 : y > 1 ? 1 : y) / Math.PI;
        // Stryker disable next-line ArithmeticOperator: v·h reaches h only at y = −1, where sin θ = 0 returned already; the row's clamp is for that
        const i = Math.min(w - 1, Math.floor(u * w)), j = Math.min(h - 1, Math.floor(v * h)), o = j * (w + 1);
        const share = (rows[o + i + 1] - rows[o + i]) / total;
        return (share * w * h) / (2 * Math.PI * Math.PI * sin);
      },
    };
  }
  lights.set(img, light);
  return light;
}
