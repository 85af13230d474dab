// Fresnel models of docs/rendering.md#fresnel-models: exact (Brewster, 0°, 90°), Schlick, classic (the original prototype's).
import { describe, expect, it } from 'vitest';
import { fresnel, fresnelClassic, fresnelExact, fresnelSchlick, FRESNEL_MODELS } from '../../src/math/fresnel';

const cosDeg = (deg: number) => Math.cos((deg * Math.PI) / 180);

describe('fresnelExact', () => {
  it('is ((n−1)/(n+1))² at normal incidence: 0.04 for ior 1.5', () => {
    expect(Math.abs(fresnelExact(1, 1.5) - 0.04)).toBeLessThan(1e-12);
    expect(Math.abs(fresnelExact(1, 2) - 1 / 9)).toBeLessThan(1e-12);
  });

  it('gives 0.07396 at Brewster’s angle for ior 1.5 (rp vanishes, R = rs²/2)', () => {
    expect(Math.abs(fresnelExact(cosDeg(56.31), 1.5) - 0.07396)).toBeLessThan(1e-5);
    const brewster = Math.cos(Math.atan(1.5));
    // At Brewster, rs = (cos θi − n cos θt)/(cos θi + n cos θt) with cos θt = sin θi: rs² = (5/13)².
    expect(Math.abs(fresnelExact(brewster, 1.5) - 0.5 * (5 / 13) ** 2)).toBeLessThan(1e-12);
  });

  it('is 1 at grazing incidence (90°)', () => {
    expect(fresnelExact(0, 1.5)).toBeCloseTo(1, 12);
    expect(fresnelExact(cosDeg(90), 1.5)).toBeCloseTo(1, 6);
  });

  it('is 0 for ior 1 when cos > 0 and finite at cos = 0', () => {
    for (const c of [1, 0.8, 0.3, 1e-3, 1e-6]) expect(fresnelExact(c, 1), `cos ${c}`).toBeCloseTo(0, 9);
    const g = fresnelExact(0, 1);
    expect(Number.isFinite(g)).toBe(true);
    expect(g).toBeGreaterThanOrEqual(0);
    expect(g).toBeLessThanOrEqual(1);
  });

  it('is 0 for ior 1 right up to grazing (no cancellation in 1 − cos²θ)', () => {
    // With ior 1 there is no interface: cos θt = cos θi exactly. Computing 1 − (1 − cos²)/n²
    // loses cos² below ~1e-8 and turns R into noise, then into 1 when 1 − cos² rounds to 1.
    for (const c of [1e-7, 1e-8, 1e-9, 1e-12]) expect(fresnelExact(c, 1), `cos ${c}`).toBeCloseTo(0, 9);
  });

  it('is the textbook form at every degree for ior 1.33, 1.5 and 2.4 (Snell\'s law, then rs and rp)', () => {
    // Written out here from sin θt = sin θi / n, rs = (cos θi − n cos θt)/(cos θi + n cos θt),
    // rp = (n cos θi − cos θt)/(n cos θi + cos θt), R = (rs² + rp²)/2, not from the module.
    for (const n of [1.33, 1.5, 2.4]) {
      for (let deg = 0; deg < 90; deg++) {
        const ti = (deg * Math.PI) / 180, tt = Math.asin(Math.sin(ti) / n);
        const rs = (Math.cos(ti) - n * Math.cos(tt)) / (Math.cos(ti) + n * Math.cos(tt));
        const rp = (n * Math.cos(ti) - Math.cos(tt)) / (n * Math.cos(ti) + Math.cos(tt));
        expect(fresnelExact(Math.cos(ti), n), `ior ${n} at ${deg}°`).toBeCloseTo((rs * rs + rp * rp) / 2, 12);
      }
    }
    // Two values worked out by hand for ior 1.5: at 45°, sin θt = √2/3, cos θt = √7/3, so
    // rs = (√2/2 − √7/2)/(√2/2 + √7/2) = (√2 − √7)/(√2 + √7) and rp = (1.5·√2/2 − √7/3)/(1.5·√2/2 + √7/3).
    const rs45 = (Math.SQRT2 - Math.sqrt(7)) / (Math.SQRT2 + Math.sqrt(7));
    const rp45 = (0.75 * Math.SQRT2 - Math.sqrt(7) / 3) / (0.75 * Math.SQRT2 + Math.sqrt(7) / 3);
    expect(fresnelExact(Math.SQRT1_2, 1.5)).toBeCloseTo((rs45 ** 2 + rp45 ** 2) / 2, 14);
    expect(fresnelExact(Math.SQRT1_2, 1.5)).toBeCloseTo(0.0502, 4);
    // At 60° (cos ½): sin θt = √3/3, cos θt = √6/3, rs = (1 − √6)/(1 + √6), rp = (0.75 − √6/3)/(0.75 + √6/3).
    const rs60 = (1 - Math.sqrt(6)) / (1 + Math.sqrt(6)), rp60 = (0.75 - Math.sqrt(6) / 3) / (0.75 + Math.sqrt(6) / 3);
    expect(fresnelExact(0.5, 1.5)).toBeCloseTo((rs60 ** 2 + rp60 ** 2) / 2, 14);
    expect(fresnelExact(0.5, 1.5)).toBeCloseTo(0.0892, 4);
  });

  it('increases with angle for ior 1.5 beyond Brewster (and from 0° too)', () => {
    let prev = -Infinity;
    for (let deg = 0; deg <= 90; deg += 0.25) {
      const r = fresnelExact(cosDeg(deg), 1.5);
      expect(r, `at ${deg}°`).toBeGreaterThanOrEqual(prev);
      prev = r;
    }
    expect(fresnelExact(cosDeg(70), 1.5)).toBeGreaterThan(fresnelExact(cosDeg(60), 1.5) + 0.02);
    expect(fresnelExact(cosDeg(85), 1.5)).toBeGreaterThan(fresnelExact(cosDeg(80), 1.5) + 0.1);
  });
});

describe('fresnelSchlick', () => {
  it('is R0 at 0° and 1 at 90°', () => {
    expect(fresnelSchlick(1, 1.5)).toBeCloseTo(0.04, 12);
    expect(fresnelSchlick(1, 3)).toBeCloseTo(0.25, 12);
    expect(fresnelSchlick(0, 1.5)).toBeCloseTo(1, 12);
  });

  it('is R0 + (1 − R0)(1 − cos)^5', () => {
    expect(fresnelSchlick(0.5, 1.5)).toBeCloseTo(0.04 + 0.96 / 32, 12);
    // ior 2: R0 = 1/9; cos 0.2: (0.8)^5 = 0.32768 → 1/9 + (8/9)·0.32768.
    expect(fresnelSchlick(0.2, 2)).toBeCloseTo(1 / 9 + (8 / 9) * 0.32768, 12);
    // cos 0.9, ior 1.5: 0.04 + 0.96·10⁻⁵.
    expect(fresnelSchlick(0.9, 1.5)).toBeCloseTo(0.04 + 0.96e-5, 12);
  });

  it('stays within 0.02..0.05 of the exact model at its worst for ior 1.5', () => {
    let worst = 0;
    for (let i = 0; i <= 10000; i++) {
      const c = i / 10000;
      worst = Math.max(worst, Math.abs(fresnelExact(c, 1.5) - fresnelSchlick(c, 1.5)));
    }
    expect(worst).toBeGreaterThan(0.02);
    expect(worst).toBeLessThan(0.05);
  });
});

describe('fresnelClassic', () => {
  it('is (1 − cosθ)³ whatever the ior', () => {
    for (const deg of [0, 15, 30, 45, 60, 75, 89, 90]) {
      const c = cosDeg(deg);
      expect(fresnelClassic(c)).toBeCloseTo((1 - c) ** 3, 14);
      expect(fresnel('classic', c, 7)).toBeCloseTo((1 - c) ** 3, 14);
    }
    expect(fresnelClassic(0.5)).toBe(0.125);
  });
});

describe('fresnel dispatch and clamping', () => {
  it('dispatches by model name', () => {
    expect(fresnel('exact', 0.6, 1.5)).toBe(fresnelExact(0.6, 1.5));
    expect(fresnel('schlick', 0.6, 1.5)).toBe(fresnelSchlick(0.6, 1.5));
    expect(fresnel('classic', 0.6, 1.5)).toBe(fresnelClassic(0.6));
  });

  it('FRESNEL_MODELS, the fresnel attribute\'s keywords, are the three models', () => {
    expect(FRESNEL_MODELS).toEqual(['exact', 'schlick', 'classic']);
  });

  it('clamps cos outside [0, 1] in every model', () => {
    for (const model of FRESNEL_MODELS) {
      for (const ior of [1, 1.5, 10]) {
        for (const c of [1.0000001, 1.5, -0.1, -2]) {
          const f = fresnel(model, c, ior);
          expect(Number.isFinite(f), `${model} ior ${ior} cos ${c}`).toBe(true);
          expect(f).toBeGreaterThanOrEqual(0);
          expect(f).toBeLessThanOrEqual(1);
        }
        expect(fresnel(model, 1.0000001, ior)).toBeCloseTo(fresnel(model, 1, ior), 12);
        expect(fresnel(model, -0.1, ior)).toBeCloseTo(fresnel(model, 0, ior), 12);
      }
    }
  });
});
