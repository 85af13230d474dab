// Reflection across a plane: points, directions and the reflection matrix (float64).
// Shared by the reference (reference/ray.ts, clip.ts, sample-tracer.ts) and both renderers
// (frame/frame-setup.ts, software/software-renderer.ts): tied down by tests/unit/mirror.test.ts's
// reflections across z = 0 and oblique planes worked out by hand.
import type { ReadonlyVec3 } from 'gl-matrix';

/** A plane [nx, ny, nz, d]: points x with n·x + d = 0; n must be unit length. */
export type Plane = readonly [number, number, number, number] | Float64Array;

type Out3 = Float64Array | Float32Array | number[];
type Out4 = Float64Array | Float32Array | number[];
type Out16 = Float64Array | Float32Array | number[];

/**
 * How close to the glass, on the viewer's side, geometry may come and still be reflected: what
 * lies nearer touches the glass — a face in its plane is against it, not in front of it (a
 * picture behind a glass wall) — and the reflection pass leaves it out. Far above rounding
 * (float32 clip distances of points a few units away), far below anything one could see.
 */
export const MIRROR_CONTACT = 1e-5;

/** Signed distance of a point from the plane (positive on the side n points to). */
export function signedDistance(plane: Plane, p: ReadonlyVec3): number {
  return plane[0] * p[0] + plane[1] * p[1] + plane[2] * p[2] + plane[3];
}

/**
 * out = sign·(n, signedDistance(plane, eye)): the plane as a function of points relative to
 * `eye`, out·(rel, 1) = sign·signedDistance(plane, eye + rel), kept where ≥ 0 by a clip.
 */
export function eyeRelativePlane<T extends Out4>(out: T, plane: Plane, eye: ReadonlyVec3, sign: number): T {
  out[0] = sign * plane[0];
  out[1] = sign * plane[1];
  out[2] = sign * plane[2];
  out[3] = sign * signedDistance(plane, eye);
  return out;
}

/** out = p mirrored across the plane. `out` may alias `p`. */
export function reflectPoint<T extends Out3>(out: T, p: ReadonlyVec3, plane: Plane): T {
  const k = 2 * signedDistance(plane, p);
  out[0] = p[0] - k * plane[0];
  out[1] = p[1] - k * plane[1];
  out[2] = p[2] - k * plane[2];
  return out;
}

/** out = direction d mirrored across the plane (translation ignored). `out` may alias `d`. */
export function reflectDirection<T extends Out3>(out: T, d: ReadonlyVec3, plane: Plane): T {
  const k = 2 * (plane[0] * d[0] + plane[1] * d[1] + plane[2] * d[2]);
  out[0] = d[0] - k * plane[0];
  out[1] = d[1] - k * plane[1];
  out[2] = d[2] - k * plane[2];
  return out;
}

/** out = the 4×4 reflection matrix of the plane (column-major, det −1, its own inverse). */
export function reflectionMatrix<T extends Out16>(out: T, plane: Plane): T {
  const a = plane[0], b = plane[1], c = plane[2], d = plane[3];
  out[0] = 1 - 2 * a * a; out[1] = -2 * a * b;    out[2] = -2 * a * c;     out[3] = 0;
  out[4] = -2 * a * b;    out[5] = 1 - 2 * b * b; out[6] = -2 * b * c;     out[7] = 0;
  out[8] = -2 * a * c;    out[9] = -2 * b * c;    out[10] = 1 - 2 * c * c; out[11] = 0;
  out[12] = -2 * a * d;   out[13] = -2 * b * d;   out[14] = -2 * c * d;    out[15] = 1;
  return out;
}
