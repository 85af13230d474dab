// The reference's light on a metallic-roughness surface from an environment (docs/pbr.md#the-reference):
// L(v) = ∫ f(l, v)·L_env(l)·(n·l) dω by Monte Carlo, one-sample multiple importance sampling over
// three ways of drawing l — the GGX lobe (h with density D(h)(n·h), l = v reflected about h), the
// cosine lobe, and the environment's own bright parts when it can draw them — each sample weighted
// by the balance heuristic, f·L·cos / Σ cᵢ·pᵢ(l), which is unbiased wherever some pᵢ covers f·L.
// It reports its own noise: the standard error of the mean, per channel.
import { ggxD } from '../math/ggx';
import { ggxNormal, reflectAbout } from '../math/ggx-sample';
import { gltfBrdf, type PbrPoint } from '../math/pbr';
import { panelSolidAngle, samplePanel, studioPanelAt, studioRadiance, STUDIO_PANELS } from '../math/studio';

/** Light arriving from a direction, and (optionally) a way to draw directions by it. */
export interface EnvironmentLight {
  /** out = the radiance arriving from the unit direction l (linear RGB). */
  radiance(out: Float64Array, x: number, y: number, z: number): void;
  /** Its bright parts, where it can draw directions by them: `draw` from (u, v, w) ∈ [0, 1)³, with density `density`. */
  lights?: {
    draw(out: Float64Array, u: number, v: number, w: number): void;
    density(x: number, y: number, z: number): number;
  };
}

export interface LightEstimate {
  /** Mean outgoing radiance toward v, linear RGB. */
  mean: Float64Array;
  /** Standard error of that mean, per channel. */
  error: Float64Array;
}

const dot = (a: ArrayLike<number>, b: ArrayLike<number>) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/**
 * The radiance a surface of material `m` (unit normal n) sends toward the unit direction v under
 * `env`, from `count` samples; `random` gives numbers in [0, 1) (the caller's seeded sequence).
 */
/**
 * How often each way draws, [GGX lobe, cosine lobe, lights]: half by the environment's lights where it
 * has them; the rest shared between the lobes by how specular the surface is — its mean F₀ plus half
 * its metallic, within [¼, ¾] — so that each lobe gets at least a quarter.
 */
export function strategyShares(m: PbrPoint, lights: boolean): [number, number, number] {
  const light = lights ? 0.5 : 0;
  const meanBase = (m.baseColor[0] + m.baseColor[1] + m.baseColor[2]) / 3;
  const f0 = 0.04 * (1 - m.metallic) + meanBase * m.metallic;
  const specular = Math.min(0.75, Math.max(0.25, f0 + m.metallic / 2));
  return [(1 - light) * specular, (1 - light) * (1 - specular), light];
}

/**
 * The radiance a surface of material `m` (unit normal n) sends toward the unit direction v under
 * `env`, from `count` samples; `random` gives numbers in [0, 1) (the caller's seeded sequence).
 */
export function environmentLight(m: PbrPoint, n: ArrayLike<number>, v: ArrayLike<number>, env: EnvironmentLight, count: number, random: () => number): LightEstimate {
  const mean = new Float64Array(3), error = new Float64Array(3);
  if (count <= 0) return { mean, error };
  const nv = dot(n, v);
  // Stryker disable next-line ConditionalExpression,EqualityOperator: a shortcut: seen from behind, f = 0 for every sample (gltfBrdf)
  if (nv <= 0) return { mean, error };
  const [cSpec, cDiff, cLight] = strategyShares(m, env.lights !== undefined);
  // α below 10⁻⁴ is a mirror for any picture: its lobe is drawn as at 10⁻⁴ (D would be a delta).
  const alpha = Math.max(m.alpha, 1e-4);
  const l = new Float64Array(3), h = new Float64Array(3), f = new Float64Array(3), L = new Float64Array(3);
  const toSurface = new Float64Array([-v[0], -v[1], -v[2]]);
  const sum = new Float64Array(3), sum2 = new Float64Array(3);
  for (let k = 0; k < count; k++) {
    // The way is picked stratified over the samples ((k + ξ)/count), so each way draws its share of them to within one: unbiased
    // still (the mean over k of a pick uniform in its stratum is a pick uniform in [0, 1)), without the noise of how many each drew.
    const pick = (k + random()) / count, u1 = random(), u2 = random();
    // Stryker disable next-line EqualityOperator: pick exactly at a share's end is one number in 2⁵³
    const way = pick < cSpec ? 0 : pick < cSpec + cDiff ? 1 : 2;
    if (way === 0) {
      ggxNormal(h, alpha, u1, u2, n);
      reflectAbout(l, toSurface, h);
    } else if (way === 1) {
      // GGX at α = 1 is the cosine lobe: D = 1/π, density cosθ/π.
      ggxNormal(l, 1, u1, u2, n);
    } else {
      env.lights!.draw(l, u1, u2, random());
    }
    const nl = dot(n, l);
    // Stryker disable next-line ConditionalExpression,EqualityOperator: a shortcut: below the surface f = 0 (gltfBrdf)
    if (nl <= 0) continue;
    // The half vector of l and v, and each way's density for this l. v·h = (1 + v·l)/|l + v| ≥ 0,
    // and p > 0: the cosine lobe's share is at least an eighth and n·l > 0.
    h[0] = l[0] + v[0]; h[1] = l[1] + v[1]; h[2] = l[2] + v[2];
    const hl = Math.hypot(h[0], h[1], h[2]);
    h[0] /= hl; h[1] /= hl; h[2] /= hl;
    const nh = dot(n, h), vh = dot(v, h);
    const pLight = cLight > 0 ? env.lights!.density(l[0], l[1], l[2]) : 0;
    const p = (cSpec * ggxD(alpha, nh) * nh) / (4 * vh) + (cDiff * nl) / Math.PI + cLight * pLight;
    gltfBrdf(f, { baseColor: m.baseColor, metallic: m.metallic, alpha }, nl, nv, nh, vh);
    env.radiance(L, l[0], l[1], l[2]);
    // Stryker disable next-line EqualityOperator: c = 3 reads f[3] (undefined) into sum[3], which a typed array ignores
    for (let c = 0; c < 3; c++) {
      const x = (f[c] * L[c] * nl) / p;
      sum[c] += x;
      sum2[c] += x * x;
    }
  }
  // Stryker disable next-line EqualityOperator: c = 3 writes mean[3] and error[3], which a typed array ignores
  for (let c = 0; c < 3; c++) {
    mean[c] = sum[c] / count;
    const variance = Math.max(0, sum2[c] / count - mean[c] * mean[c]);
    error[c] = Math.sqrt(variance / count);
  }
  return { mean, error };
}

// The studio's panels drawn by their power (solid angle × radiance), a direction uniform on each.
const POWER = STUDIO_PANELS.map((p) => panelSolidAngle(p) * p.radiance);
const TOTAL = POWER.reduce((a, b) => a + b, 0);
const CHANCE = POWER.map((w) => w / TOTAL);

/** The neutral studio (math/studio.ts) as an environment: evaluated exactly, drawn by its panels. */
export const STUDIO_LIGHT: EnvironmentLight = {
  radiance(out, x, y, z) {
    out[0] = out[1] = out[2] = studioRadiance(x, y, z);
  },
  lights: {
    draw(out, u, v, w) {
      // The panel whose share of the power w falls in: the last one for w past the others (and rounding).
      let i = 0, end = CHANCE[0];
      // Stryker disable next-line EqualityOperator,ArithmeticOperator: w at a share's end is one number in 2⁵³; the shares sum to 1, so w < 1 stops at the last
      while (w >= end && i < CHANCE.length - 1) end += CHANCE[++i];
      samplePanel(out, STUDIO_PANELS[i], u, v);
    },
    density(x, y, z) {
      const i = studioPanelAt(x, y, z);
      return i < 0 ? 0 : CHANCE[i] / panelSolidAngle(STUDIO_PANELS[i]);
    },
  },
};
