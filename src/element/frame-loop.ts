// When the element draws: on demand, only when something changed or moves, while the element is
// in view (IntersectionObserver) and the page is shown (visibilitychange); the canvas's drawing
// buffer follows the element's box (ResizeObserver) and the pixel ratio; prefers-reduced-motion is
// watched for the spin. Frames stop when nothing moves (idle), once a still view's refinement frames are drawn
// (docs/refinement.md#at-rest). What a frame draws is the host's business: no GL, no scene here.
import type { Controller } from './controller';

/** Start drawing a little before the element scrolls into view. */
const VIEW_MARGIN = '64px';

/** What FrameLoop needs of the scene element. */
export interface FrameLoopHost {
  /** The element whose box and visibility are watched. */
  readonly element: HTMLElement;
  /** Its canvas, whose drawing buffer follows the box. */
  readonly canvas: HTMLCanvasElement;
  /** Drawing-buffer pixels per CSS pixel (the `pixel-ratio` attribute). */
  pixelRatio(): number | 'auto';
  /** Largest side of the drawing buffer; null while nothing can draw (the canvas keeps its size). */
  maxSize(): number | null;
  /** A renderer is ready and nothing failed: frames can be drawn. */
  canDraw(): boolean;
  /** Something moves without a change (the clock turns an object, a control's motion): frames keep coming. */
  animating(): boolean;
  /** Frames a still view draws (docs/refinement.md#at-rest); 0: none, frames stop at once. */
  refineFrames(): number;
  /**
   * Draws one frame (or starts drawing it); `now` is the frame's timestamp, `refinement` its place in a still view (0: a
   * moving frame, or refinement off). Returns whether it was drawn (false: held back, still owed).
   */
  frame(now: number, refinement: number): boolean;
  /** Frames were cancelled (out of sight, the page hidden, a resize drawn at once). */
  paused(): void;
  /** The last frame of a motion was drawn: nothing moves any more. */
  idle(): void;
  /** prefers-reduced-motion changed. */
  motionPreferenceChanged(): void;
}

export class FrameLoop implements Controller {
  /** Something changed since the last frame drawn: the next frame draws it. */
  dirty = true;
  /** The still view's last refinement frame drawn (0: a moving frame, or none since the last change). */
  refined = 0;
  private rafId = 0;
  private inView = false;
  private resizeObserver: ResizeObserver | null = null;
  private intersectionObserver: IntersectionObserver | null = null;
  private motionQuery: MediaQueryList | null = null;

  constructor(private readonly host: FrameLoopHost) {}

  /** The page asks for reduced motion. */
  get reducedMotion(): boolean {
    return this.motionQuery?.matches ?? false;
  }

  hostConnected(): void {
    const element = this.host.element;
    this.resizeObserver = new ResizeObserver(this.onResize);
    this.resizeObserver.observe(element);
    this.intersectionObserver = new IntersectionObserver(this.onIntersection, { rootMargin: VIEW_MARGIN });
    this.intersectionObserver.observe(element);
    document.addEventListener('visibilitychange', this.onVisibility);
    this.motionQuery = typeof matchMedia === 'function' ? matchMedia('(prefers-reduced-motion: reduce)') : null;
    this.motionQuery?.addEventListener('change', this.onMotionPreference);
  }

  hostDisconnected(): void {
    this.cancel();
    this.resizeObserver?.disconnect();
    this.intersectionObserver?.disconnect();
    this.resizeObserver = this.intersectionObserver = null;
    document.removeEventListener('visibilitychange', this.onVisibility);
    this.motionQuery?.removeEventListener('change', this.onMotionPreference);
    this.motionQuery = null;
    this.inView = false;
  }

  /** Draws a frame on the next animation frame, even when nothing changed. */
  request(): void {
    this.dirty = true;
    this.schedule();
  }

  /** Draws only when something changed or moves, the element is in view and the page shown. */
  schedule(): void {
    if (this.rafId !== 0 || !this.host.canDraw() || !this.inView || document.hidden) return;
    if (!this.dirty && !this.host.animating() && !this.refining()) return;
    this.rafId = requestAnimationFrame(this.onFrame);
  }

  /**
   * A frame drawn elsewhere has landed: draw what changed meanwhile. While something moves and
   * the frame came from a worker (`offThread`), the next frame starts at once rather than at the
   * next animation frame, so the worker never sits idle waiting for the display (a 16 ms frame
   * would otherwise miss every other vsync and show at 30 Hz); drawn on this thread, it waits
   * for the animation frame, which lets the page run between frames.
   */
  resume(offThread = false): void {
    const moving = this.host.animating();
    if (!this.dirty && !moving && !this.refining()) return;
    if (!offThread || !moving || !this.host.canDraw() || !this.inView || document.hidden) {
      this.schedule();
      return;
    }
    cancelAnimationFrame(this.rafId);
    this.onFrame(performance.now());
  }

  /** Drawing buffer = CSS box × pixel ratio, within the renderer's limits. Returns true if it changed. */
  resize(): boolean {
    const { element, canvas } = this.host;
    const limit = this.host.maxSize();
    if (limit === null) return false;
    const r = this.host.pixelRatio();
    const ratio = r === 'auto' ? window.devicePixelRatio || 1 : r;
    const w = Math.max(1, Math.min(limit, Math.round(element.clientWidth * ratio)));
    const h = Math.max(1, Math.min(limit, Math.round(element.clientHeight * ratio)));
    if (w === canvas.width && h === canvas.height) return false;
    canvas.width = w;
    canvas.height = h;
    return true;
  }

  cancel(): void {
    cancelAnimationFrame(this.rafId);
    this.rafId = 0;
    this.host.paused();
  }

  /** Nothing is owed: no change undrawn, nothing moving, the still view's frames all drawn. */
  atRest(): boolean {
    return !this.dirty && !this.host.animating() && !this.refining();
  }

  /** A still view's refinement is under way and not done: frames keep coming. */
  refining(): boolean {
    return this.refined > 0 && this.refined < this.host.refineFrames();
  }

  private readonly onFrame = (now: number): void => {
    this.rafId = 0;
    if (!this.host.canDraw()) return;
    // docs/refinement.md#at-rest: a frame while something moves is a moving one; a change restarts the still view at 1.
    const frames = this.host.refineFrames();
    const refinement = frames === 0 || this.host.animating() ? 0 : this.dirty ? 1 : Math.min(frames, this.refined + 1);
    const drawn = this.host.frame(now, refinement);
    if (drawn) this.refined = refinement;
    if (this.host.animating()) this.schedule();
    // At rest only once the last frame is drawn: one held back (the GPU busy, a part on its way)
    // is still owed, and a gesture's write-back must follow the pose it shows.
    else if (!this.dirty) {
      this.host.idle();
      // The next frame of the still view; one still on its way (a worker's) asks for it when it lands (resume).
      if (drawn && this.refining()) this.schedule();
    }
  };

  private readonly onResize = (): void => {
    if (!this.resize()) return;
    // Resizing clears the canvas: draw now rather than show an empty frame.
    this.cancel();
    this.dirty = true;
    if (this.host.canDraw() && this.inView && !document.hidden) this.onFrame(performance.now());
  };

  private readonly onIntersection = (entries: IntersectionObserverEntry[]): void => {
    const entry = entries[entries.length - 1];
    this.inView = entry.isIntersecting;
    if (this.inView) this.schedule();
    else this.cancel();
  };

  private readonly onVisibility = (): void => {
    if (document.hidden) this.cancel();
    else this.schedule();
  };

  private readonly onMotionPreference = (): void => {
    this.host.motionPreferenceChanged();
  };
}
