// The PBR bench's scenes and view (bench/pbr.spec.ts): the grid of glTF spheres over a glass floor of the tests
// (tests/unit/helpers/pbr-scenes.ts) in the studio with its two lights, and two halves of it that check the three.js peer's
// conversion of our lighting: the lights alone, the studio alone.
import type { FrameState } from '../src/frame/types';
import type { Scene } from '../src/scene/scene';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import { sphereGrid, studioGrid, STUDIO } from '../tests/unit/helpers/pbr-scenes';

export type PbrSceneName = 'grid' | 'lights' | 'studio';

export function pbrScene(name: PbrSceneName): Scene {
  if (name === 'grid') return studioGrid();
  if (name === 'lights') return sphereGrid();
  return { ...sphereGrid(), lights: [], environment: STUDIO };
}

/** The tests' view of the grid (tests/e2e/environment.spec.ts), tone mapped (neutral), at `width` × `height`. */
export function pbrState(width: number, height: number, extra: Partial<FrameState> = {}): FrameState {
  return defaultFrameState({
    width, height, cameraPosition: [0, 1.5, 3.3], yaw: -90, pitch: -8, time: 0, spin: 0, samples: 4, toneMapping: 'neutral', ...extra,
  });
}
