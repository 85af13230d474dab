// Emitted light and a missing image's fallback in the GLSL (docs/gltf.md#drawing, #images): the same box as tests/unit/emissive.test.ts, lit
// from the camera, drawn by the WebGL renderer: its face is Kd·(Ia + Id) + E to the 8-bit level,
// as the reference and the software renderer draw it; without emissive, Kd·(Ia + Id) alone.
import { test, expect } from './fixtures';
import { drawScene, openRendererPage } from './helpers/scene-json';
import type { Material, Scene, Vec3 } from '../../src/scene/scene';
import { defaultFrameState } from '../unit/helpers/frame-state';

const KD: Vec3 = [0.2, 0.3, 0.4];
const E: Vec3 = [0.5, 0.1, 0.05];
const LIT = [0.2 * 0.6, 0.3 * 0.6, 0.4 * 0.6];

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

test('WebGL: a material\'s emissive adds to its lit colour', async ({ page }) => {
  await openRendererPage(page);
  const state = defaultFrameState({ width: 33, height: 33, cameraPosition: [0, 0, 4], yaw: -90, pitch: 0, colorSpace: 'none', time: 0, spin: 0, samples: 0 });
  for (const [emissive, want] of [[undefined, LIT], [E, LIT.map((c, k) => c + E[k])]] as const) {
    const image = await drawScene(page, state, scene(emissive));
    const at = 4 * (16 * 33 + 16);
    const got = [...image.data.subarray(at, at + 3)];
    // The 8-bit target rounds; a GPU may land one level either side of the exact value.
    got.forEach((g, k) => expect(Math.abs(g - want[k] * 255), `channel ${k}: ${got} against ${want.map((c) => c * 255)}`).toBeLessThanOrEqual(1));
  }
});

// A missing image (docs/gltf.md#images): with `fallback: 'none'` WebGL draws the object plain, as
// `kind: 'none'`; without it, with the procedural checker. The same rule as the CPU renderers'
// (tests/unit/texture-fallback.test.ts).
test('WebGL: a missing image with fallback none draws plain, without it the checker', async ({ page }) => {
  await openRendererPage(page);
  const state = defaultFrameState({ width: 33, height: 33, cameraPosition: [0, 0, 4], yaw: -90, pitch: 0, colorSpace: 'none', time: 0, spin: 0, samples: 0 });
  const withTexture = (texture: Material['texture']): Scene => {
    const s = scene();
    return { ...s, objects: s.objects.map((o) => ({ ...o, material: { ...o.material, texture } })) };
  };
  const draw = async (texture: Material['texture']) => [...(await drawScene(page, state, withTexture(texture))).data];
  const plain = await draw({ kind: 'none' }), checker = await draw({ kind: 'procedural' });
  expect(plain).not.toEqual(checker);
  expect(await draw({ kind: 'image', url: 'gone.png', fallback: 'none' })).toEqual(plain);
  expect(await draw({ kind: 'image', url: 'gone.png' })).toEqual(checker);
});
