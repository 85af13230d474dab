// docs/colour.md#eight-bit-targets on the GPU: a frame in linear light is drawn into an SRGB8_ALPHA8 target (multisampled
// when asked), where the GPU blends and resolves linear values and holds them encoded, so the
// darks do not band; shaders/encode.frag then encodes it once into its destination. Used only
// with `color-space="srgb"`; `none` draws straight into the destination as before. A refinement frame
// (docs/refinement.md#averaging) is first kept or averaged in half-float targets, whose blend is encoded in its place.
import { RenderTarget, type TargetFormat } from './gl/render-target';
import { MultisampleTarget } from './gl/multisample-target';
import type { ResourceCounter } from './gl/resource-counter';
import type { ProgramCache } from './programs';
import type { ToneMapping } from '../math/tone-map';
import { meanShare, refinementWeight } from '../frame/refinement';

export class LinearFrame {
  private target: RenderTarget | null = null;
  /** A still view's refinement (docs/refinement.md#averaging): its preview, the strata's mean and the two blended; made when first needed. */
  private preview: RenderTarget | null = null;
  private sum: RenderTarget | null = null;
  private shown: RenderTarget | null = null;
  /** The draw calls the last refine() took. */
  private refineCalls = 0;
  private msaa: MultisampleTarget | null = null;
  private samples = 0;
  private width = 0;
  private height = 0;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter,
    private readonly programs: ProgramCache, private readonly vao: WebGLVertexArrayObject,
    /** Half float can be rendered to (EXT_color_buffer_float): refinement's pictures are kept in it, else in SRGB8_ALPHA8. */
    private readonly halfFloat: boolean,
    /** Float32 can be rendered to and blended (EXT_float_blend too): refinement sums its strata exactly. */
    private readonly floatBlend = false,
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
   * exposed by `exposure` and tone mapped first. `refinement` k ≥ 1 of `frames` (docs/refinement.md#averaging): frame 1 is
   * kept as the preview, frames 2.. are averaged into the strata's mean, and what is encoded is the preview blended into
   * the mean by meanShare. Returns the draw calls.
   */
  end(destination: WebGLFramebuffer | null, curve: ToneMapping | null = null, exposure = 1, refinement = 0, frames = 1): number {
    const gl = this.gl;
    let source = this.target!;
    if (this.samples > 0) this.msaa!.resolve(source.framebuffer);
    let calls = 1;
    if (refinement >= 1) {
      source = this.refine(source, refinement, frames);
      calls += this.refineCalls;
    }
    gl.bindFramebuffer(gl.FRAMEBUFFER, destination);
    gl.viewport(0, 0, this.width, this.height);
    const p = this.programs.encode(curve);
    p.use();
    gl.uniform1i(p.location('uSource'), 0);
    if (curve !== null) gl.uniform1f(p.location('uExposure'), exposure);
    this.copy(source);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return calls;
  }

  /** Refinement frame k of `frames` into the preview or the strata's sum; returns what to encode (its draw calls in refineCalls). */
  private refine(frame: RenderTarget, k: number, frames: number): RenderTarget {
    if (k < 2) {
      this.refineCalls = 1;
      this.blend((this.preview = this.sized(this.preview, this.halfFloat ? 'rgba16f' : 'srgb8')), frame, 1, 0);
      return this.preview;
    }
    // Summed in float32 where it can be blended (EXT_float_blend), exact; else averaged with the weight 1/(k − 1).
    const summing = this.floatBlend;
    const sum = (this.sum = this.sized(this.sum, summing ? 'rgba32f' : this.halfFloat ? 'rgba16f' : 'srgb8'));
    this.blend(sum, frame, summing ? 1 : refinementWeight(k), k < 3 ? 0 : summing ? -1 : 1 - refinementWeight(k));
    // Shown: the preview, then the mean over it with its share (the preview's: 1 − share).
    const share = meanShare(k, frames), shown = (this.shown = this.sized(this.shown, this.halfFloat ? 'rgba16f' : 'srgb8'));
    this.blend(shown, this.preview ?? sum, 1, 0);
    this.blend(shown, sum, share / (summing ? k - 1 : 1), 1 - share);
    this.refineCalls = 3;
    return shown;
  }

  /** `target` (made the first time, or again in another format) at the frame's size. */
  private sized(target: RenderTarget | null, format: TargetFormat): RenderTarget {
    if (target !== null && target.format !== format) {
      target.dispose();
      target = null;
    }
    const t = target ?? new RenderTarget(this.gl, this.counter, format);
    t.setSize(this.width, this.height);
    return t;
  }

  /**
   * into = keep·into + scale·from, by the GPU's blend: the copy's output times `scale`, plus what `into` holds times the
   * constant alpha `keep` (−1: times one, a sum). keep 0 replaces (blending would keep a NaN of an old frame). Either
   * format blends linear values (SRGB8_ALPHA8 decodes and encodes around the blend).
   */
  private blend(into: RenderTarget, from: RenderTarget, scale: number, keep: number): void {
    const gl = this.gl;
    gl.bindFramebuffer(gl.FRAMEBUFFER, into.framebuffer);
    gl.viewport(0, 0, this.width, this.height);
    const p = this.programs.copy();
    p.use();
    gl.uniform1i(p.location('uSource'), 0);
    gl.uniform1f(p.location('uScale'), scale);
    if (keep !== 0) {
      gl.enable(gl.BLEND);
      gl.blendColor(0, 0, 0, keep < 0 ? 1 : keep);
      gl.blendFunc(gl.ONE, keep < 0 ? gl.ONE : gl.CONSTANT_ALPHA);
    }
    this.copy(from);
    gl.disable(gl.BLEND);
  }

  /** Draws `source` one texel per pixel through the program in use. */
  private copy(source: RenderTarget): void {
    const gl = this.gl;
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, source.color);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    gl.bindTexture(gl.TEXTURE_2D, null);
  }

  dispose(): void {
    this.target?.dispose();
    this.msaa?.dispose();
    this.preview?.dispose();
    this.sum?.dispose();
    this.shown?.dispose();
    this.target = this.msaa = this.preview = this.sum = this.shown = null;
  }
}
