// Scenes of light above 1 (docs/pbr.md#tone-mapping) for the tone-mapping tests of the CPU renderers (tone-mapped-frames.test.ts)
// and WebGL (tests/e2e/tone-mapping.spec.ts).
import type { Scene } from '../../../src/scene/scene';
import { defaultFrameState } from './frame-state';

/** A box face head-on to a directional light of 3: Kd (1, ½, ¼) makes it (3, 1.5, 0.75). */
export const BOX: Scene = {
  glass: null, background: [0, 0, 0],
  objects: [{
    geometry: { kind: 'box', size: 1 }, transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: { ambient: [0, 0, 0], diffuse: [1, 0.5, 0.25], specular: [0, 0, 0], shininess: 1, opacity: 1, texture: { kind: 'none' }, mapping: 'uv' },
    bounds: { center: [0, 0, 0], radius: 0.9 },
  }],
  lights: [{ kind: 'directional', vector: [0, 0, 1], ambient: [0, 0, 0], diffuse: [3, 3, 3], specular: [0, 0, 0] }],
};
export const BOX_STATE = defaultFrameState({ width: 33, height: 33, cameraPosition: [0, 0, 4], yaw: -90, pitch: 0, time: 0, spin: 0, samples: 0 });
export const CENTRE = 16 * 33 + 16;

/**
 * PBR Neutral of (3, 1.5, 0.75) by hand: the darkest channel 0.75 ≥ 0.08 takes off 0.04 → (2.96, 1.46, 0.71); the peak
 * 2.96 passes 0.76: new peak 1 − 0.24²/(2.96 + 0.24 − 0.76) = 1 − 0.0576/2.44; the colour scaled by new peak / 2.96, then
 * mixed toward the new peak by g = 1 − 1/(0.15·(2.96 − new peak) + 1).
 */
export const NEUTRAL = (() => {
  const newPeak = 1 - 0.0576 / 2.44;
  const g = 1 - 1 / (0.15 * (2.96 - newPeak) + 1);
  return [2.96, 1.46, 0.71].map((c) => (c * newPeak / 2.96) * (1 - g) + newPeak * g);
})();

/** The box over a glass floor, the camera looking down at its reflection: the glass shows R above 1 when tone mapped. */
export const FLOOR: Scene = {
  ...BOX, glass: { center: [0, -0.6, 0], normal: [0, 1, 0], size: [6, 6] },
  lights: [{ kind: 'directional', vector: [0, -0.2, 1], ambient: [0, 0, 0], diffuse: [12, 12, 12], specular: [0, 0, 0] }],
};
export const FLOOR_STATE = defaultFrameState({ width: 96, height: 54, cameraPosition: [0, 0.6, 3.5], yaw: -90, pitch: -25, time: 0, spin: 0, samples: 0, ior: 1.5 });

