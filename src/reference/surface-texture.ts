// The texture value at a hit: which texture, which mapping, and a point sample or its footprint's mean.
import { cylindricalUV, sphericalUV, triplanarUV, boundsScale, triplanarScale, TRIPLANAR_U, TRIPLANAR_V } from '../scene/mapping';
import type { Bounds, Material } from '../scene/scene';
import { imageTexture, type ChannelTexture } from './image-texture';
import type { DecodedImage } from '../scene/decoded-image';
import type { Ray } from './ray';
import type { SurfaceHit } from './surface-hit';
import { proceduralGrey, TextureSampler } from './texture-sampler';
import type { ColorSpace } from '../math/srgb';

/** 'point': bilinear at the sample's UV (GL LINEAR at mip 0). 'box': exact mean over its footprint. */
export type TextureFilter = 'point' | 'box';

/** Longest footprint edge, in texels: beyond it (grazing angles, sphere poles) it is shortened. */
export const MAX_FOOTPRINT_TEXELS = 64;

const TWO_PI = 2 * Math.PI;

/**
 * Samples textures for one frame. `singular` is set when a footprint had to be shortened (or
 * could not be formed): the caller marks the sample's key so the region map treats it as an edge.
 */
export class SurfaceTexture {
  singular = false;
  readonly procedural: ChannelTexture;
  private readonly images = new Map<string, ChannelTexture | null>();
  private readonly maps: Record<ColorSpace, Map<string, ChannelTexture | null>> = { srgb: new Map(), none: new Map() };
  private readonly alphas = new Map<string, ChannelTexture | null>();
  private readonly edge1 = new Float64Array(2);
  private readonly edge2 = new Float64Array(2);
  private readonly uv = new Float64Array(2);
  private readonly uvs = new Float64Array(6);
  private readonly weights = new Float64Array(3);
  private readonly gObj1 = new Float64Array(3);
  private readonly gObj2 = new Float64Array(3);
  private readonly gu = new Float64Array(3);
  private readonly gv = new Float64Array(3);
  private readonly part = new Float64Array(3);
  /** A plain material's texture (tex = 1). */
  private white: ChannelTexture | null = null;

  /** Texels are decoded to linear light (srgb) or used as stored (none) when a texture is made. */
  constructor(
    private readonly filter: TextureFilter, private readonly colorSpace: ColorSpace,
    private readonly decoded: ReadonlyMap<string, DecodedImage> = new Map(),
  ) {
    const sampler = new TextureSampler(proceduralGrey(colorSpace));
    this.procedural = { channels: [sampler], width: sampler.width, height: sampler.height };
  }

  /** An image texture by URL, decoded once; the procedural texture when it is missing or malformed. */
  textureOf(material: Material): ChannelTexture {
    const source = material.texture;
    if (source.kind === 'none') return this.plain();
    if (source.kind !== 'image') return this.procedural;
    let tex = this.images.get(source.url);
    if (tex === undefined) {
      const image = this.decoded.get(source.url);
      tex = image === undefined ? null : imageTexture(image, this.colorSpace);
      this.images.set(source.url, tex);
    }
    return tex ?? (source.fallback === 'none' ? this.plain() : this.procedural);
  }

  /**
   * A glTF map's image by URL at the hit's UV (TEXCOORD_0) moved by its transform `m` (u' = a·u + b·v + c, v' = d·u + e·v + f;
   * null: none) into `out` (docs/gltf.md#drawing): decoded to linear light when it is `colour` in an srgb frame, as stored
   * otherwise; null when its image is missing or malformed (the factor alone).
   */
  mapAt(url: string, colour: boolean | 'alpha', m: readonly number[] | null, hit: SurfaceHit, ray: Ray, out: Float64Array): Float64Array | null {
    // 'alpha': the image's alpha channel as stored, in out[0..2] (glTF's alpha mask, docs/gltf.md#alpha).
    const space = colour === true ? this.colorSpace : 'none', built = colour === 'alpha' ? this.alphas : this.maps[space];
    let tex = built.get(url);
    // Stryker disable next-line ConditionalExpression: decoding it again gives the same texture (the cache saves the time)
    if (tex === undefined) {
      const image = this.decoded.get(url);
      tex = image === undefined ? null : imageTexture(image, space, colour === 'alpha');
      built.set(url, tex);
    }
    if (tex === null) return null;
    if (m === null) return this.sample(tex, hit.u, hit.v, hit.gu, hit.gv, hit, ray, out);
    // The gradients move with the map's linear part: ∇u' = a∇u + b∇v, ∇v' = d∇u + e∇v.
    const { gu, gv } = this;
    // Stryker disable next-line EqualityOperator: k = 3 writes past the end of gu and gv (Float64Array(3)): dropped
    for (let k = 0; k < 3; k++) {
      gu[k] = m[0] * hit.gu[k] + m[1] * hit.gv[k];
      gv[k] = m[3] * hit.gu[k] + m[4] * hit.gv[k];
    }
    return this.sample(tex, m[0] * hit.u + m[1] * hit.v + m[2], m[3] * hit.u + m[4] * hit.v + m[5], gu, gv, hit, ray, out);
  }

  /** 1×1 white: no texture. */
  private plain(): ChannelTexture {
    return (this.white ??= imageTexture({ width: 1, height: 1, data: new Uint8Array([255, 255, 255, 255]) }, this.colorSpace)!);
  }

  /** The texture (RGB, 0..1, linear light with srgb) of `material` at an object hit, through its mapping, into `out`. */
  objectTexture(hit: SurfaceHit, ray: Ray, material: Material, bounds: Bounds, out: Float64Array): Float64Array {
    const tex = this.textureOf(material);
    const frame = hit.frame!;
    const { uv, gObj1: g1, gObj2: g2, gu, gv } = this;
    switch (material.mapping) {
      case 'uv':
        return this.sample(tex, hit.u, hit.v, hit.gu, hit.gv, hit, ray, out);
      case 'cylindrical': {
        cylindricalUV(uv, hit.q, bounds);
        // Stryker disable next-line ConditionalExpression: the point filter does not read the gradients
        if (this.filter === 'box') {
          const c = bounds.center, x = hit.q[0] - c[0], z = hit.q[2] - c[2];
          const rho2 = x * x + z * z;
          g1[0] = z / (TWO_PI * rho2); g1[1] = 0; g1[2] = -x / (TWO_PI * rho2);
          g2[0] = 0; g2[1] = 1 / (2 * boundsScale(bounds)); g2[2] = 0;
          frame.gradientToWorld(gu, g1);
          frame.gradientToWorld(gv, g2);
        }
        return this.sample(tex, uv[0], uv[1], gu, gv, hit, ray, out);
      }
      case 'spherical': {
        sphericalUV(uv, hit.q, bounds);
        // Stryker disable next-line ConditionalExpression: the point filter does not read the gradients
        if (this.filter === 'box') {
          const c = bounds.center;
          const dx = hit.q[0] - c[0], dy = hit.q[1] - c[1], dz = hit.q[2] - c[2];
          const rho2 = dx * dx + dz * dz, r2 = rho2 + dy * dy, rho = Math.sqrt(rho2);
          // ∂u/∂q = (dz, 0, −dx)/(2π ρ²); ∂v/∂q = (e_y − (d.y/|d|²)·d)/(π ρ).
          g1[0] = dz / (TWO_PI * rho2); g1[1] = 0; g1[2] = -dx / (TWO_PI * rho2);
          const k = dy / r2;
          g2[0] = -k * dx / (Math.PI * rho); g2[1] = (1 - k * dy) / (Math.PI * rho); g2[2] = -k * dz / (Math.PI * rho);
          frame.gradientToWorld(gu, g1);
          frame.gradientToWorld(gv, g2);
        }
        return this.sample(tex, uv[0], uv[1], gu, gv, hit, ray, out);
      }
      case 'triplanar': {
        const { uvs, weights: w, part } = this;
        triplanarUV(w, uvs, hit.q, hit.nq, bounds);
        const s = triplanarScale(bounds);
        out[0] = out[1] = out[2] = 0;
        // Projection i reads (q[A[i]], q[B[i]]): its gradients are the constant axes e_A/2r, e_B/2r.
        // Stryker disable next-line EqualityOperator: at i = 3 the weight w[3] is undefined, and !(undefined > 0) skips it
        for (let i = 0; i < 3; i++) {
          if (!(w[i] > 0)) continue;
          g1.fill(0); g2.fill(0);
          g1[TRIPLANAR_U[i]] = s; g2[TRIPLANAR_V[i]] = s;
          frame.gradientToWorld(gu, g1);
          frame.gradientToWorld(gv, g2);
          this.sample(tex, uvs[2 * i], uvs[2 * i + 1], gu, gv, hit, ray, part);
          for (let k = 0; k < 3; k++) out[k] += w[i] * part[k];
        }
        return out;
      }
    }
  }

  /** The procedural grey at the glass's own UV (docs/default-scene.md#texture-coordinates: the glass is textured too). */
  glassTexture(hit: SurfaceHit, ray: Ray): number {
    return this.sample(this.procedural, hit.u, hit.v, hit.gu, hit.gv, hit, ray, this.part)[0];
  }

  /**
   * `tex` at (u, v) with world gradients gu, gv: a bilinear point sample, or the exact mean over
   * the sample's footprint (its ray differentials moved onto the tangent plane at the hit).
   */
  private sample(
    tex: ChannelTexture, u: number, v: number, gu: Float64Array, gv: Float64Array, hit: SurfaceHit, ray: Ray, out: Float64Array,
  ): Float64Array {
    const channels = tex.channels;
    if (this.filter === 'point') return bilinearInto(channels, u, v, out);
    const d = ray.direction, n = hit.ng, t = hit.t;
    const dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    if (dn === 0) {
      this.singular = true;
      return bilinearInto(channels, u, v, out);
    }
    // ∂p = q − (q·n)/(d·n)·d with q = ∂o + t·∂d: the differential moved onto the tangent plane at the hit.
    const a = this.edge1, b = this.edge2;
    if (footprintEdge(ray.ddx, ray.odx, d, n, dn, t, gu, gv, tex, a)) this.singular = true;
    if (footprintEdge(ray.ddy, ray.ody, d, n, dn, t, gu, gv, tex, b)) this.singular = true;
    if (channels.length === 1) {
      out[0] = out[1] = out[2] = channels[0].boxFilter(u, v, a[0], a[1], b[0], b[1]);
    } else {
      for (let k = 0; k < 3; k++) out[k] = channels[k].boxFilter(u, v, a[0], a[1], b[0], b[1]);
    }
    return out;
  }
}

function bilinearInto(channels: readonly TextureSampler[], u: number, v: number, out: Float64Array): Float64Array {
  if (channels.length === 1) {
    out[0] = out[1] = out[2] = channels[0].bilinear(u, v);
  } else {
    for (let k = 0; k < 3; k++) out[k] = channels[k].bilinear(u, v);
  }
  return out;
}

/** One footprint edge in texels (s, t) into `out`; true when it had to be shortened to MAX_FOOTPRINT_TEXELS. */
function footprintEdge(
  dd: Float64Array, od: Float64Array, d: Float64Array, n: Float64Array, dn: number, t: number,
  gu: Float64Array, gv: Float64Array, tex: ChannelTexture, out: Float64Array,
): boolean {
  // Written so a zero ∂o (perspective) adds exact zeros: the same figures as before it existed.
  const k = (t * (dd[0] * n[0] + dd[1] * n[1] + dd[2] * n[2]) + (od[0] * n[0] + od[1] * n[1] + od[2] * n[2])) / dn;
  let es = 0, et = 0;
  for (let i = 0; i < 3; i++) {
    const dp = t * dd[i] + od[i] - k * d[i];
    es += gu[i] * dp;
    et += gv[i] * dp;
  }
  es *= tex.width;
  et *= tex.height;
  const len = Math.hypot(es, et);
  if (len <= MAX_FOOTPRINT_TEXELS) {
    out[0] = es;
    out[1] = et;
    return false;
  }
  // NaN/Infinity (a degenerate mapping) end up as NaN, which boxFilter treats as zero area.
  out[0] = (es * MAX_FOOTPRINT_TEXELS) / len;
  out[1] = (et * MAX_FOOTPRINT_TEXELS) / len;
  return true;
}
