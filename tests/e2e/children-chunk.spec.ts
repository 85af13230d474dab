// <glass-object> and <glass-light> are a chunk of their own (element/children/child-elements.ts):
// a scene without children never fetches it; the first scene that finds one loads it, and holds
// its frames until it is in — the first frame shows the children, never the default scene in
// their place; a chunk that cannot load leaves the default scene with one warning.
import { test, expect, openPage, capture } from './fixtures';
import { mountFirstFrame, mountHtml } from './helpers/scene-children';
import type { RgbaImage } from './helpers/golden';
import { samePixels as same } from './helpers/chunks';

const SCENE = `<glass-plane-scene refine="0" time="0" spin="0" style="width:160px;height:90px" pixel-ratio="1">
  <glass-object shape="sphere" position="0 1 0" diffuse="0.9 0.2 0.2" ambient="0.9 0.2 0.2"></glass-object>
  <glass-light position="2 4 3"></glass-light>
</glass-plane-scene>`;

/** Pixels of the red sphere: clearly more red than green and blue. */
function redPixels(img: RgbaImage): number {
  let red = 0;
  for (let i = 0; i < img.data.length; i += 4) if (img.data[i] - img.data[i + 1] > 60 && img.data[i] - img.data[i + 2] > 60) red++;
  return red;
}
const fetched = (page: import('@playwright/test').Page) =>
  page.evaluate(() => performance.getEntriesByType('resource').some((e) => e.name.includes('child-elements')));

test('a scene without children never fetches their chunk', async ({ page }) => {
  await openPage(page);
  await mountHtml(page, '<glass-plane-scene refine="0" time="0" style="width:160px;height:90px"></glass-plane-scene>');
  expect(await fetched(page)).toBe(false);
  expect(await page.evaluate(() => customElements.get('glass-object'))).toBeUndefined();
});

test('the first frame of a scene with children shows them, however slow their chunk (held back 600 ms)', async ({ page }) => {
  await page.route('**/child-elements*', async (route) => {
    await new Promise((r) => setTimeout(r, 600));
    await route.continue();
  });
  await openPage(page);
  const first = await mountFirstFrame(page, SCENE);
  expect(await fetched(page)).toBe(true);
  await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
  const settled = await capture(page);
  expect(same(first, settled), 'the first frame is the settled one').toBe(true);
  // The red sphere is there: measured 73 such pixels; the default scene drawn in its place has 0.
  expect(redPixels(first), 'red sphere pixels in the first frame (measured 73)').toBeGreaterThan(50);
});

test('children defined already: the first frame waits for what gathers their parts (held back 600 ms)', async ({ page }) => {
  await page.route('**/gather-parts*', async (route) => {
    await new Promise((r) => setTimeout(r, 600));
    await route.continue();
  });
  await openPage(page);
  await page.evaluate(async () => {
    const mod = await import('/src/index.ts' as string) as { defineChildren(): Promise<void> };
    await mod.defineChildren();
  });
  const first = await mountFirstFrame(page, SCENE);
  expect(redPixels(first), 'red sphere pixels in the first frame (measured 73)').toBeGreaterThan(50);
});

test('defineChildren() defines both elements, for pages that want their classes', async ({ page }) => {
  await openPage(page);
  const names = await page.evaluate(async () => {
    const mod = await import('/src/index.ts' as string) as { defineChildren(): Promise<void> };
    await mod.defineChildren();
    return [customElements.get('glass-object')?.name, customElements.get('glass-light')?.name];
  });
  expect(names).toEqual(['GlassObject', 'GlassLight']);
});

test('if the children\'s chunk cannot load, the scene is drawn without them, with one warning and no error', async ({ page, consoleLog }) => {
  await page.route('**/child-elements*', (route) => route.abort());
  await openPage(page);
  const seen = await mountHtml(page, SCENE);
  expect(seen.filter((e) => e.type === 'error')).toEqual([]);
  const img = await capture(page);
  expect(img.data.some((v, i) => i % 4 !== 3 && v > 40), 'something is drawn').toBe(true);
  expect(consoleLog.take('warning').filter((w) => w.includes('could not load'))).toHaveLength(1);
  consoleLog.take('error'); // the browser's own report of the failed fetch
});
