// What draws the element's frames: one interface, two implementations, one at a time, chosen by
// the `renderer` attribute (backend-controller.ts): WebGL2 in the page's shared context
// (webgl-backend.ts) or the CPU renderer, in a worker when it can (software-backend.ts).
import type { ReadbackSource } from '../render/renderer';
import type { FrameReport, FrameState, RenderStats } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { ImageSink } from './texture-images';

/** What a backend needs of whoever runs it. */
export interface BackendHost {
  /** The element's canvas: where frames are shown. */
  readonly canvas: HTMLCanvasElement;
  /** A frame of `state` is on the canvas. */
  drawn(state: FrameState, report: Omit<FrameReport, 'frame'>): void;
  /** Draw again (the canvas was resized while a frame was drawn). */
  requestRender(): void;
  /**
   * A frame drawn elsewhere has landed: draw what changed meanwhile. `offThread`: it was drawn
   * in a worker, so while something moves the next one may start at once.
   */
  resume(offThread: boolean): void;
  /** Drawing threw: a shader that failed, a lost context, or a bug (rethrown). */
  renderError(e: unknown): void;
}

/**
 * A renderer drawing the element's frames. It takes the scene's decoded images as they arrive
 * (setImage) and calls its renderer with them (ARCHITECTURE.md, "How a frame flows").
 */
export interface Backend extends ImageSink {
  readonly kind: 'webgl' | 'software';
  /** Where the software renderer draws (a worker, or the main thread). */
  readonly thread?: 'worker' | 'main';
  /** A frame is still being drawn: the next one waits for it. */
  readonly busy: boolean;
  /**
   * Starts loading the lazy parts a frame of `scene` and `state` needs of this renderer; true when
   * the frame must wait for them (a frame is asked for when they settle).
   */
  waitsFor(scene: Scene, state: FrameState): boolean;
  /**
   * Draws `state` of `scene` on the canvas, with the images given so far (setImage); `drawn` tells
   * when it is there (perhaps later).
   */
  draw(scene: Scene, state: FrameState): void;
  /** One pass, or the final image, drawn now off screen from `state`; null if that failed. */
  capture(scene: Scene, state: FrameState, source: ReadbackSource): ImageData | null;
  /** Its own counters (a new object), or null when it keeps none (the software renderer). */
  stats(): RenderStats | null;
  /** Frees what it holds; returns its last counters (or null). Nothing it started lands after this. */
  dispose(): RenderStats | null;
}
