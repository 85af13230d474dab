// The element's `ready`, `frame` and `refined` events (docs/element.md#events): one frozen detail per frame
// drawn, `ready` once, after the first frame drawn with nothing left loading, `refined` after a still view's last frame;
// and whenRefined()'s promises, kept until the picture on the canvas is final.
import type { FrameReport, FrameState, RenderStats } from '../frame/types';
import { refines } from '../frame/refinement';

/** What FrameEvents needs of the scene element. */
export interface FrameEventsHost {
  readonly element: HTMLElement;
  /** A frame is on the canvas: the failure message goes, the state is kept for capture. */
  drawn(state: FrameState): void;
  /** Children's models, the camera file or an element part still on their way. */
  loading(): boolean;
  /** Nothing more will be drawn until something changes: no change undrawn, no motion, the still view's frames all drawn. */
  atRest(): boolean;
  /** A failure keeps the element from drawing (no WebGL2, a lost context, a shader): whenRefined() rejects with its message. */
  failed(): boolean;
}

export class FrameEvents {
  /** Frames drawn so far. */
  frames = 0;
  /** Of them, refinement frames (docs/refinement.md#events). */
  refinementFrames = 0;
  private readyFired = false;
  /** A frame was handed to the backend and has not reached the canvas yet (the CPU renderer's workers). */
  // Stryker disable next-line BooleanLiteral: read only once a frame is drawn (frames > 0), and drawn() sets it
  private pending = false;
  private waiters: [() => void, (e: Error) => void][] = [];

  constructor(private readonly host: FrameEventsHost) {
    // A model or an image that failed is not the element failing: the rest of the scene is still drawn.
    host.element.addEventListener('error', (e) => {
      if (host.failed()) for (const [, reject] of this.waiters.splice(0)) reject(new Error((e as unknown as CustomEvent<{ message: string }>).detail.message));
    });
  }

  /** After a frame is on the canvas: counts, `ready` (once) and `frame`. */
  drawn(state: FrameState, report: Omit<FrameReport, 'frame'>): void {
    this.frames++;
    this.pending = false;
    const refinement = refines(state) ? state.refinement! : 0;
    if (refinement > 0) this.refinementFrames++;
    this.host.drawn(state);
    // One small frozen object per frame (the event is one anyway), its passes shared frozen
    // records: listeners may keep it, and nothing later changes it.
    const { time, width, height, drawCalls, passes } = report;
    const detail: FrameReport = Object.freeze({ frame: this.frames, time, width, height, drawCalls, passes, refinement });
    const el = this.host.element;
    // `ready` waits for the models of the children: loaded or failed (docs/element.md#events).
    if (!this.readyFired && !this.host.loading()) {
      this.readyFired = true;
      el.dispatchEvent(new CustomEvent('ready', { detail }));
    }
    el.dispatchEvent(new CustomEvent('frame', { detail }));
    if (refinement > 0 && refinement >= (state.refinementFrames ?? 1)) el.dispatchEvent(new CustomEvent('refined', { detail }));
    // After the frame loop has counted this frame (it does once the backend returns).
    // Stryker disable next-line ConditionalExpression,EqualityOperator: settling no waiter does nothing; the test spares a task a frame
    if (this.waiters.length > 0) queueMicrotask(this.settle);
  }

  /** A frame goes to the backend: until it is drawn the picture on the canvas is not the last one. */
  started(): void {
    this.pending = true;
  }

  /**
   * Resolves once the picture on the canvas is final (docs/refinement.md#events): at once when it is, else after the frame
   * that makes it so. Rejects when the element fails (an `error` that stops its frames).
   */
  whenRefined(): Promise<void> {
    return this.final() ? Promise.resolve() : new Promise((resolve, reject) => this.waiters.push([resolve, reject]));
  }

  private final(): boolean {
    return this.frames > 0 && !this.pending && this.host.atRest() && !this.host.failed();
  }

  private readonly settle = (): void => {
    if (this.final()) for (const [resolve] of this.waiters.splice(0)) resolve();
  };

  /** The element's counts into `stats`: frames drawn, refinement frames among them. */
  count(stats: RenderStats): void {
    stats.frames = this.frames;
    stats.refinementFrames = this.refinementFrames;
  }
}
