// A multisampled colour + depth framebuffer (renderbuffers), resolved into another framebuffer.
import type { ResourceCounter } from './resource-counter';
import { internalFormat, type TargetFormat } from './render-target';

export class MultisampleTarget {
  readonly framebuffer: WebGLFramebuffer;
  private readonly color: WebGLRenderbuffer;
  private readonly depth: WebGLRenderbuffer;
  width = 0;
  height = 0;
  samples = 0;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter, readonly format: TargetFormat = 'rgba8',
  ) {
    this.framebuffer = gl.createFramebuffer()!;
    this.color = gl.createRenderbuffer()!;
    this.depth = gl.createRenderbuffer()!;
    counter.add('framebuffers');
    counter.add('renderbuffers', 2);
  }

  /** Reallocates only when size or sample count changed; returns true if it did. */
  setSize(width: number, height: number, samples: number): boolean {
    width = Math.max(1, Math.floor(width));
    height = Math.max(1, Math.floor(height));
    if (width === this.width && height === this.height && samples === this.samples) return false;
    const gl = this.gl;
    Object.assign(this, { width, height, samples });
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.color);
    gl.renderbufferStorageMultisample(gl.RENDERBUFFER, samples, internalFormat(gl, this.format), width, height);
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.depth);
    gl.renderbufferStorageMultisample(gl.RENDERBUFFER, samples, gl.DEPTH_COMPONENT24, width, height);
    gl.bindRenderbuffer(gl.RENDERBUFFER, null);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, this.color);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, this.depth);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return true;
  }

  /**
   * Averages the samples into `target` (null = the canvas), same size. `depth`: depth too (one
   * sample per pixel, not averaged; the target's depth must be DEPTH_COMPONENT24 as well).
   */
  resolve(target: WebGLFramebuffer | null, depth = false): void {
    const gl = this.gl;
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, this.framebuffer);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, target);
    const mask = depth ? gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT : gl.COLOR_BUFFER_BIT;
    gl.blitFramebuffer(0, 0, this.width, this.height, 0, 0, this.width, this.height, mask, gl.NEAREST);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteFramebuffer(this.framebuffer);
    gl.deleteRenderbuffer(this.color);
    gl.deleteRenderbuffer(this.depth);
    this.counter.add('framebuffers', -1);
    this.counter.add('renderbuffers', -2);
  }
}
