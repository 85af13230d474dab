// Frames drawn with WebGL2 in the page's shared context (shared-context.ts) and handed to the
// element's canvas. All GL work is the renderer's; this file only calls it and presents.
import { Renderer, type ReadbackSource } from '../render/renderer';
import type { FrameState, RenderStats } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { Backend, BackendHost } from './backend';
import type { Presenter, SharedContext } from './shared-context';
import { warn } from './warnings';

function checksEnabled(): boolean {
  return (globalThis as { __GLASS_PLANE_SCENE_CHECKS__?: unknown }).__GLASS_PLANE_SCENE_CHECKS__ === true;
}

export class WebGLBackend implements Backend {
  readonly kind = 'webgl';
  /** Frames are drawn at once: none is ever on its way. */
  readonly busy = false;
  private disposed = false;
  private readonly renderer: Renderer;

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

  waitsFor(state: FrameState, scene: Scene): boolean {
    return this.renderer.load(state, scene) !== null;
  }

  setImage(url: string, image: TexImageSource | null): void {
    this.renderer.setImage(url, image);
  }

  draw(state: FrameState, scene: Scene): void {
    const { width, height } = this.host.canvas;
    let report;
    try {
      this.shared.reserve(width, height);
      report = this.renderer.render(state, scene);
      this.presenter.present(width, height);
    } catch (e) {
      this.host.renderError(e);
      return;
    }
    this.host.drawn(state, report);
  }

  capture(source: ReadbackSource, state: FrameState, scene: Scene): ImageData | null {
    try {
      this.shared.reserve(this.host.canvas.width, this.host.canvas.height);
      const px = this.renderer.read(source, state, scene);
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
    const last = this.renderer.stats;
    this.renderer.dispose();
    return last;
  }
}
