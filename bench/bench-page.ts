// In-browser half of `npm run bench`: draws configurations with our Renderer (and the
// three.js peer), times batches of frames closed by a 1-pixel readback, returns pixels.
import { Renderer } from '../src/render/renderer';
import type { FrameState } from '../src/frame/types';
import { ThreePeer } from './three-peer';
import { DEFAULTS, type Knobs } from './configs';
import type { BenchView } from './views';
import { BENCH_SCENES } from './scenes';
import { roughFloorScene } from './rough-scene';
import { finish, ourContext, ourFrames, resize, toBase64 } from './page-gl';
import type { Shading } from '../src/frame/types';
import { frameState, type Scene } from './bench-state';

export type { Scene };

const oursCanvas = document.getElementById('ours') as HTMLCanvasElement;
const peerCanvas = document.getElementById('peer') as HTMLCanvasElement;
const gl = ourContext(oursCanvas);
const renderer = new Renderer(gl, {});
const { timeFrames, screenPixels, stillTimes, stillFrame } = ourFrames(renderer, gl, oursCanvas);
let peer: ThreePeer | null = null;
let roughScene: ReturnType<typeof roughFloorScene> | null = null;

type Kind = 'ours' | 'ours-unoptimized' | 'scene-only' | 'clear-only' | 'three';

const api = {
  /** ms per frame over `frames` frames, after `warmup` untimed ones. */
  async time(kind: Kind, scene: Scene, knobs: Knobs, view: BenchView, frames: number, warmup: number): Promise<number> {
    const s = frameState(scene, knobs, view, kind === 'scene-only' ? 'scene' : 'final');
    if (kind === 'three') {
      resize(peerCanvas, s);
      peer ??= new ThreePeer(peerCanvas);
      const pgl = peerCanvas.getContext('webgl2') as WebGL2RenderingContext;
      const opts = { samples: knobs.samples, reflectionScale: knobs.reflectionScale, sphereSegments: typeof knobs.tessellation === 'number' ? knobs.tessellation : 64 };
      for (let i = 0; i < warmup; i++) peer.render(s, opts);
      finish(pgl);
      const t0 = performance.now();
      for (let i = 0; i < frames; i++) peer.render(s, opts);
      finish(pgl);
      return (performance.now() - t0) / frames;
    }
    resize(oursCanvas, s);
    // The parts this configuration needs (flat shading's mesh extras, …), as the element's frames wait for them.
    await renderer.load(null, s);
    renderer.optimize = kind !== 'ours-unoptimized';
    const draw = kind === 'clear-only'
      ? () => { gl.bindFramebuffer(gl.FRAMEBUFFER, null); gl.viewport(0, 0, s.width, s.height); gl.clearColor(0.1, 0.1, 0.1, 1); gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT); }
      : () => { renderer.render(null, s); };
    for (let i = 0; i < warmup; i++) draw();
    finish(gl);
    const t0 = performance.now();
    for (let i = 0; i < frames; i++) draw();
    finish(gl);
    renderer.optimize = true;
    return (performance.now() - t0) / frames;
  },

  /**
   * GPU ms per frame from EXT_disjoint_timer_query_webgl2 (median of `frames` queries), or
   * null where the extension is missing or the GPU reported a disjoint interval.
   */
  async gpuTime(kind: Kind, scene: Scene, knobs: Knobs, view: BenchView, frames: number): Promise<number | null> {
    const s = frameState(scene, knobs, view, kind === 'scene-only' ? 'scene' : 'final');
    let context = gl;
    let draw: () => void;
    if (kind === 'three') {
      resize(peerCanvas, s);
      peer ??= new ThreePeer(peerCanvas);
      context = peerCanvas.getContext('webgl2') as WebGL2RenderingContext;
      const opts = { samples: knobs.samples, reflectionScale: knobs.reflectionScale, sphereSegments: typeof knobs.tessellation === 'number' ? knobs.tessellation : 64 };
      draw = () => peer!.render(s, opts);
    } else {
      resize(oursCanvas, s);
      await renderer.load(null, s);
      draw = kind === 'clear-only'
        ? () => { gl.bindFramebuffer(gl.FRAMEBUFFER, null); gl.viewport(0, 0, s.width, s.height); gl.clearColor(0.1, 0.1, 0.1, 1); gl.clear(gl.COLOR_BUFFER_BIT | gl.DEPTH_BUFFER_BIT); }
        : () => { renderer.optimize = kind !== 'ours-unoptimized'; renderer.render(null, s); renderer.optimize = true; };
    }
    const ext = context.getExtension('EXT_disjoint_timer_query_webgl2') as
      { TIME_ELAPSED_EXT: number; GPU_DISJOINT_EXT: number } | null;
    if (!ext) return null;
    draw(); // warm-up: compile and allocate outside the measurement
    const queries: WebGLQuery[] = [];
    for (let i = 0; i < frames; i++) {
      const q = context.createQuery()!;
      context.beginQuery(ext.TIME_ELAPSED_EXT, q);
      draw();
      context.endQuery(ext.TIME_ELAPSED_EXT);
      queries.push(q);
    }
    finish(context);
    // Results arrive only after control returns to the event loop.
    for (let tries = 0; tries < 200; tries++) {
      if (queries.every((q) => context.getQueryParameter(q, context.QUERY_RESULT_AVAILABLE))) break;
      await new Promise((r) => setTimeout(r, 5));
    }
    const disjoint = context.getParameter(ext.GPU_DISJOINT_EXT) as boolean;
    const ns = queries.map((q) => (context.getQueryParameter(q, context.QUERY_RESULT_AVAILABLE) ? Number(context.getQueryParameter(q, context.QUERY_RESULT)) : NaN));
    for (const q of queries) context.deleteQuery(q);
    if (disjoint || ns.some(Number.isNaN)) return null;
    ns.sort((a, b) => a - b);
    return ns[Math.floor(ns.length / 2)] / 1e6;
  },

  /** RGBA8, top row first, base64, at the drawing-buffer size. */
  async pixels(kind: 'ours' | 'three', scene: Scene, knobs: Knobs, view: BenchView): Promise<{ width: number; height: number; data: string }> {
    const s = frameState(scene, knobs, view);
    if (kind === 'three') {
      resize(peerCanvas, s);
      peer ??= new ThreePeer(peerCanvas);
      peer.render(s, { samples: knobs.samples, reflectionScale: knobs.reflectionScale, sphereSegments: typeof knobs.tessellation === 'number' ? knobs.tessellation : 64 });
      return { width: s.width, height: s.height, data: toBase64(peer.readPixels()) };
    }
    resize(oursCanvas, s);
    // The parts this configuration needs (flat shading's mesh extras, …), as the element's frames wait for them.
    await renderer.load(null, s);
    const px = renderer.read(null, s, null, 'screen');
    return { width: px.width, height: px.height, data: toBase64(px.data) };
  },

  /**
   * The scenes beyond the default one (bench/scenes.ts) at the default knobs with `shading`: ms per frame over
   * `frames` frames ('final', or 'scene' for the scene pass alone), after `warmup` frames.
   */
  async sceneTime(index: number, shading: Shading, size: Scene, mode: 'final' | 'scene', frames: number, warmup: number, knobs: Partial<Knobs> = {}): Promise<number> {
    const b = BENCH_SCENES[index];
    const s = { ...frameState(size, { ...DEFAULTS, ...knobs, shading }, b.view, mode) };
    await renderer.load(b.scene, s); // the reflection's clustering, as the element would have it
    resize(oursCanvas, s);
    for (let i = 0; i < warmup; i++) renderer.render(b.scene, s);
    finish(gl);
    const t0 = performance.now();
    for (let i = 0; i < frames; i++) renderer.render(b.scene, s);
    finish(gl);
    return (performance.now() - t0) / frames;
  },

  async scenePixels(index: number, shading: Shading, size: Scene, knobs: Partial<Knobs> = {}): Promise<{ width: number; height: number; data: string }> {
    const b = BENCH_SCENES[index];
    const s = frameState(size, { ...DEFAULTS, ...knobs, shading }, b.view);
    await renderer.load(b.scene, s);
    resize(oursCanvas, s);
    const px = renderer.read(b.scene, s, null, 'screen');
    return { width: px.width, height: px.height, data: toBase64(px.data) };
  },

  /** The rough floor (bench/rough-scene.ts) in frame state `s`: ms per frame over `frames` after `warmup`. */
  async roughTime(s: FrameState, frames: number, warmup: number): Promise<number> {
    return timeFrames((roughScene ??= roughFloorScene()), s, frames, warmup, null);
  },

  async roughPixels(s: FrameState): Promise<{ width: number; height: number; data: string }> {
    return screenPixels((roughScene ??= roughFloorScene()), s, null);
  },

  /**
   * A still view of `frames` frames (docs/refinement.md) of the default scene at `knobs`, or of the rough floor
   * (bench/rough-scene.ts) in frame state `rough`: ms from its start to the end of each frame, after `warmup` moving frames.
   */
  async stillTimes(scene: Scene, knobs: Knobs, view: BenchView, frames: number, warmup: number, rough: FrameState | null = null): Promise<number[]> {
    return rough ? stillTimes((roughScene ??= roughFloorScene()), rough, frames, warmup, null) : stillTimes(null, frameState(scene, knobs, view), frames, warmup);
  },

  /** Frame k of that still view (drawn in order, 1 to `frames`): its ms, and the picture shown after it (base64) when `read`. */
  async stillFrame(
    scene: Scene, knobs: Knobs, view: BenchView, k: number, frames: number, read: boolean, warmup: number, rough: FrameState | null = null,
  ): Promise<{ ms: number; picture: string | null }> {
    return rough
      ? stillFrame((roughScene ??= roughFloorScene()), rough, k, frames, read, warmup, null)
      : stillFrame(null, frameState(scene, knobs, view), k, frames, read, warmup);
  },

  info(): { renderer: string; timerQuery: boolean; maxSamples: number } {
    const dbg = gl.getExtension('WEBGL_debug_renderer_info');
    return {
      renderer: dbg ? String(gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL)) : 'unknown',
      timerQuery: gl.getExtension('EXT_disjoint_timer_query_webgl2') !== null,
      maxSamples: gl.getParameter(gl.MAX_SAMPLES) as number,
    };
  },
};

(window as unknown as { bench: typeof api }).bench = api;
export type BenchApi = typeof api;
