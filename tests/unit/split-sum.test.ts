// The split sum (src/math/split-sum.ts, docs/pbr.md#the-split-sum): under a uniform sky it is exact to the table's
// precision (the prefiltered sky is the sky, the irradiance π); its irradiance and prefiltering against quadratures; and,
// in the studio, its error against the reference's Monte Carlo (reference/pbr-light.ts) by roughness — the
// approximation's own error, which the renderers' maps will add to.
import { describe, expect, it } from 'vitest';
import { dominantDirection, irradiance, prefiltered, splitSum, type RadianceFn } from '../../src/math/split-sum';
import { dfg } from '../../src/math/dfg';
import { environmentLight, STUDIO_LIGHT } from '../../src/reference/pbr-light';
import { studioRadiance } from '../../src/math/studio';
import { seeded } from './helpers/seeded';

const studio: RadianceFn = (out, x, y, z) => { out[0] = out[1] = out[2] = studioRadiance(x, y, z); };
const sky: RadianceFn = (out) => { out[0] = 1; out[1] = 0.5; out[2] = 0.25; };
const unit = (a: number[]) => { const l = Math.hypot(...a); return a.map((x) => x / l); };

describe('the split sum', () => {
  it('under a uniform sky: prefiltered = the sky, E = π·sky, the light = sky·(F0·A + B) + c_diff·(1 − F0)·sky', () => {
    const out = new Float64Array(3);
    expect([...prefiltered(out, sky, [0, 1, 0], 0.6, 256)].map((x) => +x.toFixed(12))).toEqual([1, 0.5, 0.25]);
    irradiance(out, sky, unit([0.3, 1, 0.2]), 256);
    [Math.PI, Math.PI / 2, Math.PI / 4].forEach((e, c) => expect(out[c]).toBeCloseTo(e, 12));
    const n = [0, 1, 0], v = unit([0.6, 0.8, 0]), ab = dfg([0, 0], 0.8, 0.5);
    splitSum(out, [0.9, 0.5, 0.2], 0.25, 0.5, n, v, sky, 256);
    [1, 0.5, 0.25].forEach((L, c) => {
      const base = [0.9, 0.5, 0.2][c], f0 = 0.04 * 0.75 + base * 0.25;
      expect(out[c]).toBeCloseTo(L * (f0 * ab[0] + ab[1]) + base * 0.75 * (1 - f0) * L, 12);
    });
    // Seen from behind, or exactly edge-on: nothing.
    expect([...splitSum(out, [1, 1, 1], 1, 0.5, n, [0, -1, 0], sky, 16)]).toEqual([0, 0, 0]);
    expect([...splitSum(out, [1, 1, 1], 1, 0.5, n, [1, 0, 0], sky, 16)]).toEqual([0, 0, 0]);
    // A tilted normal, a view with all three components: n·v = 0.8·0.6 + … worked by the same rule.
    const nt = unit([0.3, 0.8, -0.5]), vt = unit([-0.4, 0.5, -0.6]);
    const mu = nt[0] * vt[0] + nt[1] * vt[1] + nt[2] * vt[2], abt = dfg([0, 0], mu, 0.5);
    splitSum(out, [0.9, 0.5, 0.2], 0.25, 0.5, nt, vt, sky, 256);
    [1, 0.5, 0.25].forEach((L, c) => {
      const base = [0.9, 0.5, 0.2][c], f0 = 0.04 * 0.75 + base * 0.25;
      expect(out[c]).toBeCloseTo(L * (f0 * abt[0] + abt[1]) + base * 0.75 * (1 - f0) * L, 12);
    });
  });

  it('the dominant direction: the mirror direction when polished, the normal at roughness 1, between by s = (1 − α)(√(1 − α) + α)', () => {
    const out = new Float64Array(3), n = [0, 1, 0], v = unit([0.6, 0.8, 0]), toSurface = v.map((x) => -x);
    expect([...dominantDirection(out, toSurface, n, 0)].map((x) => +x.toFixed(12))).toEqual([-0.6, 0.8, 0]);
    expect([...dominantDirection(out, toSurface, n, 1)].map((x) => +x.toFixed(12))).toEqual([0, 1, 0]);
    // α = 0.25: s = 0.75·(√0.75 + 0.25) = 0.83452; n + (R − n)·s = (−0.5007, 0.8331, 0), then unit.
    const s5 = 0.75 * (Math.sqrt(0.75) + 0.25), d = [-0.6 * s5, 1 + (0.8 - 1) * s5, 0], len = Math.hypot(d[0], d[1]);
    dominantDirection(out, toSurface, n, 0.5);
    expect(out[0]).toBeCloseTo(d[0] / len, 12);
    expect(out[1]).toBeCloseTo(d[1] / len, 12);
    expect(out[2]).toBe(0);
    // A tilted normal: the mirror direction R = 2(n·v)n − v, then n + (R − n)·s, unit.
    const nt = unit([0.3, 0.8, -0.5]), vt = unit([-0.4, 0.5, -0.6]), k = 2 * (nt[0] * vt[0] + nt[1] * vt[1] + nt[2] * vt[2]);
    const rt = [0, 1, 2].map((c) => k * nt[c] - vt[c]), dt = [0, 1, 2].map((c) => nt[c] + (rt[c] - nt[c]) * s5), lt = Math.hypot(...dt);
    dominantDirection(out, vt.map((x) => -x), nt, 0.5);
    for (let c = 0; c < 3; c++) expect(out[c]).toBeCloseTo(dt[c] / lt, 12);
  });

  it('the studio\'s irradiance and prefiltered light against quadratures over the hemisphere (within 1 %)', () => {
    /** ∫ L(l)·w(l) dω and ∫ w(l) dω about the unit direction `a`, on a grid of μ = a·l and φ, for a weight w of μ. */
    const integrate = (a: number[], w: (mu: number) => number, steps = 600): [number, number] => {
      // A frame about a (a is +y here or not far from it).
      const t1 = unit([a[1], -a[0], 0]), t2 = [a[1] * t1[2] - a[2] * t1[1], a[2] * t1[0] - a[0] * t1[2], a[0] * t1[1] - a[1] * t1[0]];
      let sum = 0, wsum = 0;
      for (let i = 0; i < steps; i++) {
        const mu = (i + 0.5) / steps, sn = Math.sqrt(1 - mu * mu);
        for (let j = 0; j < 2 * steps; j++) {
          const p = ((j + 0.5) / (2 * steps)) * 2 * Math.PI, c = Math.cos(p) * sn, d = Math.sin(p) * sn;
          const l = [0, 1, 2].map((k) => a[k] * mu + t1[k] * c + t2[k] * d);
          const cell = (1 / steps) * (Math.PI / steps);
          sum += studioRadiance(l[0], l[1], l[2]) * w(mu) * cell;
          wsum += w(mu) * cell;
        }
      }
      return [sum, wsum];
    };
    const out = new Float64Array(3);
    for (const n of [[0, 1, 0], unit([0.3, 0.8, -0.5])]) {
      const [e] = integrate(n, (mu) => mu);
      irradiance(out, studio, n, 4096);
      expect(Math.abs(out[0] - e) / e, `E at ${n}: ${out[0]} against ${e}`).toBeLessThan(0.01);
    }
    // At roughness 1 (α = 1, D = 1/π) the lobe about R = n = v draws l with density D(h)(n·h)/(4 v·h) = 1/(4π) (v·h = n·h):
    // weighted by n·l, the prefiltered light is ∫ L·μ dω / ∫ μ dω = E(R)/π.
    const r = unit([0.2, 0.9, 0.3]);
    const [num, den] = integrate(r, (mu) => mu);
    expect(den).toBeCloseTo(Math.PI, 5);
    prefiltered(out, studio, r, 1, 4096);
    expect(Math.abs(out[0] - num / den) / (num / den), `prefiltered: ${out[0]} against ${num / den}`).toBeLessThan(0.01);
  });

  /**
   * The worst relative error over three views (n·v 0.96, 0.68 and 0.31; the middle one faces the key panel) measured here, by
   * metallic and roughness; each bound is the figure plus one percentage point (the reference's own noise is at most 0.92 %,
   * and every number drawn is seeded). Without the dominant direction (the mirror direction itself) the metal's were 10.0,
   * 29.2, 29.5 and 32.6 % at roughness 0.25 … 1.
   */
  const MEASURED: Record<number, Record<number, number>> = {
    1: { 0.05: 0.0092, 0.25: 0.0799, 0.5: 0.1572, 0.75: 0.1807, 1: 0.0316 },
    0: { 0.05: 0.0026, 0.25: 0.0486, 0.5: 0.0215, 0.75: 0.0074, 1: 0.0119 },
  };

  it('in the studio, against the reference by roughness (white metal; a dielectric of base 0.8)', () => {
    const rnd = seeded(7);
    const out = new Float64Array(3);
    const n = [0, 1, 0];
    const views = [unit([0, 1, 0.3]), unit([0.5, 0.6, -0.4]), unit([-0.2, 0.3, 0.9])];
    for (const [metallic, base] of [[1, 1], [0, 0.8]]) {
      for (const r of [0.05, 0.25, 0.5, 0.75, 1]) {
        let worst = 0, noise = 0;
        for (const v of views) {
          const ref = environmentLight({ baseColor: [base, base, base], metallic, alpha: Math.max(r * r, 1e-4) }, n, v, STUDIO_LIGHT, 40000, rnd);
          splitSum(out, [base, base, base], metallic, r, n, v, studio, 4096);
          worst = Math.max(worst, Math.abs(out[0] - ref.mean[0]) / ref.mean[0]);
          noise = Math.max(noise, ref.error[0] / ref.mean[0]);
        }
        console.log(`metallic ${metallic} roughness ${r}: worst relative error ${(100 * worst).toFixed(2)} % (reference noise ${(100 * noise).toFixed(2)} %)`);
        expect(worst, `metallic ${metallic}, roughness ${r}`).toBeLessThanOrEqual(MEASURED[metallic][r] + 0.01);
      }
    }
  });
});
