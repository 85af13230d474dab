// A glTF material's fragment on the CPU (docs/gltf.md#drawing): the base colour times its texture, metallic and roughness
// times the metallic-roughness map's B and G, the occlusion map's R by its strength, the lights (lighting.ts pbrLights), and
// the emission times its map.
import { pbrLights, type Lights } from './lighting';
import type { PbrMaps } from './image-textures';
import type { Material } from '../scene/scene';

const texel = new Float64Array(3), surface = new Float64Array(3), base = new Float64Array(3);

/**
 * Into out[0..2], for g as pbrLights' and `tex` the base colour texture's value; `lookup` is the fragment's UV and its
 * derivatives (the texture's lookup), null where the mapping is not `uv` (the maps are then not read: the factors alone).
 */
export function pbrFragment(
  lights: Lights, material: Material, twoSided: boolean, g: Float64Array, tex: ArrayLike<number>, maps: PbrMaps,
  lookup: Float64Array | null, out: Float64Array,
): void {
  const pbr = material.pbr!, bc = pbr.baseColor;
  base[0] = bc[0] * tex[0]; base[1] = bc[1] * tex[1]; base[2] = bc[2] * tex[2];
  let metallic = pbr.metallic, roughness = pbr.roughness, occlusion = 1;
  if (lookup !== null && maps.metalRough !== null) {
    maps.metalRough.sample(lookup, texel);
    roughness *= texel[1];
    metallic *= texel[2];
  }
  if (lookup !== null && maps.occlusion !== null) {
    maps.occlusion.sample(lookup, texel);
    occlusion = 1 + pbr.occlusionStrength * (texel[0] - 1);
  }
  surface[0] = metallic; surface[1] = roughness; surface[2] = occlusion;
  pbrLights(lights, pbr, twoSided, g, base, surface, out);
  const e = material.emissive;
  if (e === undefined) return;
  if (lookup !== null && maps.emissive !== null) {
    maps.emissive.sample(lookup, texel);
    out[0] += e[0] * texel[0]; out[1] += e[1] * texel[1]; out[2] += e[2] * texel[2];
  } else {
    out[0] += e[0]; out[1] += e[1]; out[2] += e[2];
  }
}
