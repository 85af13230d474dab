// An environment's light on glTF materials in the GLSL (docs/pbr.md#the-environment): the mirror metal whose reflection meets
// the key panel, worked out by hand in tests/unit/environment-light.test.ts, drawn by WebGL to the 8-bit level; the grid of
// spheres in the studio against the reference, every region within 2 dB of the figure measured here; the chunk fetched only
// for a glTF material under an environment; its textures freed with the renderer.
import { test, expect } from './fixtures';
import { drawScene, openRendererPage } from './helpers/scene-json';
import { expectPsnr, note } from './helpers/bounds';
import { renderScene, compareImages } from '../../src/reference';
import { defaultFrameState } from '../unit/helpers/frame-state';
import { BOX_STATE, STUDIO, mirrorToKey, pbrMaterial, studioGrid } from '../unit/helpers/pbr-scenes';

test.beforeEach(async ({ page }) => {
  await openRendererPage(page);
});

const CENTRE = 4 * (16 * 33 + 16);

test('WebGL: a mirror metal reflecting the key panel, as worked by hand (6·F(n·v) = 0.60023); twice the intensity, twice the light', async ({ page }) => {
  const want = 6 * (0.1 + 0.9 * (1 - 1.5 / Math.sqrt(3)) ** 5) * 255;
  const image = await drawScene(page, BOX_STATE, mirrorToKey());
  const got = [...image.data.subarray(CENTRE, CENTRE + 3)];
  // The 8-bit target rounds; a GPU may land one level either side of the exact value.
  got.forEach((g, k) => expect(Math.abs(g - want), `channel ${k}: ${got} against ${want}`).toBeLessThanOrEqual(1));
  const dim = mirrorToKey(pbrMaterial({ baseColor: [0.05, 0.05, 0.05, 1], metallic: 1, roughness: 0 }), { ...STUDIO, intensity: 2 });
  const twice = (await drawScene(page, BOX_STATE, dim)).data[CENTRE];
  expect(Math.abs(twice - want), `intensity 2 on half the base: ${twice} against ${want}`).toBeLessThanOrEqual(1);
  const none = (await drawScene(page, BOX_STATE, mirrorToKey(undefined, null))).data[CENTRE];
  expect(none).toBe(0);
});

test('WebGL: the grid of spheres in the studio, tone mapped, against the reference, within 2 dB of its measured PSNR', async ({ page }) => {
  const scene = studioGrid();
  const state = defaultFrameState({ width: 320, height: 180, cameraPosition: [0, 1.5, 3.3], yaw: -90, pitch: -8, time: 0, spin: 0, samples: 4, toneMapping: 'neutral' });
  const image = await drawScene(page, state, scene);
  const cmp = compareImages(renderScene(scene, state, null, { samplesPerAxis: 4, environmentSamples: 1024 }), image.data);
  const p = cmp.psnr;
  note(`PBR sphere grid in the studio, WebGL against the reference: all ${p.all.toFixed(1)}, objects ${p.objects.toFixed(1)}, glass ${p.glass.toFixed(1)}, edges ${p.edges.toFixed(1)}, dark ${p.dark.toFixed(1)} dB`);
  // Measured here: all 26.8, objects 35.9, glass 50.8, edges 19.5 dB. MSAA shades once per pixel, the reference 16 times: the
  // mirror-like spheres' reflections of the panels' edges, and their rims, where the split sum errs most (docs/pbr.md#the-split-sum).
  expectPsnr(cmp, { all: 26.8, objects: 35.9, glass: 50.8, edges: 19.5 }, 'PBR sphere grid in the studio');
});
