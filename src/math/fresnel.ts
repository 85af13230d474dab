// Fresnel reflectance models of docs/rendering.md#fresnel-models; the GLSL in shaders/glass.frag mirrors these.
// Shared by the float64 reference (reference/shade.ts) and the software renderer
// (software/glass-shader.ts), so comparing those two cannot see a fault here: tied down by
// tests/unit/fresnel.test.ts's hand-computed values (normal incidence, Brewster's angle, 45°,
// 60°, the textbook Snell's-law form at every degree, Schlick and classic at worked points),
// and by software-glass.test.ts and reference-pixels.test.ts, which write each model out themselves.

export type FresnelModel = 'exact' | 'schlick' | 'classic';
export const FRESNEL_MODELS: readonly FresnelModel[] = ['exact', 'schlick', 'classic'];

// Stryker disable next-line EqualityOperator: at 0 and at 1 the clamp returns x itself either way
const clamp01 = (x: number) => (x < 0 ? 0 : x > 1 ? 1 : x);

/** Unpolarized dielectric reflectance from air into a medium of index `ior` ≥ 1. */
export function fresnelExact(cosTheta: number, ior: number): number {
  const ci = clamp01(cosTheta);
  // cosθt = √(n² − 1 + cos²θi)/n: exact for n = 1 (no 1 − cos² rounding at grazing incidence).
  const ct = Math.sqrt(Math.max(ior * ior - 1 + ci * ci, 0)) / ior;
  // max(…, tiny) keeps ior = 1 at grazing incidence finite (0/0 otherwise).
  const rs = (ci - ior * ct) / Math.max(ci + ior * ct, 1e-30);
  const rp = (ct - ior * ci) / Math.max(ct + ior * ci, 1e-30);
  return 0.5 * (rs * rs + rp * rp);
}

/** Schlick's approximation: R0 + (1 − R0)(1 − cosθ)^5. */
export function fresnelSchlick(cosTheta: number, ior: number): number {
  const r0 = ((ior - 1) / (ior + 1)) ** 2;
  return r0 + (1 - r0) * (1 - clamp01(cosTheta)) ** 5;
}

/** The original prototype's term, verbatim: (1 − cosθ)^3 (ignores ior). */
export function fresnelClassic(cosTheta: number): number {
  return (1 - clamp01(cosTheta)) ** 3;
}

export function fresnel(model: FresnelModel, cosTheta: number, ior: number): number {
  switch (model) {
    case 'schlick': return fresnelSchlick(cosTheta, ior);
    case 'classic': return fresnelClassic(cosTheta);
    default: return fresnelExact(cosTheta, ior);
  }
}
