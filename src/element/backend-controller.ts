// Which backend draws (the `renderer` attribute): WebGL2 where asked and available, the CPU
// renderer where asked or (auto) where WebGL2 is not. Starts it on connection, switches when the
// attribute changes, follows the shared context's loss and restoration, keeps the counters of a
// renderer that is gone, and frees everything on removal.
import { ShaderError } from '../render/gl/program';
import type { ReadbackSource } from '../render/renderer';
import type { FrameState, RenderStats } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { CapturePass } from './types';
import { warn } from './warnings';
import type { Backend, BackendHost } from './backend';
import type { Controller } from './controller';
import type { Failure } from './failure';
import { SharedContext, type ContextClient, type Presenter } from './shared-context';
import { SOFTWARE_MAX_SIZE } from './software-size';
import { WebGLBackend } from './webgl-backend';

/** What BackendController needs of the scene element (and passes on to the backends). */
export interface BackendControllerHost extends Omit<BackendHost, 'renderError'> {
  /** Connected: a software renderer that loads after removal is dropped. */
  readonly element: HTMLElement;
  /** Why the element cannot draw; the controller sets and clears it. */
  readonly failure: Failure;
  /** The `renderer` attribute. */
  renderer(): 'auto' | 'webgl' | 'software';
  /** A backend is ready: feed it, fit the canvas and draw. */
  started(backend: Backend): void;
  /** No frame may be drawn now (the context is lost, the renderer changes). */
  stopFrames(): void;
}

const CAPTURE_SOURCES: Record<CapturePass, ReadbackSource> = { reflection: 'reflection', scene: 'scene', final: 'final' };

function emptyStats(): RenderStats {
  const zero = { reflection: 0, scene: 0, glass: 0 };
  return {
    frames: 0, programs: 0, sphereSegments: 0, passesRun: { ...zero }, passesSkipped: { ...zero }, drawCalls: 0, triangles: { scene: 0, reflection: 0 },
    resources: { buffers: 0, textures: 0, framebuffers: 0, renderbuffers: 0, vertexArrays: 0, programs: 0, shaders: 0, total: 0 },
  };
}

export class BackendController implements Controller, ContextClient {
  /** The backend drawing now, or null (none yet, loading, failed, or removed). */
  current: Backend | null = null;
  /** The page's shared WebGL2 context, from the first WebGL start until removal. */
  private shared: SharedContext | null = null;
  /** How WebGL frames reach this element's canvas (one per canvas). */
  private presenter: Presenter | null = null;
  /** The software start under way; a start overtaken by a change or a removal is dropped. */
  private starting: object | null = null;
  /** The counters of the last WebGL renderer, its resources zero (stats after it is gone). */
  private totals = emptyStats();
  private readonly backendHost: BackendHost;

  constructor(private readonly host: BackendControllerHost) {
    this.backendHost = {
      canvas: host.canvas,
      drawn: (state, report) => host.drawn(state, report),
      requestRender: () => host.requestRender(),
      resume: (offThread) => host.resume(offThread),
      renderError: (e) => this.renderError(e),
    };
  }

  /** Largest side of the drawing buffer; null while nothing can draw (the canvas keeps its size). */
  get maxSize(): number | null {
    if (this.shared) return this.shared.maxSize;
    return this.current ? SOFTWARE_MAX_SIZE : null;
  }

  hostConnected(): void {
    this.start();
  }

  hostDisconnected(): void {
    this.stop();
    this.shared?.release(this);
    this.shared = null;
  }

  /** `renderer` changed: let go of the renderer in use and start the one now asked for. */
  rendererChanged(): void {
    const choice = this.host.renderer();
    const kind = this.current?.kind ?? (this.starting ? 'software' : null);
    const wantSoftware = choice === 'software' || (choice === 'auto' && kind !== 'webgl' && !this.shared);
    if ((wantSoftware && kind === 'software') || (!wantSoftware && kind === 'webgl')) return;
    this.host.stopFrames();
    this.stop();
    // The CPU renderer needs no context: no longer its client, its loss no longer ours, the
    // canvas's limit the CPU's.
    if (wantSoftware) {
      this.shared?.release(this);
      this.shared = null;
    }
    if (wantSoftware || this.host.failure.type !== 'context-lost') this.host.failure.clear();
    this.start();
  }

  /** `pass` of `state` drawn now, off screen (anything but a pass name: the final image, with a warning). */
  capture(scene: Scene, state: FrameState, pass: CapturePass): ImageData | null {
    const source: ReadbackSource = CAPTURE_SOURCES[pass] ?? 'final';
    if (!(pass in CAPTURE_SOURCES)) warn(`capture("${String(pass).slice(0, 40)}") is not a pass; capturing "final"`);
    return this.current?.capture(scene, state, source) ?? null;
  }

  /** Frames, passes, draw calls, programs and live GL resources; which renderer and thread. */
  stats(): RenderStats {
    const b = this.current;
    const s = b?.stats() ?? structuredClone(this.totals);
    s.renderer = b?.kind ?? null;
    if (b?.thread) s.thread = b.thread;
    return s;
  }

  /** @internal ContextClient: every GL object died with the context. */
  contextLost(): void {
    this.host.stopFrames();
    if (this.current?.kind === 'webgl') this.stop();
    this.host.failure.fail('context-lost', new Error('WebGL context lost'));
  }

  /** @internal ContextClient: rebuild on the restored context and draw. */
  contextRestored(): void {
    if (this.host.failure.type !== 'context-lost') return;
    this.host.failure.clear();
    this.start();
  }

  private start(): void {
    const failed = this.host.failure.type;
    if (this.current || this.starting || (failed && failed !== 'context-lost')) return;
    const choice = this.host.renderer();
    if (choice === 'software') return this.startSoftware();
    this.shared ??= SharedContext.acquire(this);
    if (!this.shared) {
      // auto: no WebGL2 here, so the CPU draws the scene; nothing to report.
      if (choice === 'auto') return this.startSoftware();
      this.host.failure.fail('webgl2-unavailable', new Error('WebGL2 is not available in this browser, so this scene cannot be shown.'));
      return;
    }
    if (this.shared.lost || this.shared.gl.isContextLost()) return;
    this.presenter ??= this.shared.presenterFor(this.host.canvas);
    try {
      this.current = new WebGLBackend(this.backendHost, this.shared, this.presenter);
    } catch (e) {
      this.renderError(e);
      return;
    }
    this.host.started(this.current);
  }

  /** The software renderer, loaded as chunks of its own (software-start.ts); `error` only if it cannot start either. */
  private startSoftware(): void {
    const token = {};
    this.starting = token;
    const started = import('./software-start').then(async (chunk) => ({ chunk, software: await chunk.SoftwareHost.create() }));
    started.then(({ chunk, software }) => {
      if (this.starting !== token) return software.dispose();
      this.starting = null;
      if (!this.host.element.isConnected) return software.dispose();
      this.current = new chunk.SoftwareBackend(this.backendHost, software);
      this.host.started(this.current);
    }, (e: unknown) => {
      if (this.starting !== token) return;
      this.starting = null;
      const why = e instanceof Error ? e.message : String(e);
      this.host.failure.fail('webgl2-unavailable', new Error(`Neither WebGL2 nor the software renderer is available here (${why}), so this scene cannot be shown.`));
    });
  }

  /** Drops the backend in use and any start under way; a WebGL renderer's counters are kept. */
  private stop(): void {
    this.starting = null;
    const last = this.current?.dispose() ?? null;
    this.current = null;
    if (!last) return;
    this.totals = last;
    this.totals.resources = emptyStats().resources;
  }

  private renderError(e: unknown): void {
    if (e instanceof ShaderError) this.host.failure.fail('shader', e);
    else if (this.shared?.gl.isContextLost()) this.contextLost();
    else throw e;
  }
}
