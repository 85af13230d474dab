// glTF's metallic-roughness BRDF (src/math/pbr.ts, docs/pbr.md#the-brdf) against values worked by
// hand: D, V and F at normal incidence and at a 90° pair of directions, the metallic mix channel
// by channel, and the lobe's energy by quadrature — 1 − ln 2 for a white metal at roughness 1,
// where D = 1/π and V = ½/(n·l + n·v) make the integral one of calculus.
import { describe, expect, it } from 'vitest';
import { DIELECTRIC_F0, PUNCTUAL_MIN_ALPHA, gltfBrdf, punctualAlpha, schlickFresnel, smithVisibility } from '../../src/math/pbr';
import { ggxD } from '../../src/math/ggx';

// n = +z, l = (0.6, 0, 0.8), v = (−0.8, 0, 0.6): l ⟂ v, so h is 45° from each:
// n·l = 0.8, n·v = 0.6, h = (−0.2, 0, 1.4)/√2, n·h = 1.4/√2 = 0.98995, v·h = 1/√2.
const NL = 0.8, NV = 0.6, NH = 1.4 / Math.SQRT2, VH = Math.SQRT1_2;
const ALPHA = 0.25; // roughness 0.5

describe('the three terms', () => {
  it('V: ½ over the two height-correlated terms, and ¼ at normal incidence whatever α', () => {
    // α² = 1/16: 0.8·√(0.36·15/16 + 1/16) = 0.8·√0.4 = 0.505964; 0.6·√(0.64·15/16 + 1/16) = 0.6·√0.6625 = 0.488365.
    expect(smithVisibility(ALPHA, NL, NV)).toBeCloseTo(0.5 / (0.8 * Math.sqrt(0.4) + 0.6 * Math.sqrt(0.6625)), 14);
    expect(smithVisibility(ALPHA, NL, NV)).toBeCloseTo(0.502852, 6);
    for (const a of [0.01, 0.25, 1]) expect(smithVisibility(a, 1, 1)).toBeCloseTo(0.25, 14);
    // α = 1: √(…) = 1, V = ½/(n·l + n·v).
    expect(smithVisibility(1, NL, NV)).toBeCloseTo(0.5 / 1.4, 14);
    expect([smithVisibility(ALPHA, 0, NV), smithVisibility(ALPHA, NL, 0), smithVisibility(ALPHA, NL, -0.1)]).toEqual([0, 0, 0]);
  });

  it('F: f0 at normal incidence, 1 at grazing, (1 − 1/√2)⁵ of the way at 45°', () => {
    expect(schlickFresnel(0.04, 1)).toBeCloseTo(0.04, 15);
    expect(schlickFresnel(0.04, 0)).toBe(1);
    // (1 − 0.707107)⁵ = 0.292893⁵ = 0.00215551: 0.04 + 0.96 · 0.00215551 = 0.0420693.
    expect(schlickFresnel(0.04, VH)).toBeCloseTo(0.0420693, 7);
    expect(schlickFresnel(0.04, -VH)).toBe(schlickFresnel(0.04, VH));
    expect(schlickFresnel(0.5, 1.2)).toBe(0.5);
    expect(DIELECTRIC_F0).toBeCloseTo(((1.5 - 1) / (1.5 + 1)) ** 2, 15);
  });

  it('D (math/ggx.ts) in glTF\'s form α²/(π((n·h)²(α² − 1) + 1)²)', () => {
    // (0.98·(−15/16) + 1)² = 0.08125² = 0.0066015625: D = 0.0625 / (π · 0.0066015625) = 3.013585.
    expect(ggxD(ALPHA, NH)).toBeCloseTo(0.0625 / (Math.PI * 0.08125 ** 2), 12);
    expect(ggxD(ALPHA, 1)).toBeCloseTo(1 / (Math.PI * 0.0625), 12);
  });
});

describe('the BRDF', () => {
  const f = (baseColor: number[], metallic: number, nl = NL, nv = NV, nh = NH, vh = VH) => Array.from(gltfBrdf([0, 0, 0], { baseColor, metallic, alpha: ALPHA }, nl, nv, nh, vh));

  it('a grey dielectric at normal incidence: 0.96·0.5/π + 0.04·D·V = 0.152789 + 0.050930', () => {
    // D = 1/(π α²) = 5.092958, V = ¼, F = 0.04.
    for (const x of f([0.5, 0.5, 0.5], 0, 1, 1, 1, 1)) expect(x).toBeCloseTo(0.96 * 0.5 / Math.PI + 0.04 * 5.0929582 * 0.25, 6);
  });

  it('a metal at normal incidence: its base colour times D·V = 1.273240, no diffuse', () => {
    expect(f([1, 0.5, 0.25], 1, 1, 1, 1, 1).map((x) => Number(x.toFixed(6)))).toEqual([1.27324, 0.63662, 0.31831]);
  });

  it('a coloured dielectric and a half metal at the 90° pair, channel by channel', () => {
    // D·V = 3.013585 · 0.502852 = 1.515387. Dielectric: F = 0.0420693 in every channel.
    const dv = 3.0135847212666294 * 0.5028516498271286;
    const diel = (b: number) => (1 - 0.0420693) * b / Math.PI + 0.0420693 * dv;
    f([0.5, 0.25, 1], 0).forEach((x, c) => expect(x).toBeCloseTo(diel([0.5, 0.25, 1][c]), 6));
    // Half metal: F0 = 0.02 + b/2, diffuse b/2 · (1 − F)/π.
    const half = (b: number) => {
      const F = schlickFresnel(0.02 + b / 2, VH);
      return (1 - F) * (b / 2) / Math.PI + F * dv;
    };
    f([1, 0.5, 0.25], 0.5).forEach((x, c) => expect(x).toBeCloseTo(half([1, 0.5, 0.25][c]), 12));
    expect(f([1, 0.5, 0.25], 0.5).map((x) => Number(x.toFixed(6)))).toEqual([0.865798, 0.469505, 0.25647]);
  });

  it('is 0 with the light or the viewer below the surface', () => {
    expect(f([1, 1, 1], 0, -0.1)).toEqual([0, 0, 0]);
    expect(f([1, 1, 1], 0, 0)).toEqual([0, 0, 0]);
    expect(f([1, 1, 1], 0, NL, 0)).toEqual([0, 0, 0]);
  });
});

describe('energy: ∫ f·(n·l) dω seen from the normal', () => {
  /** 2π ∫₀^{π/2} f(θ) cosθ sinθ dθ with v = n: h halfway, n·h = v·h = cos(θ/2). Midpoint rule. */
  function albedo(base: number, metallic: number, alpha: number, steps = 20000): number {
    const out = [0, 0, 0];
    let sum = 0;
    for (let i = 0; i < steps; i++) {
      const t = ((i + 0.5) / steps) * (Math.PI / 2), h = Math.cos(t / 2);
      sum += gltfBrdf(out, { baseColor: [base, base, base], metallic, alpha }, Math.cos(t), 1, h, h)[0] * Math.cos(t) * Math.sin(t);
    }
    return 2 * Math.PI * sum * (Math.PI / 2 / steps);
  }

  it('a white metal at roughness 1 keeps 1 − ln 2 of the light: single scattering, darker than white', () => {
    // α = 1: D = 1/π, V = ½/(μ + 1), F = 1: 2π ∫ μ/(2π(μ + 1)) dμ over [0, 1] = 1 − ln 2 = 0.306853.
    expect(albedo(1, 1, 1)).toBeCloseTo(1 - Math.LN2, 6);
  });

  it('a polished white metal keeps nearly all of it, a rough white dielectric a little less than all', () => {
    expect(albedo(1, 1, 0.05 ** 2)).toBeCloseTo(1, 4);
    // Rougher lobes lose more: 0.9973 at α 0.05, 0.9158 at 0.25, 0.6878 at 0.5 (single scattering).
    expect(albedo(1, 1, 0.05)).toBeCloseTo(0.99730, 4);
    expect(albedo(1, 1, 0.25)).toBeCloseTo(0.91581, 4);
    expect(albedo(1, 1, 0.5)).toBeCloseTo(0.68785, 4);
    expect(albedo(1, 0, 1)).toBeCloseTo(0.97223, 4);
  });
});

describe('α under a point or directional light (docs/pbr.md#the-scenes-lights)', () => {
  it('is roughness², clamped to [0, 1], at least 0.002', () => {
    expect(PUNCTUAL_MIN_ALPHA).toBe(0.002);
    expect(punctualAlpha(0.5)).toBe(0.25);
    expect(punctualAlpha(1)).toBe(1);
    expect(punctualAlpha(3)).toBe(1);
    expect(punctualAlpha(0.1)).toBeCloseTo(0.01, 15);
    // √0.002 = 0.0447…: below it, the floor.
    expect(punctualAlpha(0.045)).toBeCloseTo(0.002025, 15);
    expect(punctualAlpha(0.04)).toBe(0.002);
    expect(punctualAlpha(0)).toBe(0.002);
    expect(punctualAlpha(-1)).toBe(0.002);
  });
});
