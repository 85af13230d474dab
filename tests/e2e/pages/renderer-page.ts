// Draws a Scene value with the WebGL Renderer and reads the pixels back: the scene-model tests
// use it to test what the renderer does with scenes the element cannot describe yet. Scenes
// arrive as JSON; a mesh's typed arrays as plain arrays (see tests/e2e/helpers/scene-json.ts).
import { Renderer } from '../../../src/render/renderer';
import type { FrameState } from '../../../src/frame/types';
import type { Scene } from '../../../src/scene/scene';
import type { DecodedImage } from '../../../src/scene/decoded-image';
import type { MeshData } from '../../../src/scene/geometry/mesh-data';

interface JsonMesh { positions: number[]; normals: number[]; uvs: number[]; indices: number[]; tangents?: number[]; colors?: number[] }

const canvas = document.getElementById('c') as HTMLCanvasElement;
const gl = canvas.getContext('webgl2', {
  alpha: true, antialias: false, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false,
})!;
const renderer = new Renderer(gl, { checks: true });
/** The images given so far, kept from draw to draw as the element's backend keeps them: the renderer's third argument. */
const decoded = new Map<string, DecodedImage>();

function revive(scene: Scene): Scene {
  return {
    ...scene,
    objects: scene.objects.map((o) => {
      if (o.geometry.kind !== 'mesh') return o;
      const j = o.geometry.data as unknown as JsonMesh;
      const data: MeshData = {
        positions: new Float32Array(j.positions), normals: new Float32Array(j.normals), uvs: new Float32Array(j.uvs),
        indices: new Uint32Array(j.indices), ...(j.tangents ? { tangents: new Float32Array(j.tangents) } : {}),
        ...(j.colors ? { colors: new Float32Array(j.colors) } : {}),
      };
      return { ...o, geometry: { ...o.geometry, data } };
    }),
    // An environment image's texels as a plain array (scene-json.ts): its Float32Array again.
    ...(scene.environment?.kind === 'image' ? { environment: { ...scene.environment, image: { ...scene.environment.image, rgb: new Float32Array(scene.environment.image.rgb) } } } : {}),
  };
}

function toBase64(bytes: Uint8ClampedArray): string {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

const api = {
  /**
   * Loads what a frame of `scene` needs and draws it (then reads a pixel: the GPU done), and answers the longest wait between
   * the ticks of a 5 ms timer meanwhile (ms).
   */
  async loadWatched(state: FrameState, scene: Scene): Promise<number> {
    let last = performance.now(), worst = 0;
    const tick = setInterval(() => {
      const now = performance.now();
      worst = Math.max(worst, now - last);
      last = now;
    }, 5);
    await renderer.load(revive(scene), state);
    // A task of its own after the load's last, so that the timer's wait before it counts apart from the frame's.
    await new Promise((resolve) => setTimeout(resolve, 20));
    canvas.width = state.width;
    canvas.height = state.height;
    renderer.render(revive(scene), state, decoded);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    clearInterval(tick);
    return Math.max(worst, performance.now() - last);
  },
  /**
   * RGBA8 of `state.view` of `scene`, top row first, base64 (after loading what it needs: rough
   * glass's chunk), with `images` added to those of the draws before.
   */
  async draw(state: FrameState, scene: Scene, images: Record<string, { width: number; height: number; rgba: number[] }> = {}): Promise<string> {
    await renderer.load(revive(scene), state);
    canvas.width = state.width;
    canvas.height = state.height;
    for (const [url, img] of Object.entries(images)) decoded.set(url, new ImageData(new Uint8ClampedArray(img.rgba), img.width, img.height));
    // 'passes' is drawn to the canvas and read back; the fresnel view as 'final' (its pass reads).
    const source = state.view === 'final' || state.view === 'scene' || state.view === 'reflection' ? state.view : state.view === 'passes' ? 'screen' : 'final';
    return toBase64(renderer.read(revive(scene), state, decoded, source).data);
  },
  /**
   * A still view of `frames` refinement frames (docs/refinement.md): frames 1..frames − 1 drawn, the last read from the
   * canvas as it is drawn; RGBA8, top row first, base64.
   */
  async refine(state: FrameState, scene: Scene, frames: number): Promise<string> {
    const s = revive(scene);
    await renderer.load(s, state);
    canvas.width = state.width;
    canvas.height = state.height;
    for (let k = 1; k < frames; k++) renderer.render(s, { ...state, refinement: k, refinementFrames: frames }, decoded);
    return toBase64(renderer.read(s, { ...state, refinement: frames, refinementFrames: frames }, decoded, 'screen').data);
  },
  /** A state drawn without loading first (rough glass before its chunk is in). */
  drawNow(state: FrameState, scene: Scene): string {
    canvas.width = state.width;
    canvas.height = state.height;
    return toBase64(renderer.read(revive(scene), state, decoded, 'final').data);
  },
  /** The renderer's stats after the last draw. */
  stats() {
    return renderer.stats;
  },
  /**
   * Mean ms per frame of `frames` frames of `state` drawn to the canvas, each waited for (a
   * one-pixel read), after one unmeasured frame (compiles, allocations). A rough figure only.
   */
  async time(state: FrameState, scene: Scene, frames: number): Promise<number> {
    const s = revive(scene);
    await renderer.load(s, state);
    canvas.width = state.width;
    canvas.height = state.height;
    const px = new Uint8Array(4);
    renderer.render(s, state, decoded);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    const t0 = performance.now();
    for (let i = 0; i < frames; i++) {
      renderer.render(s, state, decoded);
      gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, px);
    }
    return (performance.now() - t0) / frames;
  },
  /** Frees the renderer's GL objects (the page is done with it). */
  dispose() {
    renderer.dispose();
  },
};

(window as unknown as { __renderer: typeof api }).__renderer = api;
