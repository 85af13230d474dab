// Tensor-product Bézier patches of any degree (docs/software-renderer.md#bezier-surfaces): de Casteljau evaluation of
// the point and both partial derivatives, and the E×E grid mesh a renderer draws.
import { indexArray, type MeshData } from './mesh-data';

export const MIN_BEZIER_RESOLUTION = 2;
export const MAX_BEZIER_RESOLUTION = 1024;

/**
 * A patch of degrees (m, n) = (degreeU, degreeV): control point P(i, j), i = 0..m along u,
 * j = 0..n along v, has its xyz at `points[3·(i·(n + 1) + j)]`.
 */
export interface BezierPatch {
  degreeU: number;
  degreeV: number;
  points: ArrayLike<number>;
}

/** S(u, v) and its partial derivatives ∂S/∂u, ∂S/∂v. */
export interface BezierSample {
  point: [number, number, number];
  du: [number, number, number];
  dv: [number, number, number];
}

/** Relative size of |∂S/∂u × ∂S/∂v| below which the normal is taken from a nearby point. */
const DEGENERATE = 1e-10;
/** Steps towards the patch centre tried, in order, for a degenerate point (1 = the centre). */
const NEARBY_STEPS = [1e-4, 1e-3, 1e-2, 1e-1, 1];

/** Throws a RangeError unless the degrees are integers ≥ 1 and `points` holds (m+1)(n+1) xyz. */
export function checkBezierPatch(patch: BezierPatch): void {
  const { degreeU: m, degreeV: n, points } = patch;
  if (!Number.isInteger(m) || !Number.isInteger(n) || m < 1 || n < 1) {
    throw new RangeError(`glass-plane-scene: Bézier degrees must be integers ≥ 1, got (${m}, ${n})`);
  }
  if (points.length !== 3 * (m + 1) * (n + 1)) {
    throw new RangeError(`glass-plane-scene: a (${m}, ${n}) Bézier patch needs ${(m + 1) * (n + 1)} control points, got ${points.length / 3}`);
  }
}

/** The point and partial derivatives at (u, v) ∈ [0, 1]², by de Casteljau in v, then in u. */
export function evaluateBezierPatch(patch: BezierPatch, u: number, v: number): BezierSample {
  checkBezierPatch(patch);
  const ev = new Evaluator(patch);
  ev.setV(v);
  // Stryker disable next-line ArrayDeclaration: every element is written before it is read ([] then [0..2] is the same array)
  const out: BezierSample = { point: [0, 0, 0], du: [0, 0, 0], dv: [0, 0, 0] };
  ev.atU(u, out);
  return out;
}

/**
 * The unit normal at (u, v): ∂S/∂u × ∂S/∂v, normalised, so one orientation over the whole
 * patch. Where that cross product vanishes (|∂S/∂u × ∂S/∂v| ≤ 1e-10·m·n·L², L the diagonal of
 * the control net's bounding box: a row of coincident control points, as at the tip of the
 * Newell teapot's lid, or parallel tangents) the normal is that of the nearby point
 * (u + t·(½ − u), v + t·(½ − v)) for the first t of 1e-4, 1e-3, 1e-2, 0.1, 1 at which the cross
 * product does not vanish: a step of at most 5·10⁻⁵ in parameter towards the patch centre,
 * so the normal is off its limit by O(10⁻⁴) rad on a smooth degenerate edge. A patch that
 * is degenerate everywhere (all its control points on one line) gets (0, 0, 1).
 */
export function bezierPatchNormal(patch: BezierPatch, u: number, v: number): [number, number, number] {
  checkBezierPatch(patch);
  // Stryker disable next-line ArrayDeclaration: every element is written before it is read ([] then [0..2] is the same array)
  const out: [number, number, number] = [0, 0, 0];
  new Evaluator(patch).normalAt(u, v, out);
  return out;
}

/**
 * The patch on an E×E grid, E = `resolution` (rounded, clamped to 2..1024): vertex
 * (a, b) at (u, v) = (a/(E − 1), b/(E − 1)) is number b·E + a, with uv = (u, v); normals as in
 * `bezierPatchNormal`; (E − 1)² quads, each two triangles wound counter-clockwise seen from
 * the side the normal points to.
 */
export function bezierPatchMesh(patch: BezierPatch, resolution: number): MeshData {
  checkBezierPatch(patch);
  const e = Math.max(MIN_BEZIER_RESOLUTION, Math.min(MAX_BEZIER_RESOLUTION, Math.round(resolution) || 0));
  const count = e * e;
  const positions = new Float32Array(count * 3);
  const normals = new Float32Array(count * 3);
  const uvs = new Float32Array(count * 2);
  const ev = new Evaluator(patch);
  // Stryker disable next-line ArrayDeclaration: every element is written before it is read ([] then [0..2] is the same array)
  const sample: BezierSample = { point: [0, 0, 0], du: [0, 0, 0], dv: [0, 0, 0] };
  // Stryker disable next-line ArrayDeclaration: every element is written before it is read ([] then [0..2] is the same array)
  const normal: [number, number, number] = [0, 0, 0];
  const fallback = new Evaluator(patch); // a second one, so `ev` keeps its v row
  for (let b = 0; b < e; b++) {
    const v = b / (e - 1);
    ev.setV(v);
    for (let a = 0; a < e; a++) {
      const u = a / (e - 1);
      const k = b * e + a;
      ev.atU(u, sample);
      positions.set(sample.point, 3 * k);
      if (!ev.unitNormal(sample, normal)) fallback.nearbyNormal(u, v, normal);
      normals.set(normal, 3 * k);
      uvs[2 * k] = u;
      uvs[2 * k + 1] = v;
    }
  }
  const indices = indexArray((e - 1) * (e - 1) * 6, count);
  let o = 0;
  // Stryker disable next-line EqualityOperator,ArithmeticOperator: extra rows write past the typed index array's end, which drops them
  for (let b = 0; b < e - 1; b++) {
    for (let a = 0; a < e - 1; a++) {
      const p = b * e + a, q = p + 1, r = p + e, s = r + 1;
      // q − p ≈ ∂S/∂u·du and r − p ≈ ∂S/∂v·dv: (p, q, s) and (p, s, r) turn like ∂S/∂u × ∂S/∂v.
      indices[o++] = p; indices[o++] = q; indices[o++] = s;
      indices[o++] = p; indices[o++] = s; indices[o++] = r;
    }
  }
  return { positions, normals, uvs, indices };
}

/**
 * De Casteljau with the v direction done once per grid row: for a fixed v, each u-row of the
 * net collapses to Q(i) and Q'(i) = ∂/∂v, and the grid's points then cost two degree-m runs.
 */
class Evaluator {
  private readonly m: number;
  private readonly n: number;
  private readonly p: ArrayLike<number>;
  private readonly q: Float64Array; // Q(i), xyz, i = 0..m
  private readonly qv: Float64Array; // ∂Q(i)/∂v
  private readonly work: Float64Array;
  private readonly tolerance: number;

  constructor(patch: BezierPatch) {
    this.m = patch.degreeU;
    this.n = patch.degreeV;
    this.p = patch.points;
    this.q = new Float64Array(3 * (this.m + 1));
    this.qv = new Float64Array(3 * (this.m + 1));
    this.work = new Float64Array(3 * (Math.max(this.m, this.n) + 1));
    const size = netDiagonal(this.p);
    this.tolerance = DEGENERATE * this.m * this.n * size * size;
  }

  setV(v: number): void {
    const { m, n, p, work } = this;
    // Stryker disable next-line ArrayDeclaration: every element is written before it is read ([] then [0..2] is the same array)
    const d: [number, number, number] = [0, 0, 0];
    // Stryker disable next-line ArrayDeclaration: every element is written before it is read ([] then [0..2] is the same array)
    const pt: [number, number, number] = [0, 0, 0];
    for (let i = 0; i <= m; i++) {
      // Stryker disable next-line EqualityOperator: one more element copied is past what casteljau reads (or past `work`'s end, dropped)
      for (let k = 0; k < 3 * (n + 1); k++) work[k] = p[3 * i * (n + 1) + k];
      casteljau(work, n, v, pt, d);
      this.q.set(pt, 3 * i);
      this.qv.set(d, 3 * i);
    }
  }

  /** The sample at (u, the v of the last setV). */
  atU(u: number, out: BezierSample): void {
    const { m, work } = this;
    work.set(this.q.subarray(0, 3 * (m + 1)));
    casteljau(work, m, u, out.point, out.du);
    work.set(this.qv.subarray(0, 3 * (m + 1)));
    casteljau(work, m, u, out.dv, null);
  }

  /** out = unit ∂S/∂u × ∂S/∂v; false (out untouched) where it vanishes. */
  unitNormal(s: BezierSample, out: [number, number, number]): boolean {
    const [ax, ay, az] = s.du, [bx, by, bz] = s.dv;
    const x = ay * bz - az * by, y = az * bx - ax * bz, z = ax * by - ay * bx;
    const length = Math.hypot(x, y, z);
    if (!(length > this.tolerance)) return false;
    out[0] = x / length; out[1] = y / length; out[2] = z / length;
    return true;
  }

  normalAt(u: number, v: number, out: [number, number, number]): void {
    // Stryker disable next-line ArrayDeclaration: every element is written before it is read ([] then [0..2] is the same array)
    const s: BezierSample = { point: [0, 0, 0], du: [0, 0, 0], dv: [0, 0, 0] };
    this.setV(v);
    this.atU(u, s);
    if (!this.unitNormal(s, out)) this.nearbyNormal(u, v, out);
  }

  nearbyNormal(u: number, v: number, out: [number, number, number]): void {
    // Stryker disable next-line ArrayDeclaration: every element is written before it is read ([] then [0..2] is the same array)
    const s: BezierSample = { point: [0, 0, 0], du: [0, 0, 0], dv: [0, 0, 0] };
    for (const t of NEARBY_STEPS) {
      this.setV(v + t * (0.5 - v));
      this.atU(u + t * (0.5 - u), s);
      if (this.unitNormal(s, out)) return;
    }
    out[0] = 0; out[1] = 0; out[2] = 1;
  }
}

/**
 * De Casteljau on `deg + 1` xyz points in `b` (overwritten): the point at t, and, when `d` is
 * given, the derivative deg·(b₁ − b₀) from the level with two points left.
 */
function casteljau(b: Float64Array, deg: number, t: number, point: number[], d: number[] | null): void {
  const s = 1 - t;
  for (let level = deg; level > 1; level--) {
    // Stryker disable next-line EqualityOperator: b[3·level] is never read again (lower levels and the last step read below it)
    for (let k = 0; k < 3 * level; k++) b[k] = s * b[k] + t * b[k + 3];
  }
  for (let c = 0; c < 3; c++) {
    point[c] = s * b[c] + t * b[c + 3];
    if (d) d[c] = deg * (b[c + 3] - b[c]);
  }
}

function netDiagonal(p: ArrayLike<number>): number {
  const lo = [Infinity, Infinity, Infinity], hi = [-Infinity, -Infinity, -Infinity];
  for (let k = 0; k < p.length; k++) {
    lo[k % 3] = Math.min(lo[k % 3], p[k]);
    hi[k % 3] = Math.max(hi[k % 3], p[k]);
  }
  return Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
}
