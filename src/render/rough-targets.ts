// Rough glass (docs/rough-glass.md#roughness) before the glass pass: the reflection, unscissored (the lobe reads
// beyond the glass's rectangle), and — when the glass lets light through — the frame beyond the
// glass, each into a mip-mapped target whose alpha holds the coverage c (1 where a surface was
// drawn) and whose codes hold c·u, u = h/(1 + h) frame/rough-glass.ts's distance code
// (shaders/distance.frag, from the pass's depth, resolved with the colour when multisampled).
// shaders/rough-glass.glsl gathers R̃ and B̃ from them (bind() sets its inputs). In rough glass's
// own chunk (rough-glass-gl.ts); made on the first rough frame, kept while the renderer lives;
// nothing is allocated per frame.
import { invert4 } from '../math/invert';
import { MipTarget } from './gl/mip-target';
import { MultisampleTarget } from './gl/multisample-target';
import type { RenderTarget, TargetFormat } from './gl/render-target';
import type { ResourceCounter } from './gl/resource-counter';
import type { ProgramCache } from './programs';
import type { PassContext } from './passes/pass-context';
import type { RoughBinding } from './passes/glass-pass';
import type { Program } from './gl/program';
import { reflectionPass } from './passes/reflection-pass';
import { transmissionPass } from './passes/transmission-pass';
import { eyeRelativePlane } from '../math/mirror';
import { ggxAlpha } from '../math/ggx';
import { ROUGH_GATHER, type RoughGatherSettings } from '../frame/rough-glass';
import { gatherJitter } from '../frame/refinement';

/** What the rough variant reads beyond the sharp glass's inputs (filled in place each frame). */
interface RoughGlassInputs {
  /** GGX α = roughness². */
  alpha: number;
  settings: RoughGatherSettings;
  /** The mip-mapped reflection (the distance code in alpha) and its size in texels. */
  reflectionWidth: number;
  reflectionHeight: number;
  reflectionTextureWidth: number;
  reflectionTextureHeight: number;
  /** The frame beyond the glass, mip-mapped likewise; null when the glass lets nothing through. */
  transmission: WebGLTexture | null;
  transmissionWidth: number;
  transmissionHeight: number;
  transmissionTextureWidth: number;
  transmissionTextureHeight: number;
  /** Each image's codes (coverage × distance code in alpha), mip-mapped as the image. */
  reflectionCodes: WebGLTexture | null;
  transmissionCodes: WebGLTexture | null;
  /** The inverse of the frame's eye-relative view-projection (float32). */
  inverseViewProjection: Float32Array;
  /** FrameState.fixedBlurLevel (≥ 0), or −1: the gather. */
  fixedLevel: number;
}

/** The texture units the rough variant binds beyond the sharp glass's (unbound after the draw). */
const ROUGH_UNITS = [0x84c2, 0x84c3, 0x84c4]; // TEXTURE2..4

export class RoughTargets implements RoughBinding {
  private reflection: MipTarget | null = null;
  private transmission: MipTarget | null = null;
  private transmissionMsaa: MultisampleTarget | null = null;
  /** What the glass pass reads (glass-pass.ts), filled in place. */
  readonly inputs: RoughGlassInputs = {
    alpha: 0, settings: ROUGH_GATHER.medium, reflectionWidth: 1, reflectionHeight: 1, reflectionTextureWidth: 1, reflectionTextureHeight: 1,
    transmission: null, transmissionWidth: 1, transmissionHeight: 1, transmissionTextureWidth: 1, transmissionTextureHeight: 1,
    reflectionCodes: null, transmissionCodes: null, inverseViewProjection: new Float32Array(16), fixedLevel: -1,
  };
  private readonly inverse64 = new Float64Array(16);
  private readonly inverse = this.inputs.inverseViewProjection;
  private readonly farSide64 = new Float64Array(4);
  private readonly farSide = new Float32Array(4);
  /** Uploads (float32) of this frame's camera for the glass pass. */
  private readonly viewProjection = new Float32Array(16);
  private readonly normal = new Float32Array(3);
  private readonly forward = new Float32Array(3);
  private readonly jitter = new Float32Array(3);
  private readonly background = new Float32Array(3);

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter,
    private readonly programs: ProgramCache, private readonly vao: WebGLVertexArrayObject,
    /** The largest side of a render target (gl/limits.ts). */
    private readonly maxSize: number,
    /** Can the context render to RGBA16F? The codes then keep 16 bits, else 8. */
    private readonly halfFloat: boolean,
  ) {}

  /** The mip-mapped reflection the glass pass reads (after draw()). */
  get reflectionColor(): WebGLTexture {
    return this.reflection!.color;
  }

  /**
   * Draws both images for ctx.state (sized and formatted as `sharp`, the sharp reflection's
   * target; `msaa`: its multisampled stand-in, or null) and fills `inputs`. Returns the draw calls.
   */
  draw(ctx: PassContext, sharp: RenderTarget, msaa: MultisampleTarget | null): number {
    const { state, setup } = ctx;
    // Compiled first: a variant that fails throws before any state is set.
    this.programs.distance();
    const quality = state.roughnessQuality ?? 'medium';
    this.inputs.alpha = ggxAlpha(state.roughness ?? 0);
    this.inputs.settings = ROUGH_GATHER[quality] ?? ROUGH_GATHER.medium;
    // In pixels' levels, as the software renderer counts them; the target's own scale added there.
    const fixed = state.fixedBlurLevel;
    this.inputs.fixedLevel = fixed !== undefined && fixed >= 0 ? fixed : -1;
    // Mirror images and what lies beyond the glass both sit on its far side: h = −side·(n·x + d),
    // x unprojected by the inverse of the eye-relative view-projection (the mirrored pass's own
    // projection is that one times the plane's reflection: the same inverse gives the image).
    if (invert4(this.inverse64, setup.viewProjection)) this.inverse.set(this.inverse64);
    eyeRelativePlane(this.farSide64, setup.glass.plane, setup.eye, -setup.side);
    this.farSide.set(this.farSide64);

    ctx.scissor = null;
    const reflection = (this.reflection = this.fit(this.reflection, sharp.format, sharp.width, sharp.height));
    // Each pass's draws and its distance pass's one.
    let n = this.run(ctx, reflection, msaa, reflectionPass) + 1;
    this.inputs.reflectionWidth = reflection.width;
    this.inputs.reflectionHeight = reflection.height;
    this.inputs.reflectionTextureWidth = reflection.textureWidth;
    this.inputs.reflectionTextureHeight = reflection.textureHeight;
    this.inputs.reflectionCodes = reflection.codes;

    // docs/rendering.md#fresnel-models: exact and Schlick let through T; the classic blend 1 − (1 − T)(0.2 + 0.8F) > 0 always.
    this.inputs.transmission = this.inputs.transmissionCodes = null;
    if (state.transparency > 0 || state.fresnel === 'classic') {
      const format = state.colorSpace === 'srgb' ? 'srgb8' : 'rgba8';
      const target = (this.transmission = this.fit(this.transmission, format, state.width, state.height));
      let samples: MultisampleTarget | null = null;
      if (msaa) {
        samples = this.transmissionMsaa?.format === format ? this.transmissionMsaa : null;
        if (!samples) {
          this.transmissionMsaa?.dispose();
          samples = this.transmissionMsaa = new MultisampleTarget(this.gl, this.counter, format);
        }
        samples.setSize(target.width, target.height, msaa.samples);
      }
      n += this.run(ctx, target, samples, transmissionPass) + 1;
      this.inputs.transmission = target.color;
      this.inputs.transmissionCodes = target.codes;
      this.inputs.transmissionWidth = target.width;
      this.inputs.transmissionHeight = target.height;
      this.inputs.transmissionTextureWidth = target.textureWidth;
      this.inputs.transmissionTextureHeight = target.textureHeight;
    }
    return n;
  }

  /** `target` if it has `format`, else a new one; sized. */
  private fit(target: MipTarget | null, format: TargetFormat, width: number, height: number): MipTarget {
    if (target?.format !== format) {
      target?.dispose();
      target = new MipTarget(this.gl, this.counter, format, this.maxSize, this.halfFloat ? 'rgba16f' : 'rgba8');
    }
    target.setSize(width, height);
    return target;
  }

  /** One pass into `target` (through `msaa` when given), its distance codes, its mips; returns the pass's draw calls. */
  private run(
    ctx: PassContext, target: MipTarget, msaa: MultisampleTarget | null,
    pass: (ctx: PassContext, framebuffer: WebGLFramebuffer, width: number, height: number) => number,
  ): number {
    const { width, height } = target;
    const gl = this.gl;
    // The padding beyond the image: nothing there (the background, coverage 0).
    if (target.textureWidth > width || target.textureHeight > height) {
      const bg = ctx.background;
      gl.bindFramebuffer(gl.FRAMEBUFFER, target.framebuffer);
      gl.clearColor(bg[0], bg[1], bg[2], 0);
      gl.clearDepth(1);
      gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT);
    }
    let n: number;
    if (msaa) {
      n = pass(ctx, msaa.framebuffer, width, height);
      msaa.resolve(target.framebuffer, true);
    } else n = pass(ctx, target.framebuffer, width, height);
    this.distances(target);
    return n;
  }

  /** shaders/distance.frag into `target`'s alpha and codes (one draw call), then their mip chains. */
  private distances(target: MipTarget): void {
    const gl = this.gl;
    const p = this.programs.distance();
    gl.bindFramebuffer(gl.FRAMEBUFFER, target.colorFramebuffer);
    gl.viewport(0, 0, target.width, target.height);
    gl.colorMask(false, false, false, true);
    p.use();
    gl.uniform1i(p.location('uDepth'), 0);
    gl.uniformMatrix4fv(p.location('uInverseViewProjection'), false, this.inverse);
    gl.uniform4fv(p.location('uFarSide'), this.farSide);
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, target.depth);
    gl.bindVertexArray(this.vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
    gl.bindTexture(gl.TEXTURE_2D, null);
    gl.colorMask(true, true, true, true);
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    target.generateMips();
  }

  /** RoughBinding: the glass pass's rough inputs, after draw(). */
  bind(p: Program, ctx: PassContext): void {
    const gl = this.gl, rough = this.inputs;
    const { setup, state } = ctx;
    const { viewProjection, normal, forward, background } = this;
    viewProjection.set(setup.viewProjection);
    for (let k = 0; k < 3; k++) background[k] = ctx.background[k];
    const plane = setup.glass.plane;
    for (let k = 0; k < 3; k++) {
      normal[k] = setup.side * plane[k];
      forward[k] = setup.forward[k];
    }
    gl.uniformMatrix4fv(p.location('uViewProjection'), false, viewProjection);
    gl.uniform3fv(p.location('uGlassNormal'), normal);
    gl.uniform3fv(p.location('uForward'), forward);
    gl.uniform1f(p.location('uOrthographic'), setup.orthographic ? 1 : 0);
    gl.uniform1f(p.location('uAlpha'), rough.alpha);
    gl.uniform1i(p.location('uAngles'), rough.settings.angles);
    gl.uniform1f(p.location('uLodBias'), rough.settings.lodBias);
    gatherJitter(state, this.jitter);
    gl.uniform3fv(p.location('uGatherJitter'), this.jitter);
    gl.uniform4f(p.location('uReflectionSize'), rough.reflectionWidth, rough.reflectionHeight, rough.reflectionTextureWidth, rough.reflectionTextureHeight);
    gl.uniform4f(p.location('uTransmissionSize'), rough.transmissionWidth, rough.transmissionHeight, rough.transmissionTextureWidth, rough.transmissionTextureHeight);
    gl.uniform1f(p.location('uTransmits'), rough.transmission ? 1 : 0);
    gl.uniformMatrix4fv(p.location('uInverseViewProjection'), false, rough.inverseViewProjection);
    gl.uniform3fv(p.location('uBackground'), background);
    // In the reflection target's levels: its scale to the frame's pixels added.
    const level = rough.fixedLevel < 0 ? -1 : rough.fixedLevel + Math.log2(rough.reflectionWidth / state.width);
    gl.uniform1f(p.location('uFixedLevel'), level);
    gl.uniform1i(p.location('uTransmission'), 2);
    gl.uniform1i(p.location('uReflectionCodes'), 3);
    gl.uniform1i(p.location('uTransmissionCodes'), 4);
    gl.activeTexture(gl.TEXTURE2);
    gl.bindTexture(gl.TEXTURE_2D, rough.transmission);
    gl.activeTexture(gl.TEXTURE3);
    gl.bindTexture(gl.TEXTURE_2D, rough.reflectionCodes);
    gl.activeTexture(gl.TEXTURE4);
    gl.bindTexture(gl.TEXTURE_2D, rough.transmissionCodes);
  }

  /** RoughBinding: unbinds units 2..4, unit 1 left active. */
  unbind(): void {
    const gl = this.gl;
    for (const unit of ROUGH_UNITS) {
      gl.activeTexture(unit);
      gl.bindTexture(gl.TEXTURE_2D, null);
    }
    gl.activeTexture(gl.TEXTURE1);
  }

  dispose(): void {
    this.reflection?.dispose();
    this.transmission?.dispose();
    this.transmissionMsaa?.dispose();
    this.reflection = this.transmission = null;
    this.transmissionMsaa = null;
  }
}
