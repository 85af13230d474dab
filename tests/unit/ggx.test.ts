// Rough glass's microfacet maths (docs/rough-glass.md#ggx-microfacets, src/math/ggx.ts), which the reference shares with the renderers:
// the sampled normals against D(m)·cosθm integrated by an independent quadrature, and the
// reflected and refracted directions against Snell's law worked by hand in one plane.
import { describe, expect, it } from 'vitest';
import { ggxAlpha, ggxD, refractThin } from '../../src/math/ggx';
import { ggxNormal, reflectAbout } from '../../src/math/ggx-sample';

const DEG = Math.PI / 180;
/** A unit direction in the xz-plane at angle ψ from +z towards +x. */
const dir = (psiDeg: number) => [Math.sin(psiDeg * DEG), 0, Math.cos(psiDeg * DEG)];
const N = [0, 0, 1];

/** ∫ D(θ)·cosθ·sinθ·2π dθ over [a, b] by the midpoint rule (D written out again, not imported). */
function lobeMass(alpha: number, a: number, b: number, steps = 20000): number {
  let sum = 0;
  const h = (b - a) / steps, a2 = alpha * alpha;
  for (let i = 0; i < steps; i++) {
    const th = a + (i + 0.5) * h, c = Math.cos(th), t = Math.tan(th);
    const d = a2 / (Math.PI * c ** 4 * (a2 + t * t) ** 2);
    sum += d * c * Math.sin(th) * 2 * Math.PI * h;
  }
  return sum;
}

describe('GGX distribution', () => {
  it('α = roughness², clamped to 0..1', () => {
    expect(ggxAlpha(0.3)).toBeCloseTo(0.09, 15);
    expect(ggxAlpha(0)).toBe(0);
    expect(ggxAlpha(-1)).toBe(0);
    expect(ggxAlpha(2)).toBe(1);
  });

  for (const alpha of [0.01, 0.09, 0.36, 1]) {
    it(`α = ${alpha}: D(m)·cosθm integrates to 1 over the hemisphere, and D matches its formula`, () => {
      // Split where the lobe is: most of its mass lies within a few α of the normal.
      const knee = Math.min(Math.PI / 2, Math.atan(20 * alpha));
      expect(lobeMass(alpha, 0, knee) + lobeMass(alpha, knee, Math.PI / 2)).toBeCloseTo(1, 4);
      const th = Math.atan(alpha); // tanθ = α: D = 1/(π α² cos⁴θ · 4)
      const want = 1 / (4 * Math.PI * alpha * alpha * Math.cos(th) ** 4);
      expect(Math.abs(ggxD(alpha, Math.cos(th)) / want - 1)).toBeLessThan(1e-12);
      expect(ggxD(alpha, 0)).toBe(0);
    });

    it(`α = ${alpha}: sampled normals fall into θ bins as D(m)·cosθm says`, () => {
      const n = 4000, bins = [0, 0.5 * alpha, alpha, 2 * alpha, 4 * alpha, Infinity].map((t) => Math.atan(t));
      const counts = new Array(bins.length - 1).fill(0);
      const m = [0, 0, 0];
      for (let i = 0; i < n; i++) {
        for (let j = 0; j < 4; j++) {
          ggxNormal(m, alpha, (i + 0.5) / n, (j + 0.5) / 4, N);
          expect(Math.hypot(m[0], m[1], m[2])).toBeCloseTo(1, 12);
          const th = Math.acos(Math.min(1, m[2]));
          const b = bins.findIndex((x, k) => th >= x && th < bins[k + 1]);
          counts[b]++;
        }
      }
      for (let b = 0; b < counts.length; b++) {
        const want = lobeMass(alpha, bins[b], Math.min(bins[b + 1], Math.PI / 2));
        expect(Math.abs(counts[b] / (4 * n) - want), `bin ${b}`).toBeLessThan(1e-3);
      }
    });
  }

  it('ξ1 = ½ gives tanθm = α, ξ2 turns it about any normal', () => {
    const n = [0, 0.6, -0.8], m = [0, 0, 0], seen: number[][] = [];
    for (const xi2 of [0, 0.25, 0.5, 0.75]) {
      ggxNormal(m, 0.36, 0.5, xi2, n);
      const c = m[0] * n[0] + m[1] * n[1] + m[2] * n[2];
      expect(c).toBeCloseTo(Math.cos(Math.atan(0.36)), 12);
      seen.push([...m]);
    }
    // A quarter turn apart: the tangential parts are perpendicular, a half turn opposite.
    const tang = (v: number[]) => { const c = v[0] * n[0] + v[1] * n[1] + v[2] * n[2]; return v.map((x, k) => x - c * n[k]); };
    const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const s2 = Math.sin(Math.atan(0.36)) ** 2;
    expect(dot(tang(seen[0]), tang(seen[1]))).toBeCloseTo(0, 12);
    expect(dot(tang(seen[0]), tang(seen[2]))).toBeCloseTo(-s2, 12);
  });
});

describe('ggxNormal about any normal', () => {
  const dot = (a: ArrayLike<number>, b: ArrayLike<number>) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  // Normals with every component non-zero, on both sides of z = 0, and straight down (the frame's
  // one special case): (12, 15, 16)/25, (12, −15, −16)/25, (0, 0, −1).
  const normals = [[0.48, 0.6, 0.64], [0.48, -0.6, -0.64], [0, 0, -1]];

  for (const n of normals) {
    it(`n = (${n}): unit m at θm = atan(α·√(ξ1/(1 − ξ1))), quarter turns of ξ2 perpendicular about n`, () => {
      // α = 0.5, ξ1 = 0.8: tanθm = 0.5·√4 = 1, θm = 45°.
      const ms = [0, 0.25, 0.5].map((xi2) => ggxNormal([0, 0, 0], 0.5, 0.8, xi2, n));
      const tang = (m: number[]) => m.map((x, k) => x - dot(m, n) * n[k]);
      for (const m of ms) {
        expect(Math.hypot(m[0], m[1], m[2])).toBeCloseTo(1, 12);
        expect(dot(m, n)).toBeCloseTo(Math.SQRT1_2, 12);
      }
      expect(dot(tang(ms[0] as number[]), tang(ms[1] as number[]))).toBeCloseTo(0, 12);
      expect(dot(tang(ms[0] as number[]), tang(ms[2] as number[]))).toBeCloseTo(-0.5, 12); // sin²45°, opposite
    });
  }
});

describe('reflectAbout and refractThin off the xz-plane', () => {
  // The xz-plane cases turned 30° about z: every component in play, the angles unchanged.
  const DEG30 = 30 * DEG;
  const turned = (v: number[]) => [v[0] * Math.cos(DEG30), v[0] * Math.sin(DEG30), v[2]];

  it('reflects d = (0.48, 0.6, −0.64) about m = (0, 0.6, 0.8): d − 2(d·m)m = (0.48, 0.7824, −0.3968)', () => {
    // d·m = 0.36 − 0.512 = −0.152.
    const r = reflectAbout([0, 0, 0], [0.48, 0.6, -0.64], [0, 0.6, 0.8]);
    for (let k = 0; k < 3; k++) expect(r[k]).toBeCloseTo([0.48, 0.7824, -0.3968][k], 14);
  });

  it('through a facet tilted 10°, turned: the turned result', () => {
    const inside = Math.asin(Math.sin(35 * DEG) / 1.5) / DEG;
    const out = Math.asin(1.5 * Math.sin((10 + inside) * DEG)) / DEG;
    const t = [0, 0, 0];
    expect(refractThin(t, turned(dir(135)), turned(dir(-10)), N, 1.5)).toBe(true);
    for (let k = 0; k < 3; k++) expect(t[k]).toBeCloseTo(turned(dir(180 - out))[k], 12);
  });

  it('a facet seen from behind or edge-on loses the sample, though glass would let it through', () => {
    // d 20° off −z, m 75° off +z on the same side: d·m = sin20°·sin75° − cos20°·cos75° = 0.087 > 0.
    // Taken as the front, it would refract in and out (that path is not what is tested).
    expect(refractThin([0, 0, 0], turned(dir(160)), turned(dir(75)), N, 1.5)).toBe(false);
    // d = (0.6, 0, −0.8), m = (0.8, 0, 0.6): d·m = 0.48 − 0.48 = 0, edge-on.
    expect(refractThin([0, 0, 0], [0.6, 0, -0.8], [0.8, 0, 0.6], N, 1.5)).toBe(false);
  });

  it('a facet that sends the ray back to the viewer\'s side loses it, though the flat face would pass it', () => {
    // d 60° off +z, m 170° off +z (facing down and against d): inside, the ray runs upward at
    // about 41° from +z, inside the flat face's critical cone: out of that face alone it would leave.
    expect(refractThin([0, 0, 0], turned(dir(60)), turned(dir(-170)), N, 1.5)).toBe(false);
    // The same off every axis: n = (2, 2, 1)/3, d = (1, 2, 0)/√5, m = (−2, −1, 2)/3 (d·m = −0.596):
    // inside, the ray makes 37.3° with n, under the critical 41.8°.
    const s5 = Math.sqrt(5);
    expect(refractThin([0, 0, 0], [1 / s5, 2 / s5, 0], [-2 / 3, -1 / 3, 2 / 3], [2 / 3, 2 / 3, 1 / 3], 1.5)).toBe(false);
  });
});

describe('directions off a microfacet', () => {
  it('reflection about a normal tilted 10° turns the mirror direction by 20°', () => {
    // d at 45° incidence (ψ = 135°); about N it leaves at ψ = 45°, about m at ψ = −10° at
    // ψ = 2·(−10°) + 180° − 135° = 25°.
    const r = reflectAbout([0, 0, 0], dir(135), N);
    expect(r.map((x) => +x.toFixed(12))).toEqual(dir(45).map((x) => +x.toFixed(12)));
    const rm = reflectAbout([0, 0, 0], dir(135), dir(-10));
    for (let k = 0; k < 3; k++) expect(rm[k]).toBeCloseTo(dir(25)[k], 12);
  });

  it('through the macro normal the thin glass lets d through unchanged', () => {
    const d = dir(135), t = [0, 0, 0];
    expect(refractThin(t, d, N, N, 1.5)).toBe(true);
    for (let k = 0; k < 3; k++) expect(t[k]).toBeCloseTo(d[k], 14);
  });

  it('through a facet tilted 10°: Snell at the facet, then at the flat face (ior 1.5)', () => {
    // −d at ψ = −45°, m at −10°: incidence 35°; inside sinθ = sin35°/1.5 = 0.382384 → 22.4814°,
    // so the ray runs at 170° − 22.4814° = 147.5186° (32.4814° from −z); out of the flat face
    // sinθ = 1.5·sin 32.4814° = 0.805540 → 53.6624°: ψ = 180° − 53.6624°.
    const inside = Math.asin(Math.sin(35 * DEG) / 1.5) / DEG;
    expect(inside).toBeCloseTo(22.4814, 4);
    const out = Math.asin(1.5 * Math.sin((10 + inside) * DEG)) / DEG;
    expect(out).toBeCloseTo(53.6624, 4);
    const t = [0, 0, 0];
    expect(refractThin(t, dir(135), dir(-10), N, 1.5)).toBe(true);
    for (let k = 0; k < 3; k++) expect(t[k]).toBeCloseTo(dir(180 - out)[k], 12);
  });

  it('is lost to total internal reflection at the flat face, and where the facet faces away', () => {
    // m at −40°: incidence 5°, inside 3.33°, 43.33° from −z > asin(1/1.5) = 41.81°: TIR.
    expect(refractThin([0, 0, 0], dir(135), dir(-40), N, 1.5)).toBe(false);
    // m at 80°: d·m = cos 55° > 0, the facet's back is towards the ray.
    expect(refractThin([0, 0, 0], dir(135), dir(80), N, 1.5)).toBe(false);
    // At ior 1 nothing bends: any facet facing the ray lets d through.
    const t = [0, 0, 0];
    expect(refractThin(t, dir(135), dir(-30), N, 1)).toBe(true);
    for (let k = 0; k < 3; k++) expect(t[k]).toBeCloseTo(dir(135)[k], 12);
  });
});
