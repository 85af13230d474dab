// The glass rectangle on the CPU (shaders/glass.vert + glass.frag): its footprint (which pixels
// the reflection pass must fill), the glass equation of docs/rendering.md#the-glass-equation over what is behind it, or F.
import { fresnel, type FresnelModel } from '../math/fresnel';
import { GLASS_BODY as BODY } from '../scene/default-scene';
import type { GlassFrame } from '../scene/glass-frame';
import type { MipTexture } from './mip-texture';
import type { RoughGather } from './rough-gather';
import { GlassCache, GLASS_KEY_LENGTH } from './glass-cache';
import { CLIP_DISTANCE, VARYINGS, type FragmentShader, type Rasterizer } from './raster';

// Varyings: eye-relative position, UV.
const REL = 0, UV = 3;
const STRIDE = VARYINGS + 5;

/** How far (NDC depth) the glass is pushed back; objects on the plane or beyond it go twice as far. */
export const GLASS_TIE_BIAS = 1e-6;

export type GlassMode = 'mask' | 'compose' | 'fresnel';

export class GlassShader implements FragmentShader {
  mode: GlassMode = 'compose';
  /** The pixels the glass covers (mode 'mask' sets them to 1). */
  mask: Uint8Array = new Uint8Array(0);
  /** What pass 2 left (B), composed over in place; the reflection (R), same grid. */
  colour: Float32Array = new Float32Array(0);
  reflection: Float32Array = new Float32Array(0);
  model: FresnelModel = 'exact';
  ior = 1.5;
  transparency = 0.5;
  /** What R and the result are held to: 1 as 8-bit targets, Infinity in a tone-mapped frame (docs/pbr.md#tone-mapping). */
  top = 1;
  texture!: MipTexture;
  /** Rough glass (docs/rough-glass.md#the-gather): R̃ (and B̃ with `roughTransmission`) gathered once per pixel; null: polished. */
  rough: RoughGather | null = null;
  roughTransmission = false;
  private readonly rel = new Float64Array(3);
  private readonly rr = new Float64Array(3);
  private readonly rb = new Float64Array(3);
  /** Whether this pixel's R̃ / B̃ were gathered (else its samples keep their own R / B). */
  // Stryker disable next-line BooleanLiteral: fragment() sets it before composeRough() reads it (a rough glass is never cached)
  private hasR = false;
  // Stryker disable next-line BooleanLiteral: fragment() sets it before composeRough() reads it (a rough glass is never cached)
  private hasB = false;
  /** The frame's view vector (FrameSetup.viewVectorMain): w = 0, orthographic, xyz toward the eye. */
  // Stryker disable next-line ArrayDeclaration: setup() sets it before draw() reads it
  private view: ArrayLike<number> = [0, 0, 0, 1];
  /** The glass's unit normal. */
  private nx = 0;
  private ny = 0;
  private nz = 1;
  private readonly vertices = new Float64Array(4 * STRIDE);
  private readonly tex = new Float64Array(3);
  private cos = 1;
  private f = 0;
  private readonly lookup = new Float64Array(6);
  /** F and the texel per pixel from the frames before (the camera and glass still); this frame's key. */
  private readonly cache = new GlassCache();
  private readonly key = new Float64Array(GLASS_KEY_LENGTH);
  // Stryker disable next-line ArrayDeclaration: beginCache() empties it before filling it
  private readonly keyObjects: unknown[] = [];

  /**
   * Vertex stage of the glass rectangle (its float64 corners, u along its width, v along its
   * height, as rectangle.ts builds it) seen from `eye` through `viewProjection` (eye-relative →
   * clip); call once per frame before `draw`.
   */
  setup(frame: GlassFrame, eye: ArrayLike<number>, viewProjection: Float64Array, view: ArrayLike<number>): void {
    this.view = view;
    this.nx = frame.plane[0]; this.ny = frame.plane[1]; this.nz = frame.plane[2];
    const vp = viewProjection, out = this.vertices, uvs = CORNER_UV;
    for (let i = 0; i < 4; i++) {
      const o = i * STRIDE, v = o + VARYINGS, p = frame.corners[i];
      const rx = p[0] - eye[0], ry = p[1] - eye[1], rz = p[2] - eye[2];
      out[o] = vp[0] * rx + vp[4] * ry + vp[8] * rz + vp[12];
      out[o + 1] = vp[1] * rx + vp[5] * ry + vp[9] * rz + vp[13];
      out[o + 2] = vp[2] * rx + vp[6] * ry + vp[10] * rz + vp[14];
      out[o + 3] = vp[3] * rx + vp[7] * ry + vp[11] * rz + vp[15];
      out[o + CLIP_DISTANCE] = 0;
      out[v + REL] = rx; out[v + REL + 1] = ry; out[v + REL + 2] = rz;
      out[v + UV] = uvs[2 * i]; out[v + UV + 1] = uvs[2 * i + 1];
    }
  }

  /** Rasterizes the glass with `r` (depth-tested, no depth write, pushed back a hair). */
  draw(r: Rasterizer, indices: ArrayLike<number>): void {
    r.stride = STRIDE;
    r.userClip = false;
    r.cull = 'none';
    r.derivatives = this.mode === 'compose';
    // Stryker disable next-line ConditionalExpression,EqualityOperator,StringLiteral: on in 'mask' only computes b for a fragment that reads none; off, fragment() calls perspective() itself before reading b
    r.barycentrics = this.mode !== 'mask';
    r.depthTest = true;
    r.depthWrite = false;
    // Pushed back a hair (glass-pass.ts's polygonOffset): a face of an object on the viewer's side
    // in the glass plane stays in front — well above rounding, far below any real depth step;
    // objects on the plane or beyond it are pushed back twice as far (software-renderer.ts), so
    // the glass covers their faces there.
    r.depthBias = GLASS_TIE_BIAS;
    if (this.mode !== 'mask') this.beginCache(r);
    // With the cache in use, a pixel's barycentrics are computed only when it is not cached.
    // Stryker disable next-line ConditionalExpression,LogicalOperator,EqualityOperator,BooleanLiteral: barycentrics off only defers perspective() to fragment(), which calls it before reading b (a cached pixel reads none)
    if (this.cache.active && this.rough === null) r.barycentrics = false;
    try {
      r.drawTriangles(this.vertices, indices, indices.length, this);
    } finally {
      r.depthBias = 0;
      r.barycentrics = true;
    }
  }

  /**
   * Keeps the cache's entries when everything a pixel's F and texel depend on is as in the last
   * frame: the vertices (clip position, eye-relative point, UV), the view vector, the normal,
   * ior, the grid, and the model, texture and mode. The rough glass gathers per frame: no cache.
   */
  private beginCache(r: Rasterizer): void {
    const k = this.key, v = this.view, n = r.shadeEvery;
    if (this.rough !== null) {
      this.cache.clear();
      return;
    }
    k.set(this.vertices);
    let i = this.vertices.length;
    for (let c = 0; c < 4; c++) k[i++] = v[c];
    k[i++] = this.nx; k[i++] = this.ny; k[i++] = this.nz;
    k[i++] = this.ior; k[i++] = r.width; k[i++] = r.height; k[i++] = n;
    const o = this.keyObjects;
    o.length = 0;
    o.push(this.model, this.texture, this.mode);
    this.cache.begin(k, o, (r.width / n) * (r.height / n));
  }

  /**
   * this.f = F(this.cos): through fields, because a double returned by a call that is not
   * inlined is boxed, and this one (in a large fragment function) was half the frame's garbage.
   */
  private fresnel(): void {
    this.f = fresnel(this.model, this.cos, this.ior);
  }

  fragment(pixel: number, r: Rasterizer): void {
    if (this.mode === 'mask') {
      this.mask[pixel] = 1;
      return;
    }
    // The cache's entry: the pixel (of a multisampled grid: its n×n samples) and which sample.
    const cache = this.cache, n = r.shadeEvery, rough = this.rough;
    let entry = pixel, slot = 0;
    if (n > 1) {
      const W = r.width, y = (pixel / W) | 0, x = pixel - y * W;
      entry = ((y / n) | 0) * (W / n) + ((x / n) | 0);
      slot = (y % n) * n + (x % n);
    }
    const cached = rough === null && cache.active;
    if (cached && cache.has(entry, slot)) {
      this.f = cache.f[entry];
      this.tex[0] = cache.texel[entry];
      this.repeat(pixel);
      return;
    }
    if (!r.barycentrics) r.perspective();
    const p = r.poly, b0 = r.b0, b1 = r.b1, b2 = r.b2, i0 = r.o0, i1 = r.o1, i2 = r.o2;
    const rx = b0 * p[i0 + REL] + b1 * p[i1 + REL] + b2 * p[i2 + REL];
    const ry = b0 * p[i0 + REL + 1] + b1 * p[i1 + REL + 1] + b2 * p[i2 + REL + 1];
    const rz = b0 * p[i0 + REL + 2] + b1 * p[i1 + REL + 2] + b2 * p[i2 + REL + 2];
    // Two-sided: cosθ = |N·V|, clamped to [0, 1]; V from the eye, or (orthographic) the view's.
    const v = this.view, vx = v[3] === 0 ? v[0] : rx, vy = v[3] === 0 ? v[1] : ry, vz = v[3] === 0 ? v[2] : rz;
    const len = Math.sqrt(vx * vx + vy * vy + vz * vz);
    const c = len > 0 ? Math.abs(this.nx * vx + this.ny * vy + this.nz * vz) / len : 1;
    this.cos = c > 1 ? 1 : c;
    this.fresnel();
    if (this.mode === 'compose') {
      const ua = i0 + UV, ub = i1 + UV, uc = i2 + UV, l = this.lookup;
      l[0] = b0 * p[ua] + b1 * p[ub] + b2 * p[uc];
      l[1] = b0 * p[ua + 1] + b1 * p[ub + 1] + b2 * p[uc + 1];
      l[2] = r.dbdx0 * p[ua] + r.dbdx1 * p[ub] + r.dbdx2 * p[uc];
      l[3] = r.dbdx0 * p[ua + 1] + r.dbdx1 * p[ub + 1] + r.dbdx2 * p[uc + 1];
      l[4] = r.dbdy0 * p[ua] + r.dbdy1 * p[ub] + r.dbdy2 * p[uc];
      l[5] = r.dbdy0 * p[ua + 1] + r.dbdy1 * p[ub + 1] + r.dbdy2 * p[uc + 1];
      this.texture.sample(l, this.tex);
      if (rough !== null) {
        const rel = this.rel;
        rel[0] = rx; rel[1] = ry; rel[2] = rz;
        this.hasR = rough.gather(this.rr, rel, 0);
        this.hasB = this.roughTransmission && rough.gather(this.rb, rel, 1);
      }
    }
    if (cached) cache.set(entry, slot, this.f, this.tex[0]);
    this.repeat(pixel);
  }

  /**
   * The last fragment's F and texel at `sample`: the footprint, F, or the glass equation over
   * what that sample holds and the reflection there (a pixel's samples keep their own B and R).
   */
  repeat(sample: number): void {
    const mode = this.mode;
    if (mode === 'mask') {
      this.mask[sample] = 1;
      return;
    }
    const f = this.f, o = 3 * sample, out = this.colour;
    if (mode === 'fresnel') {
      out[o] = out[o + 1] = out[o + 2] = f;
      return;
    }
    if (this.rough !== null) {
      this.composeRough(sample);
      return;
    }
    const tex = this.tex[0], t = this.transparency, refl = this.reflection, top = this.top;
    if (this.model === 'classic') {
      // Classic, the original prototype's glass verbatim: colour = mix(D, R, F), alpha = (1 − T)(0.2 + 0.8F), straight alpha.
      const a = (1 - t) * (0.2 + 0.8 * f);
      for (let k = 0; k < 3; k++) {
        const d = tex * BODY[k], rk = Math.min(refl[o + k], top);
        const x = (d + (rk - d) * f) * a + out[o + k] * (1 - a);
        out[o + k] = x < 0 ? 0 : x > top ? top : x; // inline: a helper's double result is boxed
      }
      return;
    }
    // out = F·R + (1 − F)·(T·B + (1 − T)·D), R clamped as the 8-bit reflection target holds it (top 1; a tone-mapped frame: Infinity).
    for (let k = 0; k < 3; k++) {
      const d = tex * BODY[k], rk = Math.min(refl[o + k], top);
      const x = f * rk + (1 - f) * (t * out[o + k] + (1 - t) * d);
      out[o + k] = x < 0 ? 0 : x > top ? top : x;
    }
  }

  /** repeat()'s glass equation with the pixel's R̃ and B̃ in place of each sample's R and B. */
  private composeRough(sample: number): void {
    const f = this.f, o = 3 * sample, out = this.colour, refl = this.reflection;
    const tex = this.tex[0], t = this.transparency, rr = this.rr, rb = this.rb, hasR = this.hasR, hasB = this.hasB, top = this.top;
    const classic = this.model === 'classic', a = (1 - t) * (0.2 + 0.8 * f);
    for (let k = 0; k < 3; k++) {
      const d = tex * BODY[k], rk = Math.min(hasR ? rr[k] : refl[o + k], top), b = hasB ? rb[k] : out[o + k];
      const x = classic ? (d + (rk - d) * f) * a + b * (1 - a) : f * rk + (1 - f) * (t * b + (1 - t) * d);
      out[o + k] = x < 0 ? 0 : x > top ? top : x;
    }
  }
}

const CORNER_UV = [0, 0, 1, 0, 1, 1, 0, 1];

export const GLASS_INDICES = new Uint16Array([0, 1, 2, 0, 2, 3]);
