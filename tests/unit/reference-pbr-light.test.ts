// The reference's light from an environment on a metallic-roughness surface (src/reference/pbr-light.ts,
// docs/pbr.md#the-reference): under a uniform sky it returns the lobe's albedo (1 − ln 2 for a white
// metal at roughness 1, worked out by calculus; the dielectric's by quadrature in tests/unit/pbr.test.ts),
// under the studio what a fine quadrature of the same integral gives, within the noise it reports,
// and drawing the studio's panels makes it less noisy.
import { describe, expect, it } from 'vitest';
import { environmentLight, strategyShares, STUDIO_LIGHT, type EnvironmentLight } from '../../src/reference/pbr-light';
import { gltfBrdf, type PbrPoint } from '../../src/math/pbr';
import { seeded } from './helpers/seeded';

const UP = [0, 1, 0];
const uniform: EnvironmentLight = { radiance: (out) => out.fill(1) };
const radianceOnly: EnvironmentLight = { radiance: STUDIO_LIGHT.radiance };

/** ∫ f·L·(n·l) dω over the hemisphere about +y, on a grid of φ and μ = n·l (the studio's edges lie on it). */
function quadrature(m: PbrPoint, v: number[], env: EnvironmentLight, nMu = 2000, nPhi = 720): number[] {
  const sum = [0, 0, 0], f = [0, 0, 0], L = new Float64Array(3);
  for (let i = 0; i < nMu; i++) {
    const mu = (i + 0.5) / nMu, s = Math.sqrt(1 - mu * mu);
    for (let j = 0; j < nPhi; j++) {
      const phi = -Math.PI + ((j + 0.5) / nPhi) * 2 * Math.PI;
      const l = [s * Math.sin(phi), mu, s * Math.cos(phi)];
      const h = [l[0] + v[0], l[1] + v[1], l[2] + v[2]], hl = Math.hypot(h[0], h[1], h[2]);
      const nh = h[1] / hl, vh = (v[0] * h[0] + v[1] * h[1] + v[2] * h[2]) / hl;
      gltfBrdf(f, m, mu, v[1], nh, vh);
      env.radiance(L, l[0], l[1], l[2]);
      for (let c = 0; c < 3; c++) sum[c] += f[c] * L[c] * mu;
    }
  }
  const cell = (1 / nMu) * ((2 * Math.PI) / nPhi);
  return sum.map((x) => x * cell);
}

/** |estimate − expected| within 4 of its reported standard errors, per channel, and that error below `most`. */
function expectWithin(r: { mean: Float64Array; error: Float64Array }, expected: number[], most: number, slack = 0): void {
  for (let c = 0; c < 3; c++) {
    expect(r.error[c], `channel ${c}: noise`).toBeLessThan(most);
    expect(Math.abs(r.mean[c] - expected[c]), `channel ${c}: ${r.mean[c]} against ${expected[c]} ± ${r.error[c]}`).toBeLessThan(4 * r.error[c] + slack);
  }
}

describe('the shares of the three ways', () => {
  const shares = (baseColor: number[], metallic: number, lights: boolean) => strategyShares({ baseColor, metallic, alpha: 0.25 }, lights).map((x) => Number(x.toFixed(12)));

  it('give a dielectric a quarter of the lobes\' samples for its GGX lobe, and half of all to the lights where there are some', () => {
    // F₀ = 0.04, below the floor of ¼.
    expect(shares([0.5, 0.5, 0.5], 0, false)).toEqual([0.25, 0.75, 0]);
    expect(shares([0.5, 0.5, 0.5], 0, true)).toEqual([0.125, 0.375, 0.5]);
  });

  it('follow F₀ (the base colour\'s mean mixed by metallic) plus half the metallic, within [¼, ¾]', () => {
    // Mean 0.6; F₀ = 0.04 · 0.7 + 0.6 · 0.3 = 0.208; + 0.15 = 0.358.
    expect(shares([0.9, 0.6, 0.3], 0.3, false)).toEqual([0.358, 0.642, 0]);
    // F₀ = 0.02 + 0.1 = 0.12; + 0.25 = 0.37.
    expect(shares([0.2, 0.2, 0.2], 0.5, false)).toEqual([0.37, 0.63, 0]);
    // Gold: F₀ = 0.7333 + 0.5, above the ceiling of ¾.
    expect(shares([1, 0.8, 0.4], 1, true)).toEqual([0.375, 0.125, 0.5]);
  });
});

describe('under a uniform sky of radiance 1', () => {
  it('a white metal at roughness 1 returns 1 − ln 2 (D = 1/π, V = ½/(n·l + n·v), F = 1)', () => {
    const r = environmentLight({ baseColor: [1, 1, 1], metallic: 1, alpha: 1 }, UP, UP, uniform, 20000, seeded(1));
    // Measured: 0.30958 ± 0.00182 (seed 1).
    expectWithin(r, [1 - Math.LN2, 1 - Math.LN2, 1 - Math.LN2], 0.0025);
  });

  it('a white dielectric at roughness 0.25 returns its albedo 0.99658 (pbr.test.ts\'s quadrature), a little under 1', () => {
    const r = environmentLight({ baseColor: [1, 1, 1], metallic: 0, alpha: 0.0625 }, UP, UP, uniform, 20000, seeded(2));
    // Measured: 0.99470 ± 0.00273 (seed 2).
    expectWithin(r, [0.99658, 0.99658, 0.99658], 0.0035);
  });

  it('depends only on the angle between n and v: a tilted normal gives what +y gives', () => {
    const m = { baseColor: [1, 1, 1], metallic: 1, alpha: 1 };
    const n = [1, 2, 3].map((x) => x / Math.sqrt(14));
    const r = environmentLight(m, n, n, uniform, 20000, seeded(7));
    expectWithin(r, [1 - Math.LN2, 1 - Math.LN2, 1 - Math.LN2], 0.0025);
    // v 60° from n, about an axis off every plane: against v 60° from +y.
    const t = [3, 0, -1].map((x) => x / Math.sqrt(10)); // ⟂ n
    const v = n.map((x, c) => 0.5 * x + (Math.sqrt(3) / 2) * t[c]);
    const a = environmentLight({ ...m, alpha: 0.25 }, n, v, uniform, 20000, seeded(8));
    const b = environmentLight({ ...m, alpha: 0.25 }, UP, [Math.sqrt(3) / 2, 0.5, 0], uniform, 20000, seeded(9));
    expect(Math.abs(a.mean[0] - b.mean[0])).toBeLessThan(4 * Math.hypot(a.error[0], b.error[0]));
  });

  it('averages its samples: two samples are the mean of the two one-sample estimates drawn from the same numbers, each way picked in its half', () => {
    const m = { baseColor: [0.9, 0.6, 0.3], metallic: 0.3, alpha: 0.25 };
    const stream = seeded(10), numbers = Array.from({ length: 64 }, stream);
    let at = 0;
    const replay = () => numbers[at++];
    const two = environmentLight(m, UP, [0.6, 0.8, 0], STUDIO_LIGHT, 2, replay);
    // Of two samples, sample k picks its way at (k + ξ)/2, ξ its first number: the one-sample estimates are given that pick.
    let start = 0, k = 0;
    const onePick = () => (at === start ? (k + numbers[at++]) / 2 : numbers[at++]);
    at = start = 0;
    const first = environmentLight(m, UP, [0.6, 0.8, 0], STUDIO_LIGHT, 1, onePick);
    start = at; k = 1;
    const second = environmentLight(m, UP, [0.6, 0.8, 0], STUDIO_LIGHT, 1, onePick);
    for (let c = 0; c < 3; c++) {
      expect(two.mean[c]).toBeCloseTo((first.mean[c] + second.mean[c]) / 2, 14);
      // Two samples x₁, x₂: variance ((x₁ − x₂)/2)², standard error √(variance/2) = |x₁ − x₂| / (2√2).
      expect(two.error[c]).toBeCloseTo(Math.abs(first.mean[c] - second.mean[c]) / (2 * Math.SQRT2), 14);
    }
    expect(first.mean[0]).not.toBe(second.mean[0]);
  });

  it('picks its ways stratified: of 100 samples, the lights draw exactly their half', () => {
    // Every number ½: sample k picks at (k + ½)/100, and the lights' share is the last half, [½, 1): k = 50 … 99.
    // (Picking at the number itself, every sample would pick ½ and draw from the lights: 100.)
    const m = { baseColor: [1, 1, 1], metallic: 1, alpha: 0.25 };
    expect(strategyShares(m, true)[2]).toBe(0.5);
    let draws = 0;
    const counting: EnvironmentLight = {
      radiance: (o) => { o[0] = o[1] = o[2] = 1; },
      lights: { draw: (o) => { draws++; o[0] = 0; o[1] = 1; o[2] = 0; }, density: () => 1 },
    };
    environmentLight(m, UP, UP, counting, 100, () => 0.5);
    expect(draws).toBe(50);
  });

  it('returns nothing for a surface seen from behind, or without samples', () => {
    const m = { baseColor: [1, 1, 1], metallic: 0, alpha: 0.25 };
    expect(Array.from(environmentLight(m, UP, [0, -1, 0], uniform, 100, seeded(3)).mean)).toEqual([0, 0, 0]);
    expect(Array.from(environmentLight(m, UP, UP, uniform, 0, seeded(3)).mean)).toEqual([0, 0, 0]);
  });
});

describe('in the studio', () => {
  it('a grey dielectric seen from its normal: the quadrature\'s value within the reported noise', () => {
    const m = { baseColor: [0.5, 0.5, 0.5], metallic: 0, alpha: 0.25 };
    const r = environmentLight(m, UP, UP, STUDIO_LIGHT, 40000, seeded(4));
    // The grid's error at the panels' edges: well under 0.2 % of the value.
    const q = quadrature(m, UP, radianceOnly);
    // Measured: 0.63497 ± 0.00162 (seed 4).
    expectWithin(r, q, 0.0025, 0.002 * q[0]);
  });

  it('a gold metal seen at an angle: each channel the quadrature\'s value within the reported noise', () => {
    const m = { baseColor: [1, 0.8, 0.4], metallic: 1, alpha: 0.25 };
    const v = [-0.5, Math.SQRT1_2, 0.5];
    const r = environmentLight(m, UP, v, STUDIO_LIGHT, 40000, seeded(5));
    const q = quadrature(m, v, radianceOnly);
    // Measured: (0.72674, 0.58198, 0.29244) ± (0.00388, 0.00311, 0.00156) (seed 5).
    expectWithin(r, q, 0.005, 0.002 * q[0]);
  });

  it('is less noisy drawing the panels than drawing the lobes alone, for the same answer', () => {
    const m = { baseColor: [0.8, 0.8, 0.8], metallic: 0, alpha: 1 };
    const lit = environmentLight(m, UP, UP, STUDIO_LIGHT, 20000, seeded(6));
    const blind = environmentLight(m, UP, UP, radianceOnly, 20000, seeded(6));
    // Measured: ± 0.00380 against ± 0.01081 (0.35 times).
    expect(lit.error[0]).toBeLessThan(0.5 * blind.error[0]);
    expect(Math.abs(lit.mean[0] - blind.mean[0])).toBeLessThan(4 * Math.hypot(lit.error[0], blind.error[0]));
  });
});
