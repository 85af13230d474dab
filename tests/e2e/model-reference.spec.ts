// The accuracy bar (docs/knobs.md#bars-the-tests-hold) through the element: a model loaded by <glass-object> (OBJ + MTL with
// map_Kd, a concave hexagon, negative indices) over the default glass, drawn by the element and
// by the float64 reference from the element's own scene value, ≥ 35 dB PSNR.
import { test, expect, openPage, capture } from './fixtures';
import { mountHtml } from './helpers/scene-children';
import { renderScene, compareImages } from '../../src/reference';
import { elementScene } from './helpers/element-scene';
import { expectPsnr, note } from './helpers/bounds';

const BOUND_DB = 35;
/**
 * PSNR measured here (dB) per renderer, in linear light (the default color-space); the bounds sit
 * 2 dB under each (helpers/bounds.ts). As stored, WebGL measured 48.3 / 52.9 / 50.7; in linear
 * light with isotropic texture reads 40.7 / 49.8 / 42.2 (encoding steepens the dark glass body's
 * filtering errors), with the anisotropic reads it now makes 42.5 / 48.9 / 52.8.
 */
const MEASURED = {
  'webgl srgb': { all: 42.5, objects: 48.9, glass: 52.8 },
  // Multisampled (samples 4) as WebGL is. With one sample per pixel its aliased silhouettes,
  // steepened by the encode over the dark background, held the image to 36.3 dB (42.4 as stored).
  'software srgb': { all: 40.6, objects: 50.2, glass: 54.0 },
  'software none': { all: 46.5, objects: 53.5, glass: 51.1 },
} as const;

const CASES = [['webgl', 'srgb'], ['software', 'srgb'], ['software', 'none']] as const;
for (const [renderer, space] of CASES) test(`${renderer}, color-space ${space}: a textured OBJ with MTL, a concave n-gon and negative indices matches the reference`, async ({ page }) => {
  await openPage(page);
  // The image arrives late (a slow server): `load`, hence `ready`, must still wait for it.
  await page.route('**/models/checker.png', async (route) => {
    await new Promise((r) => setTimeout(r, 600));
    await route.continue();
  });
  await mountHtml(page, `<glass-plane-scene refine="0" renderer="${renderer}" color-space="${space}" time="0" spin="0" samples="4" camera-position="1.8 1.6 4.5" camera-rotation="-100 -12">
    <glass-object src="/tests/e2e/pages/models/ngon-textured.obj" position="-1.5 0 1"></glass-object>
    <glass-light direction="0.3 0.8 1"></glass-light>
  </glass-plane-scene>`);
  // `ready` waits for the model's load, which waits for its map_Kd image: one frame later the
  // image is on screen (no timeout; without the wait the frame shows the procedural checker).
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(null)))));
  if (renderer === 'software') {
    // The software renderer decodes the image to pixels on its own side, then draws again.
    await page.waitForTimeout(300);
    await page.evaluate(() => new Promise((r) => {
      const el = document.querySelector('glass-plane-scene') as unknown as HTMLElement & { requestRender(): void };
      el.addEventListener('frame', r, { once: true });
      el.requestRender();
    }));
  }
  const image = await capture(page);

  // The element's scene value and camera; its images (the map_Kd PNG) read back from the page.
  const { scene, state, images } = await elementScene(page, image.width, image.height, { colorSpace: space });
  const objects = scene.objects;
  expect(objects.length, 'one scene object per material').toBe(2);
  const textured = objects.find((o) => o.material.texture.kind === 'image');
  expect(textured?.material.texture, 'map_Kd resolved against the MTL').toMatchObject({ kind: 'image' });
  const ref = renderScene(scene, state, images, { samplesPerAxis: 4 });
  const cmp = compareImages(ref, image.data);
  const line = `${renderer} ${space}: textured OBJ + MTL, n-gon, negative indices: PSNR ${cmp.psnr.all.toFixed(1)} dB (objects ${cmp.psnr.objects.toFixed(1)}, glass ${cmp.psnr.glass.toFixed(1)}), max error ${cmp.maxError.toFixed(0)}`;
  note(line);
  expect(cmp.pixels.objects, 'the model covers part of the frame').toBeGreaterThan(300);
  // The bars of docs/knobs.md#bars-the-tests-hold: 35 dB for WebGL, 40 dB for both renderers, in either colour space.
  expect(cmp.psnr.all, line).toBeGreaterThanOrEqual(Math.max(BOUND_DB, 40));
  expectPsnr(cmp, MEASURED[`${renderer} ${space}` as keyof typeof MEASURED], `${renderer} ${space}`);
});
