// The reference's light from an environment image (src/reference/image-light.ts, docs/pbr.md#the-reference): its draw lands
// where its density says, the density covers the sphere once, and the estimate with it is the estimate without it (both
// unbiased; the draw only lowers the noise).
import { describe, expect, it } from 'vitest';
import { imageLight } from '../../src/reference/image-light';
import { environmentLight } from '../../src/reference/pbr-light';
import { imageDirection, type EnvironmentImage } from '../../src/math/environment-image';

function lcg(seed: number): () => number {
  let s = seed;
  return () => (s = (s * 16807) % 2147483647) / 2147483647;
}

/** A w × h image, dim everywhere (0.05) but for texel (si, sj) at `sun`. */
function sunImage(w: number, h: number, si: number, sj: number, sun: number): EnvironmentImage {
  const rgb = new Float32Array(w * h * 3).fill(0.05);
  rgb.fill(sun, 3 * (sj * w + si), 3 * (sj * w + si) + 3);
  return { width: w, height: h, rgb };
}

describe("the reference's light from an image", () => {
  it('draws a sun texel in proportion to its power, and each draw lands in the texel its density names', () => {
    const img = sunImage(16, 8, 11, 2, 1000), light = imageLight(img), random = lcg(3), d = new Float64Array(3);
    // Each cell weighs the mean of the bilinear read over it (⅛, ¾, ⅛ along each axis) × sin θ of its row: the sun's cell
    // takes 36/64 of the sun above the 0.05 everywhere, its left and right 6/64 each, above and below 6/64, the corners 1/64.
    const sin = (j: number) => Math.sin((Math.PI * (j + 0.5)) / 8), extra = 1000 - 0.05;
    let total = 0;
    for (let j = 0; j < 8; j++) total += 16 * 0.05 * sin(j);
    total += extra * ((36 + 12) / 64) * sin(2) + extra * ((6 + 2) / 64) * (sin(1) + sin(3));
    const share = ((0.05 + (extra * 36) / 64) * sin(2)) / total;
    let hits = 0;
    const n = 20000;
    for (let k = 0; k < n; k++) {
      light.lights!.draw(d, random(), random(), random());
      expect(Math.hypot(d[0], d[1], d[2])).toBeCloseTo(1, 12);
      const u = 0.5 + Math.atan2(d[2], d[0]) / (2 * Math.PI), v = Math.acos(d[1]) / Math.PI;
      if (Math.floor(u * 16) === 11 && Math.floor(v * 8) === 2) hits++;
    }
    // Binomial: 3 standard deviations.
    expect(Math.abs(hits / n - share)).toBeLessThan(3 * Math.sqrt((share * (1 - share)) / n));
  });

  it('its density integrates to 1 over the sphere (uniform directions, 200,000 of them)', () => {
    const light = imageLight(sunImage(16, 8, 3, 6, 50)), random = lcg(11);
    let sum = 0;
    const n = 200000;
    for (let k = 0; k < n; k++) {
      const y = 1 - 2 * random(), phi = 2 * Math.PI * random(), s = Math.sqrt(1 - y * y);
      sum += light.lights!.density(s * Math.cos(phi), y, s * Math.sin(phi));
    }
    // Mean density × 4π; its own noise is a few per cent with one texel 1,000 times the rest's power per area.
    expect((sum / n) * 4 * Math.PI).toBeCloseTo(1, 1);
  });

  it('a black image draws nothing of its own: the lobes alone', () => {
    expect(imageLight({ width: 4, height: 2, rgb: new Float32Array(24) }).lights).toBeUndefined();
  });

  it('the light a surface sends is the same with the draw and without it, and the draw makes it less noisy', () => {
    const img = sunImage(32, 16, 20, 5, 400), light = imageLight(img), bare = { radiance: light.radiance };
    const m = { baseColor: [0.8, 0.6, 0.4], metallic: 0.3, alpha: 0.3 * 0.3 };
    const n = [0, 1, 0], v = [Math.SQRT1_2, Math.SQRT1_2, 0];
    const a = environmentLight(m, n, v, light, 40000, lcg(5));
    const b = environmentLight(m, n, v, bare, 40000, lcg(9));
    for (let c = 0; c < 3; c++) {
      const both = Math.hypot(a.error[c], b.error[c]);
      expect(Math.abs(a.mean[c] - b.mean[c])).toBeLessThan(4 * both);
      expect(a.error[c]).toBeLessThan(b.error[c] / 2);
    }
  });
});

describe('the draw and its density by hand: a 4 × 2 image black but one blue texel (column 1, row 0)', () => {
  // Luminance 0.0722 there. Across (⅛ ¾ ⅛, wrapping): row 0 is 1, 6, 1, 0 eighths of it; down (held at the edges): row 0's
  // cells 7/8 of that, row 1's 1/8. Both rows' sin θ is sin(π/4). So the cells weigh 7, 42, 7, 0 / 1, 6, 1, 0: 64 in all.
  const rgb = new Float32Array(4 * 2 * 3);
  rgb[3 * 1 + 2] = 1;
  const light = imageLight({ width: 4, height: 2, rgb }), d = new Float64Array(3);
  const at = (u: number, v: number) => { imageDirection(d, u, v); return light.lights!.density(d[0], d[1], d[2]); };
  const perShare = 8 / (2 * Math.PI * Math.PI * Math.SQRT1_2);

  it('the density: each cell\'s share × 8 texels ÷ (2π² sin θ), 0 where the cell has none, 0 at the poles', () => {
    expect(at(1.5 / 4, 0.25)).toBeCloseTo((42 / 64) * perShare, 12);
    expect(at(0.5 / 4, 0.25)).toBeCloseTo((7 / 64) * perShare, 12);
    expect(at(2.5 / 4, 0.25)).toBeCloseTo((7 / 64) * perShare, 12);
    expect(at(0.5 / 4, 0.75)).toBeCloseTo((1 / 64) * perShare, 12);
    expect(at(1.5 / 4, 0.75)).toBeCloseTo((6 / 64) * perShare, 12);
    expect(at(3.5 / 4, 0.25)).toBe(0);
    expect(light.lights!.density(0, 1, 0)).toBe(0);
    expect(light.lights!.density(0, -1, 0)).toBe(0);
    // −x, at u = 1 exactly (atan2(+0, −1) = π): the last column's cell, not past it.
    expect(light.lights!.density(-1, 0, 0)).toBeCloseTo(0, 12);
    expect(light.lights!.density(-Math.SQRT1_2, 0, Math.SQRT1_2 * 1e-9)).toBe(0);
  });

  it('the draw: (u, v) through the CDFs to a point uniform in the cell, where its share says', () => {
    const uvOf = (u: number, v: number) => {
      light.lights!.draw(d, u, v, 0.5);
      return [0.5 + Math.atan2(d[2], d[0]) / (2 * Math.PI), Math.acos(d[1]) / Math.PI];
    };
    // v = 0.25: 16 of row 0's 56 cumulative → row 0, 16/56 of it; u = (7 + 42·¼)/56 → column 1, a quarter in.
    const [u1, v1] = uvOf((7 + 42 * 0.25) / 56, (0.25 * 56) / 64);
    expect(u1).toBeCloseTo((1 + 0.25) / 4, 12);
    expect(v1).toBeCloseTo((0 + 0.25) / 2, 12);
    // v past row 0's 56 of 64: row 1, (60 − 56)/8 = ½ into it; u = (1 + 6·0.8)/8: column 1, 0.8 in.
    const [u2, v2] = uvOf((1 + 6 * 0.8) / 8, 60 / 64);
    expect(u2).toBeCloseTo((1 + 0.8) / 4, 12);
    expect(v2).toBeCloseTo((1 + 0.5) / 2, 12);
  });
});
