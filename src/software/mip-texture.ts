// A texture as the GPU samples it, in float: a 2×2-box mip chain, REPEAT, trilinear
// (LINEAR_MIPMAP_LINEAR) with the isotropic LOD of the GL spec, from UV derivatives per pixel.
// With `srgb` (docs/colour.md#srgb) the 8-bit texels are decoded to linear light before the chain is built,
// as an SRGB8_ALPHA8 texture is on the GPU: mips and filtering then average light; and reads are
// anisotropic, as the WebGL renderer's srgb textures are (EXT_texture_filter_anisotropic, up to
// 16 taps): closer to the mean over each pixel's footprint that the reference takes than one
// isotropic level, which blurs a surface seen at a slant. `none` keeps isotropic reads, so its
// frames stay what they were.
import { SRGB_BYTE_TO_LINEAR, type ColorSpace } from '../math/srgb';
import { TEXTURE_SIZE } from '../scene/default-scene';
import { proceduralTexture } from '../scene/procedural-texture';
import type { DecodedImage } from '../scene/decoded-image';

interface Level {
  width: number;
  height: number;
  /** `channels` floats per texel, 0..1, row 0 at v = 0. */
  data: Float32Array;
}

/** Most taps an anisotropic read takes: the WebGL renderer's min(16, MAX_TEXTURE_MAX_ANISOTROPY_EXT). */
export const MAX_ANISOTROPY = 16;

export class MipTexture {
  readonly levels: Level[] = [];

  /**
   * `data`: width×height texels of `channels` floats (1: grey, 3: RGB), row 0 at v = 0.
   * `anisotropic`: read with up to MAX_ANISOTROPY taps along the footprint's major axis.
   */
  constructor(readonly channels: 1 | 3, width: number, height: number, data: Float32Array, readonly anisotropic = false) {
    let level: Level = { width, height, data };
    this.levels.push(level);
    while (level.width > 1 || level.height > 1) {
      level = halve(level, channels);
      this.levels.push(level);
    }
  }

  /**
   * The texture into out[0..2] (grey is copied to all three) at a = [u, v, ∂u/∂x, ∂v/∂x, ∂u/∂y,
   * ∂v/∂y] (screen derivatives per pixel), LOD λ = log2(max(|∂(s,t)/∂x|, |∂(s,t)/∂y|)) in base
   * texels. Arguments come in an array: doubles passed to a call that is not inlined are boxed,
   * which at one call per pixel was most of the frame's garbage.
   *
   * Anisotropic, EXT_texture_filter_anisotropic as SwiftShader (the WebGL renderer's GPU here)
   * implements it: with Pmax the longer derivative vector in texels and the anisotropy
   * r = min(Pmax² / |det(∂(s,t)/∂x, ∂(s,t)/∂y)|, MAX_ANISOTROPY) (Pmax over the footprint's width
   * across it), N = round(r) trilinear taps at λ = log2(Pmax / r), at the midpoints of N equal
   * parts of the major axis's vector centred on (u, v), averaged: together they cover the
   * footprint's length. The extension's own text takes N = ⌈Pmax/Pmin⌉ and λ = log2(Pmax/N): a
   * footprint barely longer than wide then gets two taps a level sharper than its width, which
   * aliases: the cube of the bench's 60° view (320×180, 1 sample per pixel, srgb) measured
   * objects 35.6 dB against the reference that way, 44.8 this way (44.5 isotropic).
   * A square footprint gives r = 1 and the isotropic read, to the bit.
   */
  sample(a: Float64Array, out: Float64Array): void {
    const levels = this.levels, base = levels[0];
    const dux = a[2], dvx = a[3], duy = a[4], dvy = a[5];
    const sx = dux * base.width, tx = dvx * base.height, sy = duy * base.width, ty = dvy * base.height;
    const px2 = sx * sx + tx * tx, py2 = sy * sy + ty * ty;
    let rho2 = Math.max(px2, py2);
    // n taps (an integer, so a small int) along (au, av), the major axis in UV; one at (u, v) without.
    let n = 1, au = 0, av = 0;
    if (this.anisotropic) {
      // The anisotropy: Pmax over the footprint's width across the major axis, |det|/Pmax. A
      // zero-area footprint gives Infinity (the most taps); a NaN or infinite derivative, NaN (one tap).
      const ratio = rho2 / Math.abs(sx * ty - tx * sy);
      // Stryker disable next-line EqualityOperator: at ratio = 1, r = 1: one tap at (u, v), ρ² as it was: the isotropic read
      if (ratio > 1) {
        // Stryker disable next-line EqualityOperator: at ratio = MAX_ANISOTROPY both give it
        const r = ratio < MAX_ANISOTROPY ? ratio : MAX_ANISOTROPY;
        n = Math.round(r) | 0;
        rho2 /= r * r;
        if (px2 >= py2) { au = dux; av = dvx; } else { au = duy; av = dvy; }
      }
    }
    // λ = ½·log2(ρ²); NaN (a degenerate derivative) reads the base level.
    // Stryker disable next-line ConditionalExpression,EqualityOperator: ρ² ≤ 1 or NaN gives λ ≤ 0 or NaN: level 0 below, as λ = 0
    const lambda = rho2 > 1 ? 0.5 * Math.log2(rho2) : 0;
    const top = levels.length - 1;
    // Both start as numbers (an unassigned `let` would make them tagged, boxed on every write).
    let first = 0, f = 0;
    // Stryker disable next-line EqualityOperator: at λ = top the branch below gives first = top, f = 0 too
    if (lambda >= top) first = top;
    else { first = Math.floor(lambda) | 0; f = lambda - first; } // λ ≥ 0: at 0, level 0 and f = 0
    // Sums in locals (one add per tap for grey, not three stores), in the order the taps come.
    let r = 0, g = 0, b = 0;
    const u = a[0], v = a[1], grey = this.channels === 1, share = 1 / n;
    for (let l = first, levelWeight = 1 - f; l <= first + 1 && levelWeight > 0; l++, levelWeight = f) {
      const level = levels[l], W = level.width, H = level.height, data = level.data;
      // Stryker disable next-line ConditionalExpression: as false, powers of two take the remainder: the mask's texel
      const weight = levelWeight * share, pow2W = (W & (W - 1)) === 0, pow2H = (H & (H - 1)) === 0;
      for (let k = 0; k < n; k++) {
        // The midpoint of part k of n along the major axis, −½..½ of it (0 with one tap).
        const along = (k + 0.5) * share - 0.5;
        const s = (u + along * au) * W - 0.5, t = (v + along * av) * H - 0.5;
        const fi = Math.floor(s), fj = Math.floor(t);
        const x = s - fi, y = t - fj;
        // REPEAT: a mask for powers of two, a remainder otherwise.
        let i0: number, j0: number;
        // Stryker disable next-line ConditionalExpression: pow2W false: the remainder of a power of two is the mask's texel
        if (pow2W) i0 = fi & (W - 1); else { i0 = fi % W; if (i0 < 0) i0 += W; }
        // Stryker disable next-line ConditionalExpression: the same for pow2H
        if (pow2H) j0 = fj & (H - 1); else { j0 = fj % H; if (j0 < 0) j0 += H; }
        const i1 = i0 + 1 === W ? 0 : i0 + 1, j1 = j0 + 1 === H ? 0 : j0 + 1;
        const w00 = (1 - x) * (1 - y) * weight, w10 = x * (1 - y) * weight, w01 = (1 - x) * y * weight, w11 = x * y * weight;
        if (grey) {
          r += w00 * data[j0 * W + i0] + w10 * data[j0 * W + i1] + w01 * data[j1 * W + i0] + w11 * data[j1 * W + i1];
        } else {
          const p00 = 3 * (j0 * W + i0), p10 = 3 * (j0 * W + i1), p01 = 3 * (j1 * W + i0), p11 = 3 * (j1 * W + i1);
          r += w00 * data[p00] + w10 * data[p10] + w01 * data[p01] + w11 * data[p11];
          g += w00 * data[p00 + 1] + w10 * data[p10 + 1] + w01 * data[p01 + 1] + w11 * data[p11 + 1];
          b += w00 * data[p00 + 2] + w10 * data[p10 + 2] + w01 * data[p01 + 2] + w11 * data[p11 + 2];
        }
      }
    }
    out[0] = r;
    out[1] = grey ? r : g;
    out[2] = grey ? r : b;
  }
}

/** The next level: each texel the mean of (up to) 2×2 texels of `level` (an odd last row/column folds in). */
function halve(level: Level, channels: number): Level {
  const W = level.width, H = level.height, src = level.data;
  const w = Math.max(1, W >> 1), h = Math.max(1, H >> 1);
  const data = new Float32Array(w * h * channels);
  // Stryker disable next-line EqualityOperator: j = h writes past data's end, which a Float32Array drops
  for (let j = 0; j < h; j++) {
    // Stryker disable next-line ArithmeticOperator: 2j ≤ H − 1 < H + 1: j0 = 2j either way
    const j0 = Math.min(2 * j, H - 1), j1 = Math.min(2 * j + 1, H - 1);
    // Stryker disable next-line EqualityOperator: i = w writes the next row's first texel, written again with that row (or past the end)
    for (let i = 0; i < w; i++) {
      // Stryker disable next-line ArithmeticOperator: 2i ≤ W − 1 < W + 1: i0 = 2i either way
      const i0 = Math.min(2 * i, W - 1), i1 = Math.min(2 * i + 1, W - 1);
      // Stryker disable next-line EqualityOperator: k = channels: the next texel's first value, written again with it (or past the end)
      for (let k = 0; k < channels; k++) {
        data[(j * w + i) * channels + k] = 0.25 * (
          src[(j0 * W + i0) * channels + k] + src[(j0 * W + i1) * channels + k]
          + src[(j1 * W + i0) * channels + k] + src[(j1 * W + i1) * channels + k]);
      }
    }
  }
  return { width: w, height: h, data };
}

/** 8-bit level → what the texture holds: decoded to linear light (`srgb`), or b / 255 (`none`). */
const byteTable = (space: ColorSpace): ArrayLike<number> => (space === 'srgb' ? SRGB_BYTE_TO_LINEAR : AS_STORED);
const AS_STORED = Float64Array.from({ length: 256 }, (_, b) => b / 255);

const procedural: { srgb?: MipTexture; none?: MipTexture } = {};

/** The checker-plus-noise (docs/default-scene.md#the-procedural-texture), grey, built once per colour space and shared (read-only). */
export function proceduralMipTexture(space: ColorSpace): MipTexture {
  const built = procedural[space];
  if (built) return built;
  const rgba = proceduralTexture(), level = byteTable(space);
  const n = TEXTURE_SIZE;
  const grey = new Float32Array(n * n);
  // Stryker disable next-line EqualityOperator: i = grey.length writes past its end, which a Float32Array drops
  for (let i = 0; i < grey.length; i++) grey[i] = level[rgba[4 * i]];
  return (procedural[space] = new MipTexture(1, n, n, grey, space === 'srgb'));
}

/**
 * A decoded image (RGBA8, top row first) as RGB with OBJ's convention (docs/scene-model.md#image-textures): v = 0 is the
 * image's bottom row, so texture row j is image row H − 1 − j (what the GL path gets by reading
 * at (u, 1 − v)). Its bytes are decoded to linear light with `srgb`. Null when the pixels do not
 * match the size.
 */
export function imageMipTexture(image: DecodedImage, space: ColorSpace): MipTexture | null {
  return fromImage(image, space, false);
}

/** The image's alpha channel, as stored (0..1), with imageMipTexture's orientation: what glTF's alpha mask reads (docs/gltf.md#alpha). */
export function imageAlphaMipTexture(image: DecodedImage): MipTexture | null {
  return fromImage(image, 'none', true);
}

function fromImage(image: DecodedImage, space: ColorSpace, alpha: boolean): MipTexture | null {
  const { width: w, height: h, data } = image;
  if (!(w >= 1 && h >= 1 && Number.isInteger(w) && Number.isInteger(h)) || data.length < w * h * 4) return null;
  const channels = alpha ? 1 : 3, rgb = new Float32Array(w * h * channels), level = byteTable(space);
  // Stryker disable next-line EqualityOperator: j = h writes past rgb's end, which a Float32Array drops
  for (let j = 0; j < h; j++) {
    const row = (h - 1 - j) * w;
    // Stryker disable next-line EqualityOperator: i = w writes the next row's first texel, written again with that row (or past the end)
    for (let i = 0; i < w; i++) {
      if (alpha) rgb[j * w + i] = level[data[(row + i) * 4 + 3]];
      // Stryker disable next-line EqualityOperator: k = 3 writes the next texel's red, written again with it (or past the end)
      else for (let k = 0; k < 3; k++) rgb[(j * w + i) * 3 + k] = level[data[(row + i) * 4 + k]];
    }
  }
  return new MipTexture(channels, w, h, rgb, space === 'srgb');
}
