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
import { Program } from './gl/program';
import type { ResourceCounter } from './gl/resource-counter';

export type ClipMode = 'none' | 'clip-distance' | 'discard';

export class ProgramCache {
  private readonly programs = new Map<string, Program>();

  constructor(private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter) {}

  get size(): number {
    return this.programs.size;
  }

  standard(clip: ClipMode, shading: Shading): Program {
    const header =
      clip === 'none' ? [] :
      clip === 'clip-distance' ? ['#extension GL_ANGLE_clip_cull_distance : require', '#define CLIP_PLANE', '#define CLIP_DISTANCE'] :
      ['#define CLIP_PLANE'];
    header.push(`#define SHADING_${shading.toUpperCase()}`, lighting);
    return this.get(`standard:${clip}:${shading}`, standardVert, standardFrag, header);
  }

  glass(model: FresnelModel, outputFresnel: boolean): Program {
    const header = [`#define FRESNEL_${model.toUpperCase()}`];
    if (outputFresnel) header.push('#define OUTPUT_FRESNEL');
    return this.get(`glass:${model}:${outputFresnel}`, glassVert, glassFrag, header);
  }

  blit(): Program {
    return this.get('blit', blitVert, blitFrag, []);
  }

  private get(key: string, vert: string, frag: string, header: string[]): Program {
    let p = this.programs.get(key);
    if (!p) {
      p = new Program(this.gl, this.counter, key, vert, frag, header);
      this.programs.set(key, p);
    }
    return p;
  }

  dispose(): void {
    for (const p of this.programs.values()) p.dispose();
    this.programs.clear();
  }
}
