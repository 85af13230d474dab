// The element's `ready` and `frame` events (docs/element.md#events): one frozen detail per frame
// drawn, `ready` once, after the first frame drawn with nothing left loading.
import type { FrameReport, FrameState } from '../frame/types';

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
  private readyFired = false;

  constructor(private readonly host: FrameEventsHost) {}

  /** After a frame is on the canvas: counts, `ready` (once) and `frame`. */
  drawn(state: FrameState, report: Omit<FrameReport, 'frame'>): void {
    this.frames++;
    this.host.drawn(state);
    // One small frozen object per frame (the event is one anyway), its passes shared frozen
    // records: listeners may keep it, and nothing later changes it.
    const { time, width, height, drawCalls, passes } = report;
    const detail: FrameReport = Object.freeze({ frame: this.frames, time, width, height, drawCalls, passes });
    const el = this.host.element;
    // `ready` waits for the models of the children: loaded or failed (docs/element.md#events).
    if (!this.readyFired && !this.host.loading()) {
      this.readyFired = true;
      el.dispatchEvent(new CustomEvent('ready', { detail }));
    }
    el.dispatchEvent(new CustomEvent('frame', { detail }));
  }
}
