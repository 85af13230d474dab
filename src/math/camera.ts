// Flyby camera pose → forward vector, view and projection matrices (float64, SPEC §3).
import { mat4 } from 'gl-matrix';
import type { ReadonlyVec3 } from 'gl-matrix';

export const PITCH_LIMIT = 89.9;
const DEG = Math.PI / 180;
const UP: ReadonlyVec3 = [0, 1, 0];
const ORIGIN: ReadonlyVec3 = [0, 0, 0];

export interface CameraPose {
  position: [number, number, number];
  /** Degrees about +Y; −90 looks down −Z. */
  yaw: number;
  /** Degrees, clamped to ±PITCH_LIMIT. */
  pitch: number;
}

export function clampPitch(pitch: number): number {
  return Math.max(-PITCH_LIMIT, Math.min(PITCH_LIMIT, pitch));
}

/** out = (cos p·cos y, sin p, cos p·sin y), angles in degrees. */
export function forwardFromYawPitch<T extends Float64Array | number[]>(out: T, yaw: number, pitch: number): T {
  const y = yaw * DEG;
  const p = clampPitch(pitch) * DEG;
  out[0] = Math.cos(p) * Math.cos(y);
  out[1] = Math.sin(p);
  out[2] = Math.cos(p) * Math.sin(y);
  return out;
}

/**
 * out = lookAt(0, forward, +Y): the view of a camera at the origin (camera-relative rendering:
 * positions are made relative to the eye in float64 first). `scratch` (3 elements) holds forward.
 * Pitch is clamped, so forward is never parallel to up.
 */
export function rotationOnlyView<T extends Float64Array | number[]>(
  out: T, yaw: number, pitch: number, scratch: Float64Array,
): T {
  forwardFromYawPitch(scratch, yaw, pitch);
  return mat4.lookAt(out as mat4, ORIGIN, scratch, UP) as T;
}

/** out = perspective projection, OpenGL clip depth (−1..1). */
export function projectionMatrix<T extends Float64Array | number[]>(
  out: T, fovDeg: number, aspect: number, near: number, far: number,
): T {
  return mat4.perspectiveNO(out as mat4, fovDeg * DEG, aspect, near, far) as T;
}
