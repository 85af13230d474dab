// glTF's metallic-roughness BRDF (docs/pbr.md#the-brdf; the glTF 2.0 specification, Appendix B):
// a Trowbridge-Reitz (GGX) distribution, Smith's height-correlated visibility, Schlick's Fresnel
// with F0 mixed from 0.04 to the base colour by metallic, and a Lambertian diffuse lobe weighted
// by 1 − F. Single scattering: a white rough metal in a white furnace reflects less than it gets.
// Shared by the float64 reference and the software renderer; the GLSL writes the same formulas.
// Tied down by tests/unit/pbr.test.ts (values worked by hand, the lobe's energy by quadrature).
import { ggxAlpha, ggxD } from './ggx';

/** F0 of a dielectric in glTF's model (index 1.5): ((1.5 − 1)/(1.5 + 1))² = 0.04. */
export const DIELECTRIC_F0 = 0.04;

/**
 * Smith's height-correlated visibility V = G / (4·(n·l)·(n·v)):
 * 0.5 / ((n·l)·√((n·v)²(1 − α²) + α²) + (n·v)·√((n·l)²(1 − α²) + α²)); 0 where either cosine is not positive.
 */
export function smithVisibility(alpha: number, nl: number, nv: number): number {
  if (nl <= 0 || nv <= 0) return 0;
  const a2 = alpha * alpha;
  const gv = nl * Math.sqrt(nv * nv * (1 - a2) + a2);
  const gl = nv * Math.sqrt(nl * nl * (1 - a2) + a2);
  return 0.5 / (gv + gl);
}

/** Schlick's Fresnel for one channel: f0 + (1 − f0)(1 − |v·h|)⁵. */
export function schlickFresnel(f0: number, vh: number): number {
  const k = 1 - Math.min(Math.abs(vh), 1);
  const k2 = k * k;
  return f0 + (1 - f0) * k2 * k2 * k;
}

/** The material of one shading point: linear base colour, metallic and GGX α (= roughness²). */
export interface PbrPoint {
  baseColor: ArrayLike<number>;
  metallic: number;
  alpha: number;
}

/**
 * out = f(l, v) per channel (no cosine): (1 − F)·c_diff/π + F·D·V, with c_diff = base·(1 − metallic)
 * and F0 = 0.04·(1 − metallic) + base·metallic; n·h and v·h of the half vector h = (l + v)/|l + v|.
 */
export function gltfBrdf(out: Float64Array | number[], m: PbrPoint, nl: number, nv: number, nh: number, vh: number): Float64Array | number[] {
  if (nl <= 0 || nv <= 0) {
    out[0] = 0; out[1] = 0; out[2] = 0;
    return out;
  }
  const dv = ggxD(m.alpha, nh) * smithVisibility(m.alpha, nl, nv);
  const dielectric = 1 - m.metallic;
  for (let c = 0; c < 3; c++) {
    const base = m.baseColor[c];
    const f = schlickFresnel(DIELECTRIC_F0 * dielectric + base * m.metallic, vh);
    out[c] = (1 - f) * base * dielectric / Math.PI + f * dv;
  }
  return out;
}

/**
 * The least α a point or directional light sees (docs/pbr.md#the-scenes-lights): such a light is one direction, and on
 * a smoother surface its highlight would shrink below any pixel to a value 32-bit floats cannot hold.
 */
export const PUNCTUAL_MIN_ALPHA = 0.002;

/** α of a roughness under a point or directional light: roughness², at least PUNCTUAL_MIN_ALPHA. */
export function punctualAlpha(roughness: number): number {
  const a = ggxAlpha(roughness);
  return a > PUNCTUAL_MIN_ALPHA ? a : PUNCTUAL_MIN_ALPHA;
}
