// A one-channel texture as a continuous function: bilinear point samples, or its exact box filter.
import { proceduralTexture } from '../scene/procedural-texture';
import { TEXTURE_SIZE } from '../scene/default-scene';
import { SRGB_BYTE_TO_LINEAR, type ColorSpace } from '../math/srgb';

/** b / 255 for every 8-bit level b: a byte used as stored. */
const AS_STORED: Float64Array = Float64Array.from({ length: 256 }, (_, b) => b / 255);

/**
 * What a stored 8-bit level means in `colorSpace` (docs/colour.md#srgb), by level: linear light decoded
 * from sRGB, or b / 255 as stored. Texels are looked up here before any filtering, so bilinear
 * and box filtering sum light, not encoded numbers.
 */
export function byteLevels(colorSpace: ColorSpace): Float64Array {
  return colorSpace === 'srgb' ? SRGB_BYTE_TO_LINEAR : AS_STORED;
}

/** The procedural texture's grey levels (docs/default-scene.md#the-procedural-texture: 200/255, 100/255 and noise are encoded levels). */
export function proceduralGrey(colorSpace: ColorSpace): Float64Array {
  const rgba = proceduralTexture();
  const levels = byteLevels(colorSpace);
  const grey = new Float64Array(TEXTURE_SIZE * TEXTURE_SIZE);
  // Stryker disable next-line EqualityOperator: i = grey.length writes past the end of grey: dropped
  for (let i = 0; i < grey.length; i++) grey[i] = levels[rgba[i * 4]];
  return grey;
}

/**
 * The texture is the bilinear reconstruction of its W×H texels (what GL LINEAR shows when
 * magnified), repeating; by default the 512×512 procedural texture of docs/default-scene.md#the-procedural-texture. Coordinates
 * here are "texel-centre space": σ = u·W − ½, τ = v·H − ½, so texel (i, j) sits at (i, j) and
 * each unit cell [i, i+1]×[j, j+1] holds one bilinear patch a + b·x + c·y + d·xy of its four
 * corner texels. Row j = 0 is the first row uploaded (v = 0).
 *
 * `boxFilter` integrates that function exactly over a parallelogram (the sample's footprint
 * mapped to texture space) by clipping it against every cell it covers and integrating the
 * patch over each piece with Green's theorem. Values are grey levels in 0..1 (R = G = B): linear
 * light when the colour space is srgb (byteLevels), so filtering mixes light.
 */
export class TextureSampler {
  private readonly grey: Float64Array;
  readonly width: number;
  readonly height: number;
  /** W − 1 and H − 1 when powers of two (REPEAT by masking), else −1 (REPEAT by remainder). */
  private readonly maskX: number;
  private readonly maskY: number;
  // Clip buffers (x, y interleaved): a parallelogram clipped by two slabs has ≤ 8 vertices.
  private readonly polygon = new Float64Array(16);
  private readonly strip = new Float64Array(24);
  private readonly half = new Float64Array(24);
  private readonly piece = new Float64Array(24);

  /** `grey`: W×H values in 0..1, row by row; absent, the procedural texture's grey levels as stored. */
  constructor(grey?: Float64Array, width = TEXTURE_SIZE, height = TEXTURE_SIZE) {
    if (grey === undefined) {
      // Stryker disable next-line StringLiteral: any colour space but 'srgb' reads the bytes as stored, as 'none' does
      grey = proceduralGrey('none');
      width = height = TEXTURE_SIZE;
    }
    this.grey = grey;
    this.width = width;
    this.height = height;
    // Stryker disable next-line ConditionalExpression: the mask is a faster remainder: −1 gives the same texels
    this.maskX = (width & (width - 1)) === 0 ? width - 1 : -1;
    // Stryker disable next-line ConditionalExpression: the mask is a faster remainder: −1 gives the same texels
    this.maskY = (height & (height - 1)) === 0 ? height - 1 : -1;
  }

  /** Texel (x, y) wrapped, 0..1. */
  texel(x: number, y: number): number {
    const W = this.width, H = this.height;
    // Stryker disable next-line ConditionalExpression, EqualityOperator: the mask is a faster remainder: the remainder gives the same texel
    const i = this.maskX >= 0 ? x & this.maskX : ((x % W) + W) % W;
    // Stryker disable next-line ConditionalExpression, EqualityOperator: the mask is a faster remainder: the remainder gives the same texel
    const j = this.maskY >= 0 ? y & this.maskY : ((y % H) + H) % H;
    return this.grey[j * W + i];
  }

  /** GL LINEAR at mip 0 with REPEAT, in float64. */
  bilinear(u: number, v: number): number {
    const s = u * this.width - 0.5;
    const t = v * this.height - 0.5;
    const i = Math.floor(s);
    const j = Math.floor(t);
    const x = s - i;
    const y = t - j;
    const t00 = this.texel(i, j), t10 = this.texel(i + 1, j), t01 = this.texel(i, j + 1), t11 = this.texel(i + 1, j + 1);
    return t00 + (t10 - t00) * x + (t01 - t00) * y + (t11 - t10 - t01 + t00) * x * y;
  }

  /**
   * Mean of the texture over the parallelogram centred at UV (u, v) with edge vectors
   * (e1s, e1t) and (e2s, e2t) in texels. Degenerate (zero-area) footprints fall back to
   * `bilinear`.
   */
  boxFilter(u: number, v: number, e1s: number, e1t: number, e2s: number, e2t: number): number {
    const area = e1s * e2t - e1t * e2s; // signed: clipping keeps the orientation
    const cs = u * this.width - 0.5;
    const ct = v * this.height - 0.5;
    if (!(Math.abs(area) > 1e-12)) return this.bilinear(u, v);
    const hs1 = e1s / 2, ht1 = e1t / 2, hs2 = e2s / 2, ht2 = e2t / 2;
    const p = this.polygon;
    p[0] = cs - hs1 - hs2; p[1] = ct - ht1 - ht2;
    p[2] = cs + hs1 - hs2; p[3] = ct + ht1 - ht2;
    p[4] = cs + hs1 + hs2; p[5] = ct + ht1 + ht2;
    p[6] = cs - hs1 + hs2; p[7] = ct - ht1 + ht2;
    const sMin = Math.min(p[0], p[2], p[4], p[6]);
    const sMax = Math.max(p[0], p[2], p[4], p[6]);
    // Stryker disable next-line MethodExpression: only floor(tMin) = floor(tMax) is asked, the same either way round
    const tMin = Math.min(p[1], p[3], p[5], p[7]);
    // Stryker disable next-line MethodExpression: only floor(tMin) = floor(tMax) is asked, the same either way round
    const tMax = Math.max(p[1], p[3], p[5], p[7]);
    const i0 = Math.floor(sMin), i1 = Math.floor(sMax);
    const j0 = Math.floor(tMin), j1 = Math.floor(tMax);
    if (i0 === i1 && j0 === j1) {
      // One patch: the mean of a + bx + cy + dxy over a parallelogram is exact in closed form.
      const x = cs - i0, y = ct - j0;
      return this.patchMean(i0, j0, x, y, x * y + (e1s * e1t + e2s * e2t) / 12);
    }
    let sum = 0;
    for (let i = i0; i <= i1; i++) {
      let n = clip(p, 4, 0, i, 1, this.half);
      n = clip(this.half, n, 0, i + 1, -1, this.strip);
      // Stryker disable next-line ConditionalExpression: a strip of < 3 vertices yields only pieces of < 3 vertices, skipped below
      if (n < 3) continue;
      let lo = Infinity, hi = -Infinity;
      // Stryker disable next-line EqualityOperator: k is odd, so k ≤ 2n stops where k < 2n does
      for (let k = 1; k < 2 * n; k += 2) { lo = Math.min(lo, this.strip[k]); hi = Math.max(hi, this.strip[k]); }
      for (let j = Math.floor(lo), jEnd = Math.floor(hi); j <= jEnd; j++) {
        let m = clip(this.strip, n, 1, j, 1, this.half);
        m = clip(this.half, m, 1, j + 1, -1, this.piece);
        // Stryker disable next-line ConditionalExpression: a piece of fewer than 3 vertices has zero area and zero moments: it adds 0
        if (m >= 3) sum += this.patchIntegral(i, j, this.piece, m);
      }
    }
    return sum / area;
  }

  /** Mean of patch (i, j) given the means of x, y and xy (local coordinates) over a region. */
  private patchMean(i: number, j: number, mx: number, my: number, mxy: number): number {
    const t00 = this.texel(i, j), t10 = this.texel(i + 1, j), t01 = this.texel(i, j + 1), t11 = this.texel(i + 1, j + 1);
    return t00 + (t10 - t00) * mx + (t01 - t00) * my + (t11 - t10 - t01 + t00) * mxy;
  }

  /** Signed ∫ of patch (i, j) over a polygon, from its moments ∫1, ∫x, ∫y, ∫xy (Green's theorem). */
  private patchIntegral(i: number, j: number, q: Float64Array, n: number): number {
    let a = 0, mx = 0, my = 0, mxy = 0;
    for (let k = 0; k < n; k++) {
      const k2 = k + 1 === n ? 0 : k + 1;
      const x0 = q[2 * k] - i, y0 = q[2 * k + 1] - j;
      const x1 = q[2 * k2] - i, y1 = q[2 * k2 + 1] - j;
      const c = x0 * y1 - x1 * y0;
      a += c;
      mx += (x0 + x1) * c;
      my += (y0 + y1) * c;
      mxy += (x0 * y1 + 2 * x0 * y0 + 2 * x1 * y1 + x1 * y0) * c;
    }
    a /= 2; mx /= 6; my /= 6; mxy /= 24;
    const t00 = this.texel(i, j), t10 = this.texel(i + 1, j), t01 = this.texel(i, j + 1), t11 = this.texel(i + 1, j + 1);
    return t00 * a + (t10 - t00) * mx + (t01 - t00) * my + (t11 - t10 - t01 + t00) * mxy;
  }
}

/**
 * Sutherland–Hodgman against one axis-aligned line: keeps points with
 * sign·(coordinate[axis] − bound) ≥ 0. Returns the vertex count written to `out`.
 */
function clip(src: Float64Array, n: number, axis: 0 | 1, bound: number, sign: 1 | -1, out: Float64Array): number {
  let m = 0;
  for (let k = 0; k < n; k++) {
    const k2 = k + 1 === n ? 0 : k + 1;
    const ax = src[2 * k], ay = src[2 * k + 1];
    const bx = src[2 * k2], by = src[2 * k2 + 1];
    const da = sign * ((axis === 0 ? ax : ay) - bound);
    const db = sign * ((axis === 0 ? bx : by) - bound);
    if (da >= 0) { out[2 * m] = ax; out[2 * m + 1] = ay; m++; }
    if ((da >= 0) !== (db >= 0)) {
      const f = da / (da - db);
      // Snap the crossing onto the line exactly so neighbouring cells share their edge.
      // Stryker disable next-line ConditionalExpression: the crossing interpolated lies on the line up to rounding
      out[2 * m] = axis === 0 ? bound : ax + f * (bx - ax);
      // Stryker disable next-line ConditionalExpression: the crossing interpolated lies on the line up to rounding
      out[2 * m + 1] = axis === 1 ? bound : ay + f * (by - ay);
      m++;
    }
  }
  return m;
}
