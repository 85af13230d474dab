// Radiance .hdr files made by the tests (docs/pbr.md#an-image): an image of linear light written as RGBE, each channel of a
// pixel m·2^(e − 136) with m the largest channel's mantissa in 128..255 — and read back by loaders/hdr.ts as (m + ½)·2^(e − 136).
// Scanlines run-length encoded (literals only) where the width allows it, flat otherwise, as Radiance's own writer does.
import type { EnvironmentImage } from '../../../src/math/environment-image';

function rgbe(r: number, g: number, b: number): [number, number, number, number] {
  const v = Math.max(r, g, b);
  if (!(v > 1e-32)) return [0, 0, 0, 0];
  const e = Math.ceil(Math.log2(v) + 1e-12), f = 256 / 2 ** e;
  // v·2^(8 − e) is in [128, 256): the mantissa; the exponent byte e + 128.
  return [Math.min(255, Math.floor(r * f)), Math.min(255, Math.floor(g * f)), Math.min(255, Math.floor(b * f)), e + 128];
}

export function hdrFile(img: EnvironmentImage, header: string[] = ['#?RADIANCE', 'FORMAT=32-bit_rle_rgbe']): Uint8Array {
  const { width: w, height: h, rgb } = img;
  const out: number[] = [...new TextEncoder().encode([...header, '', `-Y ${h} +X ${w}`, ''].join('\n'))];
  const rle = w >= 8 && w < 0x8000;
  for (let j = 0; j < h; j++) {
    const px = [];
    for (let i = 0; i < w; i++) px.push(rgbe(rgb[3 * (j * w + i)], rgb[3 * (j * w + i) + 1], rgb[3 * (j * w + i) + 2]));
    if (!rle) {
      for (const p of px) out.push(...p);
      continue;
    }
    out.push(2, 2, w >> 8, w & 255);
    for (let c = 0; c < 4; c++) {
      for (let x = 0; x < w; x += 128) {
        const n = Math.min(128, w - x);
        out.push(n);
        for (let k = 0; k < n; k++) out.push(px[x + k][c]);
      }
    }
  }
  return new Uint8Array(out);
}
