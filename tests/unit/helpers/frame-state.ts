// One FrameState for tests and the bench: the element's own attribute table's defaults
// (src/element/attributes.ts), filled the way the element fills each frame, with the camera the
// camera attributes give. Override what a test is about: defaultFrameState({ roughness: 0.3 }).
import { defaultAttributes } from '../../../src/element/attributes';
import { FrameStates } from '../../../src/element/frame-state';
import type { FrameState } from '../../../src/frame/types';

/** The drawing buffer tests use unless they say otherwise (the README's 640×360 pictures). */
export const WIDTH = 640, HEIGHT = 360;

/**
 * The defaults, filled once: the bench builds a state a frame, so each call only copies this. With `refine` 0: a frame drawn
 * as the knobs say (at the element's default a frame outside a still view is a moving one, at one sample a pixel); a test
 * of refinement sets `refinement` and `refinementFrames` (docs/refinement.md#at-rest).
 */
const DEFAULTS: Readonly<FrameState> = (() => {
  const values = { ...defaultAttributes(), refine: 0 };
  const s = new FrameStates().fill(values, 0, WIDTH, HEIGHT, values.spin);
  return {
    ...s, time: 0, cameraPosition: values.cameraPosition, yaw: values.cameraRotation[0], pitch: values.cameraRotation[1],
    fov: values.fov, projection: values.projection, target: values.cameraTarget,
  };
})();

/** A new FrameState: every attribute at its default, `time` 0, 640×360, then `over`. */
export function defaultFrameState(over: Partial<FrameState> = {}): FrameState {
  const [x, y, z] = DEFAULTS.cameraPosition;
  return { ...DEFAULTS, cameraPosition: [x, y, z], ...over };
}
