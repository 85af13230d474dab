// Light from an environment as the renderers will draw it (docs/pbr.md#the-split-sum): the specular lobe split into the environment
// prefiltered by roughness times the table of math/dfg.ts, and the diffuse lobe from the irradiance. Here without
// any discretisation (every lookup integrated afresh), so that comparing it with the reference's Monte Carlo
// (reference/pbr-light.ts) measures the split sum's own error; the renderers' maps add theirs on top.
// Tied down by tests/unit/split-sum.test.ts.
import { dfg, hammersley } from './dfg';
import { ggxNormal, reflectAbout } from './ggx-sample';
import { DIELECTRIC_F0 } from './pbr';

/** out = the radiance arriving from the unit direction (x, y, z), linear RGB. */
export type RadianceFn = (out: Float64Array, x: number, y: number, z: number) => void;

const xi = new Float64Array(2), h = new Float64Array(3), l = new Float64Array(3), rad = new Float64Array(3), toSurface = new Float64Array(3);

/**
 * out = the environment prefiltered for roughness r about the unit direction R: Σ L(l)(R·l) / Σ (R·l) over l = R reflected about
 * h, h drawn from the GGX lobe about R (n = v = R, the split sum's assumption) with `samples` Hammersley points; α at least 10⁻⁴.
 */
export function prefiltered(out: Float64Array, env: RadianceFn, r: ArrayLike<number>, roughness: number, samples: number): Float64Array {
  const rr = Math.min(1, Math.max(0, roughness)), alpha = Math.max(1e-4, rr * rr);
  toSurface[0] = -r[0]; toSurface[1] = -r[1]; toSurface[2] = -r[2];
  let s0 = 0, s1 = 0, s2 = 0, w = 0;
  for (let i = 0; i < samples; i++) {
    hammersley(i, samples, xi);
    ggxNormal(h, alpha, xi[0], xi[1], r);
    reflectAbout(l, toSurface, h);
    const nl = r[0] * l[0] + r[1] * l[1] + r[2] * l[2];
    if (nl <= 0) continue;
    env(rad, l[0], l[1], l[2]);
    s0 += rad[0] * nl; s1 += rad[1] * nl; s2 += rad[2] * nl;
    w += nl;
  }
  // w > 0: the first point (ξ₁ = ½/samples) is within a hair of R, whatever the roughness.
  out[0] = s0 / w; out[1] = s1 / w; out[2] = s2 / w;
  return out;
}

/** out = the irradiance E(n) = ∫ L(l)(n·l) dω: π times the mean of L over cosine-distributed l (GGX at α = 1 is the cosine lobe). */
export function irradiance(out: Float64Array, env: RadianceFn, n: ArrayLike<number>, samples: number): Float64Array {
  let s0 = 0, s1 = 0, s2 = 0;
  for (let i = 0; i < samples; i++) {
    hammersley(i, samples, xi);
    ggxNormal(l, 1, xi[0], xi[1], n);
    env(rad, l[0], l[1], l[2]);
    s0 += rad[0]; s1 += rad[1]; s2 += rad[2];
  }
  out[0] = (Math.PI * s0) / samples; out[1] = (Math.PI * s1) / samples; out[2] = (Math.PI * s2) / samples;
  return out;
}

/**
 * out = where a rough lobe's light mostly comes from (Lagarde and de Rousiers, "Moving Frostbite to PBR", 2014): v mirrored
 * about n (`toSurface` = −v), drawn toward n by 1 − s with s = (1 − α)(√(1 − α) + α), unit. α = roughness²; at α = 0 the mirror direction.
 */
export function dominantDirection(out: Float64Array, toSurface: ArrayLike<number>, n: ArrayLike<number>, roughness: number): Float64Array {
  reflectAbout(out, toSurface, n);
  const r = Math.min(1, Math.max(0, roughness)), a = r * r, s = (1 - a) * (Math.sqrt(1 - a) + a);
  out[0] = n[0] + (out[0] - n[0]) * s; out[1] = n[1] + (out[1] - n[1]) * s; out[2] = n[2] + (out[2] - n[2]) * s;
  const len = Math.hypot(out[0], out[1], out[2]);
  out[0] /= len; out[1] /= len; out[2] /= len;
  return out;
}

const ab = new Float64Array(2), spec = new Float64Array(3), diff = new Float64Array(3), refl = new Float64Array(3);

/**
 * out = the light a metallic-roughness surface (linear `base`, `metallic`, `roughness`; unit normal n, unit v toward the viewer)
 * sends toward v under `env`, by the split sum: prefiltered(R, r)·(F0·A + B) + c_diff·(1 − F0)·E(n)/π, with R the lobe's
 * dominant direction (dominantDirection), (A, B) = dfg(n·v, r), F0 = 0.04·(1 − metallic) + base·metallic and c_diff = base·(1 − metallic). Seen from behind: 0.
 */
export function splitSum(
  out: Float64Array, base: ArrayLike<number>, metallic: number, roughness: number, n: ArrayLike<number>, v: ArrayLike<number>,
  env: RadianceFn, samples: number,
): Float64Array {
  const nv = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
  if (!(nv > 0)) {
    out[0] = out[1] = out[2] = 0;
    return out;
  }
  toSurface[0] = -v[0]; toSurface[1] = -v[1]; toSurface[2] = -v[2];
  dominantDirection(refl, toSurface, n, roughness);
  prefiltered(spec, env, refl, roughness, samples);
  irradiance(diff, env, n, samples);
  dfg(ab, nv, roughness);
  for (let c = 0; c !== 3; c++) {
    const f0 = DIELECTRIC_F0 * (1 - metallic) + base[c] * metallic;
    out[c] = spec[c] * (f0 * ab[0] + ab[1]) + base[c] * (1 - metallic) * (1 - f0) * diff[c] / Math.PI;
  }
  return out;
}
