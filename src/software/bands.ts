// A frame split into bands of rows, each drawn by its own SoftwareRenderer (in its own worker:
// element/software-host.ts) and put back together: every band's pixels are the whole frame's
// rows, bit for bit (SoftwareRenderer.band).
import type { FrameState } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { SceneImages } from '../scene/decoded-image';
import type { SoftwareRenderer } from './software-renderer';

export interface Band {
  top: number;
  bottom: number;
}

/**
 * `height` rows cut into `count` bands, top first, at `weights`' shares when given (one per band,
 * positive: a band's share of the rows; the host gives a slow band fewer), else evenly. Every row
 * in exactly one band; a band may be empty.
 */
export function splitRows(height: number, count: number, weights?: readonly number[]): Band[] {
  const bands: Band[] = [];
  let sum = 0;
  for (let i = 0; i < count; i++) sum += weights?.[i] ?? 1;
  let top = 0, acc = 0;
  for (let i = 0; i < count; i++) {
    acc += weights?.[i] ?? 1;
    const bottom = i === count - 1 ? height : Math.max(top, Math.min(height, Math.round((acc / sum) * height)));
    bands.push({ top, bottom });
    top = bottom;
  }
  return bands;
}

/**
 * Draws `band` of the frame with `renderer` (SoftwareRenderer.render's scene, state and images)
 * and returns its rows' RGBA8 (a copy, the band's height × the frame's width); null band: the whole frame.
 */
export function renderBand(
  renderer: SoftwareRenderer, scene: Scene | null, state: FrameState, images: SceneImages | null | undefined, band: Band | null,
): Uint8ClampedArray {
  renderer.band = band;
  const pixels = renderer.render(scene, state, images);
  if (!band) return pixels.slice();
  const width = Math.max(0, Math.floor(state.width));
  return pixels.slice(4 * band.top * width, 4 * band.bottom * width);
}

/** Puts a band's rows (renderBand's) into the whole frame's pixels. */
export function putBand(frame: Uint8ClampedArray, pixels: Uint8ClampedArray, band: Band, width: number): void {
  frame.set(pixels.subarray(0, 4 * (band.bottom - band.top) * width), 4 * band.top * width);
}
