// The trackball's rotation of the scene (SPEC §10): every object turned as a group about the
// centre of their bounds, and the first light turned about the same centre. The page's `scene`
// and the reference see it applied to the scene value as ordinary transforms (rotateScene); the
// renderers get it with each frame (FrameState.turn) and compose it as one more matrix
// (turnMatrix), so a turn builds no new scene value. Pure math.
import { mat3, mat4, vec3, type quat, type ReadonlyQuat } from 'gl-matrix';
import type { Light, Scene, SceneObject, Vec3 } from './scene';

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

const DEG = Math.PI / 180;

/**
 * out = a·b (Hamilton product, [x, y, z, w]): the rotation b, then a. Written here rather than
 * taken from gl-matrix's quat module, whose load-time helpers (rotationTo, setAxes) a bundler
 * cannot drop: the core stays without that module (issue 22).
 */
function multiply(out: quat, a: ArrayLike<number>, b: ArrayLike<number>): quat {
  const ax = a[0], ay = a[1], az = a[2], aw = a[3], bx = b[0], by = b[1], bz = b[2], bw = b[3];
  out[0] = ax * bw + aw * bx + ay * bz - az * by;
  out[1] = ay * bw + aw * by + az * bx - ax * bz;
  out[2] = az * bw + aw * bz + ax * by - ay * bx;
  out[3] = aw * bw - ax * bx - ay * by - az * bz;
  return out;
}

/** The rotation by `deg` degrees about axis `i` (0 x, 1 y, 2 z). */
function axisQuat(i: number, deg: number): Float64Array {
  const h = (deg * DEG) / 2, q = new Float64Array([0, 0, 0, Math.cos(h)]);
  q[i] = Math.sin(h);
  return q;
}

/** Rz·Ry·Rx of Euler degrees (x applied first), as the renderers build it. */
export function eulerToQuat(out: quat, rotation: readonly number[]): quat {
  multiply(out, axisQuat(2, rotation[2]), axisQuat(1, rotation[1]));
  return multiply(out, out, axisQuat(0, rotation[0]));
}

/** Euler degrees [x, y, z] with Rz·Ry·Rx = the rotation of `q`; x = 0 at gimbal lock. */
export function quatToEuler(q: ReadonlyQuat): Vec3 {
  const m = mat3.fromQuat((new Float64Array(9) as unknown as mat3), q); // column-major: m[c*3 + r]
  const r20 = m[2], r21 = m[5], r22 = m[8], r10 = m[1], r00 = m[0], r01 = m[3], r11 = m[4];
  const y = Math.asin(Math.max(-1, Math.min(1, -r20)));
  if (Math.abs(r20) < 0.9999999) return [Math.atan2(r21, r22) / DEG, y / DEG, Math.atan2(r10, r00) / DEG];
  return [0, y / DEG, Math.atan2(-r01, r11) / DEG];
}

/** Centre of the box around the objects' world bounding spheres (their spin aside); the origin for none. */
export function boundsCenter(objects: readonly SceneObject[]): Vec3 {
  if (objects.length === 0) return [0, 0, 0];
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  const q = (new Float64Array([0, 0, 0, 1]) as unknown as quat), c = (new Float64Array(3) as unknown as vec3);
  for (const o of objects) {
    const { position, rotation, scale } = o.transform;
    vec3.multiply(c, o.bounds.center as vec3, scale as vec3);
    vec3.transformQuat(c, c, eulerToQuat(q, rotation));
    vec3.add(c, c, position as vec3);
    const r = o.bounds.radius * Math.max(Math.abs(scale[0]), Math.abs(scale[1]), Math.abs(scale[2]));
    for (let i = 0; i < 3; i++) {
      lo[i] = Math.min(lo[i], c[i] - r);
      hi[i] = Math.max(hi[i], c[i] + r);
    }
  }
  const mid = (i: number) => (Number.isFinite(lo[i] + hi[i]) ? (lo[i] + hi[i]) / 2 : 0);
  return [mid(0), mid(1), mid(2)];
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

/** The objects turned by `q` about `center`: position c + q·(p − c), rotation q·R. */
export function rotateObjects(objects: readonly SceneObject[], q: ReadonlyQuat, center: Vec3): readonly SceneObject[] {
  if (isIdentity(q)) return objects;
  const r = (new Float64Array([0, 0, 0, 1]) as unknown as quat), p = (new Float64Array(3) as unknown as vec3);
  return objects.map((o) => {
    vec3.subtract(p, o.transform.position as vec3, center as vec3);
    vec3.transformQuat(p, p, q);
    vec3.add(p, p, center as vec3);
    multiply(r, q, eulerToQuat(r, o.transform.rotation));
    return { ...o, transform: { ...o.transform, position: [p[0], p[1], p[2]], rotation: quatToEuler(r) } };
  });
}

/** A light turned by `q` about `center`: a point light's position, a directional light's direction. */
export function rotateLight(light: Light, q: ReadonlyQuat, center: Vec3): Light {
  if (isIdentity(q)) return light;
  const v = (Float64Array.from(light.vector) as unknown as vec3);
  if (light.kind === 'point') vec3.subtract(v, v, center as vec3);
  vec3.transformQuat(v, v, q);
  if (light.kind === 'point') vec3.add(v, v, center as vec3);
  return { ...light, vector: [v[0], v[1], v[2]] };
}

/** `scene` with the trackball's object and light rotations applied about the objects' centre. */
export function rotateScene(scene: Scene, objects: ReadonlyQuat, light: ReadonlyQuat): Scene {
  if (isIdentity(objects) && isIdentity(light)) return scene;
  const center = boundsCenter(scene.objects);
  return {
    ...scene,
    objects: rotateObjects(scene.objects, objects, center),
    lights: scene.lights.map((l, i) => (i === 0 ? rotateLight(l, light, center) : l)),
  };
}
