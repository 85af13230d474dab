// Brings an image drawn at pixel-ratio r back to the bench's CSS size, as a compositor would:
// a box filter when shrinking by an integer factor, bilinear otherwise. A compositor filters the
// bytes as stored; `mix` 'srgb' filters them in linear light instead (decoded, averaged,
// encoded again: what an sRGB-correct downscale gives), alpha always as stored.
import { linearToSrgb, SRGB_BYTE_TO_LINEAR, type ColorSpace } from '../src/math/srgb';

export function resample(
  src: Uint8ClampedArray | Uint8Array, sw: number, sh: number, dw: number, dh: number, mix: ColorSpace = 'none',
): Uint8ClampedArray {
  if (sw === dw && sh === dh) return Uint8ClampedArray.from(src);
  const out = new Uint8ClampedArray(dw * dh * 4);
  const linear = mix === 'srgb';
  // Channel c of byte b in the space the filter mixes in, and back to a byte.
  const value = (b: number, c: number) => (linear && c < 3 ? SRGB_BYTE_TO_LINEAR[b] : b);
  const store = (x: number, c: number) => (linear && c < 3 ? Math.round(255 * linearToSrgb(x)) : Math.round(x));
  const fx = sw / dw;
  const fy = sh / dh;
  if (Number.isInteger(fx) && Number.isInteger(fy) && fx >= 1 && fy >= 1) {
    const n = fx * fy;
    for (let y = 0; y < dh; y++) {
      for (let x = 0; x < dw; x++) {
        for (let c = 0; c < 4; c++) {
          let sum = 0;
          for (let j = 0; j < fy; j++) for (let i = 0; i < fx; i++) sum += value(src[((y * fy + j) * sw + x * fx + i) * 4 + c], c);
          out[(y * dw + x) * 4 + c] = store(sum / n, c);
        }
      }
    }
    return out;
  }
  for (let y = 0; y < dh; y++) {
    const sy = Math.min(sh - 1, Math.max(0, (y + 0.5) * fy - 0.5));
    const y0 = Math.floor(sy), y1 = Math.min(sh - 1, y0 + 1), ty = sy - y0;
    for (let x = 0; x < dw; x++) {
      const sx = Math.min(sw - 1, Math.max(0, (x + 0.5) * fx - 0.5));
      const x0 = Math.floor(sx), x1 = Math.min(sw - 1, x0 + 1), tx = sx - x0;
      for (let c = 0; c < 4; c++) {
        const a = value(src[(y0 * sw + x0) * 4 + c], c) * (1 - tx) + value(src[(y0 * sw + x1) * 4 + c], c) * tx;
        const b = value(src[(y1 * sw + x0) * 4 + c], c) * (1 - tx) + value(src[(y1 * sw + x1) * 4 + c], c) * tx;
        out[(y * dw + x) * 4 + c] = store(a * (1 - ty) + b * ty, c);
      }
    }
  }
  return out;
}
