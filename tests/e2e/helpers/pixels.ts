// Pixel statistics for the golden-free property tests: which pixels are "the sphere's green"
// or "the cube's red", and where they are.
import type { RgbaImage } from './golden';

export type Channel = 'r' | 'g' | 'b';
const INDEX: Record<Channel, number> = { r: 0, g: 1, b: 2 };

/**
 * A pixel is dominated by `channel` when that channel exceeds both others by more than `margin`
 * levels. 0.1·255 keeps out the background (grey), the glass body (tex ⊙ (0.7, 0.9, 1.0), its
 * blue ≥ green) and specular highlights (white), and keeps the lit sides of the cube
 * (albedo 0.8, 0.3, 0.3) and of the sphere (0.3, 0.8, 0.3).
 */
export const DOMINANCE_MARGIN = 0.1 * 255;

export interface Blob {
  /** Pixels dominated by the channel. */
  count: number;
  /** Their centroid in pixels, (0, 0) = top-left corner of the top-left pixel; NaN when count is 0. */
  cx: number;
  cy: number;
  /** Σ max(0, c − max(other two)) over ALL pixels: how much of the colour there is, with no threshold. */
  excess: number;
}

export function dominant(image: RgbaImage, channel: Channel, margin = DOMINANCE_MARGIN): Blob {
  const c = INDEX[channel];
  const o1 = (c + 1) % 3;
  const o2 = (c + 2) % 3;
  const { data, width, height } = image;
  let count = 0;
  let sx = 0;
  let sy = 0;
  let excess = 0;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const i = (y * width + x) * 4;
      const e = data[i + c] - Math.max(data[i + o1], data[i + o2]);
      if (e > 0) excess += e;
      if (e > margin) {
        count++;
        sx += x + 0.5;
        sy += y + 0.5;
      }
    }
  }
  return { count, cx: count ? sx / count : NaN, cy: count ? sy / count : NaN, excess };
}

/** Indices (pixel numbers) of the pixels dominated by `channel`. */
export function dominantPixels(image: RgbaImage, channel: Channel, margin = DOMINANCE_MARGIN): number[] {
  const c = INDEX[channel];
  const out: number[] = [];
  const { data } = image;
  for (let p = 0; p < image.width * image.height; p++) {
    const i = p * 4;
    if (data[i + c] - Math.max(data[i + (c + 1) % 3], data[i + (c + 2) % 3]) > margin) out.push(p);
  }
  return out;
}

/** Pixels whose RGB differs from `rgb` (0..255) by more than `tolerance` on some channel. */
export function countUnlike(image: RgbaImage, rgb: readonly [number, number, number], tolerance: number): number {
  let n = 0;
  const { data } = image;
  for (let i = 0; i < data.length; i += 4) {
    if (
      Math.abs(data[i] - rgb[0]) > tolerance ||
      Math.abs(data[i + 1] - rgb[1]) > tolerance ||
      Math.abs(data[i + 2] - rgb[2]) > tolerance
    ) n++;
  }
  return n;
}
