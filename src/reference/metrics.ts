// Error of an RGBA8 image against a reference, per region: RMSE and PSNR in 8-bit levels, and max error.
import { REGION_BACKGROUND, REGION_CUBE, REGION_EDGE, REGION_GLASS, REGION_SPHERE } from './regions';
import type { ReferenceImage } from './reference-renderer';

/**
 * 'all' and the region map's classes (glass, objects, background, edges: each pixel in one), plus
 * 'dark' across them (a dark pixel counts in its own class too): pixels whose reference is
 * below DARK_LEVEL in every channel, where colour held linearly in 8 bits would band (docs/colour.md#eight-bit-targets).
 */
export type RegionName = 'all' | 'glass' | 'objects' | 'background' | 'edges' | 'dark';
export const REGION_NAMES: readonly RegionName[] = ['all', 'glass', 'objects', 'background', 'edges', 'dark'];
export type PerRegion = Record<RegionName, number>;

/** Dark: the reference as displayed (`ref.rgb`, encoded with srgb) below 32/255 in each channel. */
export const DARK_LEVEL = 32 / 255;

export interface CompareOptions {
  /**
   * 'float' (default): against the float64 reference, so a perfect 8-bit image still shows
   * its ≤ 0.5-level rounding. 'rgba8': against the reference rounded to 8 bits.
   */
  against?: 'float' | 'rgba8';
}

export interface ImageComparison {
  /** 20·log10(255 / RMSE) in dB; Infinity when identical, NaN for an empty region. */
  psnr: PerRegion;
  /** Root mean square error over R, G and B, in 8-bit levels; NaN for an empty region. */
  rmse: PerRegion;
  /** Largest absolute channel error over the whole image, in 8-bit levels. */
  maxError: number;
  maxErrorByRegion: PerRegion;
  /** Pixels in each region. */
  pixels: PerRegion;
}

const REGION_OF: Record<number, RegionName> = {
  [REGION_BACKGROUND]: 'background',
  [REGION_CUBE]: 'objects',
  [REGION_SPHERE]: 'objects',
  [REGION_GLASS]: 'glass',
  [REGION_EDGE]: 'edges',
};

const perRegion = (v: number): PerRegion => ({ all: v, glass: v, objects: v, background: v, edges: v, dark: v });

/** Compares `rgba` (top row first, as `capture()` and the reference give it) with `ref`. */
export function compareImages(
  ref: ReferenceImage, rgba: Uint8ClampedArray | Uint8Array, options: CompareOptions = {},
): ImageComparison {
  const count = ref.width * ref.height;
  if (rgba.length !== count * 4) {
    throw new Error(`glass-plane-scene: image has ${rgba.length} bytes, the ${ref.width}×${ref.height} reference needs ${count * 4}`);
  }
  const quantised = options.against === 'rgba8';
  const squares = perRegion(0);
  const pixels = perRegion(0);
  const maxErrorByRegion = perRegion(0);
  for (let i = 0; i < count; i++) {
    const name = REGION_OF[ref.regions[i]];
    const dark = Math.max(ref.rgb[3 * i], ref.rgb[3 * i + 1], ref.rgb[3 * i + 2]) < DARK_LEVEL;
    let sq = 0, max = 0;
    for (let c = 0; c < 3; c++) {
      const expected = quantised ? ref.rgba[4 * i + c] : ref.rgb[3 * i + c] * 255;
      const e = Math.abs(rgba[4 * i + c] - expected);
      sq += e * e;
      // Stryker disable next-line EqualityOperator: at e = max either branch leaves max the same
      if (e > max) max = e;
    }
    for (const r of dark ? (['all', name, 'dark'] as const) : (['all', name] as const)) {
      squares[r] += sq;
      pixels[r]++;
      // Stryker disable next-line EqualityOperator: at a tie either branch leaves the same maximum
      if (max > maxErrorByRegion[r]) maxErrorByRegion[r] = max;
    }
  }
  const rmse = perRegion(NaN);
  const psnr = perRegion(NaN);
  for (const r of REGION_NAMES) {
    // Stryker disable next-line ConditionalExpression: an empty region not skipped gets √(0/0) = NaN and a NaN PSNR, what it starts with
    if (pixels[r] === 0) continue;
    rmse[r] = Math.sqrt(squares[r] / (3 * pixels[r]));
    // Stryker disable next-line ConditionalExpression: at RMSE 0 the formula gives 20·log10(255/0) = Infinity too
    psnr[r] = rmse[r] === 0 ? Infinity : 20 * Math.log10(255 / rmse[r]);
  }
  return { psnr, rmse, maxError: maxErrorByRegion.all, maxErrorByRegion, pixels };
}
