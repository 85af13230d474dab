// In-browser half of bench/software.spec.ts: frames of the software renderer through the
// element's SoftwareHost (its worker; the round trip the element waits for), through a bench
// worker that reports its own render time and phase split, and of the WebGL renderer, per frame.
import { SoftwareHost } from '../src/element/software-host';
import { DEFAULT_CAMERA_POSITION, DEFAULT_CAMERA_ROTATION, DEFAULT_CUBE_DISTANCE } from '../src/element/attributes';
import { Renderer } from '../src/render/renderer';
import type { ColorSpace, FrameState } from '../src/frame/types';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import type { SoftwareTiming } from '../src/software';
import { defaultScene } from '../src/scene/default-scene';
import type { SceneImages } from '../src/scene/decoded-image';
import { DEFAULTS } from './configs';
import { BENCH_SCENES } from './scenes';
import { bezierScene, BEZIER_VIEW, WHITE, WHITE_URL } from './bezier-scene';
import type { BenchView } from './views';
import type { BenchWorkerRequest, BenchWorkerResponse } from './software-worker';

export interface Size { width: number; height: number }

const DEFAULT_VIEW: BenchView = { name: 'default', cameraPosition: [...DEFAULT_CAMERA_POSITION], yaw: DEFAULT_CAMERA_ROTATION[0], pitch: DEFAULT_CAMERA_ROTATION[1] };

/** The element's defaults (bench/configs.ts DEFAULTS) at `time`, in `colorSpace` (the default's unless given). */
function frameState(size: Size, time: number, view: BenchView = DEFAULT_VIEW, colorSpace: ColorSpace = DEFAULTS.colorSpace, samples: number = DEFAULTS.samples): FrameState {
  return defaultFrameState({
    width: size.width, height: size.height, time,
    fresnel: DEFAULTS.fresnel, cameraPosition: view.cameraPosition, yaw: view.yaw, pitch: view.pitch, colorSpace,
    reflectionScale: DEFAULTS.reflectionScale, samples, shading: DEFAULTS.shading, tessellation: DEFAULTS.tessellation,
    reflectionFormat: DEFAULTS.reflectionFormat,
  });
}

const canvas = document.getElementById('gl') as HTMLCanvasElement;
// The element's own context attributes (src/element/glass-plane-scene.ts).
const gl = canvas.getContext('webgl2', {
  alpha: true, antialias: false, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false,
})!;
const renderer = new Renderer(gl, {});
/** The Bézier patch's image, for the WebGL renderer (the third argument of render and read). */
const IMAGES: SceneImages = new Map([[WHITE_URL, WHITE]]);
const pixel = new Uint8Array(4);
/** The element's SoftwareHost by worker count (null: its own default, one per core up to 4). */
const hosts = new Map<number | null, SoftwareHost>();
let worker: Worker | null = null;
let nextId = 0;

function toBase64(bytes: Uint8ClampedArray | Uint8Array): string {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

async function softwareHost(workers: number | null = null): Promise<SoftwareHost> {
  let host = hosts.get(workers);
  if (!host) hosts.set(workers, (host = await SoftwareHost.create(true, workers ?? undefined)));
  if (host.thread !== 'worker') throw new Error('the software host did not start its worker');
  return host;
}

function benchWorker(): Worker {
  worker ??= new Worker(new URL('./software-worker.ts', import.meta.url), { type: 'module' });
  return worker;
}

function ask(request: Omit<BenchWorkerRequest, 'id'>): Promise<BenchWorkerResponse> {
  const w = benchWorker(), id = ++nextId;
  return new Promise((resolve, reject) => {
    w.onmessage = (e: MessageEvent<BenchWorkerResponse>) => { if (e.data.id === id) resolve(e.data); };
    w.onerror = (e) => reject(new Error(e.message));
    w.postMessage({ ...request, id });
  });
}

const api = {
  /**
   * Round trip per frame (ms) of the default scene through the element's SoftwareHost: request
   * posted, pixels back on the main thread. The clock moves each frame so the cube turns.
   */
  async hostFrames(
    size: Size, samplesPerAxis: number, frames: number, warmup: number, colorSpace: ColorSpace = DEFAULTS.colorSpace, samples: number = DEFAULTS.samples,
    workers: number | null = null, benchScene: number | null = null,
  ): Promise<number[]> {
    return (await this.hostFramesTimed(size, samplesPerAxis, frames, warmup, colorSpace, samples, workers, benchScene)).map((f) => f.roundTrip);
  },

  /** hostFrames, with each frame's slowest band's own time in its worker (SoftwareHost.lastWorkerMs). */
  async hostFramesTimed(
    size: Size, samplesPerAxis: number, frames: number, warmup: number, colorSpace: ColorSpace = DEFAULTS.colorSpace, samples: number = DEFAULTS.samples,
    workers: number | null = null, benchScene: number | null = null,
  ): Promise<{ roundTrip: number; render: number }[]> {
    const h = await softwareHost(workers), out: { roundTrip: number; render: number }[] = [];
    const scene = benchScene === null ? defaultScene(DEFAULT_CUBE_DISTANCE, 0.8) : BENCH_SCENES[benchScene].scene;
    const view = benchScene === null ? DEFAULT_VIEW : BENCH_SCENES[benchScene].view;
    for (let i = 0; i < warmup + frames; i++) {
      const t0 = performance.now();
      await h.render(scene, frameState(size, 1 + i / 60, view, colorSpace, samples), samplesPerAxis);
      if (i >= warmup) out.push({ roundTrip: performance.now() - t0, render: h.lastWorkerMs });
    }
    return out;
  },

  /** Workers a host started by default (one per core, up to 4). */
  async defaultWorkers(): Promise<number> {
    return (await softwareHost()).workerCount;
  },

  /** The default scene at `time` through SoftwareHost's worker: RGBA8, top row first, base64. */
  async hostPixels(
    size: Size, samplesPerAxis: number, time: number, colorSpace: ColorSpace = DEFAULTS.colorSpace, samples: number = DEFAULTS.samples,
    workers: number | null = null, benchScene: number | null = null,
  ): Promise<string> {
    const h = await softwareHost(workers);
    const scene = benchScene === null ? defaultScene(DEFAULT_CUBE_DISTANCE, 0.8) : BENCH_SCENES[benchScene].scene;
    const view = benchScene === null ? DEFAULT_VIEW : BENCH_SCENES[benchScene].view;
    return toBase64(await h.render(scene, frameState(size, time, view, colorSpace, samples), samplesPerAxis));
  },

  /**
   * Frames in the bench worker: per frame the round trip and the worker's own render time, and
   * the phase split when `timing` is given (scene null: the default one; else BENCH_SCENES[i]).
   */
  async workerFrames(scene: number | null, size: Size, samplesPerAxis: number, frames: number, warmup: number, timing: { constantFragments: boolean } | null):
  Promise<{ roundTrip: number; render: number; timing: SoftwareTiming | null }[]> {
    const view = scene === null ? DEFAULT_VIEW : BENCH_SCENES[scene].view;
    const out: { roundTrip: number; render: number; timing: SoftwareTiming | null }[] = [];
    for (let i = 0; i < warmup + frames; i++) {
      const t0 = performance.now();
      const r = await ask({ scene, state: frameState(size, 1 + i / 60, view), samplesPerAxis, timing });
      if (i >= warmup) out.push({ roundTrip: performance.now() - t0, render: r.renderMs, timing: r.timing });
    }
    return out;
  },

  /**
   * WebGL ms per frame, each frame closed by a 1-pixel readback (so it is complete, as a software
   * frame is when its pixels are back): the default scene, or the Bézier patch at E (`bezier`).
   */
  glFrames(size: Size, frames: number, warmup: number, bezier: number | null = null, colorSpace: ColorSpace = DEFAULTS.colorSpace, benchScene: number | null = null): number[] {
    if (canvas.width !== size.width) canvas.width = size.width;
    if (canvas.height !== size.height) canvas.height = size.height;
    const scene = benchScene !== null ? BENCH_SCENES[benchScene].scene : bezier === null ? null : bezierScene(bezier);
    const view = benchScene !== null ? BENCH_SCENES[benchScene].view : bezier === null ? DEFAULT_VIEW : BEZIER_VIEW;
    const out: number[] = [];
    for (let i = 0; i < warmup + frames; i++) {
      const t0 = performance.now();
      renderer.render(scene, frameState(size, 1 + i / 60, view, colorSpace), IMAGES);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      if (i >= warmup) out.push(performance.now() - t0);
    }
    return out;
  },

  glPixels(size: Size, time: number, bezier: number | null = null, colorSpace: ColorSpace = DEFAULTS.colorSpace, benchScene: number | null = null): string {
    if (canvas.width !== size.width) canvas.width = size.width;
    if (canvas.height !== size.height) canvas.height = size.height;
    const scene = benchScene !== null ? BENCH_SCENES[benchScene].scene : bezier === null ? null : bezierScene(bezier);
    const view = benchScene !== null ? BENCH_SCENES[benchScene].view : bezier === null ? DEFAULT_VIEW : BEZIER_VIEW;
    const px = renderer.read(scene, frameState(size, time, view, colorSpace), IMAGES, 'screen');
    return toBase64(px.data);
  },
};

(window as unknown as { softwareBench: typeof api }).softwareBench = api;
export type SoftwareBenchApi = typeof api;
