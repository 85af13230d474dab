// An off-screen colour texture + depth renderbuffer; reallocated only when its size changes.
// Colour as RGBA8, SRGB8_ALPHA8 (linear light held encoded: no banding in the darks, blended
// and sampled in linear; docs/colour.md#srgb), RGBA16F (needs EXT_color_buffer_float) or RGBA32F (refinement's sum:
// blended only with EXT_float_blend, read with texelFetch, so filtered NEAREST).
import type { ResourceCounter } from './resource-counter';

export type TargetFormat = 'rgba8' | 'srgb8' | 'rgba16f' | 'rgba32f';

/** Internal format of a colour attachment. */
export function internalFormat(gl: WebGL2RenderingContext, format: TargetFormat): number {
  return format === 'rgba16f' ? gl.RGBA16F : format === 'rgba32f' ? gl.RGBA32F : format === 'srgb8' ? gl.SRGB8_ALPHA8 : gl.RGBA8;
}

export class RenderTarget {
  readonly framebuffer: WebGLFramebuffer;
  readonly color: WebGLTexture;
  private readonly depth: WebGLRenderbuffer;
  width = 0;
  height = 0;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter, readonly format: TargetFormat = 'rgba8',
  ) {
    this.framebuffer = gl.createFramebuffer()!;
    this.color = gl.createTexture()!;
    this.depth = gl.createRenderbuffer()!;
    counter.add('framebuffers');
    counter.add('textures');
    counter.add('renderbuffers');
    gl.bindTexture(gl.TEXTURE_2D, this.color);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    // Float32 textures are not filterable without OES_texture_float_linear: LINEAR would leave them incomplete.
    const filter = format === 'rgba32f' ? gl.NEAREST : gl.LINEAR;
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  get halfFloat(): boolean {
    return this.format === 'rgba16f';
  }

  /** Returns true when storage was (re)allocated. */
  setSize(width: number, height: number): boolean {
    width = Math.max(1, Math.floor(width));
    height = Math.max(1, Math.floor(height));
    if (width === this.width && height === this.height) return false;
    const gl = this.gl;
    this.width = width;
    this.height = height;
    gl.bindTexture(gl.TEXTURE_2D, this.color);
    if (this.halfFloat) gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA16F, width, height, 0, gl.RGBA, gl.HALF_FLOAT, null);
    else if (this.format === 'rgba32f') gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32F, width, height, 0, gl.RGBA, gl.FLOAT, null);
    else gl.texImage2D(gl.TEXTURE_2D, 0, internalFormat(gl, this.format), width, height, 0, gl.RGBA, gl.UNSIGNED_BYTE, null);
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.bindRenderbuffer(gl.RENDERBUFFER, this.depth);
    gl.renderbufferStorage(gl.RENDERBUFFER, gl.DEPTH_COMPONENT24, width, height);
    gl.bindRenderbuffer(gl.RENDERBUFFER, null);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.color, 0);
    gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.RENDERBUFFER, this.depth);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return true;
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteFramebuffer(this.framebuffer);
    gl.deleteTexture(this.color);
    gl.deleteRenderbuffer(this.depth);
    this.counter.add('framebuffers', -1);
    this.counter.add('textures', -1);
    this.counter.add('renderbuffers', -1);
  }
}
