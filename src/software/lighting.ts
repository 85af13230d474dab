// Blinn-Phong of docs/scene-model.md#lights for the CPU, term for term as shaders/lighting.glsl writes it: per
// light Ka⊙Ia + Kd⊙Id·max(N·L, 0) into `a` (which the texture multiplies) and
// Ks⊙Is·max(N·H, 0)^n into `s` where N·L > 0. Positions are relative to the eye drawn from.
import { gltfBrdf, punctualAlpha, type PbrPoint } from '../math/pbr';
import { preparedFor, type PreparedEnvironment } from '../frame/environment-cache';
import type { PbrMaterial } from '../scene/pbr-material';
import { MAX_LIGHTS, type Material, type Scene } from '../scene/scene';

export class Lights {
  count = 0;
  /** Unit direction towards a directional light, or a point light's eye-relative position. */
  readonly vector = new Float64Array(3 * MAX_LIGHTS);
  readonly point = new Uint8Array(MAX_LIGHTS);
  readonly ambient = new Float64Array(3 * MAX_LIGHTS);
  readonly diffuse = new Float64Array(3 * MAX_LIGHTS);
  readonly specular = new Float64Array(3 * MAX_LIGHTS);
  /** The scene's environment made ready (frame/environment-cache.ts), and its intensity; null without one or before it is ready. */
  environment: PreparedEnvironment | null = null;
  intensity = 0;

  /**
   * The scene's lights (up to MAX_LIGHTS) as seen from `eye`; `world` holds each light's vector
   * in the world, after the trackball's turn (FrameSetup.lightWorld).
   */
  set(scene: Scene, world: ArrayLike<number>, eye: ArrayLike<number>): void {
    const n = Math.min(scene.lights.length, MAX_LIGHTS);
    this.count = n;
    const env = scene.environment ?? null;
    this.environment = env === null ? null : preparedFor(env);
    this.intensity = env === null ? 0 : env.intensity;
    for (let i = 0; i < n; i++) {
      const l = scene.lights[i];
      let x = world[3 * i], y = world[3 * i + 1], z = world[3 * i + 2];
      if (l.kind === 'point') {
        x -= eye[0]; y -= eye[1]; z -= eye[2];
      } else {
        const len = Math.hypot(x, y, z) || 1;
        x /= len; y /= len; z /= len;
      }
      this.vector[3 * i] = x; this.vector[3 * i + 1] = y; this.vector[3 * i + 2] = z;
      this.point[i] = l.kind === 'point' ? 1 : 0;
      // Stryker disable next-line EqualityOperator: k = 3 writes NaN to light i + 1's first value (written next) or past the last: unread
      for (let k = 0; k < 3; k++) {
        this.ambient[3 * i + k] = l.ambient[k];
        this.diffuse[3 * i + k] = l.diffuse[k];
        this.specular[3 * i + k] = l.specular[k];
      }
    }
  }
}

/**
 * The two light sums into out[0..2] (a) and out[3..5] (s), for g = [eye-relative point p, unit
 * normal n, unit view vector v towards the eye] (9 values in an array: doubles passed to a
 * call that is not inlined are boxed, once per pixel). `twoSided` turns n towards the viewer
 * first (meshes from files, docs/scene-model.md#two-sided-lighting).
 */
export function blinnPhong(lights: Lights, m: Material, twoSided: boolean, g: Float64Array, out: Float64Array): void {
  const px = g[0], py = g[1], pz = g[2], vx = g[6], vy = g[7], vz = g[8];
  let nx = g[3], ny = g[4], nz = g[5];
  if (twoSided && nx * vx + ny * vy + nz * vz < 0) { nx = -nx; ny = -ny; nz = -nz; }
  const ka = m.ambient, kd = m.diffuse, ks = m.specular;
  let ar = 0, ag = 0, ab = 0, sr = 0, sg = 0, sb = 0;
  const vec = lights.vector;
  for (let i = 0; i < lights.count; i++) {
    let lx = vec[3 * i], ly = vec[3 * i + 1], lz = vec[3 * i + 2];
    if (lights.point[i] === 1) {
      lx -= px; ly -= py; lz -= pz;
      const len = Math.sqrt(lx * lx + ly * ly + lz * lz);
      // Stryker disable next-line ConditionalExpression,EqualityOperator: at len = 0, L = 0 or NaN (0/0): N·L > 0 fails either way, m0 = 0
      if (len > 0) { lx /= len; ly /= len; lz /= len; }
    }
    const nl = nx * lx + ny * ly + nz * lz;
    // Stryker disable next-line EqualityOperator: at nl = 0 both give 0
    const m0 = nl > 0 ? nl : 0;
    const ia = lights.ambient, id = lights.diffuse;
    ar += ka[0] * ia[3 * i] + kd[0] * id[3 * i] * m0;
    ag += ka[1] * ia[3 * i + 1] + kd[1] * id[3 * i + 1] * m0;
    ab += ka[2] * ia[3 * i + 2] + kd[2] * id[3 * i + 2] * m0;
    if (nl > 0) {
      const hx = lx + vx, hy = ly + vy, hz = lz + vz;
      const hl = Math.sqrt(hx * hx + hy * hy + hz * hz);
      // Stryker disable next-line ConditionalExpression,EqualityOperator: at hl = 0, nh = 0/0 = NaN, which nh > 0 below turns into 0 too
      const nh = hl > 0 ? (nx * hx + ny * hy + nz * hz) / hl : 0;
      // Stryker disable next-line EqualityOperator: at nh = 0 both give 0
      const p = (nh > 0 ? nh : 0) ** m.shininess;
      const is = lights.specular;
      sr += ks[0] * is[3 * i] * p;
      sg += ks[1] * is[3 * i + 1] * p;
      sb += ks[2] * is[3 * i + 2] * p;
    }
  }
  out[0] = ar; out[1] = ag; out[2] = ab;
  out[3] = sr; out[4] = sg; out[5] = sb;
}

const point: PbrPoint & { baseColor: Float64Array } = { baseColor: new Float64Array(3), metallic: 0, alpha: 0 };
const brdf = new Float64Array(3), normal = new Float64Array(3), toViewer = new Float64Array(3), sum = new Float64Array(3);

/**
 * A metallic-roughness surface under the scene's lights (docs/pbr.md#the-scenes-lights), into out[0..2], for g as
 * blinnPhong's, `base` the base colour times its texture and `surface` its metallic, roughness and occlusion (the factors times
 * their maps): per light Ia⊙c_diff·occlusion, and where N·L > 0 and N·V > 0, π·f(l, v)⊙Id·(N·L) with f of math/pbr.ts at
 * α = punctualAlpha(roughness); plus the environment's split sum from its maps (PreparedEnvironment.add,
 * docs/pbr.md#prefiltered-maps) times the occlusion. Unlit: the base colour.
 */
export function pbrLights(
  lights: Lights, m: PbrMaterial, twoSided: boolean, g: Float64Array, base: ArrayLike<number>, surface: ArrayLike<number>, out: Float64Array,
): void {
  const br = base[0], bg = base[1], bb = base[2];
  if (m.unlit) {
    out[0] = br; out[1] = bg; out[2] = bb;
    return;
  }
  const px = g[0], py = g[1], pz = g[2], vx = g[6], vy = g[7], vz = g[8];
  let nx = g[3], ny = g[4], nz = g[5];
  if (twoSided && nx * vx + ny * vy + nz * vz < 0) { nx = -nx; ny = -ny; nz = -nz; }
  const nv = nx * vx + ny * vy + nz * vz;
  const metallic = surface[0], roughness = surface[1], occlusion = surface[2], dielectric = 1 - metallic;
  point.baseColor[0] = br; point.baseColor[1] = bg; point.baseColor[2] = bb;
  point.metallic = metallic;
  point.alpha = punctualAlpha(roughness);
  let r = 0, gr = 0, b = 0;
  const vec = lights.vector, ia = lights.ambient, id = lights.diffuse;
  for (let i = 0; i < lights.count; i++) {
    // Light from everywhere (the ambient term, the environment) is what occlusion dims (docs/gltf.md#drawing).
    r += ia[3 * i] * br * dielectric * occlusion; gr += ia[3 * i + 1] * bg * dielectric * occlusion; b += ia[3 * i + 2] * bb * dielectric * occlusion;
    let lx = vec[3 * i], ly = vec[3 * i + 1], lz = vec[3 * i + 2];
    if (lights.point[i] === 1) {
      lx -= px; ly -= py; lz -= pz;
      const len = Math.sqrt(lx * lx + ly * ly + lz * lz);
      if (len > 0) { lx /= len; ly /= len; lz /= len; }
    }
    const nl = nx * lx + ny * ly + nz * lz;
    // Where N·L ≤ 0 or N·V ≤ 0, f is 0 (gltfBrdf), whatever the half vector (l = −v: 0/0).
    const hx = lx + vx, hy = ly + vy, hz = lz + vz;
    const hl = Math.sqrt(hx * hx + hy * hy + hz * hz);
    gltfBrdf(brdf, point, nl, nv, (nx * hx + ny * hy + nz * hz) / hl, (vx * hx + vy * hy + vz * hz) / hl);
    const k = Math.PI * nl;
    r += k * id[3 * i] * brdf[0]; gr += k * id[3 * i + 1] * brdf[1]; b += k * id[3 * i + 2] * brdf[2];
  }
  const env = lights.environment;
  if (env !== null) {
    normal[0] = nx; normal[1] = ny; normal[2] = nz; toViewer[0] = vx; toViewer[1] = vy; toViewer[2] = vz;
    sum[0] = 0; sum[1] = 0; sum[2] = 0;
    env.add(sum, lights.intensity, point.baseColor, metallic, roughness, normal, toViewer);
    r += occlusion * sum[0]; gr += occlusion * sum[1]; b += occlusion * sum[2];
  }
  out[0] = r; out[1] = gr; out[2] = b;
}
