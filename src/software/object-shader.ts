// The standard program of the GL path on the CPU (shaders/standard.vert + standard.frag): the
// vertex stage into a clip-space buffer, and per fragment the texture through its mapping,
// Blinn-Phong per pixel (phong) or interpolated from the vertices (gouraud, flat), a glTF material
// per pixel whatever the shading (docs/pbr.md#the-scenes-lights), the 8-bit clamp, and straight alpha blending for opacity < 1.
import { cylindricalUV, sphericalUV, triplanarScale, triplanarUV, TRIPLANAR_U, TRIPLANAR_V } from '../scene/mapping';
import type { MeshData } from '../scene/geometry/mesh-data';
import type { Bounds, Material } from '../scene/scene';
import type { Shading } from '../frame/types';
import { blinnPhong, type Lights } from './lighting';
import { maskedOut, pbrFragment } from './pbr-fragment';
import type { PbrMaps } from './image-textures';
import type { MipTexture } from './mip-texture';
import { CLIP_DISTANCE, VARYINGS, type FragmentShader, type Rasterizer } from './raster';
import { OBJECT_KEY_LENGTH, type ObjectCache } from './object-cache';
import { objectKey } from './object-key';

// Varyings, after the clip-space slots: phong carries the eye-relative position and normal,
// gouraud and flat the two light sums in the same slots; then UV, object position and normal.
const REL = 0, NRM = 3, UV = 6, OBJ = 8, OBJ_N = 11, TAN = 14, COL = 18;
export const OBJECT_STRIDE = VARYINGS + 21;

/** One object's draw: what the vertex stage and the fragments read. */
export interface ObjectDraw {
  mesh: MeshData;
  /** Model matrix (column-major, float64) and its normal matrix (inverse transpose, 3×3). */
  model: Float64Array;
  normal: Float64Array;
  /** The eye drawn from (world) and projection × view for eye-relative points (float64). */
  eye: ArrayLike<number>;
  /** The pass's view vector (FrameSetup.viewVector*): w = 1 toward the eye point; w = 0 orthographic, xyz toward the viewer. */
  view: ArrayLike<number>;
  viewProjection: Float64Array;
  /** Kept where plane·(rel, 1) ≥ 0 (rel eye-relative); null: no user clip. */
  clipPlane: ArrayLike<number> | null;
  material: Material;
  bounds: Bounds;
  texture: MipTexture;
  maps: PbrMaps;
  twoSided: boolean;
  shading: Shading;
  lights: Lights;
  /** The target's cache of opaque objects' colours (null: none), and the object's index in the scene. */
  cache: ObjectCache | null;
  index: number;
}

/**
 * Phase times of frames in ms, added to by SoftwareRenderer.render when its `timing` is set (the
 * bench's split of a frame; per draw, never per pixel, so the cost is nil when it is unset).
 */
export interface SoftwareTiming {
  /** The vertex stage: model, view and projection transforms (and per-vertex lighting for gouraud/flat). */
  vertex: number;
  /** The objects' triangles: clipping, setup, coverage, depth test and the fragments. */
  triangles: number;
  /** The glass's mask and composite (clipping to shading, as one). */
  glass: number;
  /** The whole of render(). */
  total: number;
  /** Objects' fragments write a constant colour instead of being shaded: `triangles` is then raster alone. */
  constantFragments: boolean;
}

/** The fragment shader of the timing run that leaves shading out (SoftwareTiming.constantFragments). */
class ConstantShader implements FragmentShader {
  colour: Float32Array = new Float32Array(0);
  fragment(pixel: number): void {
    const c = this.colour, o = 3 * pixel;
    c[o] = 0.5; c[o + 1] = 0.5; c[o + 2] = 0.5;
  }
}

export class ObjectShader implements FragmentShader {
  /** RGB per pixel, 0..1, written by the fragments. */
  colour: Float32Array = new Float32Array(0);
  /** What a colour is held to: 1 as an 8-bit target, Infinity in a tone-mapped frame (docs/pbr.md#tone-mapping). */
  top = 1;
  /** Set by the bench only: phase times are added here (see SoftwareTiming). */
  timing: SoftwareTiming | null = null;
  private readonly constant = new ConstantShader();
  private vertices = new Float64Array(0);
  private draw!: ObjectDraw;
  private readonly sums = new Float64Array(6);
  /** Lit per pixel: phong shading, or a glTF material (whatever the shading). */
  private perPixel = false;
  /**
   * Rough glass (docs/rough-glass.md#the-gather): per sample, the distance code h/(1 + h) of the opaque surface drawn
   * there (frame/rough-glass.ts), h its distance from the plane `codePlane` (positive on the side
   * the pass draws); null: not kept.
   */
  codes: Float32Array | null = null;
  readonly codePlane = new Float64Array(4);
  private code = 0;
  /** The last fragment's colour, clamped (written again at a pixel's other samples). */
  private cr = 0;
  private cg = 0;
  private cb = 0;
  /** blinnPhong's point, normal and view vector; a texture lookup's UV and derivatives. */
  private readonly geometry = new Float64Array(9);
  private readonly lookup = new Float64Array(6);
  /** The fragment's tangent (xyz and w; w 0: none), for a normal map; whether the draw's vertices carry one. */
  private readonly tangent = new Float64Array(4);
  private tangents = false;
  /** The fragment's vertex colour (a glTF material's mesh with COLOR_0), white without; whether the draw's vertices carry one. */
  private readonly color = new Float64Array(3);
  private colors = false;
  private readonly tex = new Float64Array(3);
  private readonly part = new Float64Array(3);
  private readonly uv0 = new Float64Array(2);
  private readonly uv1 = new Float64Array(2);
  private readonly q = new Float64Array(3);
  /** ∂q/∂x and ∂q/∂y per pixel; the triplanar normal, weights and three UVs. */
  private readonly dqx = new Float64Array(3);
  private readonly dqy = new Float64Array(3);
  private readonly n = new Float64Array(3);
  private readonly weights = new Float64Array(3);
  private readonly uvs = new Float64Array(6);
  /** The draw's cache while its fragments are read and kept (null: shaded every frame), and its key. */
  private cache: ObjectCache | null = null;
  private readonly key = new Float64Array(OBJECT_KEY_LENGTH);
  // Stryker disable next-line ArrayDeclaration: objectKey empties it (o.length = 0) before each use
  private readonly keyObjects: unknown[] = [];

  /** Runs the vertex stage of `d` and rasterizes its triangles with `r`. */
  render(d: ObjectDraw, r: Rasterizer): void {
    this.draw = d;
    this.perPixel = d.shading === 'phong' || d.material.pbr !== undefined;
    const count = d.mesh.positions.length / 3;
    this.tangents = d.material.pbr !== undefined && (d.mesh.tangents?.length ?? 0) >= 4 * count;
    this.colors = d.material.pbr !== undefined && (d.mesh.colors?.length ?? 0) >= 3 * count;
    if (this.vertices.length < count * OBJECT_STRIDE) this.vertices = new Float64Array(count * OBJECT_STRIDE);
    const timing = this.timing;
    const t0 = timing ? performance.now() : 0;
    this.vertexStage(d, count);
    r.stride = OBJECT_STRIDE;
    r.userClip = d.clipPlane !== null;
    r.derivatives = true;
    this.cache = null;
    // Opaque draws only: their colour goes to the Float32 target as it is (no blend, no codes); not a mask's, whose cut-away
    // fragments leave nothing to keep.
    if (d.cache !== null && this.codes === null && d.material.opacity >= 1 && d.material.pbr?.alphaMode !== 'mask' && !timing?.constantFragments) {
      const n = r.shadeEvery;
      d.cache.begin(d.index, objectKey(d, r, this.top, this.key, this.keyObjects), this.keyObjects, (r.width / n) * (r.height / n));
      if (d.cache.current !== 0) this.cache = d.cache;
    }
    if (!timing) {
      r.drawTriangles(this.vertices, d.mesh.indices, d.mesh.indices.length, this);
      return;
    }
    const t1 = performance.now();
    let shader: FragmentShader = this;
    if (timing.constantFragments) {
      this.constant.colour = this.colour;
      shader = this.constant;
    }
    r.drawTriangles(this.vertices, d.mesh.indices, d.mesh.indices.length, shader);
    timing.vertex += t1 - t0;
    timing.triangles += performance.now() - t1;
  }

  private vertexStage(d: ObjectDraw, count: number): void {
    const { positions: p, normals: nrm, uvs, centroids } = d.mesh;
    // A glTF material's mesh with tangents, for its normal map (docs/gltf.md#the-normal-map): through the model's 3×3 part.
    const tangents = this.tangents ? d.mesh.tangents! : null, colors = this.colors ? d.mesh.colors! : null;
    const m = d.model, nm = d.normal, vp = d.viewProjection, e = d.eye, cp = d.clipPlane;
    const out = this.vertices, sums = this.sums;
    const phong = this.perPixel;
    const hasNormals = nrm.length >= 3 * count, hasUvs = uvs.length >= 2 * count;
    for (let i = 0; i < count; i++) {
      const o = i * OBJECT_STRIDE, v = o + VARYINGS;
      const x = p[3 * i], y = p[3 * i + 1], z = p[3 * i + 2];
      const rx = m[0] * x + m[4] * y + m[8] * z + m[12] - e[0];
      const ry = m[1] * x + m[5] * y + m[9] * z + m[13] - e[1];
      const rz = m[2] * x + m[6] * y + m[10] * z + m[14] - e[2];
      out[o] = vp[0] * rx + vp[4] * ry + vp[8] * rz + vp[12];
      out[o + 1] = vp[1] * rx + vp[5] * ry + vp[9] * rz + vp[13];
      out[o + 2] = vp[2] * rx + vp[6] * ry + vp[10] * rz + vp[14];
      out[o + 3] = vp[3] * rx + vp[7] * ry + vp[11] * rz + vp[15];
      out[o + CLIP_DISTANCE] = cp === null ? 0 : cp[0] * rx + cp[1] * ry + cp[2] * rz + cp[3];
      const ox = hasNormals ? nrm[3 * i] : 0, oy = hasNormals ? nrm[3 * i + 1] : 0, oz = hasNormals ? nrm[3 * i + 2] : 0;
      const wx = nm[0] * ox + nm[3] * oy + nm[6] * oz;
      const wy = nm[1] * ox + nm[4] * oy + nm[7] * oz;
      const wz = nm[2] * ox + nm[5] * oy + nm[8] * oz;
      if (phong) {
        out[v + REL] = rx; out[v + REL + 1] = ry; out[v + REL + 2] = rz;
        out[v + NRM] = wx; out[v + NRM + 1] = wy; out[v + NRM + 2] = wz;
        if (tangents !== null) {
          const tx = tangents[4 * i], ty = tangents[4 * i + 1], tz = tangents[4 * i + 2];
          out[v + TAN] = m[0] * tx + m[4] * ty + m[8] * tz; out[v + TAN + 1] = m[1] * tx + m[5] * ty + m[9] * tz;
          out[v + TAN + 2] = m[2] * tx + m[6] * ty + m[10] * tz; out[v + TAN + 3] = tangents[4 * i + 3];
        }
        if (colors !== null) { out[v + COL] = colors[3 * i]; out[v + COL + 1] = colors[3 * i + 1]; out[v + COL + 2] = colors[3 * i + 2]; }
      } else {
        // Gouraud lights the vertex; flat lights the face's centroid (flat meshes carry it on
        // each of the triangle's own three vertices, with the face normal: flat.ts).
        let lx = rx, ly = ry, lz = rz;
        if (centroids !== undefined && d.shading === 'flat') {
          const cx = centroids[3 * i], cy = centroids[3 * i + 1], cz = centroids[3 * i + 2];
          lx = m[0] * cx + m[4] * cy + m[8] * cz + m[12] - e[0];
          ly = m[1] * cx + m[5] * cy + m[9] * cz + m[13] - e[1];
          lz = m[2] * cx + m[6] * cy + m[10] * cz + m[14] - e[2];
        }
        const vl = Math.sqrt(lx * lx + ly * ly + lz * lz) || 1;
        const nl = Math.sqrt(wx * wx + wy * wy + wz * wz) || 1;
        const ov = d.view;
        if (ov[3] === 0) setGeometry(this.geometry, lx, ly, lz, wx / nl, wy / nl, wz / nl, ov[0], ov[1], ov[2]);
        else setGeometry(this.geometry, lx, ly, lz, wx / nl, wy / nl, wz / nl, -lx / vl, -ly / vl, -lz / vl);
        blinnPhong(d.lights, d.material, d.twoSided, this.geometry, sums);
        for (let k = 0; k < 6; k++) out[v + k] = sums[k];
      }
      out[v + UV] = hasUvs ? uvs[2 * i] : 0;
      out[v + UV + 1] = hasUvs ? uvs[2 * i + 1] : 0;
      out[v + OBJ] = x; out[v + OBJ + 1] = y; out[v + OBJ + 2] = z;
      out[v + OBJ_N] = ox; out[v + OBJ_N + 1] = oy; out[v + OBJ_N + 2] = oz;
    }
  }

  /** False: cut away by glTF's alpha mask (nothing written; the rasterizer takes its depth back). */
  fragment(pixel: number, r: Rasterizer): boolean {
    const cache = this.cache, entry = cache === null ? 0 : r.pixelOf(pixel);
    if (cache !== null && cache.has(entry, r.face)) {
      const c = cache.rgb, o = 3 * entry;
      this.cr = c[o]; this.cg = c[o + 1]; this.cb = c[o + 2];
      this.repeat(pixel);
      return true;
    }
    const d = this.draw, p = r.poly, b0 = r.b0, b1 = r.b1, b2 = r.b2;
    const i0 = r.o0, i1 = r.o1, i2 = r.o2;
    const sums = this.sums;
    const pbr = d.material.pbr;
    if (this.perPixel) {
      const rx = b0 * p[i0 + REL] + b1 * p[i1 + REL] + b2 * p[i2 + REL];
      const ry = b0 * p[i0 + REL + 1] + b1 * p[i1 + REL + 1] + b2 * p[i2 + REL + 1];
      const rz = b0 * p[i0 + REL + 2] + b1 * p[i1 + REL + 2] + b2 * p[i2 + REL + 2];
      let nx = b0 * p[i0 + NRM] + b1 * p[i1 + NRM] + b2 * p[i2 + NRM];
      let ny = b0 * p[i0 + NRM + 1] + b1 * p[i1 + NRM + 1] + b2 * p[i2 + NRM + 1];
      let nz = b0 * p[i0 + NRM + 2] + b1 * p[i1 + NRM + 2] + b2 * p[i2 + NRM + 2];
      const nl = Math.sqrt(nx * nx + ny * ny + nz * nz);
      if (nl > 0) { nx /= nl; ny /= nl; nz /= nl; }
      const vl = Math.sqrt(rx * rx + ry * ry + rz * rz) || 1, ov = d.view;
      const g = this.geometry;
      g[0] = rx; g[1] = ry; g[2] = rz; g[3] = nx; g[4] = ny; g[5] = nz;
      // V toward the eye point, or (orthographic) the view's own direction.
      if (ov[3] === 0) { g[6] = ov[0]; g[7] = ov[1]; g[8] = ov[2]; } else { g[6] = -rx / vl; g[7] = -ry / vl; g[8] = -rz / vl; }
      if (pbr === undefined) blinnPhong(d.lights, d.material, d.twoSided, g, sums);
    } else {
      for (let k = 0; k < 6; k++) sums[k] = b0 * p[i0 + k] + b1 * p[i1 + k] + b2 * p[i2 + k];
    }
    const tex = this.texture(r);
    if (pbr !== undefined && maskedOut(pbr, d.maps, d.material.mapping === 'uv' ? this.lookup : null)) return false;
    // The 8-bit target's clamp, inline (a helper's double result is boxed when not inlined).
    // Emitted light adds to the lit colour (docs/gltf.md#drawing); without it, nothing is added.
    const e = d.material.emissive;
    let cr: number, cg: number, cb: number;
    if (pbr === undefined) {
      cr = tex[0] * sums[0] + sums[3]; cg = tex[1] * sums[1] + sums[4]; cb = tex[2] * sums[2] + sums[5];
      if (e !== undefined) { cr += e[0]; cg += e[1]; cb += e[2]; }
    } else {
      // A glTF material: its texture is in the base colour, which also sets a metal's F0; its maps read at the UV.
      const t = this.tangent;
      t[3] = 0;
      if (this.tangents && d.maps.normal !== null) {
        for (let k = 0; k < 4; k++) t[k] = b0 * p[i0 + TAN + k] + b1 * p[i1 + TAN + k] + b2 * p[i2 + TAN + k];
        t[3] = t[3] < 0 ? -1 : 1;
      }
      const c = this.color;
      if (this.colors) for (let k = 0; k < 3; k++) c[k] = b0 * p[i0 + COL + k] + b1 * p[i1 + COL + k] + b2 * p[i2 + COL + k];
      else c.fill(1);
      pbrFragment(d.lights, d.material, d.twoSided, this.geometry, d.texture, tex, c, d.maps, t, d.material.mapping === 'uv' ? this.lookup : null, sums);
      cr = sums[0]; cg = sums[1]; cb = sums[2];
    }
    this.cr = cr < 0 ? 0 : cr > this.top ? this.top : cr;
    this.cg = cg < 0 ? 0 : cg > this.top ? this.top : cg;
    this.cb = cb < 0 ? 0 : cb > this.top ? this.top : cb;
    if (cache !== null) cache.set(entry, r.face, this.cr, this.cg, this.cb);
    if (this.codes !== null) {
      // The fragment's world point (the model matrix over its object-space position) and its
      // distance from the plane, coded as distanceCode() does (inline: its double would be boxed).
      const m = d.model, pl = this.codePlane, a = i0 + OBJ, b = i1 + OBJ, c = i2 + OBJ;
      const x = b0 * p[a] + b1 * p[b] + b2 * p[c], y = b0 * p[a + 1] + b1 * p[b + 1] + b2 * p[c + 1];
      const z = b0 * p[a + 2] + b1 * p[b + 2] + b2 * p[c + 2];
      const h = pl[0] * (m[0] * x + m[4] * y + m[8] * z + m[12]) + pl[1] * (m[1] * x + m[5] * y + m[9] * z + m[13])
        + pl[2] * (m[2] * x + m[6] * y + m[10] * z + m[14]) + pl[3];
      this.code = h > 0 ? h / (1 + h) : 0;
    }
    this.repeat(pixel);
    return true;
  }

  /** Writes the last fragment's colour at `sample` (blended by the material's opacity). */
  repeat(sample: number): void {
    const c = this.colour, o = 3 * sample;
    const alpha = this.draw.material.opacity;
    // A transparent fragment writes its distance code as an opaque one does: it writes depth in
    // WebGL, whose codes come from depth; without it, one over the background was no surface to
    // rough glass, and vanished.
    if (this.codes !== null) this.codes[sample] = this.code;
    if (alpha >= 1) {
      c[o] = this.cr; c[o + 1] = this.cg; c[o + 2] = this.cb;
    } else {
      // colour·(1 − kt) + framebuffer·kt (docs/software-renderer.md#transparency), kt = 1 − opacity.
      const a = alpha > 0 ? alpha : 0;
      c[o] = this.cr * a + c[o] * (1 - a);
      c[o + 1] = this.cg * a + c[o + 1] * (1 - a);
      c[o + 2] = this.cb * a + c[o + 2] * (1 - a);
    }
  }

  /** The texture at the fragment through the material's mapping (standard.frag's surfaceTexture). */
  private texture(r: Rasterizer): Float64Array {
    const d = this.draw, p = r.poly, tex = this.tex, t = d.texture;
    const b0 = r.b0, b1 = r.b1, b2 = r.b2, x0 = r.dbdx0, x1 = r.dbdx1, x2 = r.dbdx2, y0 = r.dbdy0, y1 = r.dbdy1, y2 = r.dbdy2;
    const i0 = r.o0, i1 = r.o1, i2 = r.o2;
    const mapping = d.material.mapping;
    if (mapping === 'uv') {
      const a = i0 + UV, b = i1 + UV, c = i2 + UV, l = this.lookup;
      l[0] = b0 * p[a] + b1 * p[b] + b2 * p[c]; l[1] = b0 * p[a + 1] + b1 * p[b + 1] + b2 * p[c + 1];
      l[2] = x0 * p[a] + x1 * p[b] + x2 * p[c]; l[3] = x0 * p[a + 1] + x1 * p[b + 1] + x2 * p[c + 1];
      l[4] = y0 * p[a] + y1 * p[b] + y2 * p[c]; l[5] = y0 * p[a + 1] + y1 * p[b + 1] + y2 * p[c + 1];
      t.sample(l, tex);
      return tex;
    }
    const q = this.q;
    const a = i0 + OBJ, b = i1 + OBJ, c = i2 + OBJ;
    q[0] = b0 * p[a] + b1 * p[b] + b2 * p[c];
    q[1] = b0 * p[a + 1] + b1 * p[b + 1] + b2 * p[c + 1];
    q[2] = b0 * p[a + 2] + b1 * p[b + 2] + b2 * p[c + 2];
    // ∂q/∂x, ∂q/∂y per pixel.
    const dqx = this.dqx, dqy = this.dqy;
    for (let k = 0; k < 3; k++) {
      dqx[k] = x0 * p[a + k] + x1 * p[b + k] + x2 * p[c + k];
      dqy[k] = y0 * p[a + k] + y1 * p[b + k] + y2 * p[c + k];
    }
    const bounds = d.bounds;
    if (mapping === 'triplanar') {
      // mapping.ts's projections and weights; each projection's UV moves by s per unit of its axes.
      const na = i0 + OBJ_N, nb = i1 + OBJ_N, nc = i2 + OBJ_N, n = this.n;
      for (let k = 0; k < 3; k++) n[k] = b0 * p[na + k] + b1 * p[nb + k] + b2 * p[nc + k];
      const w = this.weights, uvs = this.uvs, part = this.part, l = this.lookup;
      triplanarUV(w, uvs, q, n, bounds);
      const s = triplanarScale(bounds);
      tex[0] = tex[1] = tex[2] = 0;
      for (let i = 0; i < 3; i++) {
        if (!(w[i] > 0)) continue;
        const u = TRIPLANAR_U[i], v = TRIPLANAR_V[i];
        setLookup(l, uvs[2 * i], uvs[2 * i + 1], dqx[u] * s, dqx[v] * s, dqy[u] * s, dqy[v] * s);
        t.sample(l, part);
        addScaled(tex, part, w[i]);
      }
      return tex;
    }
    // Cylindrical and spherical: derivatives by one-pixel differences (as dFdx does), with the
    // u seam unwrapped so the seam does not read the smallest mip level.
    const map = mapping === 'cylindrical' ? cylindricalUV : sphericalUV;
    const uv = this.uv0, uv1 = this.uv1;
    map(uv, q, bounds);
    q[0] += dqx[0]; q[1] += dqx[1]; q[2] += dqx[2];
    map(uv1, q, bounds);
    const dudx = wrap(uv1[0] - uv[0]), dvdx = uv1[1] - uv[1];
    q[0] += dqy[0] - dqx[0]; q[1] += dqy[1] - dqx[1]; q[2] += dqy[2] - dqx[2];
    map(uv1, q, bounds);
    const dudy = wrap(uv1[0] - uv[0]), dvdy = uv1[1] - uv[1];
    setLookup(this.lookup, uv[0], uv[1], dudx, dvdx, dudy, dvdy);
    t.sample(this.lookup, tex);
    return tex;
  }
}


/** A difference of u (period 1) taken the short way round. */
const wrap = (du: number): number => du - Math.round(du);

function setLookup(l: Float64Array, u: number, v: number, a: number, b: number, c: number, d: number): void {
  l[0] = u; l[1] = v; l[2] = a; l[3] = b; l[4] = c; l[5] = d;
}

function setGeometry(
  g: Float64Array, px: number, py: number, pz: number, nx: number, ny: number, nz: number, vx: number, vy: number, vz: number,
): void {
  g[0] = px; g[1] = py; g[2] = pz; g[3] = nx; g[4] = ny; g[5] = nz; g[6] = vx; g[7] = vy; g[8] = vz;
}

const addScaled = (out: Float64Array, v: Float64Array, w: number): void => { out[0] += w * v[0]; out[1] += w * v[1]; out[2] += w * v[2]; };
