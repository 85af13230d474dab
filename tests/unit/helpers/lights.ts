// Lights for the rule that a scene is lit by its first MAX_LIGHTS lights (docs/scene-model.md#lights).
import { defaultScene, DEFAULT_LIGHT } from '../../../src/scene/default-scene';
import type { Light, Scene } from '../../../src/scene/scene';

const dim = (r: number, g: number, b: number): Light => ({ ...DEFAULT_LIGHT, ambient: [0.02, 0.02, 0.02], diffuse: [r, g, b], specular: [0, 0, 0] });
export const FOUR: Light[] = [dim(0.3, 0, 0), dim(0, 0.3, 0), dim(0, 0, 0.3), dim(0.2, 0.2, 0.2)];
/** A fifth light that would be plain to see: a bright red point light beside the camera. */
export const FIFTH: Light = { kind: 'point', vector: [3, 2.5, 1], ambient: [0.3, 0, 0], diffuse: [1, 0, 0], specular: [1, 0, 0] };
/** The default scene lit by `lights`. */
export const litBy = (lights: Light[]): Scene => ({ ...defaultScene(3, 0), lights });
