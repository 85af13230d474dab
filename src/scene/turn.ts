// The trackball's turn as the renderers take it with each frame (FrameState.turn): the rotations
// and the centre they turn about, composed as one more matrix before the model matrices
// (turnMatrix). In the core: a frame without a turn needs nothing more; what builds the turned
// scene value and finds the centre (group-rotation.ts) loads when a turn is first set.
import { mat4, type ReadonlyQuat } from 'gl-matrix';

/**
 * The trackball's turn as a renderer takes it: the objects by `objects`, the first light by
 * `light` (unit quaternions [x, y, z, w]), both about `center`, the centre of the objects' bounds
 * (boundsCenter of the scene drawn).
 */
export interface SceneTurn {
  readonly objects: ReadonlyQuat;
  readonly light: ReadonlyQuat;
  readonly center: ArrayLike<number>;
}

/** No turn: the rotation's vector part is zero. */
export const isIdentity = (q: ReadonlyQuat) => q[0] === 0 && q[1] === 0 && q[2] === 0;

/**
 * The turn by `q` about `center` as one matrix, T(c)·R(q)·T(−c): put before a model matrix it
 * turns the object as rotateObjects does (equal to rounding); applied to a point light's position
 * or (its 3×3) a directional light's direction, as rotateLight does.
 */
export function turnMatrix(out: mat4, q: ReadonlyQuat, center: ArrayLike<number>): mat4 {
  mat4.fromQuat(out, q);
  const cx = center[0], cy = center[1], cz = center[2];
  out[12] = cx - (out[0] * cx + out[4] * cy + out[8] * cz);
  out[13] = cy - (out[1] * cx + out[5] * cy + out[9] * cz);
  out[14] = cz - (out[2] * cx + out[6] * cy + out[10] * cz);
  return out;
}
