// Rough glass (docs/rough-glass.md#roughness) for one renderer, from the core's side: its chunk (rough-glass-gl.ts:
// passes, targets, shaders) loaded the first time a frame asks for roughness, its targets made
// on the first rough frame. Until the chunk is in, rough glass is drawn polished.
import { isRough } from '../frame/roughness';
import { LazyPart } from './lazy-part';
import type { ResourceCounter } from './gl/resource-counter';
import type { MultisampleTarget } from './gl/multisample-target';
import type { RenderTarget } from './gl/render-target';
import type { PassContext } from './passes/pass-context';
import type { ProgramCache } from './programs';
import type { RoughTargets } from './rough-targets';
import type { FrameState } from '../frame/types';

export class RoughLoader {
  /** The chunk, its shader sources handed to the program cache as it arrives. */
  private readonly part = new LazyPart(
    () => import('./rough-glass-gl').then((chunk) => {
      this.programs.setRoughSources(chunk.ROUGH_SOURCES);
      return chunk;
    }),
    'rough glass', 'drawing the glass polished',
  );
  private targets: RoughTargets | null = null;

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter,
    private readonly programs: ProgramCache, private readonly vao: WebGLVertexArrayObject,
    /** RoughTargets' limits: the largest target side, and whether RGBA16F can be rendered to. */
    private readonly maxSize: number, private readonly halfFloat: boolean,
  ) {}

  /** See Renderer.load. */
  load(state: FrameState): Promise<void> | null {
    return this.part.load(isRough(state));
  }

  /** Is the glass rough this frame? Roughness > 0 and the chunk in. */
  active(state: FrameState): boolean {
    return isRough(state) && this.part.value !== null;
  }

  /** RoughTargets.draw (after active() said yes), the targets made on first use. */
  draw(ctx: PassContext, sharp: RenderTarget, msaa: MultisampleTarget | null): number {
    const { gl, counter, programs, vao, maxSize, halfFloat } = this;
    this.targets ??= new this.part.value!.RoughTargets(gl, counter, programs, vao, maxSize, halfFloat);
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
