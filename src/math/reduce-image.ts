// An environment image reduced to at most 512 × 256 texels (docs/pbr.md#an-image), each new texel the mean of the texels it
// covers, so that the light's total is kept: the finest prefiltered level is 256 wide, and finer texels would only be
// point-sampled. Read by the element's loader (element/environment-files.ts); tied down by tests/unit/environment-image.test.ts.
import { ENVIRONMENT_IMAGE_WIDTH, type EnvironmentImage } from './environment-image';

/** For each of `to` texels along an axis of `from`: the old texels it covers, with the share of each (summing to 1). */
function areaWeights(from: number, to: number): { first: number; weights: number[] }[] {
  const step = from / to, out: { first: number; weights: number[] }[] = [];
  // Stryker disable next-line EqualityOperator: k = to pushes one entry more, never read
  for (let k = 0; k < to; k++) {
    const a = k * step, b = (k + 1) * step, first = Math.floor(a), weights: number[] = [];
    // Stryker disable next-line EqualityOperator,ConditionalExpression: at i = b a texel of no width (weight 0), and b never passes `from` but by rounding: the guard is for that
    for (let i = first; i < b && i < from; i++) weights.push((Math.min(b, i + 1) - Math.max(a, i)) / step);
    out.push({ first, weights });
  }
  return out;
}

/** `img` reduced so that it is at most `maxWidth` wide and `maxWidth`/2 high, each new texel the mean of what it covers; `img` itself if it is. */
export function reduceImage(img: EnvironmentImage, maxWidth = ENVIRONMENT_IMAGE_WIDTH): EnvironmentImage {
  const { width, height, rgb } = img;
  const scale = Math.min(1, maxWidth / width, maxWidth / 2 / height);
  if (scale === 1) return img;
  const w = Math.max(1, Math.round(width * scale)), h = Math.max(1, Math.round(height * scale));
  // Across first (height × w), then down (h × w).
  const across = areaWeights(width, w), down = areaWeights(height, h);
  const mid = new Float32Array(height * w * 3), out = new Float32Array(h * w * 3);
  // Stryker disable next-line EqualityOperator: j = height writes past mid's end: dropped
  for (let j = 0; j < height; j++) {
    for (let k = 0; k < w; k++) {
      const { first, weights } = across[k];
      // Stryker disable next-line EqualityOperator: c = 3 writes the next texel's red, written again with it (or past the end: dropped)
      for (let c = 0; c < 3; c++) {
        let s = 0;
        for (let q = 0; q < weights.length; q++) s += weights[q] * rgb[3 * (j * width + first + q) + c];
        mid[3 * (j * w + k) + c] = s;
      }
    }
  }
  for (let m = 0; m < h; m++) {
    const { first, weights } = down[m];
    // Stryker disable next-line EqualityOperator: k = w writes the next row's first texel, written again with that row (or past the end)
    for (let k = 0; k < w; k++) {
      // Stryker disable next-line EqualityOperator: c = 3 writes the next texel's red, written again with it (or past the end: dropped)
      for (let c = 0; c < 3; c++) {
        let s = 0;
        for (let q = 0; q < weights.length; q++) s += weights[q] * mid[3 * ((first + q) * w + k) + c];
        out[3 * (m * w + k) + c] = s;
      }
    }
  }
  return { width: w, height: h, rgb: out };
}
