// Public types of the element's events, stats and captures.
import type { PassName, FrameReport, RenderStats } from '../frame/types';

export type { PassName, FrameReport, RenderStats };

export type CapturePass = 'reflection' | 'scene' | 'final';

export type ErrorType = 'webgl2-unavailable' | 'context-lost' | 'shader' | 'load';

export interface GlassPlaneSceneErrorDetail {
  type: ErrorType;
  message: string;
  /** A `camera-src` that failed (type 'load'): its URL, and the line of a parse error. */
  url?: string;
  line?: number;
}

export interface CameraChangeDetail {
  position: [number, number, number];
  rotation: [number, number];
  /** `camera-target`, when it is set. */
  target?: [number, number, number];
}

export interface GlassPlaneSceneEventMap extends Omit<HTMLElementEventMap, 'error'> {
  ready: CustomEvent<FrameReport>;
  frame: CustomEvent<FrameReport>;
  /** docs/refinement.md#events: a still view's last refinement frame is on the canvas. */
  refined: CustomEvent<FrameReport>;
  error: CustomEvent<GlassPlaneSceneErrorDetail>;
  'camera-change': CustomEvent<CameraChangeDetail>;
}
