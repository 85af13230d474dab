// An object's Material by precedence (docs/scene-model.md#material-precedence): attribute over MTL over default. Pure.
import type { Mapping, Material, TextureSource, Vec3 } from '../../scene/scene';
import type { PbrMaterial } from '../../scene/pbr-material';
import { OBJECT_DEFAULTS, type ObjectAttributes } from './object-attributes';

/** The MTL values that matter here, with map_Kd already resolved to an absolute URL. */
export interface MtlValues {
  ambient?: Vec3;
  diffuse?: Vec3;
  specular?: Vec3;
  shininess?: number;
  opacity?: number;
  texture?: string;
  /** A glTF material, carried into the scene value as it is (docs/gltf.md#materials). */
  pbr?: PbrMaterial;
  /** Light given off (a glTF material's emissive factor times its strength). */
  emissive?: Vec3;
}

export type MaterialAttributes = Pick<ObjectAttributes, 'ambient' | 'diffuse' | 'specular' | 'shininess' | 'opacity' | 'texture' | 'mapping'>;

/** Element-wide material (the course's `iluminacao.txt`, docs/course-files.md#lighting-file) and how the object is textured. */
export interface MaterialContext {
  /** Below the object's attributes and its MTL, above the defaults. */
  file?: MtlValues | null;
  /** No texture unless the `texture` attribute sets one (the course's `.byu` objects). */
  plain?: boolean;
}

/**
 * `textureUrl` is the `texture` attribute already resolved against the document; `hasUvs`
 * picks the default mapping (the built-in shapes have UVs; a model may not). Precedence:
 * attribute, then the model's MTL, then the element's lighting file, then the default.
 */
export function resolveMaterial(
  attrs: MaterialAttributes, mtl: MtlValues | undefined, hasUvs: boolean, textureUrl: string | null,
  context: MaterialContext = {},
): Material {
  const image = textureUrl ?? mtl?.texture ?? null;
  // A plain object (a glTF's, a course file's) is never drawn with the checker: plain while its image is missing.
  const texture: TextureSource = image !== null ? { kind: 'image', url: image, ...(context.plain ? { fallback: 'none' as const } : {}) }
    : context.plain ? { kind: 'none' } : { kind: 'procedural' };
  const mapping: Mapping = attrs.mapping ?? (hasUvs ? 'uv' : 'spherical');
  const file = context.file ?? undefined;
  return {
    ambient: attrs.ambient ?? mtl?.ambient ?? file?.ambient ?? OBJECT_DEFAULTS.ambient,
    diffuse: attrs.diffuse ?? mtl?.diffuse ?? file?.diffuse ?? OBJECT_DEFAULTS.diffuse,
    specular: attrs.specular ?? mtl?.specular ?? file?.specular ?? OBJECT_DEFAULTS.specular,
    shininess: attrs.shininess ?? mtl?.shininess ?? file?.shininess ?? OBJECT_DEFAULTS.shininess,
    opacity: attrs.opacity ?? mtl?.opacity ?? file?.opacity ?? OBJECT_DEFAULTS.opacity,
    texture,
    mapping,
    ...(mtl?.emissive ? { emissive: mtl.emissive } : {}),
    ...(mtl?.pbr ? { pbr: mtl.pbr } : {}),
  };
}
