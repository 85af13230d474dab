// `environment="url"` (docs/pbr.md#an-image): an equirectangular image as the light on glTF materials, a chunk of its own
// (the ENVIRONMENT_FILE part, element/parts.ts), fetched when the attribute names a URL and the scene has a glTF material.
// Loaded once per URL per page (children/model-cache.ts): a Radiance .hdr read by loaders/hdr.ts, or an image the browser
// decodes (PNG, JPEG) taken as sRGB; reduced to at most 512 × 256 (math/environment-image.ts); then its prefiltered maps are made
// on this thread in slices (frame/environment-light.ts) before the scene names it, so no frame waits on them. Meanwhile
// glTF materials are lit by the lights alone; a file that fails fires `error` on the element, which lights them by the
// neutral studio instead.
import { parseHdr } from '../loaders/hdr';
import { LoadError } from '../loaders/load-error';
import type { EnvironmentImage } from '../math/environment-image';
import { reduceImage } from '../math/reduce-image';
import { SRGB_BYTE_TO_LINEAR } from '../math/srgb';
import { acquire, loadErrorDetail, type Handle } from './children/model-cache';
import { absoluteUrl } from './absolute-url';
import type { EnvironmentPart } from './compose-scene';

interface LoadedEnvironment {
  url: string;
  image: EnvironmentImage;
  warnings: string[];
}

/** The first byte that is not white space (after a UTF-8 BOM). */
function firstByte(b: Uint8Array): number {
  let p = b[0] === 0xef && b[1] === 0xbb && b[2] === 0xbf ? 3 : 0;
  while (p < b.length && (b[p] === 0x20 || b[p] === 0x09 || b[p] === 0x0d || b[p] === 0x0a)) p++;
  return b[p];
}

/** An image the browser decodes, its bytes taken as sRGB, as linear light. */
async function decodeImage(bytes: Uint8Array, url: string): Promise<EnvironmentImage> {
  let bitmap: ImageBitmap;
  try {
    bitmap = await createImageBitmap(new Blob([bytes as Uint8Array<ArrayBuffer>]), { colorSpaceConversion: 'none', premultiplyAlpha: 'none' });
  } catch {
    throw new LoadError(url, 'not an environment image: neither a Radiance .hdr (it does not begin with "#?") nor an image the browser can decode (PNG, JPEG)');
  }
  const { width, height } = bitmap;
  const ctx = new OffscreenCanvas(width, height).getContext('2d', { willReadFrequently: true })!;
  ctx.drawImage(bitmap, 0, 0);
  bitmap.close();
  const px = ctx.getImageData(0, 0, width, height).data, rgb = new Float32Array(width * height * 3);
  for (let k = 0, n = width * height; k < n; k++) {
    rgb[3 * k] = SRGB_BYTE_TO_LINEAR[px[4 * k]];
    rgb[3 * k + 1] = SRGB_BYTE_TO_LINEAR[px[4 * k + 1]];
    rgb[3 * k + 2] = SRGB_BYTE_TO_LINEAR[px[4 * k + 2]];
  }
  return { width, height, rgb };
}

/**
 * `url`'s bytes. Not the models' fetch (children/model-fetch.ts, with progress for the loading bar): its chunk carries the text
 * loaders' decoding, which an image does not need.
 */
async function fetchImage(url: string, signal: AbortSignal): Promise<Uint8Array> {
  const response = await fetch(url, { signal });
  if (!response.ok) throw new LoadError(url, `HTTP ${response.status}${response.statusText ? ` ${response.statusText}` : ''}`);
  return new Uint8Array(await response.arrayBuffer());
}

/** `url`'s image, reduced, its maps made on this page. */
async function loadEnvironment(url: string, signal: AbortSignal): Promise<LoadedEnvironment> {
  const bytes = await fetchImage(url, signal);
  signal.throwIfAborted();
  const first = firstByte(bytes);
  // '#' a Radiance header, '<' an HTML page (the reader names it); anything else the browser's decoders try.
  const image = reduceImage(first === 0x23 || first === 0x3c ? parseHdr(bytes, { url }) : await decodeImage(bytes, url));
  const { prepareEnvironmentSliced } = await import('../frame/environment-light');
  await prepareEnvironmentSliced({ kind: 'image', intensity: 1, url, image });
  return { url, image, warnings: [] };
}

/** What EnvironmentFiles needs of the scene element. */
export interface EnvironmentFilesHost {
  /** `error` is fired on it. */
  readonly element: HTMLElement;
  /** An image arrived, or failed: the scene is built again. */
  changed(): void;
}

/** The image of the `environment` attribute, for the scene value. */
export class EnvironmentFiles {
  private src: string | null = null;
  private handle: Handle<LoadedEnvironment> | null = null;
  private part: EnvironmentPart | null = null;
  /** Not asked yet: the scene is built again after this code arrived, and a CPU frame in flight may come first. */
  private fresh = true;

  constructor(private readonly host: EnvironmentFilesHost) {}

  /** An image on its way, or about to be asked for (`ready` waits for it). */
  get loading(): boolean {
    return this.fresh || (this.handle !== null && this.part === null);
  }

  /**
   * The environment of `src` (the attribute as written: a URL), for a scene being built: its image once in; `neutral` after a
   * failure; null while it loads. A new `src` lets go of the one before.
   */
  partFor(src: string): EnvironmentPart | null {
    this.fresh = false;
    if (src === this.src) return this.part;
    this.release();
    this.src = src;
    const url = absoluteUrl(src);
    if (url === null) {
      this.fail({ type: 'load', url: src, message: 'not a usable URL' });
      return this.part;
    }
    const handle = (this.handle = acquire(`environment ${url}`, url, () => {}, (signal) => loadEnvironment(url, signal)));
    handle.promise.then(
      (loaded) => {
        if (this.handle !== handle) return;
        this.part = { url, image: loaded.image };
        this.host.changed();
      },
      (e) => {
        if (this.handle !== handle) return;
        this.fail(loadErrorDetail(url, e));
      },
    );
    return null;
  }

  /** The attribute no longer names a URL, or the element left the page: the load stops. */
  release(): void {
    this.fresh = false;
    this.handle?.release();
    this.handle = null;
    this.src = null;
    this.part = null;
  }

  private fail(detail: ReturnType<typeof loadErrorDetail>): void {
    this.part = 'neutral';
    this.host.changed();
    queueMicrotask(() => this.host.element.dispatchEvent(new CustomEvent('error', { detail })));
  }
}
