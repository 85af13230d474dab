// The seeded checker-plus-noise texture of docs/default-scene.md#the-procedural-texture (never Math.random: frames are reproducible).
// Shared by the reference (reference/texture-sampler.ts) and both renderers
// (software/mip-texture.ts, render/gl/shared-resources.ts): tied down by
// tests/unit/texture.test.ts's texels worked out by hand and its BigInt re-implementation of the hash.
import { TEXTURE_SIZE } from './default-scene';

const CELL = 64;
const LIGHT = 200;
const DARK = 100;

/** Per-texel noise in −15..15 levels, from the §3 integer hash. */
export function textureNoise(x: number, y: number): number {
  let h = (Math.imul(x, 374761393) + Math.imul(y, 668265263)) | 0;
  h = Math.imul(h ^ (h >>> 13), 1274126177);
  return (((h ^ (h >>> 16)) >>> 0) % 31) - 15;
}

/** The 8-bit grey level of texel (x, y), 0 ≤ x, y < 512. */
export function texel(x: number, y: number): number {
  // Stryker disable next-line ArithmeticOperator: a sum and a difference of two integers have the same parity
  const base = ((Math.floor(x / CELL) + Math.floor(y / CELL)) & 1) === 0 ? LIGHT : DARK;
  const v = base + textureNoise(x, y);
  // Stryker disable next-line ConditionalExpression,EqualityOperator: LIGHT or DARK ± 15 stays within 85..215: the clamp is a guard, never reached
  return v < 0 ? 0 : v > 255 ? 255 : v;
}

/** RGBA8 pixels, row y = 0 first, built afresh (proceduralTexture() keeps one). */
export function buildProceduralTexture(): Uint8Array {
  const n = TEXTURE_SIZE;
  const data = new Uint8Array(n * n * 4);
  // Stryker disable next-line EqualityOperator: a row past the end writes past the typed array's end, which drops it
  for (let y = 0; y < n; y++) {
    // Stryker disable next-line EqualityOperator: a texel past the row's end lands on the next row's first, rewritten next; the last one past the array's end
    for (let x = 0; x < n; x++) {
      const v = texel(x, y);
      const i = (y * n + x) * 4;
      data[i] = data[i + 1] = data[i + 2] = v;
      data[i + 3] = 255;
    }
  }
  return data;
}

let cached: Uint8Array | undefined;

/** RGBA8 pixels, row y = 0 first (the first row uploaded). Built once, shared, read-only. */
export function proceduralTexture(): Uint8Array {
  return (cached ??= buildProceduralTexture());
}
