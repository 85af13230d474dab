// What both bench pages (bench-page.ts, pbr-page.ts) do with our renderer in the browser: a context made as the element makes
// its own, the canvas sized to a frame state, batches of frames timed and closed by a one-pixel read, pixels as base64; and a
// still view's frames (docs/refinement.md), each timed, or read as the picture shown after it.
import { Renderer } from '../src/render/renderer';
import type { FrameState } from '../src/frame/types';
import type { Scene } from '../src/scene/scene';
import { readFramebuffer } from '../src/render/gl/read-pixels';
import { stillState } from './bench-state';

const pixel = new Uint8Array(4);

/** A WebGL2 context with the element's own attributes (src/element/glass-plane-scene.ts). */
export function ourContext(canvas: HTMLCanvasElement): WebGL2RenderingContext {
  return canvas.getContext('webgl2', {
    alpha: true, antialias: false, depth: true, stencil: false, premultipliedAlpha: true, preserveDrawingBuffer: false,
  })!;
}

export function resize(canvas: HTMLCanvasElement, s: Pick<FrameState, 'width' | 'height'>): void {
  if (canvas.width !== s.width) canvas.width = s.width;
  if (canvas.height !== s.height) canvas.height = s.height;
}

/** Waits for the GPU's work so far: a one-pixel read. */
export function finish(context: WebGL2RenderingContext): void {
  context.readPixels(0, 0, 1, 1, context.RGBA, context.UNSIGNED_BYTE, pixel);
}

export function toBase64(bytes: Uint8ClampedArray | Uint8Array): string {
  let s = '';
  for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
  return btoa(s);
}

/** A still view after which the next one's meshes are reset (beforeStill): its strata cut spheres with 3× the segments. */
const RESET_FRAMES = 82;

/** Our renderer on `canvas`: frames timed, and read from the screen. */
export function ourFrames(renderer: Renderer, gl: WebGL2RenderingContext, canvas: HTMLCanvasElement) {
  /**
   * What comes before a still view of `s`: a strata frame of a fine grid, then `warmup` moving frames (what brought the camera
   * there, drawn as a moving one is with refinement on). mesh-choice.ts keeps a sphere's mesh while it has at most twice the
   * segments needed, so a still view right after another of the same view would keep the last one's finer cut in its
   * preview (measured: up to 2.9 dB better, 0.01 from the plane); after these, the meshes are those a moving frame asks for.
   */
  const beforeStill = (scene: Scene | null, s: FrameState, frames: number, warmup: number) => {
    renderer.render(scene, stillState(s, 2, RESET_FRAMES));
    for (let i = 0; i < warmup; i++) renderer.render(scene, stillState(s, 0, frames));
    finish(gl);
  };
  return {
    /**
     * `scene` in frame state `s` after loading what `loadFor` needs (the scene itself, or null: the default's parts): ms per
     * frame over `frames` after `warmup`, each run waited for.
     */
    async timeFrames(scene: Scene, s: FrameState, frames: number, warmup: number, loadFor: Scene | null = scene): Promise<number> {
      await renderer.load(loadFor, s);
      resize(canvas, s);
      for (let i = 0; i < warmup; i++) renderer.render(scene, s);
      finish(gl);
      const t0 = performance.now();
      for (let i = 0; i < frames; i++) renderer.render(scene, s);
      finish(gl);
      return (performance.now() - t0) / frames;
    },

    /**
     * A still view of `frames` frames (docs/refinement.md#at-rest) of `scene` (null: the default one) from state `s`, after
     * `warmup` moving frames (beforeStill): ms from the view's start to the end of each of its frames, each waited for by a
     * one-pixel read.
     */
    async stillTimes(scene: Scene | null, s: FrameState, frames: number, warmup: number, loadFor: Scene | null = scene): Promise<number[]> {
      await renderer.load(loadFor, stillState(s, 1, frames));
      await renderer.load(loadFor, stillState(s, 2, frames));
      resize(canvas, s);
      beforeStill(scene, s, frames, warmup);
      const out: number[] = [];
      const t0 = performance.now();
      for (let k = 1; k <= frames; k++) {
        renderer.render(scene, stillState(s, k, frames));
        finish(gl);
        out.push(performance.now() - t0);
      }
      return out;
    },

    /**
     * Frame k of a still view of `frames` frames of `scene` from state `s`: the ms it took, waited for by a one-pixel read,
     * and when `read` the picture shown after it, read from the canvas it was drawn on (base64; the read is not timed). The
     * view's frames must be drawn in order, 1 to `frames`: each adds to the mean the frames before it left. Frame 1 comes after
     * `warmup` moving frames (beforeStill, untimed).
     */
    async stillFrame(scene: Scene | null, s: FrameState, k: number, frames: number, read: boolean, warmup: number, loadFor: Scene | null = scene): Promise<{ ms: number; picture: string | null }> {
      const f = stillState(s, k, frames);
      await renderer.load(loadFor, f);
      resize(canvas, s);
      if (k === 1) beforeStill(scene, s, frames, warmup);
      const t0 = performance.now();
      renderer.render(scene, f);
      finish(gl);
      const ms = performance.now() - t0;
      // The drawing buffer is not preserved, but it holds the frame until this task ends.
      return { ms, picture: read ? toBase64(readFramebuffer(gl, null, s.width, s.height).data) : null };
    },

    /** `scene`'s frame in state `s`, read from the screen, base64. */
    async screenPixels(scene: Scene, s: FrameState, loadFor: Scene | null = scene): Promise<{ width: number; height: number; data: string }> {
      await renderer.load(loadFor, s);
      resize(canvas, s);
      const px = renderer.read(scene, s, null, 'screen');
      return { width: px.width, height: px.height, data: toBase64(px.data) };
    },
  };
}
