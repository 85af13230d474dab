// Analytic ray intersection with the default scene: the rotated cube, the sphere and the glass rectangle.
import { mat4 } from 'gl-matrix';
import { BOX_FACES } from '../scene/geometry/box';
import { CUBE, GLASS, SPHERE } from '../scene/default-scene';
import type { Ray } from './ray';
import type { ReferenceState } from './reference-state';

/** Surface codes: 0 nothing, 1..6 cube face BOX_FACES[code − 1], 7 sphere, 8 glass. */
export const SURFACE_NONE = 0;
export const SURFACE_SPHERE = 7;
export const SURFACE_GLASS = 8;
export const isCube = (surface: number): boolean => surface >= 1 && surface <= 6;

/**
 * One intersection: where (p), the unit normal facing the ray's origin side (n), the
 * texture coordinates (u, v) and their gradients with respect to the world position
 * (gu, gv; only their components in the surface's tangent plane matter).
 */
export class SurfaceHit {
  surface = SURFACE_NONE;
  t = Infinity;
  readonly p = new Float64Array(3);
  readonly n = new Float64Array(3);
  u = 0;
  v = 0;
  readonly gu = new Float64Array(3);
  readonly gv = new Float64Array(3);
}

/** Face lookup: FACE_OF[axis][0 for +, 1 for −] = the BOX_FACES index with that outward normal. */
const FACE_OF = [0, 1, 2].map((axis) => [1, -1].map((sign) => BOX_FACES.findIndex(([n]) => n[axis] === sign)));

const HALF = CUBE.edge / 2;
const R = SPHERE.radius;
const [SCX, SCY, SCZ] = SPHERE.centre;
const TWO_PI = 2 * Math.PI;

export class RayScene {
  /** The cube's model matrix, composed exactly as the renderer composes it. */
  readonly cubeModel = new Float64Array(16);
  // Object-space scratch.
  private readonly o = new Float64Array(3);
  private readonly d = new Float64Array(3);

  constructor(state: ReferenceState) {
    const m = this.cubeModel as unknown as mat4;
    mat4.fromTranslation(m, [CUBE.x, CUBE.y, state.cubeDistance]);
    mat4.rotateY(m, m, state.spin * state.time);
  }

  /**
   * The cube's entry (front-face) hit for t ≥ −∞; false when the line misses it. The GPU
   * culls back faces, so an exit point is never visible: callers range-check `hit.t`.
   */
  hitCube(ray: Ray, hit: SurfaceHit): boolean {
    const m = this.cubeModel;
    const { o, d } = this;
    const ro = ray.origin, rd = ray.direction;
    const px = ro[0] - m[12], py = ro[1] - m[13], pz = ro[2] - m[14];
    // Object space = Rᵀ·(world − centre): the model's columns are the object axes.
    for (let k = 0; k < 3; k++) {
      const c = 4 * k;
      o[k] = m[c] * px + m[c + 1] * py + m[c + 2] * pz;
      d[k] = m[c] * rd[0] + m[c + 1] * rd[1] + m[c + 2] * rd[2];
    }
    let tNear = -Infinity, tFar = Infinity, axis = -1;
    for (let k = 0; k < 3; k++) {
      if (d[k] === 0) {
        if (o[k] < -HALF || o[k] > HALF) return false;
        continue;
      }
      const ta = (-HALF - o[k]) / d[k];
      const tb = (HALF - o[k]) / d[k];
      const lo = Math.min(ta, tb);
      if (lo > tNear) { tNear = lo; axis = k; }
      tFar = Math.min(tFar, Math.max(ta, tb));
    }
    if (axis < 0 || !(tNear <= tFar)) return false;
    const face = FACE_OF[axis][d[axis] > 0 ? 1 : 0];
    const [fn, fa, fb] = BOX_FACES[face];
    hit.surface = face + 1;
    hit.t = tNear;
    let u = 0.5, v = 0.5;
    for (let k = 0; k < 3; k++) {
      const q = o[k] + tNear * d[k];
      u += (q * fa[k]) / CUBE.edge;
      v += (q * fb[k]) / CUBE.edge;
    }
    hit.u = u;
    hit.v = v;
    for (let k = 0; k < 3; k++) {
      hit.p[k] = ro[k] + tNear * rd[k];
      // World vector = R·(object vector): rows of R are (m[k], m[4 + k], m[8 + k]).
      hit.n[k] = m[k] * fn[0] + m[4 + k] * fn[1] + m[8 + k] * fn[2];
      hit.gu[k] = (m[k] * fa[0] + m[4 + k] * fa[1] + m[8 + k] * fa[2]) / CUBE.edge;
      hit.gv[k] = (m[k] * fb[0] + m[4 + k] * fb[1] + m[8 + k] * fb[2]) / CUBE.edge;
    }
    return true;
  }

  /** The sphere's entry (front-face) hit, in the numerically stable closest-approach form. */
  hitSphere(ray: Ray, hit: SurfaceHit): boolean {
    const ro = ray.origin, rd = ray.direction;
    const ox = ro[0] - SCX, oy = ro[1] - SCY, oz = ro[2] - SCZ;
    const a = rd[0] * rd[0] + rd[1] * rd[1] + rd[2] * rd[2];
    const tc = -(ox * rd[0] + oy * rd[1] + oz * rd[2]) / a; // closest approach
    const qx = ox + tc * rd[0], qy = oy + tc * rd[1], qz = oz + tc * rd[2];
    const h2 = R * R - (qx * qx + qy * qy + qz * qz);
    if (!(h2 >= 0)) return false;
    const t = tc - Math.sqrt(h2 / a);
    hit.surface = SURFACE_SPHERE;
    hit.t = t;
    const p = hit.p, n = hit.n;
    for (let k = 0; k < 3; k++) p[k] = ro[k] + t * rd[k];
    n[0] = p[0] - SCX; n[1] = p[1] - SCY; n[2] = p[2] - SCZ;
    const len = Math.hypot(n[0], n[1], n[2]);
    n[0] /= len; n[1] /= len; n[2] /= len;
    // SPEC §3: u = ½ + atan2(n.x, n.z)/2π, v = acos(−n.y)/π (object space = world: no rotation).
    hit.u = 0.5 + Math.atan2(n[0], n[2]) / TWO_PI;
    hit.v = Math.acos(Math.max(-1, Math.min(1, -n[1]))) / Math.PI;
    // ∂u/∂p and ∂v/∂p along the surface; singular at the poles (bounded by the sampler's cap).
    const rho2 = Math.max(n[0] * n[0] + n[2] * n[2], 1e-300);
    hit.gu[0] = n[2] / (TWO_PI * R * rho2); hit.gu[1] = 0; hit.gu[2] = -n[0] / (TWO_PI * R * rho2);
    hit.gv[0] = 0; hit.gv[1] = 1 / (Math.PI * R * Math.sqrt(rho2)); hit.gv[2] = 0;
    return true;
  }

  /** The glass rectangle (two-sided), any t; normal +Z as the mesh has it. */
  hitGlass(ray: Ray, hit: SurfaceHit): boolean {
    const ro = ray.origin, rd = ray.direction;
    if (rd[2] === 0) return false;
    const t = -ro[2] / rd[2];
    const x = ro[0] + t * rd[0];
    const y = ro[1] + t * rd[1];
    if (!(x >= GLASS.xMin && x <= GLASS.xMax && y >= GLASS.yMin && y <= GLASS.yMax)) return false;
    hit.surface = SURFACE_GLASS;
    hit.t = t;
    hit.p[0] = x; hit.p[1] = y; hit.p[2] = 0;
    hit.n[0] = 0; hit.n[1] = 0; hit.n[2] = 1;
    const w = GLASS.xMax - GLASS.xMin, h = GLASS.yMax - GLASS.yMin;
    hit.u = (x - GLASS.xMin) / w;
    hit.v = (y - GLASS.yMin) / h;
    hit.gu[0] = 1 / w; hit.gu[1] = 0; hit.gu[2] = 0;
    hit.gv[0] = 0; hit.gv[1] = 1 / h; hit.gv[2] = 0;
    return true;
  }
}
