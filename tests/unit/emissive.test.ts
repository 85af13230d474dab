// Emitted light (docs/gltf.md#drawing): a material's emissive adds to its lit colour, in the float64
// reference (by hand) and in the software renderer (against the same numbers); the default scene,
// whose materials give off nothing, is untouched (small-frames.test.ts holds it to the bit).
import { describe, expect, it } from 'vitest';
import { renderScene } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import type { Material, Scene, Vec3 } from '../../src/scene/scene';
import { defaultFrameState } from './helpers/frame-state';

const KD: Vec3 = [0.2, 0.3, 0.4];
const E: Vec3 = [0.5, 0.1, 0.05];

/** A unit box at the origin, its +Z face head-on to the camera, lit from the camera (Ia 0.1, Id 0.5, no specular). */
function scene(emissive?: Vec3): Scene {
  const material: Material = {
    ambient: KD, diffuse: KD, specular: [0, 0, 0], shininess: 1, opacity: 1, texture: { kind: 'none' }, mapping: 'uv',
    ...(emissive ? { emissive } : {}),
  };
  return {
    glass: null, background: [0, 0, 0],
    objects: [{ geometry: { kind: 'box', size: 1 }, transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 }, material, bounds: { center: [0, 0, 0], radius: 0.9 } }],
    lights: [{ kind: 'directional', vector: [0, 0, 1], ambient: [0.1, 0.1, 0.1], diffuse: [0.5, 0.5, 0.5], specular: [0, 0, 0] }],
  };
}

const STATE = defaultFrameState({ width: 33, height: 33, cameraPosition: [0, 0, 4], yaw: -90, pitch: 0, colorSpace: 'none', time: 0, spin: 0 });
const centre = 3 * (16 * 33 + 16);
/** Kd·(Ia + Id·N·L) with N·L = 1, plus E: written out, not computed by the code under test. */
const LIT = [0.2 * 0.6, 0.3 * 0.6, 0.4 * 0.6];

describe('emissive', () => {
  it('the reference adds it to the lit colour, and a material without it is lit alone', () => {
    const plain = renderScene(scene(), STATE, null, { samplesPerAxis: 1 }).rgb;
    const glowing = renderScene(scene(E), STATE, null, { samplesPerAxis: 1 }).rgb;
    [0, 1, 2].forEach((k) => {
      expect(plain[centre + k]).toBeCloseTo(LIT[k], 12);
      expect(glowing[centre + k]).toBeCloseTo(LIT[k] + E[k], 12);
    });
  });

  it('the software renderer adds the same, to the 8-bit level', () => {
    for (const [emissive, want] of [[undefined, LIT], [E, LIT.map((c, k) => c + E[k])]] as const) {
      const rgba = new SoftwareRenderer({ samplesPerAxis: 1 }).render(scene(emissive), { ...STATE, samples: 0 });
      const at = 4 * (16 * 33 + 16);
      expect([...rgba.subarray(at, at + 3)]).toEqual(want.map((c) => Math.round(c * 255)));
    }
  });
});
