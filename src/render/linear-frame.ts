// docs/colour.md#eight-bit-targets on the GPU: a frame in linear light is drawn into an SRGB8_ALPHA8 target (multisampled
// when asked), where the GPU blends and resolves linear values and holds them encoded, so the
// darks do not band; shaders/encode.frag then encodes it once into its destination. Used only
// with `color-space="srgb"`; `none` draws straight into the destination as before.
import { RenderTarget } from './gl/render-target';
import { MultisampleTarget } from './gl/multisample-target';
import type { ResourceCounter } from './gl/resource-counter';
import type { ProgramCache } from './programs';
import type { ToneMapping } from '../math/tone-map';

export class LinearFrame {
  private target: RenderTarget | null = null;
  private msaa: MultisampleTarget | null = null;
  private samples = 0;
  private width = 0;
  private height = 0;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter,
    private readonly programs: ProgramCache, private readonly vao: WebGLVertexArrayObject,
  ) {}

  /**
   * The framebuffer a `width` × `height` frame is drawn into (linear light): SRGB8_ALPHA8, or with `hdr` half float, which
   * keeps light above 1 for the tone mapping (docs/pbr.md#tone-mapping).
   */
  begin(width: number, height: number, samples: number, hdr = false): WebGLFramebuffer {
    const gl = this.gl;
    this.width = width;
    this.height = height;
    this.samples = samples;
    const format = hdr ? 'rgba16f' : 'srgb8';
    if (this.target !== null && this.target.format !== format) this.dispose();
    const target = (this.target ??= new RenderTarget(gl, this.counter, format));
    target.setSize(width, height);
    if (samples === 0) return target.framebuffer;
    const msaa = (this.msaa ??= new MultisampleTarget(gl, this.counter, format));
    msaa.setSize(width, height, samples);
    return msaa.framebuffer;
  }

  /**
   * Resolves the samples (in linear) and writes the frame, encoded, into `destination` (null: the canvas); with `curve`,
   * exposed by `exposure` and tone mapped first. Returns the draw calls.
   */
  end(destination: WebGLFramebuffer | null, curve: ToneMapping | null = null, exposure = 1): number {
    const gl = this.gl, target = this.target!;
    if (this.samples > 0) this.msaa!.resolve(target.framebuffer);
    gl.bindFramebuffer(gl.FRAMEBUFFER, destination);
    gl.viewport(0, 0, this.width, this.height);
    const p = this.programs.encode(curve);
    p.use();
    gl.uniform1i(p.location('uSource'), 0);
    if (curve !== null) gl.uniform1f(p.location('uExposure'), exposure);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, target.color);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return 1;
  }

  dispose(): void {
    this.target?.dispose();
    this.msaa?.dispose();
    this.target = this.msaa = null;
  }
}
