// glTF's metallic-roughness material as scene data (docs/gltf.md#materials). The loader fills it
// with image indices (GltfTextureRef), the element with image URLs (PbrTexture). Until the PBR
// shading of docs/gltf.md#drawing lands, renderers draw it through its Blinn-Phong stand-in
// (the Material it sits in); it travels with the scene so that nothing of the file is lost.

/** The GL sampler enums glTF uses (undefined filters: the renderer's choice). */
export interface PbrSampler {
  magFilter: number | undefined;
  minFilter: number | undefined;
  wrapS: number;
  wrapT: number;
}

export interface PbrTextureOf<Source> {
  source: Source;
  /** TEXCOORD_n. */
  texCoord: number;
  sampler: PbrSampler;
  /**
   * KHR_texture_transform, row-major [a, b, c, d, e, f]: u' = a·u + b·v + c, v' = d·u + e·v + f; in the UV of whoever holds it:
   * glTF's (v down) as the loader reads it, the scene's (the OBJ way up, loaders/gltf/as-obj.ts) in a scene value. Null: none.
   */
  transform: readonly number[] | null;
}

export type AlphaMode = 'opaque' | 'mask' | 'blend';

export interface PbrMaterialOf<Source> {
  name: string;
  /** Linear RGBA. */
  baseColor: readonly [number, number, number, number];
  baseColorTexture: PbrTextureOf<Source> | null;
  metallic: number;
  roughness: number;
  metallicRoughnessTexture: PbrTextureOf<Source> | null;
  normalTexture: PbrTextureOf<Source> | null;
  normalScale: number;
  occlusionTexture: PbrTextureOf<Source> | null;
  occlusionStrength: number;
  /** Linear RGB; the light emitted is emissive × emissiveStrength × the emissive texture. */
  emissive: readonly [number, number, number];
  emissiveTexture: PbrTextureOf<Source> | null;
  emissiveStrength: number;
  alphaMode: AlphaMode;
  alphaCutoff: number;
  doubleSided: boolean;
  unlit: boolean;
}

/** A texture of the scene: an image by URL (absolute, data: or blob:). */
export type PbrTexture = PbrTextureOf<{ url: string }>;
export type PbrMaterial = PbrMaterialOf<{ url: string }>;

/**
 * A map as every renderer reads it (docs/gltf.md#drawing): on TEXCOORD_0, the mesh's UV; one on TEXCOORD_1 is not read (the
 * material's factor alone), as the base colour's is not.
 */
export const readMap = (t: PbrTexture | null): PbrTexture | null => (t !== null && t.texCoord === 0 ? t : null);
