// One WebGL2 context for every <glass-plane-scene> on the page. Browsers keep only ~16 live
// contexts, so each element renders here in turn and copies its frame into its own 2D canvas.
// DOM side only: the renderer never sees this canvas, just the context.

export interface ContextClient {
  /** The context is gone: drop every GL object (they are dead) and stop drawing. */
  contextLost(): void;
  /** A fresh context: rebuild and draw. */
  contextRestored(): void;
}

const ATTRIBUTES: WebGLContextAttributes = {
  // alpha: true so the default framebuffer is RGBA8 like the multisampled targets (a
  // multisample resolve cannot convert formats); every pass writes alpha 1.
  alpha: true, antialias: false, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false,
};

function exposeForTests(gl: WebGL2RenderingContext | null): void {
  const g = globalThis as { __GLASS_PLANE_SCENE_CHECKS__?: unknown; __GLASS_PLANE_SCENE_GL__?: unknown };
  if (g.__GLASS_PLANE_SCENE_CHECKS__ === true) g.__GLASS_PLANE_SCENE_GL__ = gl ?? undefined;
}

export class SharedContext {
  private static instance: SharedContext | null = null;

  private readonly clients = new Set<ContextClient>();
  lost = false;

  /** The page's shared context, created on first use; null when WebGL2 is unavailable. */
  static acquire(client: ContextClient): SharedContext | null {
    if (!SharedContext.instance) {
      const canvas = document.createElement('canvas');
      const gl = canvas.getContext('webgl2', ATTRIBUTES);
      if (!gl) return null;
      SharedContext.instance = new SharedContext(canvas, gl);
    }
    SharedContext.instance.clients.add(client);
    return SharedContext.instance;
  }

  private constructor(readonly canvas: HTMLCanvasElement, readonly gl: WebGL2RenderingContext) {
    canvas.width = canvas.height = 1;
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

  /** Largest drawing buffer the context can take on either side. */
  get maxSize(): number {
    const gl = this.gl;
    const dims = gl.getParameter(gl.MAX_VIEWPORT_DIMS) as Int32Array | null;
    if (!dims) return 4096; // lost context: any sane bound
    return Math.min(dims[0], dims[1], gl.getParameter(gl.MAX_TEXTURE_SIZE) as number, gl.getParameter(gl.MAX_RENDERBUFFER_SIZE) as number);
  }

  /** Grows the shared canvas to hold a width × height frame in its bottom-left corner. */
  reserve(width: number, height: number): void {
    const c = this.canvas;
    if (c.width < width) c.width = width;
    if (c.height < height) c.height = height;
  }

  /** Copies the width × height frame just drawn (bottom-left of the canvas) into `target`. */
  present(target: CanvasRenderingContext2D, width: number, height: number): void {
    target.drawImage(this.canvas, 0, this.canvas.height - height, width, height, 0, 0, width, height);
  }
}
