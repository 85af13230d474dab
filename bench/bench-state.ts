// The bench's frame states, without DOM, so the page (bench-page.ts) and the specs in Node (the software renderer's rows)
// draw the same frame: the default scene at a size, a clock, the knobs of bench/configs.ts and a view of bench/views.ts; and a
// still view's frames as the element draws them.
import type { FrameState } from '../src/frame/types';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import type { Knobs } from './configs';
import type { BenchView } from './views';

export interface Scene {
  width: number;
  height: number;
  time: number;
}

export function frameState(scene: Scene, knobs: Knobs, view: BenchView, mode: FrameState['view'] = 'final'): FrameState {
  return defaultFrameState({
    width: Math.max(1, Math.round(scene.width * knobs.pixelRatio)),
    height: Math.max(1, Math.round(scene.height * knobs.pixelRatio)),
    time: scene.time, fresnel: knobs.fresnel,
    cameraPosition: view.cameraPosition, yaw: view.yaw, pitch: view.pitch, colorSpace: knobs.colorSpace, view: mode,
    reflectionScale: knobs.reflectionScale, samples: knobs.samples, shading: knobs.shading, tessellation: knobs.tessellation,
    reflectionFormat: knobs.reflectionFormat, projection: view.projection,
  });
}

/**
 * Frame k of a still view of `frames` frames from `s` (docs/refinement.md#at-rest), as the element fills it
 * (src/element/frame-state.ts): k = 1 the preview, at the samples `s` asks for; k ≥ 2 a strata frame, and k = 0 a moving
 * frame, both at one sample a pixel.
 */
export function stillState(s: FrameState, k: number, frames: number): FrameState {
  return { ...s, samples: k === 1 ? s.samples : 0, refinement: k, refinementFrames: frames };
}
