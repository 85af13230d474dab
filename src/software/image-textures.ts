// The textures an object draws with on the CPU: its texture (the procedural one, an image, or white) and a glTF material's
// maps (docs/gltf.md#drawing), each image built into a MipTexture once per colour space it is read in.
import { imageAlphaMipTexture, imageMipTexture, proceduralMipTexture, type MipTexture } from './mip-texture';
import type { ColorSpace } from '../math/srgb';
import type { DecodedImage, SceneImages } from '../scene/decoded-image';
import { readMap, type PbrMaterial } from '../scene/pbr-material';
import type { Material } from '../scene/scene';

/** A plain material's texture (tex = 1, in either colour space). */
// Stryker disable next-line StringLiteral: 255 is 1 as stored and decoded alike
const WHITE = imageMipTexture({ width: 1, height: 1, data: new Uint8Array([255, 255, 255, 255]) }, 'none')!;

/** A glTF material's maps besides its base colour, null where it has none or its image is not there (the factor alone). */
export interface PbrMaps {
  /** G roughness, B metallic: data, as stored. */
  metalRough: MipTexture | null;
  /** R: data, as stored. */
  occlusion: MipTexture | null;
  /** Colour: decoded to linear light in srgb. */
  emissive: MipTexture | null;
  /** A tangent-space normal (2·RGB − 1): data, as stored. */
  normal: MipTexture | null;
  /** The base colour image's alpha, as stored: read only under alphaMode `mask` (docs/gltf.md#alpha). */
  alpha: MipTexture | null;
}

export class ImageTextures {
  private readonly built: Record<ColorSpace, WeakMap<DecodedImage, MipTexture | null>> = { srgb: new WeakMap(), none: new WeakMap() };
  private readonly alphas = new WeakMap<DecodedImage, MipTexture | null>();

  /** The texture `m` draws with in `space`: white without one, the procedural one while its image is missing (unless it falls back to none). */
  base(m: Material, images: SceneImages | null | undefined, space: ColorSpace): MipTexture {
    const source = m.texture;
    if (source.kind === 'none') return WHITE;
    // Stryker disable next-line ConditionalExpression: the procedural source names no URL: the image path finds none and falls back to the same texture
    if (source.kind !== 'image') return proceduralMipTexture(space);
    return this.image(source.url, images, space) ?? (source.fallback === 'none' ? WHITE : proceduralMipTexture(space));
  }

  /** `pbr`'s maps into `out` (each null when the material is not a glTF one). */
  maps(pbr: PbrMaterial | undefined, images: SceneImages | null | undefined, space: ColorSpace, out: PbrMaps): void {
    out.metalRough = this.map(pbr?.metallicRoughnessTexture, images, 'none');
    out.occlusion = this.map(pbr?.occlusionTexture, images, 'none');
    out.emissive = this.map(pbr?.emissiveTexture, images, space);
    out.normal = this.map(pbr?.normalTexture, images, 'none');
    const base = pbr?.alphaMode === 'mask' ? readMap(pbr.baseColorTexture) : null, image = base === null ? undefined : images?.get(base.source.url);
    let alpha = image === undefined ? null : this.alphas.get(image);
    // Stryker disable next-line ConditionalExpression: building it again gives the same texture (the cache saves the time)
    if (image !== undefined && alpha === undefined) this.alphas.set(image, (alpha = imageAlphaMipTexture(image)));
    out.alpha = alpha ?? null;
  }

  private map(t: PbrMaterial['emissiveTexture'] | undefined, images: SceneImages | null | undefined, space: ColorSpace): MipTexture | null {
    const read = readMap(t ?? null);
    return read === null ? null : this.image(read.source.url, images, space);
  }

  /** `url`'s image as a texture in `space`; null when it is not in `images` or its pixels do not match its size. */
  private image(url: string, images: SceneImages | null | undefined, space: ColorSpace): MipTexture | null {
    const image = images?.get(url);
    if (image === undefined) return null;
    const built = this.built[space];
    let t = built.get(image);
    // Stryker disable next-line ConditionalExpression: building it again gives the same texture (the cache saves the time)
    if (t === undefined) built.set(image, (t = imageMipTexture(image, space)));
    return t;
  }
}
