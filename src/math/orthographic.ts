// The orthographic camera's size and projection (docs/interaction.md#orthographic-projection), shared by the float64 reference
// (reference/view-camera.ts) and the renderers' orthographic part (frame/orthographic-view.ts,
// a chunk loaded by frames that ask for it): tied down by tests/unit/orthographic.test.ts with
// sizes and clip coordinates worked out by hand.
import type { ReadonlyVec3 } from 'gl-matrix';
import { CAMERA, clampPitch, tanHalfFov } from './camera';

const DEG = Math.PI / 180;
const ORIGIN: ReadonlyVec3 = [0, 0, 0];

/** The part of a frame's state the orthographic size depends on. */
export interface OrthoView {
  cameraPosition: readonly [number, number, number];
  yaw: number;
  pitch: number;
  fov: number;
  target?: readonly [number, number, number] | null;
}

/**
 * Smallest depth the orthographic size is taken at: the near distance (docs/default-scene.md#the-camera), the nearest
 * slice the perspective view draws. A target at or behind the eye would otherwise give a
 * zero or negative size (a singular projection).
 */
export const MIN_ORTHO_DEPTH = CAMERA.near;

/**
 * Half-height of the orthographic view (docs/interaction.md#orthographic-size): depth·tan(fov/2), the depth of the target
 * (or else the glass centre, or else the origin) measured along the view direction, so the
 * orthographic view keeps there the size the perspective view had.
 */
export function orthoHalfHeight(state: OrthoView, glassCenter: ReadonlyVec3 | null): number {
  const y = state.yaw * DEG;
  const p = clampPitch(state.pitch) * DEG;
  const point = state.target ?? glassCenter ?? ORIGIN;
  const e = state.cameraPosition;
  const depth = (point[0] - e[0]) * Math.cos(p) * Math.cos(y) + (point[1] - e[1]) * Math.sin(p)
    + (point[2] - e[2]) * Math.cos(p) * Math.sin(y);
  return Math.max(depth, MIN_ORTHO_DEPTH) * tanHalfFov(state.fov);
}

/**
 * out = orthographic projection of half-height `halfHeight` (width by `aspect`), OpenGL clip
 * depth: x/hw, y/hh, and z from −near..−far to −1..1 (column-major; the only non-zero entries).
 */
export function orthographicMatrix<T extends Float64Array | number[]>(
  out: T, halfHeight: number, aspect: number, near: number, far: number,
): T {
  const depth = 1 / (near - far);
  out.fill(0);
  out[0] = 1 / (halfHeight * aspect);
  out[5] = 1 / halfHeight;
  out[10] = 2 * depth;
  out[14] = (far + near) * depth;
  out[15] = 1;
  return out;
}
