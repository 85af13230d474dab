// Shader variants, compiled on first use only (SPEC §7), keyed by their #define header.
import standardVert from '../../shaders/standard.vert?raw';
import standardFrag from '../../shaders/standard.frag?raw';
import glassVert from '../../shaders/glass.vert?raw';
import glassFrag from '../../shaders/glass.frag?raw';
import blitVert from '../../shaders/blit.vert?raw';
import blitFrag from '../../shaders/blit.frag?raw';
import lighting from '../../shaders/lighting.glsl?raw';
import type { FresnelModel } from '../math/fresnel';
import type { Shading } from './types';
import { Program, ShaderError } from './gl/program';
import type { SharedResources } from './gl/shared-resources';

export type ClipMode = 'none' | 'clip-distance' | 'discard';

function standardHeader(clip: ClipMode, shading: Shading, twoSided: boolean): string[] {
  const header: string[] =
    clip === 'none' ? [] :
    clip === 'clip-distance' ? ['#extension GL_ANGLE_clip_cull_distance : require', '#define CLIP_PLANE', '#define CLIP_DISTANCE'] :
    ['#define CLIP_PLANE'];
  header.push(`#define SHADING_${shading.toUpperCase()}`);
  if (twoSided) header.push('#define TWO_SIDED');
  header.push(lighting);
  return header;
}

function glassHeader(model: FresnelModel, outputFresnel: boolean): string[] {
  const header = [`#define FRESNEL_${model.toUpperCase()}`];
  if (outputFresnel) header.push('#define OUTPUT_FRESNEL');
  return header;
}

/**
 * The variants one renderer uses, found without building a key in a frame that compiles
 * nothing. The programs themselves are compiled once per context and shared (SharedResources).
 */
export class ProgramCache {
  /** Every program this renderer uses, in order of first use (for size and dispose). */
  private readonly all: Program[] = [];
  // Found by their variant's parts, so a frame that compiles nothing builds no key, header or
  // array: those are made only on a miss.
  /** [clip][shading][one-sided 0 | two-sided 1] */
  private standards: Partial<Record<ClipMode, Partial<Record<Shading, [Program?, Program?]>>>> = {};
  private glasses: Partial<Record<FresnelModel, { colour?: Program; fresnel?: Program }>> = {};
  private blitProgram: Program | undefined;
  /**
   * Variants that failed to compile, by key: asked again (the same state drawn again), they throw
   * the same error without compiling again. A new context means a new cache, so a restore retries.
   */
  private readonly broken = new Map<string, ShaderError>();

  constructor(private readonly gl: WebGL2RenderingContext, private readonly shared: SharedResources) {}

  get size(): number {
    return this.all.length;
  }

  /** `twoSided`: lit on the side facing the viewer (meshes from files, SPEC §9). */
  standard(clip: ClipMode, shading: Shading, twoSided = false): Program {
    const sides = ((this.standards[clip] ??= {})[shading] ??= []);
    const i = twoSided ? 1 : 0;
    return (sides[i] ??= this.build(
      `standard:${clip}:${shading}${twoSided ? ':two-sided' : ''}`, standardVert, standardFrag, standardHeader(clip, shading, twoSided),
    ));
  }

  glass(model: FresnelModel, outputFresnel: boolean): Program {
    const variants = (this.glasses[model] ??= {});
    return outputFresnel
      ? (variants.fresnel ??= this.build(`glass:${model}:true`, glassVert, glassFrag, glassHeader(model, true)))
      : (variants.colour ??= this.build(`glass:${model}:false`, glassVert, glassFrag, glassHeader(model, false)));
  }

  blit(): Program {
    return (this.blitProgram ??= this.build('blit', blitVert, blitFrag, []));
  }

  private build(key: string, vert: string, frag: string, header: string[]): Program {
    const known = this.broken.get(key);
    if (known) throw known;
    try {
      const p = this.shared.program(key, (counter) => new Program(this.gl, counter, key, vert, frag, header));
      this.all.push(p);
      return p;
    } catch (e) {
      if (e instanceof ShaderError) this.broken.set(key, e);
      throw e;
    }
  }

  dispose(): void {
    for (const p of this.all) this.shared.releaseProgram(p.name);
    this.all.length = 0;
    this.standards = {};
    this.glasses = {};
    this.blitProgram = undefined;
    this.broken.clear();
  }
}
