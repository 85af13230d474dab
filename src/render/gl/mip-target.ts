// An off-screen target for rough glass (SPEC §14): a colour texture with a full mip chain
// (trilinear reads at a per-ring level) and a depth texture (read back to write each texel's
// distance from the glass into the colour's alpha; frame/rough-glass.ts). Two framebuffers:
// colour and depth (drawn into, or resolved into from a multisampled one), and colour alone
// (the distance pass reads the depth texture, which must not be attached while it draws).
// Immutable storage, remade only when the size changes.
import type { ResourceCounter } from './resource-counter';
import { internalFormat, type TargetFormat } from './render-target';

export class MipTarget {
  readonly framebuffer: WebGLFramebuffer;
  readonly colorFramebuffer: WebGLFramebuffer;
  color: WebGLTexture;
  depth: WebGLTexture;
  width = 0;
  height = 0;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter, readonly format: TargetFormat,
  ) {
    this.framebuffer = gl.createFramebuffer()!;
    this.colorFramebuffer = gl.createFramebuffer()!;
    this.color = gl.createTexture()!;
    this.depth = gl.createTexture()!;
    counter.add('framebuffers', 2);
    counter.add('textures', 2);
  }

  /** Remakes the storage when the size changed; returns true if it did. */
  setSize(width: number, height: number): boolean {
    width = Math.max(1, Math.floor(width));
    height = Math.max(1, Math.floor(height));
    if (width === this.width && height === this.height) return false;
    const gl = this.gl;
    // texStorage2D is immutable: a new size needs new textures (the count is unchanged).
    if (this.width > 0) {
      gl.deleteTexture(this.color);
      gl.deleteTexture(this.depth);
      this.color = gl.createTexture()!;
      this.depth = gl.createTexture()!;
    }
    this.width = width;
    this.height = height;
    const levels = Math.floor(Math.log2(Math.max(width, height))) + 1;
    gl.bindTexture(gl.TEXTURE_2D, this.color);
    gl.texStorage2D(gl.TEXTURE_2D, levels, internalFormat(gl, this.format), width, height);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    gl.bindTexture(gl.TEXTURE_2D, this.depth);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.DEPTH_COMPONENT24, width, height);
    // Depth is not filterable: read texel by texel.
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.color, 0);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.TEXTURE_2D, this.depth, 0);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.colorFramebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.color, 0);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return true;
  }

  /** Rebuilds the mip chain from level 0 (box filtered, colour and distance code alike). */
  generateMips(): void {
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, this.color);
    gl.generateMipmap(gl.TEXTURE_2D);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteFramebuffer(this.framebuffer);
    gl.deleteFramebuffer(this.colorFramebuffer);
    gl.deleteTexture(this.color);
    gl.deleteTexture(this.depth);
    this.counter.add('framebuffers', -2);
    this.counter.add('textures', -2);
  }
}
