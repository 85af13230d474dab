// The seeded checker-plus-noise texture of docs/default-scene.md#the-procedural-texture.
import { beforeEach, describe, expect, it } from 'vitest';
import { buildProceduralTexture, proceduralTexture, texel, textureNoise } from '../../src/scene/procedural-texture';
import { TEXTURE_SIZE } from '../../src/scene/default-scene';
import { differingBytes } from './helpers/pixel-diff';

/** The §3 hash written again, in BigInt arithmetic modulo 2³², so it shares no code with the module. */
function referenceNoise(x: number, y: number): number {
  const M = 1n << 32n;
  let h = (BigInt(x) * 374761393n + BigInt(y) * 668265263n) % M;
  h = ((h ^ (h >> 13n)) * 1274126177n) % M;
  return Number((h ^ (h >> 16n)) % 31n) - 15;
}

function referenceTexel(x: number, y: number): number {
  const light = (Math.floor(x / 64) + Math.floor(y / 64)) % 2 === 0;
  return Math.max(0, Math.min(255, (light ? 200 : 100) + referenceNoise(x, y)));
}

describe('textureNoise', () => {
  it('is an integer in −15..15 and deterministic', () => {
    const seen = new Set<number>();
    for (let y = 0; y < 512; y += 3) {
      for (let x = 0; x < 512; x += 5) {
        const n = textureNoise(x, y);
        expect(Number.isInteger(n)).toBe(true);
        expect(n).toBeGreaterThanOrEqual(-15);
        expect(n).toBeLessThanOrEqual(15);
        expect(textureNoise(x, y)).toBe(n);
        seen.add(n);
      }
    }
    expect(seen.size).toBe(31); // every level appears
  });

  it('matches an independent implementation of the §3 hash', () => {
    for (let y = 0; y < 512; y += 7) {
      for (let x = 0; x < 512; x += 11) expect(textureNoise(x, y), `(${x}, ${y})`).toBe(referenceNoise(x, y));
    }
  });
});

describe('texel', () => {
  it('has the hand-computed values at three texels', () => {
    // (0,0): light cell, n = −15 → 185. (64,0): dark cell, n = −7 → 93. (100,37): dark cell, n = 0 → 100.
    expect(texel(0, 0)).toBe(185);
    expect(texel(64, 0)).toBe(93);
    expect(texel(100, 37)).toBe(100);
    expect(texel(511, 511)).toBe(190);
    expect(texel(0, 1)).toBe(211);
  });

  it('follows the checker: (0,0) light, (64,0) dark, (64,64) light', () => {
    const cellMean = (cx: number, cy: number) => {
      let s = 0;
      for (let y = 0; y < 64; y++) for (let x = 0; x < 64; x++) s += texel(cx * 64 + x, cy * 64 + y);
      return s / 4096;
    };
    expect(Math.abs(cellMean(0, 0) - 200)).toBeLessThan(1.5);
    expect(Math.abs(cellMean(1, 0) - 100)).toBeLessThan(1.5);
    expect(Math.abs(cellMean(1, 1) - 200)).toBeLessThan(1.5);
    expect(Math.abs(cellMean(0, 7) - 100)).toBeLessThan(1.5);
    for (const [x, y] of [[0, 0], [64, 64], [127, 127], [384, 0]]) expect(texel(x, y)).toBeGreaterThanOrEqual(185);
    for (const [x, y] of [[64, 0], [63, 64], [0, 511], [511, 0]]) expect(texel(x, y)).toBeLessThanOrEqual(115);
  });

  it('matches the reference everywhere on a coarse grid', () => {
    for (let y = 0; y < 512; y += 13) for (let x = 0; x < 512; x += 17) expect(texel(x, y)).toBe(referenceTexel(x, y));
  });
});

describe('proceduralTexture', () => {
  let data: ReturnType<typeof proceduralTexture>;
  beforeEach(() => { data = proceduralTexture(); });

  it('is 512×512 RGBA8, grey, opaque, row y = 0 first', () => {
    expect(TEXTURE_SIZE).toBe(512);
    expect(data).toBeInstanceOf(Uint8Array);
    expect(data.length).toBe(512 * 512 * 4);
    for (let y = 0; y < 512; y++) {
      for (let x = 0; x < 512; x++) {
        const i = (y * 512 + x) * 4;
        if (data[i + 3] !== 255 || data[i] !== data[i + 1] || data[i] !== data[i + 2] || data[i] !== texel(x, y)) {
          expect.fail(`texel (${x}, ${y}) = ${Array.from(data.subarray(i, i + 4))}, expected grey ${texel(x, y)} opaque`);
        }
      }
    }
    expect(data[(37 * 512 + 100) * 4]).toBe(100);
    expect(data[64 * 4]).toBe(93);
  });

  it('averages 150 ± 1', () => {
    let s = 0;
    for (let i = 0; i < data.length; i += 4) s += data[i];
    expect(Math.abs(s / (512 * 512) - 150)).toBeLessThan(1);
  });

  it('is deterministic: a second build has the same bytes', () => {
    // proceduralTexture() caches its array, so calling it again would compare the array with
    // itself: build it again from scratch instead.
    const again = buildProceduralTexture();
    expect(again === data, 'a new array').toBe(false); // not .not.toBe: that formats both 1 MB arrays
    expect(again.length).toBe(data.length);
    expect(differingBytes(data, again), 'bytes that differ between two builds').toBe(0);
  });

  it('is built once: later calls return the same array', () => {
    expect(proceduralTexture()).toBe(data);
  });
});
