// The textures objects draw with: the procedural one of docs/default-scene.md#the-procedural-texture, and the images each
// frame is given by URL (the renderer contract's SceneImages): uploaded when a frame's scene first
// names one its map has, freed when a frame naming it finds it gone from the map or replaced there
// (else with the renderer). An object whose image is not in the frame's map draws with the
// procedural texture. Each is held in the frame's colour space (docs/colour.md#srgb:
// SRGB8_ALPHA8 for `srgb`, so the GPU filters linear light, anisotropically as the procedural
// texture is read there), uploaded again only when the space
// changes, and always before any pass: creating a texture binds it, which would unbind the one
// a draw has just bound (a first frame in a new space drew its images black that way).
import { Texture } from './gl/texture';
import type { ResourceCounter } from './gl/resource-counter';
import type { SharedResources } from './gl/shared-resources';
import type { Scene, TextureSource } from '../scene/scene';
import type { DecodedImage, SceneImages } from '../scene/decoded-image';

interface ImageEntry {
  source: DecodedImage;
  texture: Texture;
}

export class TextureCache {
  private readonly images = new Map<string, ImageEntry>();
  /** 1×1 white, for `{ kind: 'none' }` (white decodes to white), made when a scene first needs it. */
  private white: Texture | null = null;
  /** Images are held as sRGB colour data (the default `color-space`), or as stored. */
  private srgb = true;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter, private readonly shared: SharedResources,
  ) {}

  /** The colour space of the frame about to be drawn; called before any pass. */
  setColorSpace(srgb: boolean): void {
    this.shared.texture(srgb); // made now if it is the first frame in this space, not mid-pass
    if (srgb === this.srgb) return;
    this.srgb = srgb;
    for (const e of this.images.values()) {
      e.texture.dispose();
      e.texture = this.upload(e.source, srgb);
    }
  }

  /** The procedural texture in this frame's colour space. */
  get procedural(): Texture {
    return this.shared.texture(this.srgb);
  }

  /**
   * The frame's images, before any pass: for each image `scene` names, one new in `images` is
   * uploaded, one gone from it (or replaced there) freed. An unchanged map uploads and allocates nothing.
   */
  sync(scene: Scene, images: SceneImages | null | undefined): void {
    for (const o of scene.objects) {
      const t = o.material.texture;
      if (t.kind !== 'image') continue;
      const image = images?.get(t.url), e = this.images.get(t.url);
      if (e?.source === image) continue;
      e?.texture.dispose();
      if (image) this.images.set(t.url, { source: image, texture: this.upload(image, this.srgb) });
      else this.images.delete(t.url);
    }
  }

  /** The texture for `source`, and whether it is an image (read at (u, 1 − v)). */
  textureFor(source: TextureSource): Texture {
    if (source.kind === 'none') return this.plain();
    if (source.kind !== 'image') return this.procedural;
    return this.images.get(source.url)?.texture ?? (source.fallback === 'none' ? this.plain() : this.procedural);
  }

  /** 1×1 white: no texture. Made before the caller binds what textureFor returns, so its creation unbinds nothing in use. */
  private plain(): Texture {
    return (this.white ??= new Texture(this.gl, this.counter, { width: 1, height: 1, data: new Uint8Array([255, 255, 255, 255]), repeat: true }));
  }

  isImage(texture: Texture): boolean {
    return texture !== this.procedural;
  }

  dispose(): void {
    for (const e of this.images.values()) e.texture.dispose();
    this.images.clear();
    this.white?.dispose();
    this.white = null;
  }

  private upload(image: DecodedImage, srgb: boolean): Texture {
    return new Texture(this.gl, this.counter, { width: image.width, height: image.height, data: image.data, mipmap: true, repeat: true, srgb, anisotropic: srgb });
  }
}
