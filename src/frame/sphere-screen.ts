// How big a sphere looks on screen, and the silhouette error 'auto' tessellation aims for:
// pure math, shared by the GL sphere LOD and the software renderer (no GL here).
import type { FrameState } from './types';
import { focalPixels, orthoPixelsPerUnit } from './reflection-lod';

/**
 * Silhouette error 'auto' aims for, in pixels. Half a pixel (the first bound tried, docs/knobs.md#level-of-detail) left the
 * interpolated shading visibly coarse: in the bench, auto at 0.5 px scored 0.6 dB below 32
 * fixed segments at the same cost; a quarter pixel closes that gap.
 */
export const AUTO_SILHOUETTE_ERROR_PX = 0.25;

/**
 * Radius in pixels of a sphere (world `centre`, `radius`) seen from `state`'s camera: its
 * largest on-screen extent. `orthoHalfHeight` > 0: an orthographic view of that half-height,
 * where the size does not depend on distance (height/(2·halfHeight) pixels per unit).
 */
export function sphereScreenRadius(
  state: Pick<FrameState, 'cameraPosition' | 'height' | 'fov'>, centre: ArrayLike<number>, radius: number, orthoHalfHeight = 0,
): number {
  if (orthoHalfHeight > 0) return radius * orthoPixelsPerUnit(state.height, orthoHalfHeight);
  const [x, y, z] = state.cameraPosition;
  const d = Math.hypot(centre[0] - x, centre[1] - y, centre[2] - z);
  const focal = focalPixels(state.height, state.fov);
  if (d <= radius * 1.0001) return Number.POSITIVE_INFINITY; // inside it
  // Silhouette of a sphere: angular radius asin(r/d).
  return focal * Math.tan(Math.asin(radius / d));
}
