// The trackball's rotation of the scene (docs/interaction.md#trackball): every object turned as a group about the
// centre of their bounds, and the first light turned about the same centre. The page's `scene`
// and the reference see it applied to the scene value as ordinary transforms (rotateScene); the
// renderers get it with each frame (FrameState.turn, turn.ts) and compose it as one more matrix,
// so a turn builds no new scene value. Pure math, in a chunk of its own (docs/package.md#chunks): the element
// fetches it when a turn is first set, and the `controls` chunk brings it with the trackball.
import type { quat, ReadonlyQuat } from 'gl-matrix';
import type { Light, Scene, SceneObject, Vec3 } from './scene';
import { isIdentity } from './turn';

const DEG = Math.PI / 180;

/**
 * out = a·b (Hamilton product, [x, y, z, w]): the rotation b, then a. Written here rather than
 * taken from gl-matrix's quat module, whose load-time helpers (rotationTo, setAxes) a bundler
 * cannot drop: the core stays without that module.
 */
function multiply(out: quat, a: ArrayLike<number>, b: ArrayLike<number>): quat {
  const ax = a[0], ay = a[1], az = a[2], aw = a[3], bx = b[0], by = b[1], bz = b[2], bw = b[3];
  out[0] = ax * bw + aw * bx + ay * bz - az * by;
  out[1] = ay * bw + aw * by + az * bx - ax * bz;
  out[2] = az * bw + aw * bz + ax * by - ay * bx;
  out[3] = aw * bw - ax * bx - ay * by - az * bz;
  return out;
}

/** out = the rotation by `deg` degrees about axis `i` (0 x, 1 y, 2 z). */
function axisQuat(out: Float64Array, i: number, deg: number): Float64Array {
  const h = (deg * DEG) / 2;
  out.fill(0);
  out[i] = Math.sin(h);
  out[3] = Math.cos(h);
  return out;
}

// eulerToQuat's two axis rotations: a frame's and a gesture's turns allocate nothing.
const AXIS_A = new Float64Array(4), AXIS_B = new Float64Array(4);

/**
 * out = v turned by the unit quaternion q: t = 2 (q⃗ × v), out = v + w t + q⃗ × t (the same
 * operations, in the same order, as gl-matrix's vec3.transformQuat, so the same bits; its vec3
 * module stays out of the core with the quat one).
 */
function rotateVector(out: number[] | Float64Array, q: ArrayLike<number>, vx: number, vy: number, vz: number): void {
  const qx = q[0], qy = q[1], qz = q[2], qw = q[3];
  let tx = qy * vz - qz * vy, ty = qz * vx - qx * vz, tz = qx * vy - qy * vx;
  tx = tx + tx;
  ty = ty + ty;
  tz = tz + tz;
  out[0] = vx + qw * tx + qy * tz - qz * ty;
  out[1] = vy + qw * ty + qz * tx - qx * tz;
  out[2] = vz + qw * tz + qx * ty - qy * tx;
}

/** Rz·Ry·Rx of Euler degrees (x applied first), as the renderers build it. */
export function eulerToQuat(out: quat, rotation: readonly number[]): quat {
  multiply(out, axisQuat(AXIS_A, 2, rotation[2]), axisQuat(AXIS_B, 1, rotation[1]));
  return multiply(out, out, axisQuat(AXIS_A, 0, rotation[0]));
}

/** Euler degrees [x, y, z] with Rz·Ry·Rx = the rotation of `q`; x = 0 at gimbal lock. */
export function quatToEuler(q: ReadonlyQuat): Vec3 {
  // The rotation matrix's entries rRC (row R, column C) that the angles need, from q as
  // gl-matrix's mat3.fromQuat forms them.
  const x = q[0], y2 = q[1] + q[1], z = q[2], w = q[3], x2 = x + x, z2 = z + z;
  const xx = x * x2, yx = q[1] * x2, yy = q[1] * y2, zx = z * x2, zy = z * y2, zz = z * z2, wx = w * x2, wy = w * y2, wz = w * z2;
  const r20 = zx - wy, r21 = zy + wx, r22 = 1 - xx - yy, r10 = yx + wz, r00 = 1 - yy - zz, r01 = yx - wz, r11 = 1 - xx - zz;
  const y = Math.asin(Math.max(-1, Math.min(1, -r20)));
  // Stryker disable next-line EqualityOperator: only an exact tie |r20| = 0.9999999 tells < from <=, and there either branch decomposes the turn to ~0.02°
  if (Math.abs(r20) < 0.9999999) return [Math.atan2(r21, r22) / DEG, y / DEG, Math.atan2(r10, r00) / DEG];
  return [0, y / DEG, Math.atan2(-r01, r11) / DEG];
}

/** Centre of the box around the objects' world bounding spheres (their spin aside); the origin for none. */
export function boundsCenter<T extends [number, number, number] | Float64Array | Float32Array>(objects: readonly SceneObject[], out: T): T {
  out[0] = 0; out[1] = 0; out[2] = 0;
  // Stryker disable next-line ConditionalExpression: without objects lo + hi is NaN and the loop below writes the same zeros
  if (objects.length === 0) return out;
  const lo = BOX_LO.fill(Infinity), hi = BOX_HI.fill(-Infinity), q = BOX_Q, c = BOX_C;
  for (let k = 0; k < objects.length; k++) {
    const o = objects[k], { position, rotation, scale } = o.transform, b = o.bounds.center;
    rotateVector(c, eulerToQuat(q, rotation), b[0] * scale[0], b[1] * scale[1], b[2] * scale[2]);
    // Stryker disable next-line EqualityOperator: index 3 of a Float64Array(3) is dropped
    for (let i = 0; i < 3; i++) c[i] += position[i];
    const r = o.bounds.radius * Math.max(Math.abs(scale[0]), Math.abs(scale[1]), Math.abs(scale[2]));
    // Stryker disable next-line EqualityOperator: index 3 of a Float64Array(3) is dropped
    for (let i = 0; i < 3; i++) {
      lo[i] = Math.min(lo[i], c[i] - r);
      hi[i] = Math.max(hi[i], c[i] + r);
    }
  }
  for (let i = 0; i < 3; i++) out[i] = Number.isFinite(lo[i] + hi[i]) ? (lo[i] + hi[i]) / 2 : 0;
  return out;
}

// boundsCenter's scratch: a gesture's start asks for the centre, and asks allocate nothing.
const BOX_LO = new Float64Array(3), BOX_HI = new Float64Array(3), BOX_C = new Float64Array(3);
const BOX_Q = new Float64Array(4) as unknown as quat;

/** The objects turned by `q` about `center`: position c + q·(p − c), rotation q·R. */
export function rotateObjects(objects: readonly SceneObject[], q: ReadonlyQuat, center: Vec3): readonly SceneObject[] {
  if (isIdentity(q)) return objects;
  const r = (new Float64Array([0, 0, 0, 1]) as unknown as quat), p = new Float64Array(3);
  return objects.map((o) => {
    const t = o.transform.position;
    rotateVector(p, q, t[0] - center[0], t[1] - center[1], t[2] - center[2]);
    // Stryker disable next-line EqualityOperator: index 3 of a Float64Array(3) is dropped
    for (let i = 0; i < 3; i++) p[i] += center[i];
    multiply(r, q, eulerToQuat(r, o.transform.rotation));
    return { ...o, transform: { ...o.transform, position: [p[0], p[1], p[2]], rotation: quatToEuler(r) } };
  });
}

/** A light turned by `q` about `center`: a point light's position, a directional light's direction. */
export function rotateLight(light: Light, q: ReadonlyQuat, center: Vec3): Light {
  if (isIdentity(q)) return light;
  const l = light.vector, point = light.kind === 'point', v = new Float64Array(3);
  if (point) rotateVector(v, q, l[0] - center[0], l[1] - center[1], l[2] - center[2]);
  else rotateVector(v, q, l[0], l[1], l[2]);
  // Stryker disable next-line EqualityOperator: index 3 of a Float64Array(3) is dropped
  if (point) for (let i = 0; i < 3; i++) v[i] += center[i];
  return { ...light, vector: [v[0], v[1], v[2]] };
}

/** `scene` with the trackball's object and light rotations applied about the objects' centre. */
export function rotateScene(scene: Scene, objects: ReadonlyQuat, light: ReadonlyQuat): Scene {
  if (isIdentity(objects) && isIdentity(light)) return scene;
  // Stryker disable next-line ArrayDeclaration: boundsCenter writes all three
  const center = boundsCenter(scene.objects, [0, 0, 0]);
  return {
    ...scene,
    objects: rotateObjects(scene.objects, objects, center),
    lights: scene.lights.map((l, i) => (i === 0 ? rotateLight(l, light, center) : l)),
  };
}
