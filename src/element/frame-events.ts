// The element's `ready`, `frame` and `refined` events (docs/element.md#events): one frozen detail per frame
// drawn, `ready` once, after the first frame drawn with nothing left loading, `refined` after a still view's last frame.
import type { FrameReport, FrameState, RenderStats } from '../frame/types';
import { refines } from '../frame/refinement';

/** What FrameEvents needs of the scene element. */
export interface FrameEventsHost {
  readonly element: HTMLElement;
  /** A frame is on the canvas: the failure message goes, the state is kept for capture. */
  drawn(state: FrameState): void;
  /** Children's models, the camera file or an element part still on their way. */
  loading(): boolean;
}

export class FrameEvents {
  /** Frames drawn so far. */
  frames = 0;
  /** Of them, refinement frames (docs/refinement.md#events). */
  refinementFrames = 0;
  private readyFired = false;

  constructor(private readonly host: FrameEventsHost) {}

  /** After a frame is on the canvas: counts, `ready` (once) and `frame`. */
  drawn(state: FrameState, report: Omit<FrameReport, 'frame'>): void {
    this.frames++;
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
  }

  /** The element's counts into `stats`: frames drawn, refinement frames among them. */
  count(stats: RenderStats): void {
    stats.frames = this.frames;
    stats.refinementFrames = this.refinementFrames;
  }
}
