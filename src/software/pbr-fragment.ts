// A glTF material's fragment on the CPU (docs/gltf.md#drawing): the base colour times its texture, metallic and roughness
// times the metallic-roughness map's B and G, the occlusion map's R by its strength, the lights (lighting.ts pbrLights), and
// the emission times its map; each texture read through its KHR_texture_transform (docs/gltf.md#the-maps).
import { pbrLights, type Lights } from './lighting';
import type { PbrMaps } from './image-textures';
import type { MipTexture } from './mip-texture';
import { readMap, type PbrTexture } from '../scene/pbr-material';
import type { Material } from '../scene/scene';

const texel = new Float64Array(3), surface = new Float64Array(3), base = new Float64Array(3), moved = new Float64Array(6);

/**
 * Into out[0..2], for g as pbrLights' and `tex` the base colour texture `baseTexture`'s value; `lookup` is the fragment's UV
 * and its derivatives (the texture's lookup), null where the mapping is not `uv` (the maps are then not read: the factors
 * alone, and the base colour texture's transform not applied).
 */
export function pbrFragment(
  lights: Lights, material: Material, twoSided: boolean, g: Float64Array, baseTexture: MipTexture, tex: ArrayLike<number>,
  maps: PbrMaps, lookup: Float64Array | null, out: Float64Array,
): void {
  const pbr = material.pbr!, bc = pbr.baseColor;
  if (lookup !== null && readMap(pbr.baseColorTexture)?.transform) tex = sampleAt(baseTexture, pbr.baseColorTexture, lookup);
  base[0] = bc[0] * tex[0]; base[1] = bc[1] * tex[1]; base[2] = bc[2] * tex[2];
  let metallic = pbr.metallic, roughness = pbr.roughness, occlusion = 1;
  if (lookup !== null && maps.metalRough !== null) {
    sampleAt(maps.metalRough, pbr.metallicRoughnessTexture, lookup);
    roughness *= texel[1];
    metallic *= texel[2];
  }
  if (lookup !== null && maps.occlusion !== null) occlusion = 1 + pbr.occlusionStrength * (sampleAt(maps.occlusion, pbr.occlusionTexture, lookup)[0] - 1);
  surface[0] = metallic; surface[1] = roughness; surface[2] = occlusion;
  pbrLights(lights, pbr, twoSided, g, base, surface, out);
  const e = material.emissive;
  if (e === undefined) return;
  if (lookup !== null && maps.emissive !== null) {
    sampleAt(maps.emissive, pbr.emissiveTexture, lookup);
    out[0] += e[0] * texel[0]; out[1] += e[1] * texel[1]; out[2] += e[2] * texel[2];
  } else {
    out[0] += e[0]; out[1] += e[1]; out[2] += e[2];
  }
}

/** `t` at the lookup `l` ([u, v, ∂u/∂x, ∂v/∂x, ∂u/∂y, ∂v/∂y]) moved by the texture's transform `m` (u' = a·u + b·v + c, …): into texel. */
function sampleAt(t: MipTexture, map: PbrTexture | null, l: Float64Array): Float64Array {
  const m = map?.transform;
  if (!m) {
    t.sample(l, texel);
    return texel;
  }
  moved[0] = m[0] * l[0] + m[1] * l[1] + m[2]; moved[1] = m[3] * l[0] + m[4] * l[1] + m[5];
  moved[2] = m[0] * l[2] + m[1] * l[3]; moved[3] = m[3] * l[2] + m[4] * l[3];
  moved[4] = m[0] * l[4] + m[1] * l[5]; moved[5] = m[3] * l[4] + m[4] * l[5];
  t.sample(moved, texel);
  return texel;
}
