// The PBR peer's lights check (bench/three-pbr-peer.ts `matched`): MeshStandardMaterial's shader with our single-scattering
// glTF BRDF (docs/pbr.md#the-brdf) in place of three's energy compensation, so that the grid under the lights alone measures
// the conversion of our lights to three's units and nothing else. Each replacement must find its text: a three.js whose
// chunks changed fails loudly here instead of checking something else.
import * as THREE from 'three';

type Chunk = keyof typeof THREE.ShaderChunk;

const EDITS: [Chunk, string, string][] = [
  // No Turquin factor on the lights' specular.
  ['lights_fragment_begin', 'material.multiScatteringCompensation = 1.0 + material.specularColorBlended * ( 1.0 / EssMs - 1.0 );', 'material.multiScatteringCompensation = vec3( 1.0 );'],
  // Roughness as given (at least 0.045: α ≥ 0.002, ours for lights), without the normal's screen-space derivative.
  ['lights_physical_fragment', 'material.roughness += geometryRoughness;', ''],
  // The diffuse lobe under a light taken down by 1 − F of the blended F0 (glTF Appendix B), not of the dielectric's 0.04.
  ['lights_physical_pars_fragment', 'vec3 F = F_Schlick( material.specularColor, material.specularF90, dotVH );', 'vec3 F = F_Schlick( material.specularColorBlended, material.specularF90, dotVH );'],
  // The ambient fill Ia ⊙ c_diff (three's irradiance is π·Ia), not scaled by what the specular lobe takes.
  ['lights_physical_pars_fragment', 'vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution ) * ( 1.0 - singleScattering - multiScattering );', 'vec3 diffuse = irradiance * BRDF_Lambert( material.diffuseContribution );'],
  // The environment's split sum single-scattered, its diffuse c_diff·(1 − F0)·E/π (math/split-sum.ts).
  ['lights_physical_pars_fragment', 'indirectSpecular += multiScattering * cosineWeightedIrradiance;', ''],
  ['lights_physical_pars_fragment', 'vec3 diffuse = material.diffuseContribution * ( 1.0 - totalScatteringDielectric );', 'vec3 diffuse = material.diffuseContribution * ( 1.0 - material.specularColorBlended );'],
];

function edited(chunk: Chunk): string {
  let text = THREE.ShaderChunk[chunk] as string;
  for (const [c, from, to] of EDITS) {
    if (c !== chunk) continue;
    if (!text.includes(from)) throw new Error(`glass-plane-scene: the PBR peer's matched shader: ${chunk} no longer has "${from}"`);
    text = text.replace(from, to);
  }
  return text;
}

/** onBeforeCompile of the matched materials: the edited chunks written in place of their includes. */
export function matchedShader(shader: { fragmentShader: string }): void {
  for (const chunk of new Set(EDITS.map((e) => e[0]))) {
    const include = `#include <${chunk}>`;
    if (!shader.fragmentShader.includes(include)) throw new Error(`glass-plane-scene: the PBR peer's matched shader: no ${include}`);
    shader.fragmentShader = shader.fragmentShader.replace(include, edited(chunk));
  }
}
