// A glTF material at a hit for the reference (docs/gltf.md#drawing): metallic and roughness times the metallic-roughness
// map's B and G, the occlusion map's R by its strength, the emission times the emissive map — each map read by the
// reference's own sampler (surface-texture.ts) at the hit's UV moved by its transform, where the mapping is `uv`; the base
// colour texture read again where it has a transform — then shadePbr.
import { readMap } from '../scene/pbr-material';
import type { Material } from '../scene/scene';
import type { Ray } from './ray';
import { shadePbr, type EnvironmentShading, type PbrSurface, type PreparedLight } from './shade';
import type { SurfaceHit } from './surface-hit';
import type { SurfaceTexture } from './surface-texture';

const texel = new Float64Array(3), emitted = new Float64Array(3);
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
  if (bt !== null && bt.transform !== null) textures.mapAt(bt.source.url, true, bt.transform, hit, ray, tex);
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
  return shadePbr(hit, pbr, emissive, tex, lights, eye, out, towardsViewer, environment, surface);
}
