// A glTF material at a hit for the reference (docs/gltf.md#drawing): metallic and roughness times the metallic-roughness
// map's B and G, the occlusion map's R by its strength, the emission times the emissive map — each map read by the
// reference's own sampler (surface-texture.ts) at the hit's UV moved by its transform, where the mapping is `uv`; the base
// colour texture read again where it has a transform; the normal map turning the shading normal — then shadePbr. And its alpha
// mask (docs/gltf.md#alpha): a hit on a material of alphaMode `mask` whose base colour alpha — its factor times its texture's
// alpha, read as the base colour is, where the mapping is `uv` — is below the cutoff is no surface: the ray goes on past it
// (keptHit, which sample-tracer.ts's nearest asks).
import { readMap } from '../scene/pbr-material';
import type { Material } from '../scene/scene';
import type { Ray } from './ray';
import type { ObjectTracer } from './analytic-tracers';
import type { Plane } from '../math/mirror';
import { shadePbr, type EnvironmentShading, type PbrSurface, type PreparedLight } from './shade';
import type { SurfaceHit } from './surface-hit';
import type { SurfaceTexture } from './surface-texture';

const texel = new Float64Array(3), emitted = new Float64Array(3), interpolated = new Float64Array(3);
// Stryker disable next-line ObjectLiteral: first values, each field set by shadeGltf before shadePbr reads it
const surface: PbrSurface = { metallic: 0, roughness: 0, occlusion: 1 };

/** shadePbr of `m` (a glTF material) at `hit`, its maps read; `tex` is its base colour texture's value there. */
export function shadeGltf(
  textures: SurfaceTexture, hit: SurfaceHit, ray: Ray, m: Material, tex: Float64Array, lights: readonly PreparedLight[],
  eye: Float64Array, out: Float64Array, towardsViewer: Float64Array | null, environment: EnvironmentShading | null,
): Float64Array {
  const pbr = m.pbr!, uv = m.mapping === 'uv';
  surface.metallic = pbr.metallic;
  surface.roughness = pbr.roughness;
  surface.occlusion = 1;
  const bt = uv ? readMap(pbr.baseColorTexture) : null;
  // Stryker disable next-line ConditionalExpression: read again without a transform, the base colour texture gives objectTexture's value
  if (bt !== null && bt.transform !== null) textures.mapAt(bt.source.url, true, bt.transform, hit, ray, tex);
  // The vertex colour multiplies the base colour with its texture (docs/gltf.md#vertex-colours).
  // Stryker disable next-line EqualityOperator: k = 3 writes tex[3], past the end of its 3 elements: dropped
  for (let k = 0; k < 3; k++) tex[k] *= hit.color[k];
  const mr = uv ? readMap(pbr.metallicRoughnessTexture) : null;
  if (mr !== null && textures.mapAt(mr.source.url, false, mr.transform, hit, ray, texel) !== null) {
    surface.roughness *= texel[1];
    surface.metallic *= texel[2];
  }
  const ao = uv ? readMap(pbr.occlusionTexture) : null;
  if (ao !== null && textures.mapAt(ao.source.url, false, ao.transform, hit, ray, texel) !== null) surface.occlusion = 1 + pbr.occlusionStrength * (texel[0] - 1);
  let emissive: ArrayLike<number> | undefined = m.emissive;
  const em = uv ? readMap(pbr.emissiveTexture) : null;
  if (emissive !== undefined && em !== null && textures.mapAt(em.source.url, true, em.transform, hit, ray, texel) !== null) {
    // Stryker disable next-line EqualityOperator: k = 3 writes emitted[3], past the end of its 3 elements: dropped
    for (let k = 0; k < 3; k++) emitted[k] = emissive[k] * texel[k];
    emissive = emitted;
  }
  // Stryker disable next-line ConditionalExpression: w is 0 only on a box's or sphere's hit, whose tracers zero the whole tangent: a zero tangent turns nothing
  const nm = uv && hit.tangent[3] !== 0 ? readMap(pbr.normalTexture) : null;
  if (nm === null || textures.mapAt(nm.source.url, false, nm.transform, hit, ray, texel) === null) {
    return shadePbr(hit, pbr, emissive, tex, lights, eye, out, towardsViewer, environment, surface);
  }
  interpolated.set(hit.n);
  mappedNormal(hit, texel, pbr.normalScale);
  shadePbr(hit, pbr, emissive, tex, lights, eye, out, towardsViewer, environment, surface);
  hit.n.set(interpolated);
  return out;
}

/**
 * hit.n perturbed by a normal map's texel `t` (docs/gltf.md#the-normal-map): in the frame of the interpolated normal N (as
 * it was before it was turned to the viewer), the tangent T made orthogonal to it and the bitangent B = w·(N × T),
 * normalize(x·T + y·B + z·N) for (x, y, z) = 2t − 1, x and y times `scale`; turned to the viewer as N was.
 */
function mappedNormal(hit: SurfaceHit, t: Float64Array, scale: number): void {
  const n = hit.n, tg = hit.tangent, s = hit.flipped ? -1 : 1;
  const nx = s * n[0], ny = s * n[1], nz = s * n[2];
  const d = tg[0] * nx + tg[1] * ny + tg[2] * nz;
  let tx = tg[0] - d * nx, ty = tg[1] - d * ny, tz = tg[2] - d * nz;
  const tl = Math.hypot(tx, ty, tz) || 1;
  tx /= tl; ty /= tl; tz /= tl;
  const w = tg[3], bx = w * (ny * tz - nz * ty), by = w * (nz * tx - nx * tz), bz = w * (nx * ty - ny * tx);
  const x = (2 * t[0] - 1) * scale, y = (2 * t[1] - 1) * scale, z = 2 * t[2] - 1;
  const mx = x * tx + y * bx + z * nx, my = x * ty + y * by + z * ny, mz = x * tz + y * bz + z * nz;
  const ml = s / (Math.hypot(mx, my, mz) || 1);
  n[0] = mx * ml; n[1] = my * ml; n[2] = mz * ml;
}

const alpha = new Float64Array(3);

/** Whether `hit` on material `m` is cut away by its alpha mask. */
export function maskedOut(textures: SurfaceTexture, m: Material, hit: SurfaceHit, ray: Ray): boolean {
  const pbr = m.pbr;
  if (pbr === undefined || pbr.alphaMode !== 'mask') return false;
  let a = pbr.baseColor[3];
  const bt = m.mapping === 'uv' ? readMap(pbr.baseColorTexture) : null;
  if (bt !== null && textures.mapAt(bt.source.url, 'alpha', bt.transform, hit, ray, alpha) !== null) a *= alpha[0];
  return a < pbr.alphaCutoff;
}

/** How many cut-away surfaces of one object a ray goes through before it is taken as hitting none. */
export const MAX_CUTS = 64;

/**
 * After `tracer`'s hit in `hit` on an object of material `m`: on past each of its surfaces the mask cuts away (up to MAX_CUTS),
 * the next one in `hit`; false when none is left.
 */
export function keptHit(tracer: ObjectTracer, textures: SurfaceTexture, m: Material, ray: Ray, clipSide: number, plane: Plane | null, hit: SurfaceHit): boolean {
  for (let cut = 0; maskedOut(textures, m, hit, ray); cut++) {
    // Stryker disable next-line ArithmeticOperator: a hit must lie past tMin, so tMin = t already leaves the cut surface; the step (tested at t ½, where −1e-9 would not leave it) guards a re-hit a rounding away
    if (cut === MAX_CUTS || !tracer.hit(ray, hit.t * (1 + 1e-9) + 1e-9, clipSide, plane, hit)) return false;
  }
  return true;
}
