// Error of a captured pass against the float64 reference over a chosen set of pixels: the
// region where one pass shows (the glass reflecting the cube, the glass, the cube in the
// mirror), picked from the reference's geometry keys and regions, never from colours.
import { REGION_EDGE, REGION_GLASS, glassReflectsCube, type ReferenceImage } from '../../../src/reference';
import type { RgbaImage } from './golden';

export interface MaskedError {
  /** Pixels in the mask. */
  pixels: number;
  /** 20·log10(255 / RMSE) over R, G and B of those pixels, against the unrounded reference. */
  psnr: number;
  /** Largest channel error among them, in 8-bit levels. */
  max: number;
}

export function maskedError(ref: ReferenceImage, image: RgbaImage, mask: Uint8Array): MaskedError {
  if (image.width !== ref.width || image.height !== ref.height) {
    throw new Error(`image ${image.width}×${image.height}, reference ${ref.width}×${ref.height}`);
  }
  let sq = 0, pixels = 0, max = 0;
  for (let p = 0; p < mask.length; p++) {
    if (!mask[p]) continue;
    pixels++;
    for (let c = 0; c < 3; c++) {
      const e = Math.abs(image.data[4 * p + c] - ref.rgb[3 * p + c] * 255);
      sq += e * e;
      if (e > max) max = e;
    }
  }
  const rmse = Math.sqrt(sq / (3 * Math.max(1, pixels)));
  return { pixels, psnr: rmse === 0 ? Infinity : 20 * Math.log10(255 / rmse), max };
}

export const formatError = (e: MaskedError): string => `${e.psnr.toFixed(1)} dB over ${e.pixels} px (max ${e.max.toFixed(0)})`;

/**
 * Pixels of a 'final' reference whose centre sample sees the glass and, in its mirror, the
 * cube, away from the edge band (where the error is the edges' antialiasing, not the pass).
 */
export function reflectsCubeMask(ref: ReferenceImage): Uint8Array {
  return Uint8Array.from(ref.keys, (k, p) => (glassReflectsCube(k) && ref.regions[p] !== REGION_EDGE ? 1 : 0));
}

/** Glass pixels of a 'final' reference, away from the edge band. */
export function glassMask(ref: ReferenceImage): Uint8Array {
  return Uint8Array.from(ref.regions, (r) => (r === REGION_GLASS ? 1 : 0));
}

/** Every pixel not in the edge band: the whole image, its antialiased edges left out. */
export function interiorMask(ref: ReferenceImage): Uint8Array {
  return Uint8Array.from(ref.regions, (r) => (r === REGION_EDGE ? 0 : 1));
}
