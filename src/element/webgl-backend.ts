// Frames drawn with WebGL2 in the page's shared context (shared-context.ts) and handed to the
// element's canvas. All GL work is the renderer's; this file only calls it and presents.
import { Renderer, type ReadbackSource } from '../render/renderer';
import type { FrameState, RenderStats } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { DecodedImage } from '../scene/decoded-image';
import type { Backend, BackendHost } from './backend';
import type { Presenter, SharedContext } from './shared-context';
import { warn } from './warnings';

function checksEnabled(): boolean {
  return (globalThis as { __GLASS_PLANE_SCENE_CHECKS__?: unknown }).__GLASS_PLANE_SCENE_CHECKS__ === true;
}

export class WebGLBackend implements Backend {
  readonly kind = 'webgl';
  /**
   * Signalled when the GPU has drawn the last frame. The page never gets ahead of the GPU by more
   * than one frame: a slow GPU (a software one) would queue frame after frame, and the page's
   * main thread then stalls for seconds as the queue drains (docs/interaction.md#inertia).
   */
  private fence: WebGLSync | null = null;
  private disposed = false;
  private readonly renderer: Renderer;
  /** The images given so far, by URL: the renderer's third argument (it uploads each once). */
  private readonly images = new Map<string, DecodedImage>();

  /** Throws what the renderer's constructor throws (a shader that fails, a lost context). */
  constructor(private readonly host: BackendHost, private readonly shared: SharedContext, private readonly presenter: Presenter) {
    this.renderer = new Renderer(shared.gl, {
      checks: checksEnabled(),
      parts: {
        settled: () => {
          if (!this.disposed) host.requestRender();
        },
        warn,
      },
    });
  }

  /** The GPU still draws the last frame: this one is skipped and the next animation frame looks again. */
  get busy(): boolean {
    const gl = this.shared.gl, fence = this.fence;
    if (!fence) return false;
    if (gl.getSyncParameter(fence, gl.SYNC_STATUS) === gl.UNSIGNALED) {
      this.host.resume(false);
      return true;
    }
    this.dropFence();
    return false;
  }

  private dropFence(): void {
    this.shared.gl.deleteSync(this.fence);
    this.fence = null;
  }

  waitsFor(scene: Scene, state: FrameState): boolean {
    return this.renderer.load(scene, state) !== null;
  }

  /** ImageSink: the next frame uploads it (null: the next frame frees it). */
  setImage(url: string, image: DecodedImage | null): void {
    if (image) this.images.set(url, image);
    else this.images.delete(url);
  }

  draw(scene: Scene, state: FrameState): void {
    const { width, height } = this.host.canvas;
    let report;
    try {
      this.shared.reserve(width, height);
      report = this.renderer.render(scene, state, this.images);
      this.presenter.present(width, height);
      const gl = this.shared.gl;
      this.fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      gl.flush();
    } catch (e) {
      this.host.renderError(e);
      return;
    }
    this.host.drawn(state, report);
  }

  capture(scene: Scene, state: FrameState, source: ReadbackSource): ImageData | null {
    try {
      this.shared.reserve(this.host.canvas.width, this.host.canvas.height);
      const px = this.renderer.read(scene, state, this.images, source);
      return new ImageData(px.data, px.width, px.height);
    } catch (e) {
      this.host.renderError(e);
      return null;
    }
  }

  stats(): RenderStats {
    return this.renderer.stats;
  }

  dispose(): RenderStats {
    this.disposed = true;
    this.dropFence();
    const last = this.renderer.stats;
    this.renderer.dispose();
    return last;
  }
}
