// An environment image (docs/pbr.md#an-image): an equirectangular picture of linear light — a Radiance .hdr, or a PNG or JPEG
// taken as sRGB — reduced by area to at most 512 × 256 texels (math/reduce-image.ts), and read as the light arriving from a direction the way three.js and model-viewer read such an image: the
// centre column toward +x, a quarter of the way across toward −z, three quarters toward +z, the top row toward +y. Bilinear
// between texel centres, wrapping across the seam at −x, held at the first and last rows' centres toward the poles.
// The same lookup is the light of all three renderers (its maps are made from it; the reference integrates it): tied down by
// tests/unit/environment-image.test.ts, by hand.
import type { RadianceFn } from './split-sum';

/** Linear RGB, `width` × `height`, row 0 at the top. */
export interface EnvironmentImage {
  width: number;
  height: number;
  rgb: Float32Array;
}

/** The width an environment image is reduced to, at most (its height to half). */
export const ENVIRONMENT_IMAGE_WIDTH = 512;

/** out = the unit direction of the point (u, v) of the image (u across from the left edge, v down from the top, both 0..1). */
export function imageDirection(out: Float64Array, u: number, v: number): Float64Array {
  // Stryker disable next-line ArithmeticOperator: u + ½ turns φ by one whole turn from u − ½: the same direction
  const phi = 2 * Math.PI * (u - 0.5), theta = Math.PI * v, s = Math.sin(theta);
  out[0] = s * Math.cos(phi); out[1] = Math.cos(theta); out[2] = s * Math.sin(phi);
  return out;
}

/** The image's light from the unit direction (x, y, z): a bilinear read at texel centres. */
export function imageRadiance(img: EnvironmentImage): RadianceFn {
  const { width, height, rgb: t } = img;
  return (out, x, y, z) => {
    const u = (0.5 + Math.atan2(z, x) / (2 * Math.PI)) * width - 0.5;
    // Stryker disable next-line EqualityOperator: at y = ±1 the clamp returns y itself either way
    const v = (Math.acos(y < -1 ? -1 : y > 1 ? 1 : y) / Math.PI) * height - 0.5;
    const i0 = Math.floor(u), fu = u - i0;
    // Stryker disable next-line EqualityOperator: at v = 0 and v = height − 1 the clamp returns v itself either way
    const vv = v < 0 ? 0 : v > height - 1 ? height - 1 : v;
    // One row: both rows are row 0 (fv 0).
    // Stryker disable next-line ArithmeticOperator: at the bottom row j0 = height − 1 reads it whole (fv 0, j1 held): what height − 2 gives
    const j0 = Math.max(0, Math.min(height - 2, Math.floor(vv))), fv = vv - j0;
    const j1 = Math.min(height - 1, j0 + 1);
    const a = ((i0 % width) + width) % width, b = (a + 1) % width;
    const r0 = j0 * width, r1 = j1 * width;
    // Stryker disable next-line EqualityOperator: c = 3 writes out[3], past the end of its 3 elements: dropped
    for (let c = 0; c < 3; c++) {
      const upper = t[3 * (r0 + a) + c] * (1 - fu) + t[3 * (r0 + b) + c] * fu;
      const lower = t[3 * (r1 + a) + c] * (1 - fu) + t[3 * (r1 + b) + c] * fu;
      out[c] = upper * (1 - fv) + lower * fv;
    }
  };
}
