// How coarse the reflection of a dense mesh may be drawn (tessellation 'auto'). The glass shows
// the reflection faint (Fresnel R is 4 % head-on for ior 1.5) and through the mirror; a mesh whose
// triangles are a pixel or two wide on screen costs the reflection pass as much as the scene pass
// (on SwiftShader the frame is bound by triangles, not by the reflection's resolution). The
// reflection draws a vertex-clustered copy (scene/geometry/cluster.ts) whose cells span at most
// REFLECTION_CELL_PX pixels of the reflection target at the object's centre.
import { tanHalfFov } from '../math/camera';

/** Cell size of the reflection's mesh, in pixels of the reflection target. */
export const REFLECTION_CELL_PX = 4;
/** The grids a reflection mesh is built at (cells along the mesh's largest side): few levels, each built once. */
export const REFLECTION_GRIDS: readonly number[] = [16, 32, 64, 128, 256];
/** A clustered mesh is used only when it has at most this fraction of the full mesh's triangles. */
export const REFLECTION_MAX_FRACTION = 0.5;

/**
 * The grid for a mesh of largest side `worldExtent` seen `pixelsPerUnit` pixels per world unit
 * at its centre in the reflection target: the coarsest of REFLECTION_GRIDS whose cells span at
 * most REFLECTION_CELL_PX pixels, or 0 (draw the full mesh) when even the finest is too coarse
 * or the input is not finite.
 */
export function reflectionGrid(worldExtent: number, pixelsPerUnit: number): number {
  const cells = (worldExtent * pixelsPerUnit) / REFLECTION_CELL_PX;
  if (!(cells > 0) || !Number.isFinite(cells)) return 0;
  for (const g of REFLECTION_GRIDS) if (g >= cells) return g;
  return 0;
}

/**
 * Focal length in pixels of a perspective eye of vertical field of view `fovDeg` over a target
 * `height` pixels tall: pixels per world unit at unit distance.
 */
export function focalPixels(height: number, fovDeg: number): number {
  return height / (2 * tanHalfFov(fovDeg));
}

/**
 * Pixels per world unit at distance `distance` from a perspective eye of vertical field of
 * view `fovDeg` over a target `height` pixels tall; Infinity when the eye is at the point.
 */
export function pixelsPerUnit(height: number, fovDeg: number, distance: number): number {
  return focalPixels(height, fovDeg) / distance;
}

/** Pixels per world unit anywhere in an orthographic view of half-height `halfHeight` over `height` pixels. */
export function orthoPixelsPerUnit(height: number, halfHeight: number): number {
  return height / (2 * halfHeight);
}
