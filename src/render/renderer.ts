// Decides which passes run for a view, owns every GL resource of one scene, and reads pixels back.
// Knows nothing of the DOM: it takes a WebGL2 context, then per frame a scene, a FrameState and decoded images.
import { Mesh } from './gl/mesh';
import { RenderTarget } from './gl/render-target';
import { MultisampleTarget } from './gl/multisample-target';
import { ObjectMeshes } from './object-meshes';
import { glassScreenRect, type ScreenRect } from '../frame/glass-bounds';
import { reflectionScissor, reflectionTargetSide } from '../frame/reflection-scissor';
import { glassSkipReason, PASSES, passesFor } from '../frame/pass-reports';
import { maxTargetSize } from './gl/limits';
import { LazyParts, type PartListener } from '../frame/lazy-parts';
import { DEBUG_VIEWS, FRAME_CHECKS, RENDER_PARTS, type RenderPartsHost } from './parts';
import { ResourceCounter } from './gl/resource-counter';
import { TextureCache } from './texture-cache';
import { LinearFrame } from './linear-frame';
import { srgbToLinear } from '../math/srgb';
import { encodesAtEnd, toneMapped } from '../frame/linear-light';
import { refinementScale, refines } from '../frame/refinement';
import { readFramebuffer, type Pixels } from './gl/read-pixels';
import { SharedResources } from './gl/shared-resources';
import { FrameSetup } from '../frame/frame-setup';
import { ProgramCache } from './programs';
import { beginTarget, type PassContext } from './passes/pass-context';
import { reflectionPass } from './passes/reflection-pass';
import { scenePass } from './passes/scene-pass';
import { glassPass } from './passes/glass-pass';
import { RoughGlass } from './rough-glass';
import { glassMesh } from '../scene/geometry/rectangle';
import { DefaultSceneCache } from '../scene/default-scene';
import type { GlassFrame } from '../scene/glass-frame';
import type { Scene } from '../scene/scene';
import type { SceneImages } from '../scene/decoded-image';
import type { FrameReport, FrameState, RenderStats, Viewport } from '../frame/types';
import type { DebugViewFrame } from './debug-views';

export { passesFor }; // the element's software frames report their passes the same way

export interface RendererOptions {
  /** Check gl.getError() and the uniforms after every frame (tests and debugging). */
  checks?: boolean;
  /** Told when a lazy part settles and when one fails (default: failures on the console). */
  parts?: PartListener;
}

const CONSOLE_PARTS: PartListener = {
  settled: () => {},
  warn: (message) => console.warn(`glass-plane-scene: ${message}`),
};

export type { Pixels };

export type ReadbackSource = 'screen' | 'reflection' | 'scene' | 'final';

function setViewport(out: Viewport, x: number, y: number, width: number, height: number): Viewport {
  out.x = x;
  out.y = y;
  out.width = width;
  out.height = height;
  return out;
}

export class Renderer implements DebugViewFrame {
  private readonly counter = new ResourceCounter();
  /** @internal */
  readonly programs: ProgramCache;
  private readonly objectMeshes: ObjectMeshes;
  private glassMesh: Mesh;
  /** The glass frame `glassMesh` was built for. */
  private glassMeshFrame: GlassFrame | null = null;
  /** The default scene (docs/default-scene.md) for callers that pass none (the bench, tests), rebuilt only when it changes. */
  private readonly defaultScene = new DefaultSceneCache();
  /** Programs, the procedural texture and meshes, shared with every renderer on this context. */
  private readonly shared: SharedResources;
  private readonly textures: TextureCache;
  /** The frame in linear light and its final encode (docs/colour.md#the-transfer-curve, `color-space="srgb"`). */
  private readonly linearFrame: LinearFrame;
  /** The clear colour in the frame's colour space. */
  private readonly background = [0, 0, 0];
  private reflection: RenderTarget;
  private captureTarget: RenderTarget | null = null;
  /** Multisampled stand-ins, created only when `samples` > 0. */
  private reflectionMsaa: MultisampleTarget | null = null;
  private mainMsaa: MultisampleTarget | null = null;
  /** Rough glass (docs/rough-glass.md#the-gather): its chunk, once loaded, and its mip-mapped images. */
  private readonly rough: RoughGlass;
  private readonly maxSamples: number;
  /** Can the context render to RGBA16F (EXT_color_buffer_float)? */
  private readonly canHalfFloat: boolean;
  /** Largest side of any render target (texture, renderbuffer and viewport limits). */
  private readonly maxTargetSize: number;
  /** @internal */
  readonly blitVao: WebGLVertexArrayObject;
  private readonly setup = new FrameSetup();
  /** What only some frames need (render/parts.ts), loaded by load(). */
  private readonly parts: LazyParts<RenderPartsHost>;
  /** @internal */
  readonly ctx: PassContext;
  private readonly report: FrameReport = {
    frame: 0, time: 0, width: 0, height: 0, drawCalls: 0,
    passes: passesFor('final'),
  };
  /** Why the final view needs neither reflection nor glass this frame, if it does not. */
  private glassSkipReason: string | undefined;
  private readonly glassRect: ScreenRect = { x0: 0, y0: 0, x1: 0, y1: 0, area: 0 };
  private readonly scissor: Viewport = { x: 0, y: 0, width: 0, height: 0 };
  /** The viewports of this frame's drawing (filled in place: nothing is allocated per frame). */
  private readonly full: Viewport = { x: 0, y: 0, width: 0, height: 0 };
  /**
   * Skip the reflection and glass when the glass is not on screen, cull objects beyond the
   * glass from the reflection, scissor it to the glass (docs/knobs.md#reflection-skips). Off only to measure savings.
   */
  optimize = true;
  private readonly counts = {
    frames: 0,
    passesRun: { reflection: 0, scene: 0, glass: 0 },
    passesSkipped: { reflection: 0, scene: 0, glass: 0 },
  };

  constructor(readonly gl: WebGL2RenderingContext, options: RendererOptions = {}) {
    const c = this.counter;
    this.shared = SharedResources.acquire(gl);
    this.programs = new ProgramCache(gl, this.shared);
    this.objectMeshes = new ObjectMeshes(gl, c, this.shared);
    this.glassMesh = new Mesh(gl, c, glassMesh(this.setup.glass));
    this.glassMeshFrame = this.setup.glass;
    this.maxSamples = gl.getParameter(gl.MAX_SAMPLES) as number;
    this.maxTargetSize = maxTargetSize(gl);
    this.textures = new TextureCache(gl, c, this.shared);
    this.canHalfFloat = gl.getExtension('EXT_color_buffer_float') !== null;
    this.reflection = new RenderTarget(gl, c, 'srgb8'); // the default color-space's; prepare() remakes it for another
    this.blitVao = gl.createVertexArray()!;
    c.add('vertexArrays');
    this.rough = new RoughGlass(gl, c, this.programs, this.blitVao, this.maxTargetSize, this.canHalfFloat);
    this.linearFrame = new LinearFrame(gl, c, this.programs, this.blitVao, this.canHalfFloat, this.canHalfFloat && gl.getExtension('EXT_float_blend') !== null);
    this.ctx = {
      gl, programs: this.programs, objectMeshes: this.objectMeshes, glassMesh: this.glassMesh, textures: this.textures, background: this.background,
      setup: this.setup, state: undefined as unknown as FrameState, scene: undefined as unknown as Scene,
      clipExtension: gl.getExtension('WEBGL_clip_cull_distance') as { CLIP_DISTANCE0_WEBGL: number } | null,
      cull: true,
      transparentDepth: false,
      hdr: false,
      footprint: 1,
      environment: null,
      pbrMaps: null,
      scissor: null,
      triangles: { scene: 0, reflection: 0 },
    };
    this.parts = new LazyParts(RENDER_PARTS, { ctx: this.ctx, checks: options.checks === true, rough: this.rough, counter: this.counter }, options.parts ?? CONSOLE_PARTS);
  }

  /**
   * Draws one frame of `state.view` of `scene` to the canvas and returns its report (reused object;
   * its `passes` are frozen and shared). The renderer contract (ARCHITECTURE.md, "How a frame
   * flows"): `scene` null is the default scene for `state` (docs/default-scene.md), kept between
   * frames; `images` the decoded images the scene names, by URL (null: none), each uploaded when
   * a frame's scene first names it and freed when a frame naming it finds it gone or replaced.
   */
  render(scene: Scene | null, state: FrameState, images?: SceneImages | null): FrameReport {
    this.ctx.scene = scene ?? this.defaultScene.get(state.cubeDistance, state.spin);
    const drawCalls = this.draw(state, images, null);
    const r = this.report;
    this.counts.frames++;
    r.frame = this.counts.frames;
    r.time = state.time;
    r.width = state.width;
    r.height = state.height;
    r.drawCalls = drawCalls;
    const passes = passesFor(state.view, this.glassSkipReason);
    r.passes = passes;
    for (const p of PASSES) {
      if (passes[p].ran) this.counts.passesRun[p]++;
      else this.counts.passesSkipped[p]++;
    }
    this.parts.get(FRAME_CHECKS)?.reportGlErrors(this.gl, this.counts.frames);
    return r;
  }

  /**
   * Starts loading what a frame of `scene` (null: the default scene) and `state` needs that
   * the core leaves out (render/parts.ts); a promise settled when all of it has (it never
   * rejects: a part that fails is warned about through RendererOptions.parts and drawn without),
   * or null when the frame needs nothing more. Until then render() and read() draw without it.
   */
  load(scene: Scene | null, state: FrameState): Promise<void> | null {
    this.ctx.state = state;
    this.ctx.scene = scene ?? this.defaultScene.get(state.cubeDistance, state.spin);
    return this.parts.request();
  }

  /**
   * Pixels of a frame drawn as render() draws it (the same arguments), then `source`: 'screen'
   * redraws the canvas and reads it back (the drawing buffer is not preserved between frames; a refinement frame
   * is a frame of the mean, as render() draws it); the others draw one pass off screen, unaveraged.
   */
  read(scene: Scene | null, state: FrameState, images: SceneImages | null | undefined, source: ReadbackSource): Pixels {
    this.ctx.scene = scene ?? this.defaultScene.get(state.cubeDistance, state.spin);
    const gl = this.gl;
    if (source === 'screen') {
      this.draw(state, images, null);
      return readFramebuffer(this.gl, null, state.width, state.height);
    }
    // One pass as a frame drawn alone: unmoved, and the mean on the canvas not advanced.
    if ((state.refinement ?? 0) !== 0) state = { ...state, refinement: 0 };
    this.prepare(state, images);
    if (source === 'reflection') {
      this.runReflection();
      return readFramebuffer(this.gl, this.reflection.framebuffer, this.reflection.width, this.reflection.height, this.reflection.halfFloat, state.colorSpace === 'srgb');
    }
    const target = (this.captureTarget ??= new RenderTarget(gl, this.counter));
    target.setSize(state.width, state.height);
    this.draw({ ...state, view: source }, images, target.framebuffer);
    return readFramebuffer(this.gl, target.framebuffer, target.width, target.height);
  }

  get stats(): RenderStats {
    // What this element's frames hold live: its own objects and the context's shared ones.
    const counts = { ...this.counter.counts };
    const shared = this.shared.counter.counts;
    for (const k in counts) counts[k as keyof typeof counts] += shared[k as keyof typeof counts];
    return {
      frames: this.counts.frames,
      programs: this.programs.size,
      sphereSegments: this.objectMeshes.sphereSegments,
      passesRun: { ...this.counts.passesRun },
      passesSkipped: { ...this.counts.passesSkipped },
      drawCalls: this.report.drawCalls,
      triangles: { ...this.ctx.triangles },
      resources: { ...counts, total: this.counter.total + this.shared.counter.total },
    };
  }

  dispose(): void {
    const gl = this.gl;
    this.programs.dispose();
    this.objectMeshes.dispose();
    this.reflectionMsaa?.dispose();
    this.mainMsaa?.dispose();
    this.reflectionMsaa = this.mainMsaa = null;
    this.rough.dispose();
    this.ctx.environment?.dispose();
    this.ctx.pbrMaps?.dispose();
    this.glassMesh.dispose();
    this.textures.dispose();
    this.shared.release();
    this.reflection.dispose();
    this.linearFrame.dispose();
    this.captureTarget?.dispose();
    this.captureTarget = null;
    gl.deleteVertexArray(this.blitVao);
    this.counter.add('vertexArrays', -1);
  }

  private prepare(state: FrameState, images: SceneImages | null | undefined): void {
    this.ctx.state = state;
    const scene = this.ctx.scene;
    // docs/colour.md#srgb: colour data (textures, the background) decoded in srgb; light is mixed linearly.
    const srgb = state.colorSpace === 'srgb';
    this.textures.setColorSpace(srgb);
    this.textures.sync(scene, images);
    this.ctx.pbrMaps?.sync(scene, images, srgb);
    for (let k = 0; k < 3; k++) this.background[k] = srgb ? srgbToLinear(scene.background[k]) : scene.background[k];
    this.setup.update(state, scene);
    this.ctx.hdr = toneMapped(state) && this.canHalfFloat && this.programs.hasPbr;
    this.ctx.footprint = 1 / refinementScale(state);
    this.objectMeshes.trim(scene.objects.length);
    this.objectMeshes.beginFrame(this.setup.halfHeight);
    this.ctx.triangles.scene = this.ctx.triangles.reflection = 0;
    if (this.setup.glass !== this.glassMeshFrame) {
      this.glassMesh.dispose();
      this.glassMesh = this.ctx.glassMesh = new Mesh(this.gl, this.counter, glassMesh(this.setup.glass));
      this.glassMeshFrame = this.setup.glass;
    }
    if (this.parts.get(FRAME_CHECKS)) this.checkFinite(state);
    const rect = glassScreenRect(this.setup.viewProjection, this.setup.eye, state.width, state.height, this.glassRect, this.setup.glass.corners);
    this.glassSkipReason = glassSkipReason(this.setup, rect, this.optimize);
    this.ctx.cull = this.optimize;
    this.ctx.transparentDepth = this.rough.active(state);
    // Clamped like the canvas (the glass reads it with normalised coordinates). rgba16f: at
    // grazing incidence F nears 1 and an 8-bit reflection's rounding shows through undimmed
    // (+3.6 dB on the glass at 89° in the bench); rgba8 where half float cannot be rendered to.
    // In linear light an 8-bit reflection is held encoded (SRGB8_ALPHA8): linear in 8 bits bands.
    const format = (state.reflectionFormat === 'rgba16f' && this.canHalfFloat) || this.ctx.hdr ? 'rgba16f' : srgb ? 'srgb8' : 'rgba8';
    if (format !== this.reflection.format) {
      this.reflection.dispose();
      this.reflectionMsaa?.dispose();
      this.reflectionMsaa = null;
      this.reflection = new RenderTarget(this.gl, this.counter, format);
    }
    const scale = state.reflectionScale;
    const max = this.maxTargetSize;
    this.reflection.setSize(reflectionTargetSide(state.width, scale, max), reflectionTargetSide(state.height, scale, max));
  }

  private samplesFor(state: FrameState): number {
    return Math.min(state.samples, this.maxSamples);
  }

  /** The glass's screen rectangle in reflection texels (of the target as clamped, not as asked). */
  private reflectionScissor(): Viewport {
    const { width, height } = this.ctx.state;
    return reflectionScissor(this.glassRect, width, height, this.reflection.width, this.reflection.height, this.scissor);
  }

  /** @internal DebugViewFrame: this frame's sharp reflection texture. */
  reflectionColor(): WebGLTexture {
    return this.reflection.color;
  }

  /** @internal DebugViewFrame: rough glass's images when the final image has rough glass (their draw calls), else null. */
  roughImages(): number | null {
    return this.rough.active(this.ctx.state) && this.glassSkipReason === undefined ? this.rough.draw(this.ctx, this.reflection, this.reflectionSamples()) : null;
  }

  /**
   * Pass 1 into the reflection texture, through a multisampled target when asked. `scissored`
   * limits it to the glass (the final image); debug views and captures of it draw it whole.
   * @internal DebugViewFrame
   */
  runReflection(scissored = false): number {
    const { width, height } = this.reflection;
    this.ctx.scissor = scissored && this.optimize ? this.reflectionScissor() : null;
    const msaa = this.reflectionSamples();
    const n = reflectionPass(this.ctx, msaa?.framebuffer ?? this.reflection.framebuffer, width, height);
    msaa?.resolve(this.reflection.framebuffer);
    return n;
  }

  /** The reflection's multisampled stand-in at this frame's size and samples, or null for none. */
  private reflectionSamples(): MultisampleTarget | null {
    const samples = this.samplesFor(this.ctx.state);
    if (samples === 0) return null;
    const msaa = (this.reflectionMsaa ??= new MultisampleTarget(this.gl, this.counter, this.reflection.format));
    msaa.setSize(this.reflection.width, this.reflection.height, samples);
    return msaa;
  }

  /** Draws `state.view` into `destination` (null = canvas), multisampled when asked. */
  private draw(state: FrameState, images: SceneImages | null | undefined, destination: WebGLFramebuffer | null): number {
    this.prepare(state, images);
    const samples = this.samplesFor(state);
    // The fresnel view is a number, not a picture: drawn as stored in either space (docs/colour.md#debug-views).
    if (encodesAtEnd(state)) {
      const hdr = this.ctx.hdr;
      const n = this.drawView(state, this.linearFrame.begin(state.width, state.height, samples, hdr));
      return n + this.linearFrame.end(destination, hdr ? state.toneMapping ?? 'none' : null, state.exposure ?? 1, refines(state) ? state.refinement! : 0, state.refinementFrames ?? 1);
    }
    if (samples === 0) return this.drawView(state, destination);
    const msaa = (this.mainMsaa ??= new MultisampleTarget(this.gl, this.counter));
    msaa.setSize(state.width, state.height, samples);
    const n = this.drawView(state, msaa.framebuffer);
    msaa.resolve(destination);
    return n;
  }

  /** Draws `state.view` into `framebuffer` (a debug view whose chunk is not in: the final image); returns the draw calls. */
  private drawView(state: FrameState, framebuffer: WebGLFramebuffer | null): number {
    const full = setViewport(this.full, 0, 0, state.width, state.height);
    const view = state.view, views = this.parts.get(DEBUG_VIEWS);
    if (view !== 'final' && view !== 'scene' && views) return views.drawDebugView(this, view, framebuffer, full);
    if (view === 'scene' || this.glassSkipReason !== undefined) {
      beginTarget(this.gl, framebuffer, full, this.background);
      return scenePass(this.ctx);
    }
    const rough = this.rough.active(state);
    const n = rough ? this.rough.draw(this.ctx, this.reflection, this.reflectionSamples()) : this.runReflection(true);
    beginTarget(this.gl, framebuffer, full, this.background);
    return n + this.sceneAndGlass(rough);
  }

  /** @internal DebugViewFrame: passes 2 and 3; rough (after RoughGlass.draw), the opaque glass then the transparent objects, which it erased drawn first. */
  sceneAndGlass(rough: boolean): number {
    const ctx = this.ctx, r = this.rough.current;
    if (!rough || !r) return scenePass(ctx) + glassPass(ctx, this.reflection.color);
    return scenePass(ctx, false, 'opaque') + glassPass(ctx, r.reflectionColor, false, r) + scenePass(ctx, false, 'transparent');
  }

  private checkFinite(state: FrameState): void {
    const bad = this.parts.get(FRAME_CHECKS)!.findNonFinite(this.setup, state, this.ctx.scene.objects.length);
    if (bad) console.error(`glass-plane-scene: non-finite uniform ${bad} in frame ${this.counts.frames + 1}`);
  }
}
