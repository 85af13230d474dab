// The reference's texture sampler: bilinear point samples and the exact box filter over a parallelogram.
import { describe, expect, it } from 'vitest';
import { TextureSampler } from '../../src/reference/texture-sampler';
import { texel } from '../../src/scene/procedural-texture';

const sampler = new TextureSampler();
const at = (x: number, y: number) => texel(((x % 512) + 512) % 512, ((y % 512) + 512) % 512) / 255;
const uvOf = (s: number, t: number): [number, number] => [(s + 0.5) / 512, (t + 0.5) / 512];

/** Mean of the bilinear texture over a parallelogram by brute force: m×m stratum centres. */
function bruteForce(cs: number, ct: number, e1: [number, number], e2: [number, number], m: number): number {
  let sum = 0;
  for (let j = 0; j < m; j++) {
    for (let i = 0; i < m; i++) {
      const a = (i + 0.5) / m - 0.5, b = (j + 0.5) / m - 0.5;
      sum += sampler.bilinear(...uvOf(cs + a * e1[0] + b * e2[0], ct + a * e1[1] + b * e2[1]));
    }
  }
  return sum / (m * m);
}

describe('TextureSampler.bilinear', () => {
  it('returns the texel at texel centres, row y = 0 at v ≈ 0, and repeats', () => {
    for (const [x, y] of [[0, 0], [63, 64], [200, 350], [511, 511], [100, 300]]) {
      expect(sampler.bilinear(...uvOf(x, y))).toBe(at(x, y));
      expect(sampler.bilinear(...uvOf(x + 512, y - 1024))).toBeCloseTo(at(x, y), 12);
    }
  });

  it('interpolates linearly between texel centres (and wraps across u = 0)', () => {
    expect(sampler.bilinear(...uvOf(10.25, 20))).toBeCloseTo(0.75 * at(10, 20) + 0.25 * at(11, 20), 12);
    expect(sampler.bilinear(...uvOf(-0.5, 7))).toBeCloseTo(0.5 * at(511, 7) + 0.5 * at(0, 7), 12);
    const mean4 = (at(255, 255) + at(256, 255) + at(255, 256) + at(256, 256)) / 4;
    expect(sampler.bilinear(0.5, 0.5)).toBeCloseTo(mean4, 12);
  });
});

describe('TextureSampler.boxFilter', () => {
  it('over one whole period (any lattice parallelogram) is the mean of all texels', () => {
    let mean = 0;
    for (let y = 0; y < 512; y++) for (let x = 0; x < 512; x++) mean += at(x, y);
    mean /= 512 * 512;
    expect(sampler.boxFilter(0.3, 0.7, 512, 0, 0, 512)).toBeCloseTo(mean, 10);
    // A sheared fundamental domain of the 512-periodic lattice integrates the same.
    expect(sampler.boxFilter(0.1, 0.2, 512, 0, 256, 512)).toBeCloseTo(mean, 10);
  });

  it('tends to the bilinear value as the footprint shrinks, and tiny footprints are exact', () => {
    const [u, v] = uvOf(123.37, 401.81);
    expect(sampler.boxFilter(u, v, 0, 0, 0, 0)).toBe(sampler.bilinear(u, v));
    expect(sampler.boxFilter(u, v, 1e-3, 2e-4, -3e-4, 1e-3)).toBeCloseTo(sampler.bilinear(u, v), 8);
  });

  it('matches brute-force integration over rotated footprints crossing many texels and a checker edge', () => {
    const cases: [number, number, [number, number], [number, number]][] = [
      [63.7, 127.2, [3.3, 1.1], [-0.8, 2.5]],
      [10.1, 5.9, [0.6, 0.1], [0.2, 0.7]], // inside one patch: the closed form
      [511.6, 0.3, [7.9, -2.2], [1.5, 6.4]], // wraps in both directions
      [300.2, 200.8, [20.5, 0.3], [0.2, -0.9]], // long and thin, mirrored orientation
    ];
    for (const [cs, ct, e1, e2] of cases) {
      const exact = sampler.boxFilter(...uvOf(cs, ct), e1[0], e1[1], e2[0], e2[1]);
      expect(Math.abs(exact - bruteForce(cs, ct, e1, e2, 600)), `${cs},${ct}`).toBeLessThan(2e-4);
    }
  });

  it('does not depend on how the footprint\'s edges are ordered or signed', () => {
    const [u, v] = uvOf(77.3, 88.6);
    const ref = sampler.boxFilter(u, v, 4.2, 1.3, -0.7, 3.1);
    expect(sampler.boxFilter(u, v, -0.7, 3.1, 4.2, 1.3)).toBeCloseTo(ref, 12);
    expect(sampler.boxFilter(u, v, -4.2, -1.3, -0.7, 3.1)).toBeCloseTo(ref, 12);
  });
});
