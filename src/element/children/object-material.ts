// An object's Material by SPEC §9's precedence: attribute over MTL over default. Pure.
import type { Mapping, Material, TextureSource, Vec3 } from '../../scene/scene';
import { OBJECT_DEFAULTS, type ObjectAttributes } from './object-attributes';

/** The MTL values that matter here, with map_Kd already resolved to an absolute URL. */
export interface MtlValues {
  ambient?: Vec3;
  diffuse?: Vec3;
  specular?: Vec3;
  shininess?: number;
  opacity?: number;
  texture?: string;
}

export type MaterialAttributes = Pick<ObjectAttributes, 'ambient' | 'diffuse' | 'specular' | 'shininess' | 'opacity' | 'texture' | 'mapping'>;

/**
 * `textureUrl` is the `texture` attribute already resolved against the document; `hasUvs`
 * picks the default mapping (the built-in shapes have UVs; a model may not).
 */
export function resolveMaterial(
  attrs: MaterialAttributes, mtl: MtlValues | undefined, hasUvs: boolean, textureUrl: string | null,
): Material {
  const image = textureUrl ?? mtl?.texture ?? null;
  const texture: TextureSource = image === null ? { kind: 'procedural' } : { kind: 'image', url: image };
  const mapping: Mapping = attrs.mapping ?? (hasUvs ? 'uv' : 'spherical');
  return {
    ambient: attrs.ambient ?? mtl?.ambient ?? OBJECT_DEFAULTS.ambient,
    diffuse: attrs.diffuse ?? mtl?.diffuse ?? OBJECT_DEFAULTS.diffuse,
    specular: attrs.specular ?? mtl?.specular ?? OBJECT_DEFAULTS.specular,
    shininess: attrs.shininess ?? mtl?.shininess ?? OBJECT_DEFAULTS.shininess,
    opacity: attrs.opacity ?? mtl?.opacity ?? OBJECT_DEFAULTS.opacity,
    texture,
    mapping,
  };
}
