// One WebGL2 context for every <glass-plane-scene> on the page. Browsers keep only ~16 live
// contexts, so each element renders here in turn and hands its frame to its own canvas:
// with OffscreenCanvas as an ImageBitmap transfer (no copy), else by a 2D drawImage.
// DOM side only: the renderer never sees this canvas, just the context.

import { maxTargetSize } from '../render/gl/limits';

export interface ContextClient {
  /** The context is gone: drop every GL object (they are dead) and stop drawing. */
  contextLost(): void;
  /** A fresh context: rebuild and draw. */
  contextRestored(): void;
}

/** Shows the frame just drawn in the shared context on one element's canvas. */
export interface Presenter {
  present(width: number, height: number): void;
}

const ATTRIBUTES: WebGLContextAttributes = {
  // alpha: true so the default framebuffer is RGBA8 like the multisampled targets (a
  // multisample resolve cannot convert formats); every pass writes alpha 1.
  alpha: true, antialias: false, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false,
};

function exposeForTests(gl: WebGL2RenderingContext): void {
  const g = globalThis as { __GLASS_PLANE_SCENE_CHECKS__?: unknown; __GLASS_PLANE_SCENE_GL__?: unknown };
  if (g.__GLASS_PLANE_SCENE_CHECKS__ === true) g.__GLASS_PLANE_SCENE_GL__ = gl;
}

type AnyCanvas = OffscreenCanvas | HTMLCanvasElement;

export class SharedContext {
  private static instance: SharedContext | null = null;

  private readonly clients = new Set<ContextClient>();
  lost = false;

  /** The page's shared context, created on first use; null when WebGL2 is unavailable. */
  static acquire(client: ContextClient): SharedContext | null {
    if (!SharedContext.instance) {
      const canvas: AnyCanvas = typeof OffscreenCanvas === 'function' ? new OffscreenCanvas(1, 1) : document.createElement('canvas');
      const gl = canvas.getContext('webgl2', ATTRIBUTES) as WebGL2RenderingContext | null;
      if (!gl) return null;
      SharedContext.instance = new SharedContext(canvas, gl);
    }
    SharedContext.instance.clients.add(client);
    return SharedContext.instance;
  }

  private constructor(private readonly canvas: AnyCanvas, readonly gl: WebGL2RenderingContext) {
    canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault(); // we will restore
      this.lost = true;
      for (const c of [...this.clients]) c.contextLost();
    });
    canvas.addEventListener('webglcontextrestored', () => {
      this.lost = false;
      for (const c of [...this.clients]) c.contextRestored();
    });
    exposeForTests(gl);
  }

  release(client: ContextClient): void {
    this.clients.delete(client);
  }

  private get transfers(): boolean {
    return typeof OffscreenCanvas === 'function' && this.canvas instanceof OffscreenCanvas;
  }

  /** Largest drawing buffer the context can take on either side. */
  get maxSize(): number {
    return maxTargetSize(this.gl);
  }

  /**
   * Makes room for a width × height frame in the bottom-left of the default framebuffer:
   * exactly that size when frames are transferred (elements of one size never reallocate),
   * at least that size when they are copied.
   */
  reserve(width: number, height: number): void {
    const c = this.canvas;
    if (this.transfers) {
      if (c.width !== width) c.width = width;
      if (c.height !== height) c.height = height;
    } else {
      if (c.width < width) c.width = width;
      if (c.height < height) c.height = height;
    }
  }

  /** How `target` shows frames from this context (call once per element canvas). */
  presenterFor(target: HTMLCanvasElement): Presenter {
    if (this.transfers) {
      const bitmaps = target.getContext('bitmaprenderer');
      if (bitmaps) {
        const source = this.canvas as OffscreenCanvas;
        return { present: () => bitmaps.transferFromImageBitmap(source.transferToImageBitmap()) };
      }
    }
    const ctx = target.getContext('2d', { alpha: false })!;
    return {
      present: (width, height) => {
        // Fallback: grow-only canvas, frame in its bottom-left corner.
        if (target.width !== width) target.width = width;
        if (target.height !== height) target.height = height;
        ctx.drawImage(this.canvas, 0, this.canvas.height - height, width, height, 0, 0, width, height);
      },
    };
  }
}
