// The element's side of the software renderer (docs/software-renderer.md#worker): frames drawn in workers, so the page
// stays responsive, and on the main thread where no worker can start (a strict CSP without
// worker-src, a failed worker script). The renderer's code is a chunk of its own, fetched only
// when a page uses it. One frame in flight at a time; the element asks again when it is back.
// With several workers (one per core, up to MAX_WORKERS) a frame is cut into bands of rows, one
// per worker, each drawn as in the whole frame (software/bands.ts) and put back together here.
import { hasPbrMaterial } from '../scene/scene';
import type { FrameState } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { DecodedImage } from '../scene/decoded-image';
import type { SoftwareRenderer } from '../software/software-renderer';
import { putBand, splitRows, type Band } from '../software/bands';
import { refines } from '../frame/refinement';
import { SentResources, type SoftwareRequest, type SoftwareResponse } from '../software/protocol';

export type SoftwareThread = 'worker' | 'main';

/** Workers a frame is split across at most: past 4 bands the vertex stage each repeats eats the gain. */
export const MAX_WORKERS = 4;
/** Frames too short to split: below this many rows per band the bands' overhead outweighs them. */
const MIN_BAND_ROWS = 16;

interface Drawn { pixels: Uint8ClampedArray; ms: number }

/** One worker, what it holds and its frame in flight. */
class BandWorker {
  sent = new SentResources();
  pending: { id: number; resolve(d: Drawn): void; reject(e: Error): void } | null = null;

  constructor(readonly worker: Worker, failed: () => void) {
    worker.onmessage = (e: MessageEvent<SoftwareResponse>) => {
      const p = this.pending;
      if (!p || p.id !== e.data.id) return;
      this.pending = null;
      if ('error' in e.data) p.reject(new Error(e.data.error));
      else p.resolve({ pixels: e.data.pixels, ms: e.data.ms });
    };
    // A worker that cannot load (CSP, a missing file) reports here: frames go to the main thread.
    worker.onerror = (e) => {
      e.preventDefault?.();
      failed();
    };
  }

  draw(request: Omit<SoftwareRequest, 'scene' | 'meshes' | 'images'>, scene: Scene, images: ReadonlyMap<string, DecodedImage>): Promise<Drawn> {
    return new Promise<Drawn>((resolve, reject) => {
      this.pending = { id: request.id, resolve, reject };
      try {
        this.worker.postMessage({ ...request, ...this.sent.pack(scene, images) });
      } catch (e) {
        this.pending = null;
        this.sent = new SentResources(); // it did not arrive: send it all with the next frame
        reject(e instanceof Error ? e : new Error(String(e)));
      }
    });
  }

  stop(): void {
    this.worker.terminate();
    const p = this.pending;
    this.pending = null;
    p?.reject(new Error('worker unavailable'));
  }
}

export class SoftwareHost {
  /** Workers a new host starts (tests and the bench set it); null: one per core, up to MAX_WORKERS. */
  static workerCount: number | null = null;
  private workers: BandWorker[] = [];
  private nextId = 0;
  /** Each band's rows per ms in the frames before (smoothed): a slower band gets fewer rows. */
  private speeds: number[] = [];
  /** Disposed: a frame its workers were stopped in is dropped, not drawn again on the main thread. */
  private disposed = false;
  /** The last frame's slowest band: its worker's own time, ms (the bench reads it). */
  lastWorkerMs = 0;

  /**
   * The decoded images the scene names, by URL (texture-images.ts decodes each once per page):
   * the renderer's third argument, here and in the workers (each sent to a worker once).
   */
  readonly images = new Map<string, DecodedImage>();

  private constructor(private readonly local: SoftwareRenderer) {}

  /** ImageSink: an image arrives, or goes (null). */
  setImage(url: string, image: DecodedImage | null): void {
    if (image) this.images.set(url, image);
    else this.images.delete(url);
  }

  /** Loads the renderer and starts its workers (or settles for the main thread). */
  static async create(useWorker = true, count = SoftwareHost.workerCount ?? defaultWorkerCount()): Promise<SoftwareHost> {
    const { SoftwareRenderer } = await import('../software/software-renderer');
    const host = new SoftwareHost(new SoftwareRenderer());
    if (useWorker && typeof Worker === 'function') host.startWorkers(Math.max(1, Math.min(MAX_WORKERS, Math.floor(count))));
    return host;
  }

  /** Where frames are drawn. */
  get thread(): SoftwareThread {
    return this.workers.length ? 'worker' : 'main';
  }

  /** Workers drawing frames (0: the main thread draws them). */
  get workerCount(): number {
    return this.workers.length;
  }

  private startWorkers(count: number): void {
    try {
      for (let i = 0; i < count; i++) {
        const worker = new Worker(new URL('../software/worker.ts', import.meta.url), { type: 'module', name: 'glass-plane-scene software renderer' });
        this.workers.push(new BandWorker(worker, () => this.stopWorkers()));
      }
    } catch {
      this.stopWorkers(); // the constructor itself refused (CSP): main thread
    }
  }

  /** Every worker terminated (one failed, or the element went): frames on the main thread. */
  private stopWorkers(): void {
    const workers = this.workers;
    this.workers = [];
    for (const w of workers) w.stop();
  }

  /**
   * The bands this frame is cut into, one per worker: none (the whole frame in the first
   * worker) for rough glass, whose glass gathers from the whole frame around each pixel (a band
   * would need the whole frame's reflection and mips anyway), for the `passes` view, which tiles
   * whole frames, and for frames too short to share.
   */
  private bandsOf(state: FrameState): (Band | null)[] {
    const n = this.workers.length, height = Math.max(0, Math.floor(state.height));
    if (n < 2 || !this.local.drawsBands(state) || height < n * MIN_BAND_ROWS) return [null];
    if (this.speeds.length !== n) this.speeds = new Array<number>(n).fill(1);
    return splitRows(height, n, this.speeds);
  }

  /**
   * Draws `state` of `scene` with the images given so far: RGBA8, top row first, `state.width` ×
   * `state.height`. In the workers when there are some (the request is a copy: the caller may
   * change `state` at once), else now. A worker that fails mid-way hands the frame to the main thread.
   */
  render(scene: Scene, state: FrameState, samplesPerAxis = 1): Promise<Uint8ClampedArray> {
    if (!this.workers.length) {
      // On the main thread the environment's maps are made here, once (the workers make their own): its code loaded only then.
      if (scene.environment && hasPbrMaterial(scene)) {
        return import('../software/environment-ready').then((m) => m.environmentReady(scene)).then(() => this.renderNow(scene, state, samplesPerAxis));
      }
      return Promise.resolve(this.renderNow(scene, state, samplesPerAxis));
    }
    // A still view's frames keep their bands (docs/refinement.md#averaging): each worker averages its own rows.
    const id = ++this.nextId, bands = this.bandsOf(state), still = refines(state);
    const drawn = bands.map((band, i) => this.workers[i].draw({ id, state, samplesPerAxis, band }, scene, this.images));
    return Promise.all(drawn).then((parts) => {
      this.lastWorkerMs = Math.max(...parts.map((p) => p.ms));
      if (bands[0] === null) return parts[0].pixels;
      const width = Math.max(0, Math.floor(state.width));
      const frame = new Uint8ClampedArray(4 * width * Math.max(0, Math.floor(state.height)));
      parts.forEach((p, i) => {
        const b = bands[i]!;
        putBand(frame, p.pixels, b, width);
        // Rows per ms, smoothed over a few frames; an empty or instant band keeps its speed.
        if (!still && b.bottom > b.top && p.ms > 0) this.speeds[i] = 0.5 * this.speeds[i] + 0.5 * ((b.bottom - b.top) / p.ms);
      });
      return frame;
    }).catch(() => (this.disposed ? new Uint8ClampedArray(0) : this.renderNow(scene, state, samplesPerAxis)));
  }

  /** Draws on the main thread, now (capture of a pass, the fallback). A copy of the pixels. */
  renderNow(scene: Scene, state: FrameState, samplesPerAxis = 1): Uint8ClampedArray {
    this.local.samplesPerAxis = samplesPerAxis;
    return this.local.render(scene, state, this.images).slice();
  }

  dispose(): void {
    this.disposed = true;
    this.stopWorkers();
  }
}

/** One worker per core the browser reports, up to MAX_WORKERS. */
function defaultWorkerCount(): number {
  const cores = typeof navigator === 'object' ? navigator.hardwareConcurrency : 0;
  return Math.max(1, Math.min(MAX_WORKERS, cores || 1));
}
