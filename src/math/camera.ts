// Flyby camera pose → forward vector, view and projection matrices (float64, docs/default-scene.md#the-camera, docs/interaction.md#flyby).
// Shared by the reference (reference/view-camera.ts: the view basis, the projections' scale,
// orthoHalfHeight; sample-tracer.ts: viewerSide) and both renderers (frame/frame-setup.ts): tied
// down by tests/unit/camera.test.ts and orthographic.test.ts with values worked out by hand
// (forward vectors, the fov's edge at NDC ±1, near and far at ∓1, no roll, orthographic sizes),
// and reference-pixels.test.ts casts its camera rays by hand.
import { mat4 } from 'gl-matrix';
import type { ReadonlyVec3 } from 'gl-matrix';
import { signedDistance, type Plane } from './mirror';

/** Near and far planes of every projection (docs/default-scene.md#the-camera); scene/default-scene.ts re-exports them. */
export const CAMERA = { near: 0.1, far: 100 } as const;

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

/**
 * Degrees wrapped into [−180, 180): 180 becomes −180. The one yaw convention (the
 * camera-rotation attribute, the flyby, the orbit), so huge values keep their precision and a
 * pose read back is the pose written.
 */
export function wrapYaw(yaw: number): number {
  // Stryker disable next-line ArithmeticOperator: yaw − 180 is the same angle as yaw + 180 modulo 360
  return ((((yaw + 180) % 360) + 360) % 360) - 180;
}

/** Copies a pose in; yaw is wrapped, pitch clamped, non-finite components leave the old value. */
export function setPose(p: CameraPose, position: readonly [number, number, number], yaw: number, pitch: number): void {
  // Stryker disable next-line EqualityOperator: i ≤ 3 reads position[3], undefined, which is not finite: no write
  for (let i = 0; i < 3; i++) if (Number.isFinite(position[i])) p.position[i] = position[i];
  if (Number.isFinite(yaw)) p.yaw = wrapYaw(yaw);
  if (Number.isFinite(pitch)) p.pitch = clampPitch(pitch);
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

/**
 * tan(fov/2) of a vertical field of view `fovDeg` in degrees: half the view's height at unit
 * depth. The one place it is written: the orthographic size, the size of things on screen (level
 * of detail) and the orbit's pan all read it.
 */
export function tanHalfFov(fovDeg: number): number {
  return Math.tan((fovDeg * DEG) / 2);
}

/** out = perspective projection, OpenGL clip depth (−1..1). */
export function projectionMatrix<T extends Float64Array | number[]>(
  out: T, fovDeg: number, aspect: number, near: number, far: number,
): T {
  return mat4.perspectiveNO(out as mat4, fovDeg * DEG, aspect, near, far) as T;
}

export type Projection = 'perspective' | 'orthographic';

/**
 * +1 when the camera sees the side of `plane` its normal points to, −1 otherwise. A perspective
 * eye sees the side it stands on (on the plane counts as +). An orthographic camera sees the
 * side its view direction comes from, wherever its eye is: every ray is parallel to `forward`,
 * so a ray meeting the plane meets it from the side −forward points to; with forward in the
 * plane (edge-on) the eye's side decides, as for perspective.
 */
export function viewerSide(plane: Plane, eye: ReadonlyVec3, forward: ReadonlyVec3, projection: Projection): number {
  if (projection === 'orthographic') {
    const c = plane[0] * forward[0] + plane[1] * forward[1] + plane[2] * forward[2];
    // Stryker disable next-line EqualityOperator: c ≤ 0 differs from c < 0 only at c = 0, which the guard excludes
    if (c !== 0) return c < 0 ? 1 : -1;
  }
  return signedDistance(plane, eye) >= 0 ? 1 : -1;
}
