// An off-screen target for rough glass (docs/rough-glass.md#the-gather): a colour texture with a full mip chain
// (trilinear reads at a per-ring level), a second one as large with as many levels (the codes:
// coverage × distance code in its alpha), and a depth texture (read back to write each texel's
// coverage into the colour's alpha and its code into the codes; frame/rough-glass.ts). Two
// framebuffers: colour and depth (drawn into, or resolved into from a multisampled one), and
// colour with the codes (the distance pass reads the depth texture, which must not be attached
// while it draws). Immutable storage, remade only when the size changes; padded beyond the image
// (setSize), the padding holding nothing (coverage 0: RoughTargets clears the colour's; the
// codes' starts as zeros, as WebGL initialises every texture, and is never drawn).
import type { ResourceCounter } from './resource-counter';
import { internalFormat, type TargetFormat } from './render-target';

/** The colour framebuffer's draw buffers: coverage into the colour's alpha, codes into the second. */
const DRAW_BOTH = [0x8ce0, 0x8ce1]; // COLOR_ATTACHMENT0, COLOR_ATTACHMENT1

export class MipTarget {
  readonly framebuffer: WebGLFramebuffer;
  readonly colorFramebuffer: WebGLFramebuffer;
  color: WebGLTexture;
  /** Coverage × distance code in alpha, mip-mapped with the colour. */
  codes: WebGLTexture;
  depth: WebGLTexture;
  width = 0;
  height = 0;
  /** The storage's size: width × height rounded up (see setSize); the image fills its corner. */
  textureWidth = 0;
  textureHeight = 0;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter, readonly format: TargetFormat,
    /** The largest side the storage may have (gl/limits.ts). */
    private readonly maxSize: number,
    /** The codes' format: rgba16f where the context renders half float, else rgba8. */
    readonly codesFormat: TargetFormat,
  ) {
    this.framebuffer = gl.createFramebuffer()!;
    this.colorFramebuffer = gl.createFramebuffer()!;
    this.color = gl.createTexture()!;
    this.codes = gl.createTexture()!;
    this.depth = gl.createTexture()!;
    counter.add('framebuffers', 2);
    counter.add('textures', 3);
  }

  /** Remakes the storage when the image's size changed (width, height ≤ maxSize); returns true if it did. */
  setSize(width: number, height: number): boolean {
    width = Math.max(1, Math.floor(width));
    height = Math.max(1, Math.floor(height));
    if (width === this.width && height === this.height) return false;
    const gl = this.gl;
    // texStorage2D is immutable: a new size needs new textures (the count is unchanged).
    if (this.width > 0) {
      gl.deleteTexture(this.color);
      gl.deleteTexture(this.codes);
      gl.deleteTexture(this.depth);
      this.color = gl.createTexture()!;
      this.codes = gl.createTexture()!;
      this.depth = gl.createTexture()!;
    }
    this.width = width;
    this.height = height;
    // Stored padded to multiples of 2^k, k levels down to the shorter side's 1 (as far as the
    // size limit allows): every level then halves the one before exactly, each texel the mean of
    // 2×2 (as the software renderer's mips). Floored NPOT levels (45 → 22 rows) stretch the
    // coarse ones over the image: 1.6 dB lost at roughness 0.6 on the bench's floor.
    let k = Math.floor(Math.log2(Math.min(width, height)));
    const padded = (n: number) => Math.ceil(n / 2 ** k) * 2 ** k;
    while (k > 0 && Math.max(padded(width), padded(height)) > this.maxSize) k--;
    const tw = padded(width), th = padded(height), levels = k + 1;
    this.textureWidth = tw;
    this.textureHeight = th;
    for (const [texture, format] of [[this.color, this.format], [this.codes, this.codesFormat]] as const) {
      gl.bindTexture(gl.TEXTURE_2D, texture);
      gl.texStorage2D(gl.TEXTURE_2D, levels, internalFormat(gl, format), tw, th);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.LINEAR_MIPMAP_LINEAR);
      gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.LINEAR);
    }
    gl.bindTexture(gl.TEXTURE_2D, this.depth);
    gl.texStorage2D(gl.TEXTURE_2D, 1, gl.DEPTH_COMPONENT24, tw, th);
    // Depth is not filterable: read texel by texel.
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.framebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.color, 0);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.DEPTH_ATTACHMENT, gl.TEXTURE_2D, this.depth, 0);
    gl.bindFramebuffer(gl.FRAMEBUFFER, this.colorFramebuffer);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, this.color, 0);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT1, gl.TEXTURE_2D, this.codes, 0);
    gl.drawBuffers(DRAW_BOTH);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return true;
  }

  /** Rebuilds both mip chains from level 0 (box filtered, colour, coverage and codes alike). */
  generateMips(): void {
    const gl = this.gl;
    gl.bindTexture(gl.TEXTURE_2D, this.color);
    gl.generateMipmap(gl.TEXTURE_2D);
    gl.bindTexture(gl.TEXTURE_2D, this.codes);
    gl.generateMipmap(gl.TEXTURE_2D);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  dispose(): void {
    const gl = this.gl;
    gl.deleteFramebuffer(this.framebuffer);
    gl.deleteFramebuffer(this.colorFramebuffer);
    gl.deleteTexture(this.color);
    gl.deleteTexture(this.codes);
    gl.deleteTexture(this.depth);
    this.counter.add('framebuffers', -2);
    this.counter.add('textures', -3);
  }
}
