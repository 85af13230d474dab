// Image textures named by a scene (`texture`, an MTL's map_Kd): fetched and decoded once per URL
// per page into the pixels every renderer takes (DecodedImage), handed to the element's backend
// when ready. Until then, or when an image fails (one warning per URL), the object keeps the
// procedural texture and the scene keeps drawing.
import { materialImages, type Scene } from '../scene/scene';
import type { DecodedImage } from '../scene/decoded-image';
import { warn } from './warnings';

const decoded = new Map<string, Promise<DecodedImage | null>>();
/** The images whose decoding has settled (null: failed), for whoever asks after: handed over at once, not a task later. */
const settled = new Map<string, DecodedImage | null>();

/** A bitmap's pixels, read once through a 2D canvas (RGBA8, top row first); the bitmap is closed. */
function pixelsOf(bitmap: ImageBitmap): DecodedImage {
  const { width, height } = bitmap;
  const ctx = new OffscreenCanvas(width, height).getContext('2d')!;
  ctx.drawImage(bitmap, 0, 0);
  bitmap.close();
  return ctx.getImageData(0, 0, width, height);
}

/** The decoded pixels of `url` (null when it failed, with one warning); fetched once per page. */
export function decodeImage(url: string): Promise<DecodedImage | null> {
  let p = decoded.get(url);
  if (!p) {
    p = fetch(url)
      .then((r) => {
        if (!r.ok) throw new Error(`HTTP ${r.status}`);
        return r.blob();
      })
      .then((blob) => createImageBitmap(blob))
      .then(pixelsOf)
      .catch((e: unknown) => {
        warn(`texture "${url}" could not be loaded (${e instanceof Error ? e.message : String(e)}); using the procedural texture`);
        return null;
      })
      .then((image) => {
        settled.set(url, image);
        return image;
      });
    decoded.set(url, p);
  }
  return p;
}

/** Where the decoded images go: a backend keeps them and hands them to its renderer with each frame. */
export interface ImageSink {
  /** `image` for `url` (null: freed). */
  setImage(url: string, image: DecodedImage | null): void;
}

/** What TextureImages needs of the scene element. */
export interface TextureImagesHost {
  /** The renderer drawing now, which takes the images (null while there is none). */
  sink(): ImageSink | null;
  /** An image arrived: draw again. */
  loaded(): void;
}

/**
 * Not a Controller: it listens to nothing and holds nothing open while connected, so it has no
 * hooks. An image on its way lands in whichever renderer draws when it arrives, or in none.
 */
export class TextureImages {
  private readonly ready = new Map<string, DecodedImage>();
  private readonly asked = new Set<string>();
  private lastScene: Scene | null = null;

  constructor(private readonly host: TextureImagesHost) {}

  /** A renderer that starts drawing: it gets every image decoded so far. */
  feed(sink: ImageSink): void {
    for (const [url, image] of this.ready) sink.setImage(url, image);
  }

  /** Asks for the images `scene` names; a new scene value only (nothing to do per frame). */
  sync(scene: Scene): void {
    // Stryker disable next-line ConditionalExpression: the same scene again asks for nothing new (`asked`): the test saves the walk
    if (scene === this.lastScene) return;
    this.lastScene = scene;
    for (const o of scene.objects) for (const url of materialImages(o.material)) {
      if (this.asked.has(url)) continue;
      this.asked.add(url);
      // Decoded already (a child's `load` waits for its images): in this frame, the one `load` promised them to.
      const now = settled.get(url);
      if (now !== undefined) {
        if (now) this.take(url, now);
        continue;
      }
      void decodeImage(url).then((image) => {
        if (!image) return;
        this.take(url, image);
        this.host.loaded();
      });
    }
  }

  private take(url: string, image: DecodedImage): void {
    this.ready.set(url, image);
    this.host.sink()?.setImage(url, image);
  }
}
