// The textures objects draw with: the procedural one of SPEC §3, and images by URL once their
// owner (the element) has decoded them. An object whose image is not there yet, or failed,
// draws with the procedural texture.
import { Texture } from './gl/texture';
import type { ResourceCounter } from './gl/resource-counter';
import type { TextureSource } from '../scene/scene';

export class TextureCache {
  private readonly images = new Map<string, Texture>();
  /** 1×1 white, for `{ kind: 'none' }`: made when a scene first needs it. */
  private white: Texture | null = null;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter, readonly procedural: Texture,
  ) {}

  /** Uploads (or, with null, frees) the image for `url`. */
  setImage(url: string, image: TexImageSource | null): void {
    this.images.get(url)?.dispose();
    this.images.delete(url);
    if (!image) return;
    this.images.set(url, new Texture(this.gl, this.counter, { width: 0, height: 0, data: null, image, mipmap: true, repeat: true }));
  }

  /** The texture for `source`, and whether it is an image (read at (u, 1 − v)). */
  textureFor(source: TextureSource): Texture {
    if (source.kind === 'none') {
      return (this.white ??= new Texture(this.gl, this.counter, { width: 1, height: 1, data: new Uint8Array([255, 255, 255, 255]), repeat: true }));
    }
    return source.kind === 'image' ? (this.images.get(source.url) ?? this.procedural) : this.procedural;
  }

  isImage(texture: Texture): boolean {
    return texture !== this.procedural;
  }

  dispose(): void {
    for (const t of this.images.values()) t.dispose();
    this.images.clear();
    this.white?.dispose();
    this.white = null;
  }
}
