// A glTF material's maps besides its base colour in WebGL (docs/gltf.md#drawing): metallic-roughness and occlusion held as
// stored (RGBA8, read isotropically, as the software renderer reads data), the emissive map as colour in the frame's space
// (SRGB8_ALPHA8 in srgb, anisotropic, as an image texture is); a white texel stands for a map a material lacks or whose image
// is not in (the factor alone). Uploaded by sync() before any pass (creating a texture binds it), bound per draw on units
// 5–7, freed with the renderer. In the PBR chunk (pbr-gl): a scene without glTF materials never loads it.
import { Texture } from './gl/texture';
import type { ResourceCounter } from './gl/resource-counter';
import type { Program } from './gl/program';
import { readMap, type PbrMaterial, type PbrTexture } from '../scene/pbr-material';
import type { Scene } from '../scene/scene';
import type { DecodedImage, SceneImages } from '../scene/decoded-image';

/** Each texture's transform, two rows of three (u' = a·u + b·v + c, v' = d·u + e·v + f), for uUvRows; none is the identity. */
const ROWS = new Float32Array(30), IDENTITY = [1, 0, 0, 0, 1, 0];
const rows = (i: number, t: PbrTexture | null): void => ROWS.set(t?.transform ?? IDENTITY, 6 * i);

/** Units 0 (the base colour) and 3–4 (the environment) are the draw's others. */
const METAL_ROUGH_UNIT = 5, OCCLUSION_UNIT = 6, EMISSIVE_UNIT = 7, NORMAL_UNIT = 8;

interface Held {
  source: DecodedImage;
  texture: Texture;
}

export class PbrMapsGl {
  /** By URL (no key is built per frame): the maps held as colour in srgb, and those held as stored. */
  private readonly colour = new Map<string, Held>();
  private readonly data = new Map<string, Held>();
  private white: Texture | null = null;
  private srgb = true;

  constructor(private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter) {}

  /** The frame's maps, before any pass: each image new in `images` uploaded, each gone (or replaced) freed; an unchanged map allocates nothing. */
  sync(scene: Scene, images: SceneImages | null | undefined, srgb: boolean): void {
    this.white ??= new Texture(this.gl, this.counter, { width: 1, height: 1, data: new Uint8Array([255, 255, 255, 255]), repeat: true });
    this.srgb = srgb;
    for (const o of scene.objects) {
      const pbr = o.material.pbr;
      if (pbr === undefined) continue;
      this.hold(pbr.metallicRoughnessTexture, images, false);
      this.hold(pbr.occlusionTexture, images, false);
      this.hold(pbr.emissiveTexture, images, srgb);
      this.hold(pbr.normalTexture, images, false);
    }
  }

  /** `m`'s maps on their units, and the uniforms that read them (the PBR program is in use). */
  bind(p: Program, m: PbrMaterial): void {
    const gl = this.gl;
    this.texture(m.metallicRoughnessTexture, false).bind(METAL_ROUGH_UNIT);
    this.texture(m.occlusionTexture, false).bind(OCCLUSION_UNIT);
    this.texture(m.emissiveTexture, this.srgb).bind(EMISSIVE_UNIT);
    const normal = this.texture(m.normalTexture, false);
    normal.bind(NORMAL_UNIT);
    gl.activeTexture(gl.TEXTURE0);
    gl.uniform1i(p.location('uMetalRough'), METAL_ROUGH_UNIT);
    gl.uniform1i(p.location('uOcclusion'), OCCLUSION_UNIT);
    gl.uniform1i(p.location('uEmissiveMap'), EMISSIVE_UNIT);
    gl.uniform1i(p.location('uNormalMap'), NORMAL_UNIT);
    // White stands for a missing map: flat only at scale 0 (its 2·1 − 1 = 1 in x and y too).
    gl.uniform1f(p.location('uNormalScale'), normal === this.white ? 0 : m.normalScale);
    gl.uniform1f(p.location('uOcclusionStrength'), m.occlusionStrength);
    // The ALPHA_MASK variant's (docs/gltf.md#alpha): the base colour factor's alpha and the cutoff.
    gl.uniform2f(p.location('uAlphaMask'), m.baseColor[3], m.alphaCutoff);
    rows(0, m.baseColorTexture);
    rows(1, m.metallicRoughnessTexture);
    rows(2, m.occlusionTexture);
    rows(3, m.emissiveTexture);
    rows(4, m.normalTexture);
    gl.uniform3fv(p.location('uUvRows'), ROWS);
  }

  dispose(): void {
    for (const held of [this.colour, this.data]) {
      for (const e of held.values()) e.texture.dispose();
      held.clear();
    }
    this.white?.dispose();
    this.white = null;
  }

  private texture(t: PbrTexture | null, srgb: boolean): Texture {
    const map = readMap(t);
    return (map && (srgb ? this.colour : this.data).get(map.source.url)?.texture) ?? this.white!;
  }

  private hold(t: PbrTexture | null, images: SceneImages | null | undefined, srgb: boolean): void {
    const map = readMap(t);
    if (map === null) return;
    const url = map.source.url, held = srgb ? this.colour : this.data, image = images?.get(url), e = held.get(url);
    if (e?.source === image) return;
    e?.texture.dispose();
    held.delete(url);
    if (image) {
      const { width, height, data } = image;
      held.set(url, { source: image, texture: new Texture(this.gl, this.counter, { width, height, data, mipmap: true, repeat: true, srgb, anisotropic: srgb }) });
    }
  }
}
