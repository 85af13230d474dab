// Rough glass (docs/rough-glass.md) for one renderer, from the core's side: its chunk
// (rough-glass-gl.ts: passes, targets, shaders; the part ROUGH_GLASS of render/parts.ts) and
// the targets made from it on the first rough frame. Until the chunk is in, rough glass is drawn polished.
import { isRough } from '../frame/roughness';
import type { ResourceCounter } from './gl/resource-counter';
import type { MultisampleTarget } from './gl/multisample-target';
import type { RenderTarget } from './gl/render-target';
import type { PassContext } from './passes/pass-context';
import type { ProgramCache } from './programs';
import type { RoughTargets } from './rough-targets';
import type { FrameState } from '../frame/types';

type RoughChunk = typeof import('./rough-glass-gl');

export class RoughGlass {
  private targets: RoughTargets | null = null;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter,
    private readonly programs: ProgramCache, private readonly vao: WebGLVertexArrayObject,
    /** RoughTargets' limits: the largest target side, and whether RGBA16F can be rendered to. */
    private readonly maxSize: number, private readonly halfFloat: boolean,
  ) {}

  /** The chunk, once in (render/parts.ts's ROUGH_GLASS hands it over). */
  chunk: RoughChunk | null = null;

  /** Is the glass rough this frame? Roughness > 0 and the chunk in. */
  active(state: FrameState): boolean {
    return isRough(state) && this.chunk !== null;
  }

  /** RoughTargets.draw (after active() said yes), the targets made on first use. */
  draw(ctx: PassContext, sharp: RenderTarget, msaa: MultisampleTarget | null): number {
    const { gl, counter, programs, vao, maxSize, halfFloat } = this;
    this.targets ??= new this.chunk!.RoughTargets(gl, counter, programs, vao, maxSize, halfFloat);
    return this.targets.draw(ctx, sharp, msaa);
  }

  /** The targets once drawn (the glass pass reads them). */
  get current(): RoughTargets | null {
    return this.targets;
  }

  dispose(): void {
    this.targets?.dispose();
    this.targets = null;
  }
}
