// The textures objects draw with: the procedural one of docs/default-scene.md#the-procedural-texture, and images by URL once their
// owner (the element) has decoded them. An object whose image is not there yet, or failed,
// draws with the procedural texture. Each is held in the frame's colour space (docs/colour.md#srgb:
// SRGB8_ALPHA8 for `srgb`, so the GPU filters linear light, anisotropically as the procedural
// texture is read there), uploaded again only when the space
// changes, and always before any pass: creating a texture binds it, which would unbind the one
// a draw has just bound (a first frame in a new space drew its images black that way).
import { Texture } from './gl/texture';
import type { ResourceCounter } from './gl/resource-counter';
import type { SharedResources } from './gl/shared-resources';
import type { TextureSource } from '../scene/scene';

interface ImageEntry {
  source: TexImageSource;
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

  /** Uploads (or, with null, frees) the image for `url`. */
  setImage(url: string, image: TexImageSource | null): void {
    this.images.get(url)?.texture.dispose();
    this.images.delete(url);
    if (!image) return;
    this.images.set(url, { source: image, texture: this.upload(image, this.srgb) });
  }

  /** The texture for `source`, and whether it is an image (read at (u, 1 − v)). */
  textureFor(source: TextureSource): Texture {
    if (source.kind === 'none') {
      // Made before the caller binds what this returns, so its creation unbinds nothing in use.
      return (this.white ??= new Texture(this.gl, this.counter, { width: 1, height: 1, data: new Uint8Array([255, 255, 255, 255]), repeat: true }));
    }
    if (source.kind !== 'image') return this.procedural;
    return this.images.get(source.url)?.texture ?? this.procedural;
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

  private upload(image: TexImageSource, srgb: boolean): Texture {
    return new Texture(this.gl, this.counter, { width: 0, height: 0, data: null, image, mipmap: true, repeat: true, srgb, anisotropic: srgb });
  }
}
