// The element's side of the software renderer (SPEC §11): frames drawn in a worker, so the page
// stays responsive, and on the main thread where no worker can start (a strict CSP without
// worker-src, a failed worker script). The renderer's code is a chunk of its own, fetched only
// when a page uses it. One frame in flight at a time; the element asks again when it is back.
import type { FrameState } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { DecodedImage } from '../scene/decoded-image';
import type { SoftwareRenderer } from '../software/software-renderer';
import { SentResources, type SoftwareRequest, type SoftwareResponse } from '../software/protocol';

export type SoftwareThread = 'worker' | 'main';

export class SoftwareHost {
  private worker: Worker | null = null;
  private sent = new SentResources();
  private nextId = 0;
  private pending: { id: number; resolve(p: Uint8ClampedArray): void; reject(e: Error): void } | null = null;

  /**
   * Decoded pixels of the scene's image textures by URL. The host is the element's image sink
   * (texture-images.ts) while it draws: each image is decoded once per page, as for WebGL.
   */
  readonly images = new Map<string, DecodedImage>();

  private constructor(private readonly local: SoftwareRenderer) {}

  /** ImageSink: an image arrives (as pixels: the CPU reads them), or goes (null). */
  setImage(url: string, image: TexImageSource | null): void {
    if (!image) {
      this.images.delete(url);
      return;
    }
    const { width, height } = image as { width: number; height: number };
    const canvas = new OffscreenCanvas(width, height);
    const ctx = canvas.getContext('2d')!;
    ctx.drawImage(image as CanvasImageSource, 0, 0);
    this.images.set(url, ctx.getImageData(0, 0, width, height));
  }

  /** Loads the renderer and starts its worker (or settles for the main thread). */
  static async create(useWorker = true): Promise<SoftwareHost> {
    const { SoftwareRenderer } = await import('../software/software-renderer');
    const host = new SoftwareHost(new SoftwareRenderer());
    if (useWorker && typeof Worker === 'function') host.startWorker();
    return host;
  }

  /** Where frames are drawn. */
  get thread(): SoftwareThread {
    return this.worker ? 'worker' : 'main';
  }

  private startWorker(): void {
    try {
      const worker = new Worker(new URL('../software/worker.ts', import.meta.url), { type: 'module', name: 'glass-plane-scene software renderer' });
      worker.onmessage = (e: MessageEvent<SoftwareResponse>) => {
        const p = this.pending;
        if (!p || p.id !== e.data.id) return;
        this.pending = null;
        if ('error' in e.data) p.reject(new Error(e.data.error));
        else p.resolve(e.data.pixels);
      };
      // A worker that cannot load (CSP, a missing file) reports here: frames go to the main thread.
      worker.onerror = (e) => {
        e.preventDefault?.();
        this.stopWorker();
      };
      this.worker = worker;
    } catch {
      this.worker = null; // the constructor itself refused (CSP): main thread
    }
  }

  private stopWorker(): void {
    this.worker?.terminate();
    this.worker = null;
    this.sent = new SentResources();
    const p = this.pending;
    this.pending = null;
    p?.reject(new Error('worker unavailable'));
  }

  /**
   * Draws `state` of `scene`: RGBA8, top row first, `state.width` × `state.height`. In the worker
   * when there is one (the request is a copy: the caller may change `state` at once), else now.
   * A worker that fails mid-way hands the frame to the main thread.
   */
  render(state: FrameState, scene: Scene, samplesPerAxis = 1): Promise<Uint8ClampedArray> {
    const images = this.images;
    if (!this.worker) return Promise.resolve(this.renderNow(state, scene, samplesPerAxis));
    const id = ++this.nextId;
    const request: SoftwareRequest = { id, state, samplesPerAxis, ...this.sent.pack(scene, images) };
    return new Promise<Uint8ClampedArray>((resolve, reject) => {
      this.pending = { id, resolve, reject };
      try {
        this.worker!.postMessage(request);
      } catch (e) {
        this.pending = null;
        this.sent = new SentResources(); // it did not arrive: send it all with the next frame
        reject(e instanceof Error ? e : new Error(String(e)));
      }
    }).catch(() => this.renderNow(state, scene, samplesPerAxis));
  }

  /** Draws on the main thread, now (capture of a pass, the fallback). A copy of the pixels. */
  renderNow(state: FrameState, scene: Scene, samplesPerAxis = 1): Uint8ClampedArray {
    this.local.samplesPerAxis = samplesPerAxis;
    return this.local.render(state, scene, this.images).slice();
  }

  dispose(): void {
    this.stopWorker();
  }
}
