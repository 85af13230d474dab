// Which hits the GPU keeps: view depth within [near, far] and, for the mirrored pass, the eye's side of the glass.
import { MIRROR_CONTACT, signedDistance, type Plane } from '../math/mirror';
import { CAMERA } from '../scene/default-scene';
import type { Ray } from './ray';
import type { SurfaceHit } from './surface-hit';

/**
 * The view depths kept: the near and far of docs/default-scene.md#the-camera, or a course camera's (docs/course-files.md#near-and-far, from the
 * scene's geometry). Set by the sample tracer before it traces (one image at a time).
 */
export const clipRange = { near: CAMERA.near as number, far: CAMERA.far as number };

export function setClipRange(near: number, far: number): void {
  clipRange.near = near;
  clipRange.far = far;
}

export function visible(t: number): boolean {
  return t >= clipRange.near && t <= clipRange.far;
}

/**
 * A hit at depth t is kept when t > tMin (what lies beyond a transparent surface), within
 * [near, far], and, when `clipSide` ≠ 0 (the mirrored pass), on that side of the glass plane, at
 * least MIRROR_CONTACT from it (what touches the glass is not reflected).
 */
export function kept(hit: SurfaceHit, tMin: number, clipSide: number, plane: Plane | null): boolean {
  return hit.t > tMin && visible(hit.t) && (clipSide === 0 || clipSide * signedDistance(plane!, hit.p) >= MIRROR_CONTACT);
}

/**
 * The same rule as an interval of t along `ray`, for surfaces searched by nearest hit (meshes),
 * into out = [lo, hi] (tMin exclusive, the rest inclusive; the difference is measure zero).
 * Returns false when the interval is empty.
 */
export function keptInterval(ray: Ray, tMin: number, clipSide: number, plane: Plane | null, out: Float64Array): boolean {
  let lo = Math.max(tMin, clipRange.near);
  let hi: number = clipRange.far;
  if (clipSide !== 0) {
    const o = ray.origin, d = ray.direction;
    const s0 = clipSide * signedDistance(plane!, o) - MIRROR_CONTACT;
    const s1 = clipSide * (plane![0] * d[0] + plane![1] * d[1] + plane![2] * d[2]);
    if (s1 > 0) lo = Math.max(lo, -s0 / s1);
    else if (s1 < 0) hi = Math.min(hi, -s0 / s1);
    else if (!(s0 >= 0)) return false;
  }
  out[0] = lo;
  out[1] = hi;
  return lo <= hi;
}
