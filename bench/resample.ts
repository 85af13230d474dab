// Brings an image drawn at pixel-ratio r back to the bench's CSS size, as a compositor would:
// a box filter when shrinking by an integer factor, bilinear otherwise.

export function resample(
  src: Uint8ClampedArray | Uint8Array, sw: number, sh: number, dw: number, dh: number,
): Uint8ClampedArray {
  if (sw === dw && sh === dh) return Uint8ClampedArray.from(src);
  const out = new Uint8ClampedArray(dw * dh * 4);
  const fx = sw / dw;
  const fy = sh / dh;
  if (Number.isInteger(fx) && Number.isInteger(fy) && fx >= 1 && fy >= 1) {
    const n = fx * fy;
    for (let y = 0; y < dh; y++) {
      for (let x = 0; x < dw; x++) {
        for (let c = 0; c < 4; c++) {
          let sum = 0;
          for (let j = 0; j < fy; j++) for (let i = 0; i < fx; i++) sum += src[((y * fy + j) * sw + x * fx + i) * 4 + c];
          out[(y * dw + x) * 4 + c] = Math.round(sum / n);
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
        const a = src[(y0 * sw + x0) * 4 + c] * (1 - tx) + src[(y0 * sw + x1) * 4 + c] * tx;
        const b = src[(y1 * sw + x0) * 4 + c] * (1 - tx) + src[(y1 * sw + x1) * 4 + c] * tx;
        out[(y * dw + x) * 4 + c] = Math.round(a * (1 - ty) + b * ty);
      }
    }
  }
  return out;
}
