// A glTF material's metallic-roughness, occlusion and emissive maps in the GLSL (docs/gltf.md#drawing): the cases of
// tests/unit/helpers/pbr-map-cases.ts (the box head-on, each map a 1×1 image, the centre pixel worked out by hand), drawn by
// the WebGL renderer to within one 8-bit level; the emissive map decoded as colour in srgb; occlusion dims the environment.
import { test, expect } from './fixtures';
import { drawScene, openRendererPage, type Images } from './helpers/scene-json';
import { BOX_STATE, STUDIO, mirrorToKey } from '../unit/helpers/pbr-scenes';
import { AO, COLOURED, EM, IMAGES, MAP_CASES, NORMAL_CASES, QUADRANTS, QUADRANTS_MOVED, TILTED_NORMAL_MAP, box, map } from '../unit/helpers/pbr-map-cases';
import { compareImages, renderScene } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import { note } from './helpers/bounds';
import { linearToSrgb, srgbToLinear } from '../../src/math/srgb';
import type { DecodedImage } from '../../src/scene/decoded-image';
import type { Scene } from '../../src/scene/scene';

const CENTRE = 4 * (16 * 33 + 16);

const asImages = (images: Map<string, DecodedImage>): Images =>
  Object.fromEntries([...images].map(([url, im]) => [url, { width: im.width, height: im.height, rgba: [...im.data] }]));

test.beforeEach(async ({ page }) => {
  await openRendererPage(page);
});

test('WebGL: each map on the box as worked by hand, to one 8-bit level', async ({ page }) => {
  for (const c of MAP_CASES) {
    const image = await drawScene(page, BOX_STATE, c.scene, asImages(c.images));
    const got = [...image.data.subarray(CENTRE, CENTRE + 3)];
    // The 8-bit target rounds; a GPU may land one level either side of the exact value.
    c.want.forEach((w, k) => expect(Math.abs(got[k] - Math.min(w, 1) * 255), `${c.name}, channel ${k}: ${got} against ${c.want.map((x) => x * 255)}`).toBeLessThanOrEqual(1));
  }
});

test('WebGL: the emissive map is colour, decoded to linear light in srgb (128 → 0.2158)', async ({ page }) => {
  const scene = box({ baseColor: [0, 0, 0, 1], metallic: 0, roughness: 1, emissiveTexture: map(EM) }, [0.5, 0.5, 0.5]);
  const image = await drawScene(page, { ...BOX_STATE, colorSpace: 'srgb' }, scene, asImages(IMAGES));
  const got = [...image.data.subarray(CENTRE, CENTRE + 3)];
  const want = [1, srgbToLinear(128 / 255), 0].map((t) => linearToSrgb(0.5 * t + 0.2 * 0.04 / 4) * 255);
  want.forEach((w, k) => expect(Math.abs(got[k] - w), `channel ${k}: ${got} against ${want}`).toBeLessThanOrEqual(1));
});

test('WebGL: occlusion dims the environment: the mirror metal reflecting the key panel, 6·F(n·v) = 0.60023 times 64/255', async ({ page }) => {
  const plain = mirrorToKey(undefined, STUDIO);
  const o = plain.objects[0];
  const dimmed: Scene = { ...plain, objects: [{ ...o, material: { ...o.material, pbr: { ...o.material.pbr!, occlusionTexture: map(AO) } } }] };
  const image = await drawScene(page, BOX_STATE, dimmed, asImages(IMAGES));
  const want = 6 * (0.1 + 0.9 * (1 - 1.5 / Math.sqrt(3)) ** 5) * (64 / 255) * 255;
  const got = [...image.data.subarray(CENTRE, CENTRE + 3)];
  got.forEach((g, k) => expect(Math.abs(g - want), `channel ${k}: ${got} against ${want}`).toBeLessThanOrEqual(1));
});

test('WebGL: 2×2 maps over the face read the same way up as the software renderer\'s (within 2 dB of the agreement measured)', async ({ page }) => {
  const state = { ...BOX_STATE, width: 65, height: 65, samples: 0 };
  const image = await drawScene(page, state, QUADRANTS.scene, asImages(QUADRANTS.images));
  const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(QUADRANTS.scene, state, QUADRANTS.images);
  // The reference's regions only (which pixel is the face's), the software renderer's bytes what is compared with.
  const regions = renderScene(QUADRANTS.scene, state, null, { samplesPerAxis: 1 });
  const p = compareImages({ ...regions, rgba: new Uint8ClampedArray(soft) }, image.data, { against: 'rgba8' }).psnr;
  note(`2×2 maps, WebGL against the software renderer: objects ${p.objects.toFixed(1)} dB`);
  // Measured here: 54.2 dB (the half floats and rasterisation of a 65×65 frame).
  expect(p.objects).toBeGreaterThan(52.2);
});

test('WebGL: 2×2 maps and a base colour texture under one KHR_texture_transform, as the software renderer reads them (within 2 dB of the agreement measured)', async ({ page }) => {
  const state = { ...BOX_STATE, width: 65, height: 65, samples: 0 };
  const image = await drawScene(page, state, QUADRANTS_MOVED.scene, asImages(QUADRANTS_MOVED.images));
  const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(QUADRANTS_MOVED.scene, state, QUADRANTS_MOVED.images);
  const regions = renderScene(QUADRANTS_MOVED.scene, state, null, { samplesPerAxis: 1 });
  const p = compareImages({ ...regions, rgba: new Uint8ClampedArray(soft) }, image.data, { against: 'rgba8' }).psnr;
  note(`2×2 maps transformed, WebGL against the software renderer: objects ${p.objects.toFixed(1)} dB`);
  // Measured here: 57.3 dB.
  expect(p.objects).toBeGreaterThan(55.3);
});

test('WebGL: the normal map on a quad with tangents, as worked by hand, to one 8-bit level', async ({ page }) => {
  for (const c of NORMAL_CASES) {
    const got = [...(await drawScene(page, BOX_STATE, c.scene, asImages(c.images))).data.subarray(CENTRE, CENTRE + 3)];
    c.want.forEach((w, k) => expect(Math.abs(got[k] - Math.min(w, 1) * 255), `${c.name}, channel ${k}: ${got} against ${c.want.map((x) => x * 255)}`).toBeLessThanOrEqual(1));
  }
});

test('WebGL: vertex colours multiply the base colour, interpolated: half red, half blue on the quad\'s diagonal (by hand)', async ({ page }) => {
  const got = [...(await drawScene(page, BOX_STATE, COLOURED.scene)).data.subarray(CENTRE, CENTRE + 3)];
  COLOURED.want.forEach((w, k) => expect(Math.abs(got[k] - w * 255), `channel ${k}: ${got} against ${COLOURED.want.map((x) => x * 255)}`).toBeLessThanOrEqual(1));
});

test('WebGL: the normal map in no special pose, as the software renderer turns it (within 2 dB of the agreement measured)', async ({ page }) => {
  const state = { ...BOX_STATE, width: 65, height: 65, samples: 0 };
  const c = TILTED_NORMAL_MAP;
  const image = await drawScene(page, state, c.scene, asImages(c.images));
  const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(c.scene, state, c.images);
  const regions = renderScene(c.scene, state, null, { samplesPerAxis: 1 });
  const p = compareImages({ ...regions, rgba: new Uint8ClampedArray(soft) }, image.data, { against: 'rgba8' }).psnr;
  note(`tilted normal map, WebGL against the software renderer: objects ${p.objects.toFixed(1)} dB`);
  // Measured here: 69.2 dB.
  expect(p.objects).toBeGreaterThan(67.2);
});
