// Rough glass's test scenes (docs/rough-glass.md#roughness): a glass floor with a cube resting on it (its
// reflection sharp at the contact) and a sphere whose lowest point is 1.5 above it (blurred), as
// on the bench's rough floor; and the default glass wall with the cube in front of it (reflected)
// and the sphere behind it (seen through it, blurred by the transmission).
import { DEFAULT_LIGHT, defaultMaterial, defaultScene } from '../../../src/scene/default-scene';
import { roughFloorScene, SPHERE_HEIGHT } from '../../../bench/rough-scene';
import type { FrameState } from '../../../src/frame/types';
import { defaultFrameState } from '../../unit/helpers/frame-state';
import type { Scene, Vec3 } from '../../../src/scene/scene';
import { lookAt } from './stability';

/** The bench's rough floor (bench/rough-scene.ts): one scene for the bench and the tests. */
export { SPHERE_HEIGHT };
export const FLOOR_SCENE: Scene = roughFloorScene();

/** The default scene (docs/default-scene.md): the cube 0.75 in front of the glass wall z = 0, the sphere 1.5 behind it. */
export const WALL_SCENE: Scene = defaultScene(0.75, 0);

export interface RoughView {
  width: number;
  height: number;
  roughness: number;
  ior?: number;
  quality?: FrameState['roughnessQuality'];
  transparency?: number;
}

function state(from: Vec3, to: Vec3, v: RoughView): FrameState {
  const { yaw, pitch } = lookAt(from, to);
  return defaultFrameState({
    width: v.width, height: v.height, spin: 0, transparency: v.transparency ?? 0.5, ior: v.ior ?? 10, cameraPosition: from, yaw, pitch,
    roughness: v.roughness, ...(v.quality ? { roughnessQuality: v.quality } : {}),
  });
}

/** The floor seen from above at a slant (the bench's rough-floor view). */
export const floorState = (v: RoughView): FrameState => state([0.3, 1.9, 5.2], [0, 0.6, 0], v);

/** The wall from in front, the cube's reflection and the sphere through the glass both in view. */
export const wallState = (v: RoughView): FrameState => state([1.5, 1.4, 4.5], [-0.2, 0.9, 0], v);

/** `scene` with its objects untextured (flat colours: edges in its reflection are the objects' outlines alone). */
export const untextured = (scene: Scene): Scene => ({
  ...scene, objects: scene.objects.map((o) => ({ ...o, material: { ...o.material, texture: { kind: 'none' } } })),
});

/** `scene` without its objects (the glass, the lights and the background alone). */
export const withoutObjects = (scene: Scene): Scene => ({ ...scene, objects: [] });

/**
 * A long glass floor seen at grazing incidence (the camera 0.6 above it), a bright wall far off
 * on it: near the glass's far end much of each pixel's lobe would leave through the glass's far
 * side, and the reference drops those rays (docs/rough-glass.md#reflection) where keeping them would mix in the dark
 * beyond the horizon.
 */
export const HORIZON_SCENE: Scene = {
  glass: { center: [0, 0, -10], normal: [0, 1, 0], size: [60, 40] },
  objects: [{
    geometry: { kind: 'box', size: 1 },
    transform: { position: [0, 2, -25], rotation: [0, 0, 0], scale: [16, 4, 1], spin: 0 },
    material: { ...defaultMaterial([1, 0.9, 0.4]), texture: { kind: 'none' } },
    bounds: { center: [0, 0, 0], radius: 9 },
  }],
  lights: [DEFAULT_LIGHT],
  background: [0.05, 0.05, 0.1],
};

export const horizonState = (v: RoughView): FrameState => state([0, 0.6, 4], [0, 0.3, -10], v);
