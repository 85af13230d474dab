// The resolve's sRGB encode (docs/colour.md#the-transfer-curve): round(encode(l)·255) for a linear value, the same byte as
// math/srgb.ts's linearToSrgbByte, by one table read and one comparison instead of its 8-step
// search (8.4 ms of a 30 ms frame at 640×360 and 1 sample per pixel; this takes 2.4).
// Also the resolve itself: n×n samples per pixel averaged (in linear light when encoding) to RGBA8.
import { linearToSrgbByte, srgbToLinear } from '../math/srgb';
import { toneMap, type ToneMapping } from '../math/tone-map';
import { encodesAtEnd, toneMapped } from '../frame/linear-light';
import type { FrameState } from '../frame/types';

/**
 * Bins per unit of linear light. Two byte thresholds are never closer than 1/(255·12.92) ≈
 * 3.0e-4 (in the curve's linear segment; its slope only falls after), wider than a bin, so a bin
 * holds at most one: the byte at its low end, or the next.
 */
export const ENCODE_BINS = 4096;

/** The byte at each bin's low end, i / ENCODE_BINS. */
const BASE: Uint8Array = /* @__PURE__ */ (() => {
  const t = new Uint8Array(ENCODE_BINS);
  for (let i = 0; i < ENCODE_BINS; i++) t[i] = linearToSrgbByte(i / ENCODE_BINS);
  return t;
})();

/** NEXT[b]: the linear value at which the byte steps from b to b + 1, decode((b + ½)/255); never for 255. */
const NEXT: Float64Array = /* @__PURE__ */ (() => {
  const t = new Float64Array(256);
  for (let b = 0; b < 255; b++) t[b] = srgbToLinear((b + 0.5) / 255);
  t[255] = Infinity;
  return t;
})();

/** round(encode(l)·255) for linear light l, clipped to 0..1 first (NaN: 0). */
export function encodeByte(l: number): number {
  if (!(l > 0)) return 0;
  if (l >= 1) return 255;
  const b = BASE[(l * ENCODE_BINS) | 0];
  return l >= NEXT[b] ? b + 1 : b;
}

const LITTLE_ENDIAN = new Uint8Array(new Uint32Array([1]).buffer)[0] === 1;
/** Alpha 255 in a packed pixel's high byte. */
const OPAQUE = 0xff000000 | 0;

/**
 * Box filter of n×n samples per pixel, rounded to RGBA8. With `encode` the mean (linear light)
 * is encoded to sRGB after the average, as an MSAA resolve into an sRGB target does, by a
 * table read (no pow per pixel).
 */
export function resolveSamples(
  out: Uint8ClampedArray, source: Float32Array, width: number, height: number, n: number, encode: boolean,
): void {
  const W = width * n, k = 255 / (n * n), mean = 1 / (n * n);
  if (n === 1 && encode && LITTLE_ENDIAN && out.byteOffset % 4 === 0) {
    // One store per pixel (R in the low byte, as RGBA8 lies in memory on a little-endian host).
    const packed = new Uint32Array(out.buffer, out.byteOffset, width * height);
    for (let i = 0, o = 0; i < width * height; i++, o += 3) {
      packed[i] = encodeByte(source[o]) | (encodeByte(source[o + 1]) << 8) | (encodeByte(source[o + 2]) << 16) | OPAQUE;
    }
    return;
  }
  if (n === 1 && encode) {
    for (let i = 0, o = 0, p = 0; i < width * height; i++, o += 3, p += 4) {
      out[p] = encodeByte(source[o]);
      out[p + 1] = encodeByte(source[o + 1]);
      out[p + 2] = encodeByte(source[o + 2]);
      out[p + 3] = 255;
    }
    return;
  }
  if (n === 1) {
    // Values are in [0, 1]: (x·255 + ½) | 0 is Math.round, without the call.
    for (let i = 0, o = 0, p = 0; i < width * height; i++, o += 3, p += 4) {
      out[p] = (source[o] * 255 + 0.5) | 0;
      out[p + 1] = (source[o + 1] * 255 + 0.5) | 0;
      out[p + 2] = (source[o + 2] * 255 + 0.5) | 0;
      out[p + 3] = 255;
    }
    return;
  }
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      let r = 0, g = 0, b = 0;
      for (let sy = 0; sy < n; sy++) {
        let o = 3 * ((y * n + sy) * W + x * n);
        for (let sx = 0; sx < n; sx++, o += 3) {
          r += source[o]; g += source[o + 1]; b += source[o + 2];
        }
      }
      const p = 4 * (y * width + x);
      out[p] = encode ? encodeByte(r * mean) : Math.round(r * k);
      out[p + 1] = encode ? encodeByte(g * mean) : Math.round(g * k);
      out[p + 2] = encode ? encodeByte(b * mean) : Math.round(b * k);
      out[p + 3] = 255;
    }
  }
}

const mapped = new Float64Array(3);

/**
 * The resolve of a tone-mapped frame (docs/pbr.md#tone-mapping): n×n samples averaged in linear light, times
 * `exposure`, through the tone-mapping curve, then encoded (each step as the GPU's resolve and encode pass).
 */
export function resolveToneMapped(
  out: Uint8ClampedArray, source: Float32Array, width: number, height: number, n: number, curve: ToneMapping, exposure: number,
): void {
  const W = width * n, k = exposure / (n * n);
  // Stryker disable next-line EqualityOperator: y = height writes past the end of `out` (its band): dropped
  for (let y = 0; y < height; y++) {
    // Stryker disable next-line EqualityOperator: x = width writes the next row's first pixel, which that row writes again (or past the end)
    for (let x = 0; x < width; x++) {
      let r = 0, g = 0, b = 0;
      for (let sy = 0; sy < n; sy++) {
        let o = 3 * ((y * n + sy) * W + x * n);
        for (let sx = 0; sx < n; sx++, o += 3) {
          r += source[o]; g += source[o + 1]; b += source[o + 2];
        }
      }
      toneMap(curve, mapped, r * k, g * k, b * k);
      const p = 4 * (y * width + x);
      out[p] = encodeByte(mapped[0]);
      out[p + 1] = encodeByte(mapped[1]);
      out[p + 2] = encodeByte(mapped[2]);
      out[p + 3] = 255;
    }
  }
}

/**
 * What the shaders hold a colour to (docs/pbr.md#tone-mapping): Infinity in a tone-mapped frame, which keeps light above 1
 * until the resolve; else 1, as 8-bit targets clamp.
 */
export const colourCeiling = (state: FrameState): number => (toneMapped(state) ? Infinity : 1);

/** A frame's resolve: tone mapped (toneMapped), else resolveSamples, encoded when the frame encodes at its end (docs/colour.md#srgb). */
export function resolveFrame(out: Uint8ClampedArray, source: Float32Array, width: number, height: number, n: number, state: FrameState): void {
  if (toneMapped(state)) resolveToneMapped(out, source, width, height, n, state.toneMapping ?? 'none', state.exposure ?? 1);
  else resolveSamples(out, source, width, height, n, encodesAtEnd(state));
}
