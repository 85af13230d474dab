// Triangle meshes (the Gaussian surface, loaded models) through a BVH built once per mesh, in object space.
import type { Plane } from '../math/mirror';
import type { MeshData } from '../scene/geometry/mesh-data';
import type { ObjectTracer } from './analytic-tracers';
import { Bvh, BvhHit } from './bvh';
import { keptInterval } from './clip';
import type { ObjectFrame } from './object-frame';
import type { Ray } from './ray';
import type { SurfaceHit } from './surface-hit';

/** A mesh without (enough) UVs reads (0, 0) everywhere; its mapping should not be 'uv'. */
const NO_UVS = new Float32Array(2);

/** BVHs by mesh: a mesh shared by many objects, or rendered many times, is built once. */
const BVHS = new WeakMap<MeshData, Bvh>();

export function bvhOf(mesh: MeshData): Bvh {
  let bvh = BVHS.get(mesh);
  if (bvh === undefined) {
    bvh = new Bvh(mesh.positions, mesh.indices);
    BVHS.set(mesh, bvh);
  }
  return bvh;
}

/**
 * Nearest triangle in the kept interval, both faces (user meshes are not back-face culled) unless `frontOnly`.
 * Normals and UVs are interpolated with the barycentric weights; the shading normal is then
 * turned towards the viewer (two-sided lighting, docs/scene-model.md#two-sided-lighting): it faces against the ray.
 */
export class MeshTracer implements ObjectTracer {
  private readonly bvh: Bvh;
  private readonly o = new Float64Array(3);
  private readonly d = new Float64Array(3);
  private readonly range = new Float64Array(2);
  private readonly found = new BvhHit();
  private readonly g = new Float64Array(3);

  constructor(
    readonly frame: ObjectFrame, private readonly mesh: MeshData, private readonly object: number, private readonly code: number,
    /** Front faces alone (counter-clockwise seen from outside, as glTF winds them); false: both. */
    private readonly frontOnly = false,
  ) {
    this.bvh = bvhOf(mesh);
  }

  hit(ray: Ray, tMin: number, clipSide: number, plane: Plane | null, out: SurfaceHit): boolean {
    const { o, d, range, found, frame } = this;
    if (!keptInterval(ray, tMin, clipSide, plane, range)) return false;
    frame.pointToObject(o, ray.origin);
    frame.directionToObject(d, ray.direction);
    if (!this.bvh.intersect(o[0], o[1], o[2], d[0], d[1], d[2], range[0], range[1], found, this.frontOnly)) return false;
    this.fill(ray, found, out);
    return true;
  }

  /** The tangent interpolated at the hit, in the world, unit (docs/gltf.md#the-normal-map); w 0 where the mesh has none. */
  private tangentAt(hit: SurfaceHit, i0: number, i1: number, i2: number, w0: number, w1: number, w2: number): void {
    const t = this.mesh.tangents, out = hit.tangent, g = this.g;
    // Stryker disable next-line ConditionalExpression,ArithmeticOperator: a scene's tangents are 4 a vertex or absent (the reader's, merge.ts): the length test is a guard
    if (t === undefined || t.length < 4 * (this.mesh.positions.length / 3)) {
      out[3] = 0;
      return;
    }
    // Stryker disable next-line EqualityOperator: k = 3 writes g[3], past the end of its 3 elements: dropped
    for (let k = 0; k < 3; k++) g[k] = w0 * t[4 * i0 + k] + w1 * t[4 * i1 + k] + w2 * t[4 * i2 + k];
    this.frame.directionToWorld(out, g);
    // Stryker disable next-line ConditionalExpression: a zero tangent divided by 1 or read as it is stays zero
    const len = Math.hypot(out[0], out[1], out[2]) || 1;
    out[0] /= len; out[1] /= len; out[2] /= len;
    // Stryker disable next-line EqualityOperator,ArithmeticOperator: w is ±1 (x·w = x/w), and a sum of exactly 0 needs corners of both sides weighed equal
    out[3] = w0 * t[4 * i0 + 3] + w1 * t[4 * i1 + 3] + w2 * t[4 * i2 + 3] < 0 ? -1 : 1;
  }

  private fill(ray: Ray, found: BvhHit, hit: SurfaceHit): void {
    const { o, d, g, frame } = this;
    const { normals, uvs, indices, positions } = this.mesh;
    const t = found.t, w1 = found.b1, w2 = found.b2, w0 = 1 - w1 - w2;
    const i0 = indices[3 * found.triangle], i1 = indices[3 * found.triangle + 1], i2 = indices[3 * found.triangle + 2];
    hit.surface = this.code;
    hit.object = this.object;
    hit.frame = frame;
    hit.t = t;
    const ro = ray.origin, rd = ray.direction;
    // Stryker disable next-line EqualityOperator: k = 3 writes past the end of the hit's three-element arrays: dropped
    for (let k = 0; k < 3; k++) {
      hit.p[k] = ro[k] + t * rd[k];
      hit.q[k] = o[k] + t * d[k];
    }
    // Geometric normal (object e1 × e2) and the UV gradients over the triangle's plane.
    const e1x = positions[i1 * 3] - positions[i0 * 3], e1y = positions[i1 * 3 + 1] - positions[i0 * 3 + 1], e1z = positions[i1 * 3 + 2] - positions[i0 * 3 + 2];
    const e2x = positions[i2 * 3] - positions[i0 * 3], e2y = positions[i2 * 3 + 1] - positions[i0 * 3 + 1], e2z = positions[i2 * 3 + 2] - positions[i0 * 3 + 2];
    const nx = e1y * e2z - e1z * e2y, ny = e1z * e2x - e1x * e2z, nz = e1x * e2y - e1y * e2x;
    g[0] = nx; g[1] = ny; g[2] = nz;
    frame.normalToWorld(hit.ng, g);
    // Shading normal: interpolated, or the face's where the corners' normals cancel out.
    const nq = hit.nq;
    const vertices = positions.length / 3;
    // Stryker disable next-line EqualityOperator: k = 3 writes past the end of nq (Float64Array(3)): dropped
    for (let k = 0; k < 3; k++) {
      nq[k] = normals.length >= 3 * vertices
        ? w0 * normals[i0 * 3 + k] + w1 * normals[i1 * 3 + k] + w2 * normals[i2 * 3 + k] : 0;
    }
    let len = Math.hypot(nq[0], nq[1], nq[2]);
    if (!(len > 0)) { nq[0] = nx; nq[1] = ny; nq[2] = nz; len = Math.hypot(nx, ny, nz) || 1; }
    nq[0] /= len; nq[1] /= len; nq[2] /= len;
    frame.normalToWorld(hit.n, nq);
    const n = hit.n;
    // Two-sided: turned to the viewer. A single-sided mesh is not (its back faces are not hit; WebGL's variant does not turn it).
    hit.flipped = !this.frontOnly && n[0] * rd[0] + n[1] * rd[1] + n[2] * rd[2] > 0;
    if (hit.flipped) { n[0] = -n[0]; n[1] = -n[1]; n[2] = -n[2]; }
    this.tangentAt(hit, i0, i1, i2, w0, w1, w2);
    const colors = this.mesh.colors;
    if (colors !== undefined && colors.length >= 3 * vertices) {
      // Stryker disable next-line EqualityOperator: k = 3 writes hit.color[3], past the end of its 3 elements: dropped
      for (let k = 0; k < 3; k++) hit.color[k] = w0 * colors[3 * i0 + k] + w1 * colors[3 * i1 + k] + w2 * colors[3 * i2 + k];
    } else hit.color.fill(1);
    // UVs and their gradients: ∇β = (e2 × N)/|N|², ∇γ = (N × e1)/|N|² for p = p0 + β·e1 + γ·e2.
    const uv = uvs.length >= 2 * vertices ? uvs : NO_UVS;
    const j0 = uv === NO_UVS ? 0 : i0, j1 = uv === NO_UVS ? 0 : i1, j2 = uv === NO_UVS ? 0 : i2;
    const u0 = uv[j0 * 2], v0 = uv[j0 * 2 + 1];
    const du1 = uv[j1 * 2] - u0, dv1 = uv[j1 * 2 + 1] - v0, du2 = uv[j2 * 2] - u0, dv2 = uv[j2 * 2 + 1] - v0;
    hit.u = u0 + w1 * du1 + w2 * du2;
    hit.v = v0 + w1 * dv1 + w2 * dv2;
    const nn = nx * nx + ny * ny + nz * nz || 1;
    const bx = (e2y * nz - e2z * ny) / nn, by = (e2z * nx - e2x * nz) / nn, bz = (e2x * ny - e2y * nx) / nn;
    const cx = (ny * e1z - nz * e1y) / nn, cy = (nz * e1x - nx * e1z) / nn, cz = (nx * e1y - ny * e1x) / nn;
    g[0] = du1 * bx + du2 * cx; g[1] = du1 * by + du2 * cy; g[2] = du1 * bz + du2 * cz;
    frame.gradientToWorld(hit.gu, g);
    g[0] = dv1 * bx + dv2 * cx; g[1] = dv1 * by + dv2 * cy; g[2] = dv1 * bz + dv2 * cz;
    frame.gradientToWorld(hit.gv, g);
  }
}
