// The built-in shapes, intersected analytically in object space: the box (slab test) and the sphere.
// Both are drawn by the GPU with back faces culled, so only the entry (front-face) point counts.
import type { Plane } from '../math/mirror';
import { BOX_FACES } from '../scene/geometry/box';
import { kept } from './clip';
import type { ObjectFrame } from './object-frame';
import type { Ray } from './ray';
import type { SurfaceHit } from './surface-hit';

/** Face lookup: FACE_OF[axis][0 for +, 1 for −] = the BOX_FACES index with that outward normal. */
const FACE_OF = [0, 1, 2].map((axis) => [1, -1].map((sign) => BOX_FACES.findIndex(([n]) => n[axis] === sign)));

const TWO_PI = 2 * Math.PI;

/** An object the ray tracer can hit; `hit` fills `out` and returns true only for a kept hit. */
export interface ObjectTracer {
  readonly frame: ObjectFrame;
  hit(ray: Ray, tMin: number, clipSide: number, plane: Plane | null, out: SurfaceHit): boolean;
}

/** Edge-`size` cube centred on the object origin; faces coded firstCode + BOX_FACES index, UVs per face. */
export class BoxTracer implements ObjectTracer {
  private readonly o = new Float64Array(3);
  private readonly d = new Float64Array(3);
  private readonly half: number;
  /** Per axis ±1: a negative scale turns that axis's faces inside out in the world. */
  private readonly flip = new Float64Array(3);

  constructor(readonly frame: ObjectFrame, private readonly size: number, private readonly object: number, private readonly firstCode: number) {
    this.half = size / 2;
    // Stryker disable next-line EqualityOperator: flip[3] is dropped; a zero scale makes NaN slabs, never entered
    for (let k = 0; k < 3; k++) this.flip[k] = frame.scale[k] < 0 ? -1 : 1;
  }

  hit(ray: Ray, tMin: number, clipSide: number, plane: Plane | null, out: SurfaceHit): boolean {
    return this.entry(ray, out) && kept(out, tMin, clipSide, plane);
  }

  /** The entry hit for t ≥ −∞; false when the line misses the box. */
  private entry(ray: Ray, hit: SurfaceHit): boolean {
    const { o, d, half, size, frame } = this;
    const m = frame.matrix, s = frame.scale;
    frame.pointToObject(o, ray.origin);
    frame.directionToObject(d, ray.direction);
    let tNear = -Infinity, tFar = Infinity, axis = -1;
    for (let k = 0; k < 3; k++) {
      if (d[k] === 0) {
        if (o[k] < -half || o[k] > half) return false;
        continue;
      }
      const ta = (-half - o[k]) / d[k];
      const tb = (half - o[k]) / d[k];
      const lo = Math.min(ta, tb);
      if (lo > tNear) { tNear = lo; axis = k; }
      tFar = Math.min(tFar, Math.max(ta, tb));
    }
    if (axis < 0 || !(tNear <= tFar)) return false;
    // Stryker disable next-line EqualityOperator: the entry axis always has d[axis] ≠ 0 (a zero component skips its slab)
    const face = FACE_OF[axis][d[axis] > 0 ? 1 : 0];
    const [fn, fa, fb] = BOX_FACES[face];
    hit.surface = this.firstCode + face;
    hit.tangent.fill(0); // no tangents: no normal map (docs/gltf.md#the-normal-map)
    hit.color.fill(1);
    hit.flipped = false;
    hit.object = this.object;
    hit.frame = frame;
    hit.t = tNear;
    let u = 0.5, v = 0.5;
    for (let k = 0; k < 3; k++) {
      const q = o[k] + tNear * d[k];
      hit.q[k] = q;
      hit.nq[k] = fn[k];
      u += (q * fa[k]) / size;
      v += (q * fb[k]) / size;
    }
    hit.u = u;
    hit.v = v;
    const ro = ray.origin, rd = ray.direction, f = this.flip;
    // Stryker disable next-line ArithmeticOperator: f is ±1, so fn/f = fn·f
    const n0 = fn[0] * f[0], n1 = fn[1] * f[1], n2 = fn[2] * f[2];
    const a0 = fa[0] / s[0], a1 = fa[1] / s[1], a2 = fa[2] / s[2];
    const b0 = fb[0] / s[0], b1 = fb[1] / s[1], b2 = fb[2] / s[2];
    // Stryker disable next-line EqualityOperator: k = 3 writes past the end of the hit's three-element arrays: dropped
    for (let k = 0; k < 3; k++) {
      hit.p[k] = ro[k] + tNear * rd[k];
      // World vector = R·(object vector): rows of R are (m[k], m[4 + k], m[8 + k]). The face
      // normal is an axis, so R·S⁻¹·n is R·n up to length and the scale's sign.
      hit.n[k] = m[k] * n0 + m[4 + k] * n1 + m[8 + k] * n2;
      hit.ng[k] = hit.n[k];
      hit.gu[k] = (m[k] * a0 + m[4 + k] * a1 + m[8 + k] * a2) / size;
      hit.gv[k] = (m[k] * b0 + m[4 + k] * b1 + m[8 + k] * b2) / size;
    }
    return true;
  }
}

/** Sphere of `radius` about the object origin (an ellipsoid under non-uniform scale), with the default sphere's UVs (docs/default-scene.md#texture-coordinates). */
export class SphereTracer implements ObjectTracer {
  private readonly o = new Float64Array(3);
  private readonly d = new Float64Array(3);
  private readonly g = new Float64Array(3);

  constructor(readonly frame: ObjectFrame, private readonly radius: number, private readonly object: number, private readonly code: number) {}

  hit(ray: Ray, tMin: number, clipSide: number, plane: Plane | null, out: SurfaceHit): boolean {
    return this.entry(ray, out) && kept(out, tMin, clipSide, plane);
  }

  /** The entry hit, in object space, in the numerically stable closest-approach form. */
  private entry(ray: Ray, hit: SurfaceHit): boolean {
    const { o, d, g, frame } = this;
    const r = this.radius;
    frame.pointToObject(o, ray.origin);
    frame.directionToObject(d, ray.direction);
    const a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    const tc = -(o[0] * d[0] + o[1] * d[1] + o[2] * d[2]) / a; // closest approach
    const qx = o[0] + tc * d[0], qy = o[1] + tc * d[1], qz = o[2] + tc * d[2];
    const h2 = r * r - (qx * qx + qy * qy + qz * qz);
    if (!(h2 >= 0)) return false;
    const t = tc - Math.sqrt(h2 / a);
    hit.surface = this.code;
    hit.tangent.fill(0);
    hit.color.fill(1);
    hit.flipped = false;
    hit.object = this.object;
    hit.frame = frame;
    hit.t = t;
    const ro = ray.origin, rd = ray.direction, p = hit.p;
    // Stryker disable next-line EqualityOperator: k = 3 writes past the end of p (Float64Array(3)): dropped
    for (let k = 0; k < 3; k++) p[k] = ro[k] + t * rd[k];
    // The object-space point from the world point (not o + t·d): with no rotation and unit
    // scale this is p − centre exactly, as the world-space formula had it.
    const q = frame.pointToObject(hit.q, p), nq = hit.nq;
    const len = Math.hypot(q[0], q[1], q[2]);
    nq[0] = q[0] / len; nq[1] = q[1] / len; nq[2] = q[2] / len;
    if (frame.unitScale) frame.gradientToWorld(hit.n, nq);
    else frame.normalToWorld(hit.n, nq);
    hit.ng[0] = hit.n[0]; hit.ng[1] = hit.n[1]; hit.ng[2] = hit.n[2];
    // docs/default-scene.md#texture-coordinates: u = ½ + atan2(n.x, n.z)/2π, v = acos(−n.y)/π on the object-space normal.
    hit.u = 0.5 + Math.atan2(nq[0], nq[2]) / TWO_PI;
    hit.v = Math.acos(Math.max(-1, Math.min(1, -nq[1]))) / Math.PI;
    // ∂u/∂q and ∂v/∂q along the surface; singular at the poles (bounded by the sampler's cap).
    const rho2 = Math.max(nq[0] * nq[0] + nq[2] * nq[2], 1e-300);
    g[0] = nq[2] / (TWO_PI * r * rho2); g[1] = 0; g[2] = -nq[0] / (TWO_PI * r * rho2);
    frame.gradientToWorld(hit.gu, g);
    g[0] = 0; g[1] = 1 / (Math.PI * r * Math.sqrt(rho2)); g[2] = 0;
    frame.gradientToWorld(hit.gv, g);
    return true;
  }
}
