// docs/colour.md#srgb in the element: `color-space="srgb"` (the default) decodes colour data, mixes light
// linearly and encodes the frame once; `none` uses values as stored. The case worked out in docs/colour.md#the-transfer-curve:
// a white image under Ka 0.2159 and Ia 1 is encode(0.2159) = 128/255 in srgb, 0.2159·255 = 55 in
// none, in both renderers.
import { test, expect, openPage, capture } from './fixtures';
import { mountHtml } from './helpers/scene-children';
import { note } from './helpers/bounds';
import { compareImages, type RgbaImage } from './helpers/golden';
import { drawScene, openRendererPage } from './helpers/scene-json';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from '../unit/helpers/frame-state';
import type { Scene } from '../../src/scene/scene';

const WHITE = '/tests/e2e/pages/models/white.png';
const GREY_128 = '/tests/e2e/pages/models/grey128.png';

/**
 * A cube filling the middle of the frame, lit by ambient light only (`space`: the color-space
 * attribute, or none): colour = tex · Ka.
 */
const AMBIENT_CUBE = (renderer: string, space: string | null, texture = WHITE, ka = 0.2159) => `<glass-plane-scene refine="0" renderer="${renderer}"
  ${space === null ? '' : `color-space="${space}"`} time="0" spin="0" glass-size="0 0" background="0 0 0" samples="0"
  camera-position="0 0 2.5" camera-rotation="-90 0"><glass-object shape="cube" texture="${texture}" ambient="${ka} ${ka} ${ka}"
  diffuse="0 0 0" specular="0 0 0"></glass-object><glass-light ambient="1 1 1" diffuse="0 0 0" specular="0 0 0"></glass-light></glass-plane-scene>`;

/** The element's image once its texture image has been decoded and drawn. */
async function settled(page: import('@playwright/test').Page): Promise<RgbaImage> {
  await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(null)))));
  return capture(page);
}

const centre = (img: RgbaImage) => {
  const i = 4 * (Math.floor(img.height / 2) * img.width + Math.floor(img.width / 2));
  return [img.data[i], img.data[i + 1], img.data[i + 2]];
};

for (const renderer of ['webgl', 'software']) {
  test.describe(`${renderer} renderer`, () => {
    for (const [space, expected] of [[null, 128], ['srgb', 128], ['none', 55]] as const) {
      test(`white image × Ka 0.2159 × Ia 1 is ${expected} with color-space ${space ?? '(default)'}`, async ({ page }) => {
        await openPage(page);
        await mountHtml(page, AMBIENT_CUBE(renderer, space));
        for (const c of centre(await settled(page))) {
          expect(Math.abs(c - expected), `channel ${c}, expected ${expected} ± 1`).toBeLessThanOrEqual(1);
        }
      });
    }

    // An image is colour data: level 128 is 0.2158605 of light, halved by Ka 0.5 and encoded:
    // 92. Used as stored: 64. (Not decoded, srgb would show encode(0.5·128/255) = 188.)
    for (const [space, expected] of [['srgb', 92], ['none', 64]] as const) {
      test(`an image's level 128 under Ka 0.5 is ${expected} with color-space ${space}`, async ({ page }) => {
        await openPage(page);
        await mountHtml(page, AMBIENT_CUBE(renderer, space, GREY_128, 0.5));
        for (const c of centre(await settled(page))) expect(Math.abs(c - expected), `channel ${c}`).toBeLessThanOrEqual(1);
      });
    }

    // The reflection holds linear light without banding too: a white box lit to 0.0015 behind the
    // camera, seen in clear glass (T 1, ior 10: F = 81/121 at normal incidence) over black:
    // encode(0.6694·0.0015) = 0.01297 → 3. An 8-bit linear reflection would hold 0.0015 as 0.
    test('a dark reflection keeps its level: 3 where an 8-bit linear reflection would give 0', async ({ page }) => {
      await openPage(page);
      await mountHtml(page, `<glass-plane-scene refine="0" renderer="${renderer}" time="0" spin="0" samples="0" background="0 0 0"
        glass-center="0 0 0" glass-normal="0 0 1" glass-size="8 8" ior="10" transparency="1" camera-position="0 0 5"
        camera-rotation="-90 0"><glass-object shape="cube" position="0 0 7" scale="4" texture="${WHITE}" ambient="0.0015 0.0015 0.0015"
        diffuse="0 0 0" specular="0 0 0"></glass-object><glass-light ambient="1 1 1" diffuse="0 0 0" specular="0 0 0"></glass-light>
        </glass-plane-scene>`);
      for (const c of centre(await settled(page))) expect(Math.abs(c - 3), `channel ${c}`).toBeLessThanOrEqual(1);
    });

    // No banding in the darks: light of 0.0015 encodes to 5 (0.0194); a frame held as 8-bit
    // linear levels would round it to 0 before the encode.
    test('a light level of 0.0015 shows as 5 in srgb (an 8-bit linear frame would hold 0)', async ({ page }) => {
      await openPage(page);
      await mountHtml(page, AMBIENT_CUBE(renderer, 'srgb', WHITE, 0.0015));
      for (const c of centre(await settled(page))) expect(Math.abs(c - 5), `channel ${c}`).toBeLessThanOrEqual(1);
    });
  });
}

test.describe('WebGL renderer', () => {
  const W = 64, H = 48;
  const state = (colorSpace: 'srgb' | 'none'): FrameState =>
    defaultFrameState({ width: W, height: H, spin: 0, cameraPosition: [0, 0, 2.5], yaw: -90, pitch: 0, colorSpace });
  // A 2×2 checker of 0 and 200 (not 255: decoding 255 gives 255 back), the box's face filling the view.
  const CHECKER = { checker: { width: 2, height: 2, rgba: [0, 0, 0, 255, 200, 200, 200, 255, 200, 200, 200, 255, 0, 0, 0, 255] } };
  const scene: Scene = {
    glass: null, background: [0.1, 0.1, 0.1], lights: [{ kind: 'directional', vector: [0, 0, 1], ambient: [1, 1, 1], diffuse: [0, 0, 0], specular: [0, 0, 0] }],
    objects: [{
      geometry: { kind: 'box', size: 1 }, transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
      material: { ambient: [1, 1, 1], diffuse: [0, 0, 0], specular: [0, 0, 0], shininess: 32, opacity: 1, texture: { kind: 'image', url: 'checker' }, mapping: 'uv' },
      bounds: { center: [0, 0, 0], radius: Math.sqrt(3) / 2 },
    }],
  };

  test('switching color-space re-reads its images in the new space: each frame is the one a fresh renderer draws', async ({ page }) => {
    await openRendererPage(page);
    const srgb = await drawScene(page, state('srgb'), scene, CHECKER);
    const none = await drawScene(page, state('none'), scene);
    const srgbAgain = await drawScene(page, state('srgb'), scene);
    await openRendererPage(page);
    const freshNone = await drawScene(page, state('none'), scene, CHECKER);
    expect(compareImages(srgb, srgbAgain).differing).toBe(0);
    expect(compareImages(none, freshNone).differing).toBe(0);
    // The image is drawn in both (not the procedural texture, not black): its texels of 200,
    // magnified and filtered, reach 195 (srgb) and 188 (none), measured.
    const max = (img: RgbaImage) => Math.max(...img.data.filter((_, i) => i % 4 === 0));
    note(`brightest red: srgb ${max(srgb)}, none ${max(none)}`);
    expect(max(none)).toBeGreaterThanOrEqual(185);
    expect(max(srgb)).toBeGreaterThanOrEqual(185);
  });
});
