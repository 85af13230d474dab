// Per-sample shading in float64: Blinn-Phong for the objects (SPEC §3) and the glass equation (SPEC §4).
import { fresnel, type FresnelModel } from '../math/fresnel';
import { GLASS, LIGHT, MATERIAL } from '../scene/default-scene';
import type { SurfaceHit } from './ray-scene';

const [LX, LY, LZ] = LIGHT.direction;
const BODY = GLASS.tint.map((c) => c * GLASS.darkness);

export const clamp01 = (x: number): number => (x < 0 ? 0 : x > 1 ? 1 : x);

/**
 * out = albedo ⊙ tex · (Ia + Id·max(N·L, 0)) + (N·L > 0 ? Ks·Is·max(N·H, 0)^32 : 0), unclamped,
 * with V = normalize(eye − p), H = normalize(L + V): the GPU's per-fragment (phong) shading.
 * `eye` is the real eye for direct views and the mirrored eye for what the glass reflects.
 */
export function shadeObject(
  hit: SurfaceHit, albedo: readonly number[], tex: number, eye: Float64Array, out: Float64Array,
): Float64Array {
  const n = hit.n, p = hit.p;
  const nl = n[0] * LX + n[1] * LY + n[2] * LZ;
  const diffuse = LIGHT.ambient + LIGHT.diffuse * Math.max(nl, 0);
  let specular = 0;
  if (nl > 0) {
    let vx = eye[0] - p[0], vy = eye[1] - p[1], vz = eye[2] - p[2];
    const vl = Math.hypot(vx, vy, vz);
    vx /= vl; vy /= vl; vz /= vl;
    const hx = LX + vx, hy = LY + vy, hz = LZ + vz;
    const nh = (n[0] * hx + n[1] * hy + n[2] * hz) / Math.hypot(hx, hy, hz);
    specular = MATERIAL.ks * LIGHT.specular * Math.max(nh, 0) ** MATERIAL.shininess;
  }
  for (let k = 0; k < 3; k++) out[k] = albedo[k] * tex * diffuse + specular;
  return out;
}

/** F for a glass hit seen along `direction`: cosθ = |N·V| clamped to [0, 1], as glass.frag does. */
export function glassFresnel(model: FresnelModel, ior: number, hit: SurfaceHit, direction: Float64Array): number {
  const n = hit.n, d = direction;
  const c = Math.abs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / Math.hypot(d[0], d[1], d[2]);
  return fresnel(model, clamp01(c), ior);
}

/**
 * The glass over what is behind it, SPEC §4, given R (reflection) and B (behind) already
 * clamped as the GPU's 8-bit targets hold them and the glass texture value `tex`:
 * exact/schlick: out = F·R + (1 − F)(T·B + (1 − T)·D);
 * classic: a = (1 − T)(0.2 + 0.8F), out = mix(D, R, F)·a + B·(1 − a).
 * D = tex ⊙ tint ⊙ darkness. `out` is clamped to [0, 1].
 */
export function composeGlass(
  model: FresnelModel, f: number, transparency: number, tex: number,
  r: Float64Array, b: Float64Array, out: Float64Array,
): Float64Array {
  const t = transparency;
  const a = (1 - t) * (0.2 + 0.8 * f);
  for (let k = 0; k < 3; k++) {
    const d = tex * BODY[k];
    const c = model === 'classic'
      ? (d + (r[k] - d) * f) * a + b[k] * (1 - a)
      : f * r[k] + (1 - f) * (t * b[k] + (1 - t) * d);
    out[k] = clamp01(c);
  }
  return out;
}
