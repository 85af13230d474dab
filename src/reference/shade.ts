// Per-sample shading in float64: Blinn-Phong for the objects (docs/default-scene.md#material-and-lighting, docs/scene-model.md#lights) and the glass equation (docs/rendering.md#the-glass-equation).
import { fresnel, type FresnelModel } from '../math/fresnel';
import { gltfBrdf, punctualAlpha, type PbrPoint } from '../math/pbr';
import type { PbrMaterial } from '../scene/pbr-material';
import { GLASS_BODY as BODY } from '../scene/default-scene';
import type { Light, Material } from '../scene/scene';
import type { SurfaceHit } from './surface-hit';
import { environmentLight, type EnvironmentLight } from './pbr-light';
import { ggxAlpha } from '../math/ggx';

/** An environment as the reference lights glTF materials with it (docs/pbr.md#the-reference): its light times `intensity`, `samples` per shading. */
export interface EnvironmentShading {
  light: EnvironmentLight;
  intensity: number;
  samples: number;
  /** Numbers in [0, 1): the sample's own seeded stream. */
  random: () => number;
}

// Stryker disable next-line EqualityOperator: at 0 and at 1 the clamp returns x itself either way
export const clamp01 = (x: number): number => (x < 0 ? 0 : x > 1 ? 1 : x);

/** x held to [0, top] (top 1: an 8-bit target's clamp; Infinity: a tone-mapped frame's, reference-state.ts colourCeiling). */
// Stryker disable next-line EqualityOperator: at 0 and at top the clamp returns x itself either way
export const clampTo = (x: number, top: number): number => (x < 0 ? 0 : x > top ? top : x);

/** A light with its vector ready: a unit direction towards it, or its position. */
export interface PreparedLight {
  point: boolean;
  x: number;
  y: number;
  z: number;
  ambient: readonly number[];
  diffuse: readonly number[];
  specular: readonly number[];
}

export function prepareLight(light: Light): PreparedLight {
  let [x, y, z] = light.vector;
  if (light.kind === 'directional') {
    const len = Math.hypot(x, y, z);
    if (len > 0) { x /= len; y /= len; z /= len; }
  }
  return { point: light.kind === 'point', x, y, z, ambient: light.ambient, diffuse: light.diffuse, specular: light.specular };
}

const sums = new Float64Array(9);

/**
 * out = Σ over lights of Ka⊙tex⊙Ia + Kd⊙tex⊙Id·max(N·L, 0) + (N·L > 0 ? Ks⊙Is·max(N·H, 0)^n : 0),
 * unclamped, with V = normalize(eye − p), H = normalize(L + V), L the unit vector towards a
 * directional light or normalize(P − p) for a point light (no distance attenuation: docs/scene-model.md#lights
 * names none): the GPU's per-fragment (phong) shading. `eye` is the real eye for direct views
 * and the mirrored eye for what the glass reflects; `towardsViewer`, when given, is V instead
 * (an orthographic camera's constant view vector, docs/interaction.md#orthographic-projection). Where Ka = Kd (the default objects, docs/default-scene.md#material-and-lighting) the sum
 * is formed as Kd⊙tex⊙(ΣIa + ΣId·max): the same value with fewer roundings.
 */
export function shadeObject(
  hit: SurfaceHit, material: Material, tex: Float64Array, lights: readonly PreparedLight[], eye: Float64Array, out: Float64Array,
  towardsViewer: Float64Array | null = null,
): Float64Array {
  const n = hit.n, p = hit.p;
  sums.fill(0); // ambient 0..2, diffuse 3..5, specular 6..8
  let vx = 0, vy = 0, vz = 0, haveV = false;
  const ks = material.specular;
  for (const light of lights) {
    let lx = light.x, ly = light.y, lz = light.z;
    if (light.point) {
      lx -= p[0]; ly -= p[1]; lz -= p[2];
      const len = Math.hypot(lx, ly, lz);
      if (len > 0) { lx /= len; ly /= len; lz /= len; }
    }
    const nl = n[0] * lx + n[1] * ly + n[2] * lz;
    const m = Math.max(nl, 0);
    for (let k = 0; k < 3; k++) {
      sums[k] += light.ambient[k];
      sums[3 + k] += light.diffuse[k] * m;
    }
    if (nl > 0) {
      if (!haveV && towardsViewer) {
        vx = towardsViewer[0]; vy = towardsViewer[1]; vz = towardsViewer[2];
        // Stryker disable next-line BooleanLiteral: V is the same for every light: working it out again gives the same numbers
        haveV = true;
      } else if (!haveV) {
        vx = eye[0] - p[0]; vy = eye[1] - p[1]; vz = eye[2] - p[2];
        const vl = Math.hypot(vx, vy, vz);
        vx /= vl; vy /= vl; vz /= vl;
        // Stryker disable next-line BooleanLiteral: V is the same for every light: working it out again gives the same numbers
        haveV = true;
      }
      const hx = lx + vx, hy = ly + vy, hz = lz + vz;
      const nh = (n[0] * hx + n[1] * hy + n[2] * hz) / Math.hypot(hx, hy, hz);
      const s = Math.max(nh, 0) ** material.shininess;
      // Stryker disable next-line EqualityOperator: k = 3 writes sums[9], past the end of its 9 elements: dropped
      for (let k = 0; k < 3; k++) sums[6 + k] += ks[k] * light.specular[k] * s;
    }
  }
  const ka = material.ambient, kd = material.diffuse, e = material.emissive;
  for (let k = 0; k < 3; k++) {
    const lit = ka[k] === kd[k]
      ? kd[k] * tex[k] * (sums[k] + sums[3 + k])
      : ka[k] * tex[k] * sums[k] + kd[k] * tex[k] * sums[3 + k];
    // Emitted light adds to the lit colour (docs/gltf.md#drawing); a material without it adds nothing.
    out[k] = e === undefined ? lit + sums[6 + k] : lit + sums[6 + k] + e[k];
  }
  return out;
}

const pbrPoint: PbrPoint & { baseColor: Float64Array } = { baseColor: new Float64Array(3), metallic: 0, alpha: 0 };
const brdf = new Float64Array(3);

/**
 * A glTF material (docs/pbr.md#the-scenes-lights): out = Σ over lights of Ia⊙c_diff + π·f(l, v)⊙Id·max(N·L, 0), with
 * f the glTF BRDF at α = punctualAlpha(roughness), the base colour times `tex` (so the texture sets a
 * metal's F0 too), c_diff = base·(1 − metallic), V as shadeObject's (unlit: the base colour times `tex`);
 * plus, under an environment, its light integrated by Monte Carlo at α = roughness² (docs/pbr.md#the-reference);
 * plus the material's emissive (which the element does not give an unlit material).
 */
export function shadePbr(
  hit: SurfaceHit, pbr: PbrMaterial, emissive: ArrayLike<number> | undefined, tex: Float64Array, lights: readonly PreparedLight[],
  eye: Float64Array, out: Float64Array, towardsViewer: Float64Array | null = null, environment: EnvironmentShading | null = null,
  surface: PbrSurface | null = null,
): Float64Array {
  const base = pbrPoint.baseColor;
  // Stryker disable next-line EqualityOperator: k = 3 writes base[3], past the end of its 3 elements: dropped
  for (let k = 0; k < 3; k++) base[k] = pbr.baseColor[k] * tex[k];
  if (pbr.unlit) out.set(base);
  else litPbr(hit, surface ?? { metallic: pbr.metallic, roughness: pbr.roughness, occlusion: 1 }, lights, eye, out, towardsViewer, environment);
  // Stryker disable next-line EqualityOperator: k = 3 writes out[3], past the end of its 3 elements: dropped
  if (emissive !== undefined) for (let k = 0; k < 3; k++) out[k] += emissive[k];
  return out;
}

const view = new Float64Array(3);

/** A glTF material's metallic, roughness and occlusion at a point: its factors times its maps (reference/gltf-surface.ts). */
export interface PbrSurface {
  metallic: number;
  roughness: number;
  /** 1 + strength·(map − 1): what the ambient term and the environment are multiplied by. */
  occlusion: number;
}

function litPbr(
  hit: SurfaceHit, pbr: PbrSurface, lights: readonly PreparedLight[], eye: Float64Array, out: Float64Array, towardsViewer: Float64Array | null,
  environment: EnvironmentShading | null,
): void {
  const base = pbrPoint.baseColor;
  const n = hit.n, p = hit.p;
  let vx: number, vy: number, vz: number;
  if (towardsViewer) {
    vx = towardsViewer[0]; vy = towardsViewer[1]; vz = towardsViewer[2];
  } else {
    vx = eye[0] - p[0]; vy = eye[1] - p[1]; vz = eye[2] - p[2];
    const vl = Math.hypot(vx, vy, vz);
    vx /= vl; vy /= vl; vz /= vl;
  }
  const nv = n[0] * vx + n[1] * vy + n[2] * vz;
  pbrPoint.metallic = pbr.metallic;
  pbrPoint.alpha = punctualAlpha(pbr.roughness);
  const dielectric = 1 - pbr.metallic;
  out[0] = 0; out[1] = 0; out[2] = 0;
  for (const light of lights) {
    let lx = light.x, ly = light.y, lz = light.z;
    if (light.point) {
      lx -= p[0]; ly -= p[1]; lz -= p[2];
      const len = Math.hypot(lx, ly, lz);
      if (len > 0) { lx /= len; ly /= len; lz /= len; }
    }
    const nl = n[0] * lx + n[1] * ly + n[2] * lz;
    const hx = lx + vx, hy = ly + vy, hz = lz + vz;
    const hl = Math.hypot(hx, hy, hz);
    gltfBrdf(brdf, pbrPoint, nl, nv, (n[0] * hx + n[1] * hy + n[2] * hz) / hl, (vx * hx + vy * hy + vz * hz) / hl);
    const m = Math.PI * Math.max(nl, 0);
    // Stryker disable next-line EqualityOperator: k = 3 writes out[3], past the end of its 3 elements: dropped
    for (let k = 0; k < 3; k++) out[k] += light.ambient[k] * base[k] * dielectric * pbr.occlusion + m * light.diffuse[k] * brdf[k];
  }
  if (environment === null) return;
  view[0] = vx; view[1] = vy; view[2] = vz;
  pbrPoint.alpha = ggxAlpha(pbr.roughness);
  const { mean } = environmentLight(pbrPoint, n, view, environment.light, environment.samples, environment.random);
  // Stryker disable next-line EqualityOperator: k = 3 writes out[3], past the end of its 3 elements: dropped
  for (let k = 0; k < 3; k++) out[k] += environment.intensity * pbr.occlusion * mean[k];
}

/** F for a glass hit seen along `direction`: cosθ = |N·V| clamped to [0, 1], as glass.frag does. */
export function glassFresnel(model: FresnelModel, ior: number, hit: SurfaceHit, direction: Float64Array): number {
  const n = hit.n, d = direction;
  const c = Math.abs(n[0] * d[0] + n[1] * d[1] + n[2] * d[2]) / Math.hypot(d[0], d[1], d[2]);
  return fresnel(model, clamp01(c), ior);
}

/**
 * The glass over what is behind it, docs/rendering.md#the-glass-equation, given R (reflection) and B (behind) already
 * clamped as the GPU's 8-bit targets hold them and the glass texture value `tex`:
 * exact/schlick: out = F·R + (1 − F)(T·B + (1 − T)·D);
 * classic: a = (1 − T)(0.2 + 0.8F), out = mix(D, R, F)·a + B·(1 − a).
 * D = tex ⊙ tint ⊙ darkness. `out` is clamped to [0, top] (1 but in a tone-mapped frame).
 */
export function composeGlass(
  model: FresnelModel, f: number, transparency: number, tex: number,
  r: Float64Array, b: Float64Array, out: Float64Array, top = 1,
): Float64Array {
  const t = transparency;
  const a = (1 - t) * (0.2 + 0.8 * f);
  for (let k = 0; k < 3; k++) {
    const d = tex * BODY[k];
    const c = model === 'classic'
      ? (d + (r[k] - d) * f) * a + b[k] * (1 - a)
      : f * r[k] + (1 - f) * (t * b[k] + (1 - t) * d);
    out[k] = clampTo(c, top);
  }
  return out;
}
