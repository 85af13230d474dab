// SPEC §13 in the element: `color-space="srgb"` (the default) decodes colour data, mixes light
// linearly and encodes the frame once; `none` uses values as stored. Issue 20's Done-when case:
// a white image under Ka 0.2159 and Ia 1 is encode(0.2159) = 128/255 in srgb, 0.2159·255 = 55 in
// none, in both renderers.
import { test, expect, openPage, capture } from './fixtures';
import { mountHtml } from './helpers/scene-children';
import type { RgbaImage } from './helpers/golden';

const WHITE = '/tests/e2e/pages/models/white.png';

/** A cube filling the middle of the frame, lit by ambient light only (`space`: the color-space attribute, or none). */
const AMBIENT_CUBE = (renderer: string, space: string | null, texture = `texture="${WHITE}"`) => `<glass-plane-scene renderer="${renderer}"
  ${space === null ? '' : `color-space="${space}"`} time="0" spin="0" glass-size="0 0" background="0 0 0" samples="0"
  camera-position="0 0 2.5" camera-rotation="-90 0"><glass-object shape="cube" ${texture} ambient="0.2159 0.2159 0.2159"
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

for (const renderer of ['webgl']) {
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
  });
}
