// Image textures in the element (`texture` in docs/scene-model.md#glass-object, MTL map_Kd): decoded once per URL, drawn when
// ready; a missing image warns once and the object keeps the procedural texture.
import { test, expect, openPage, capture } from './fixtures';
import { note } from './helpers/bounds';
import { mountHtml } from './helpers/scene-children';
import { compareImages } from './helpers/golden';

const CUBE = (texture: string) => `<glass-plane-scene refine="0" time="0" spin="0" glass-size="0 0" camera-position="0 0 2.5" camera-rotation="-90 0"
  style="width: 160px; height: 90px"><glass-object shape="cube" ${texture}></glass-object></glass-plane-scene>`;

/** Frames until `done()` holds in the page (images decode asynchronously). */
async function settle(page: import('@playwright/test').Page): Promise<void> {
  await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(null)))));
}

test('a texture image replaces the procedural texture once decoded', async ({ page }) => {
  await openPage(page);
  await mountHtml(page, CUBE(''));
  const procedural = await capture(page);
  await page.evaluate(() => document.querySelector('glass-plane-scene')!.remove());
  await mountHtml(page, CUBE('texture="/tests/e2e/pages/models/checker.png"'));
  await settle(page);
  const image = await capture(page);
  // The cube fills the middle of the frame: most of it changes with the texture.
  note(`image texture vs procedural: ${compareImages(procedural, image).differing} px differ`);
  // Measured 1,226 px; 10 % under it at most (edge pixels).
  expect(compareImages(procedural, image).differing, 'pixels changed by the image texture').toBeGreaterThanOrEqual(0.9 * 1226);
});

test('a missing texture image warns once and keeps the procedural texture', async ({ page, consoleLog }) => {
  await openPage(page);
  await mountHtml(page, CUBE(''));
  const procedural = await capture(page);
  await page.evaluate(() => document.querySelector('glass-plane-scene')!.remove());
  await mountHtml(page, CUBE('texture="/tests/e2e/pages/models/no-such-image.png"'));
  await settle(page);
  expect(compareImages(procedural, await capture(page)).differing).toBe(0);
  const warnings = consoleLog.take('warning');
  expect(warnings.filter((w) => w.includes('no-such-image.png'))).toHaveLength(1);
  consoleLog.take('error'); // the browser's own 404 line for the fetch
});
