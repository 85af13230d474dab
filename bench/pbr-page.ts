// In-browser half of the PBR bench (bench/pbr.spec.ts): the environment's preparation timed on a fresh page, then frames of
// our WebGL renderer and of the three.js peer (bench/three-pbr-peer.ts), timed in batches closed by a one-pixel read, and
// their pixels.
import { Renderer } from '../src/render/renderer';
import { prepareEnvironment, prepareEnvironmentSliced } from '../src/frame/environment-light';
import type { FrameState } from '../src/frame/types';
import type { Scene } from '../src/scene/scene';
import { STUDIO } from '../tests/unit/helpers/pbr-scenes';
import { pbrScene, type PbrSceneName } from './pbr-scene';
import { ThreePbrPeer, type PbrPeerOptions } from './three-pbr-peer';
import type { Prep } from './pbr-report';
import { ourContext, ourFrames, resize, toBase64 } from './page-gl';

const oursCanvas = document.getElementById('ours') as HTMLCanvasElement;
const peerCanvas = document.getElementById('peer') as HTMLCanvasElement;
const gl = ourContext(oursCanvas);
const renderer = new Renderer(gl, {});
const { timeFrames, screenPixels } = ourFrames(renderer, gl, oursCanvas);
let peer: ThreePbrPeer | null = null;
let peerScene: PbrSceneName | null = null;
const scenes = new Map<PbrSceneName, Scene>();
const scene = (name: PbrSceneName): Scene => scenes.get(name) ?? scenes.set(name, pbrScene(name)).get(name)!;

/** The table frame/environment-light.ts keeps the prepared environments in (on the global object). */
const table = () => (globalThis as Record<symbol, Map<string, unknown> | undefined>)[Symbol.for('glass-plane-scene.environments')];

function threePeer(name: PbrSceneName): ThreePbrPeer {
  peer ??= new ThreePbrPeer(peerCanvas);
  if (peerScene !== name) {
    peer.setScene(scene(name));
    peerScene = name;
  }
  return peer;
}

const api = {
  /**
   * ms of the studio's maps and table made on this page: at once (prepareEnvironment, the first making on the page) and,
   * the table emptied, in slices of 8 ms (prepareEnvironmentSliced, wall time); then three's: the studio baked to an
   * equirect and through PMREM (the first making: its programs compiled; and again), and RoomEnvironment through PMREM.
   */
  async prepare(): Promise<Omit<Prep, 'node' | 'nodeWasPrepared'>> {
    if (table()?.has('studio')) throw new Error('glass-plane-scene: the studio was prepared before the bench timed it');
    let t0 = performance.now();
    prepareEnvironment(STUDIO);
    const once = performance.now() - t0;
    table()!.delete('studio');
    t0 = performance.now();
    await prepareEnvironmentSliced(STUDIO);
    const sliced = performance.now() - t0;
    resize(peerCanvas, { width: 16, height: 16 } as FrameState);
    peer ??= new ThreePbrPeer(peerCanvas);
    const first = peer.prepareEnvironment();
    const again = peer.prepareEnvironment();
    const room = peer.roomEnvironment();
    const roomAgain = peer.roomEnvironment();
    return {
      once, sliced, bake: first.bake, pmremFirst: first.pmrem, pmremAgain: again.pmrem, bakeAgain: again.bake, room, roomAgain,
    };
  },

  /** ms per frame of ours over `frames` frames after `warmup`. */
  time(name: PbrSceneName, s: FrameState, frames: number, warmup: number): Promise<number> {
    return timeFrames(scene(name), s, frames, warmup);
  },

  pixels(name: PbrSceneName, s: FrameState): Promise<{ width: number; height: number; data: string }> {
    return screenPixels(scene(name), s);
  },

  /** ms per frame of the three.js peer over `frames` frames after `warmup`. */
  threeTime(name: PbrSceneName, s: FrameState, options: PbrPeerOptions, frames: number, warmup: number): number {
    const p = threePeer(name);
    resize(peerCanvas, s);
    for (let i = 0; i < warmup; i++) p.render(s, options);
    p.finish();
    const t0 = performance.now();
    for (let i = 0; i < frames; i++) p.render(s, options);
    p.finish();
    return (performance.now() - t0) / frames;
  },

  threePixels(name: PbrSceneName, s: FrameState, options: PbrPeerOptions): string {
    const p = threePeer(name);
    resize(peerCanvas, s);
    p.render(s, options);
    return toBase64(p.readPixels());
  },

  info(): { renderer: string; maxSamples: number } {
    const dbg = gl.getExtension('WEBGL_debug_renderer_info');
    return {
      renderer: dbg ? String(gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL)) : 'unknown',
      maxSamples: gl.getParameter(gl.MAX_SAMPLES) as number,
    };
  },
};

(window as unknown as { pbr: typeof api }).pbr = api;
export type PbrBenchApi = typeof api;
