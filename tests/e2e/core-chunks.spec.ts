// Four more parts the core leaves out (docs/package.md#chunks), each fetched when a page first needs it: the
// orthographic projection (frame/orthographic-view.ts), what gathers the children's parts
// (element/children/gather-parts.ts), image textures (element/texture-images.ts) and the
// failure messages (element/failure-messages.ts). The default scene fetches none of them; a
// frame that needs the projection waits for it; each that cannot load gives its stated fallback
// (image textures come only with children, whose chunk imports the decoder: it fails with them).
import type { Page } from '@playwright/test';
import { test, expect, openPage, capture } from './fixtures';
import { mountHtml } from './helpers/scene-children';
import { withoutWebGL2 } from './helpers/no-webgl2';
import { blockChunk, expectFrameHeldFor, expectOneWarning, fetchedChunks as fetched, samePixels as same, wait } from './helpers/chunks';

const ORTHO = 'orthographic-view';
const GATHER = 'gather-parts';
const IMAGES = 'texture-images';
const MESSAGES = 'failure-messages';
const CHECKER = '/tests/e2e/pages/models/checker.png';
const SCENE = (attrs = '', children = '') => `<glass-plane-scene refine="0" time="0" spin="0" ${attrs}>${children}</glass-plane-scene>`;

const settled = async (page: Page) => {
  await wait(page, 300);
  return capture(page);
};

test('the default scene fetches none of the four; each page that needs one fetches it', async ({ page }) => {
  const ALL = [ORTHO, GATHER, IMAGES, MESSAGES];
  await openPage(page);
  await mountHtml(page, SCENE());
  await wait(page, 200);
  expect(await fetched(page, ALL)).toEqual([]);
  await mountHtml(page, SCENE('projection="orthographic"'));
  expect(await fetched(page, ALL)).toEqual([ORTHO]);
  // Image textures come only with children (texture, map_Kd): the children's chunk brings the decoder.
  await mountHtml(page, SCENE('', '<glass-object shape="sphere"></glass-object>'));
  expect(await fetched(page, ALL)).toEqual([ORTHO, GATHER, IMAGES]);
});

test('projection="orthographic" held back 600 ms: no frame until it is in, then the orthographic picture', async ({ page }) => {
  await expectFrameHeldFor(page, ORTHO, 'projection', 'orthographic');
});

test('if the orthographic projection cannot load: one warning, no error, drawn in perspective', async ({ page, consoleLog }) => {
  await openPage(page);
  await mountHtml(page, SCENE());
  const perspective = await settled(page);
  await blockChunk(page, ORTHO);
  await openPage(page);
  const seen = await mountHtml(page, SCENE('projection="orthographic"'));
  expect(seen.filter((e) => e.type === 'error')).toEqual([]);
  expect(same(await settled(page), perspective)).toBe(true);
  expectOneWarning(consoleLog, 'projection="orthographic" could not load');
});

test('if what gathers the children cannot load: one warning, no error, the default scene', async ({ page, consoleLog }) => {
  await openPage(page);
  await mountHtml(page, SCENE());
  const plain = await settled(page);
  await blockChunk(page, GATHER);
  await openPage(page);
  const seen = await mountHtml(page, SCENE('', '<glass-object shape="sphere" position="0 1 0"></glass-object>'));
  expect(seen.filter((e) => e.type === 'error')).toEqual([]);
  expect(same(await settled(page), plain)).toBe(true);
  expectOneWarning(consoleLog, 'the scene is drawn without its children');
});

test('a texture set on a child after the first frames: its image is fetched and drawn', async ({ page }) => {
  const cube = (texture: string) => SCENE('glass-size="0 0" camera-position="0 0 2.5" camera-rotation="-90 0"', `<glass-object shape="cube" ${texture}></glass-object>`);
  await openPage(page);
  await mountHtml(page, cube(`texture="${CHECKER}"`));
  const image = await settled(page);
  await openPage(page);
  await mountHtml(page, cube(''));
  const procedural = await settled(page);
  expect(same(image, procedural), 'the image changes the cube').toBe(false);
  // The same element, its scene value rebuilt without images and then with one.
  await page.evaluate(() => document.querySelector('glass-plane-scene')!.setAttribute('background', '0.1 0.1 0.1'));
  await settled(page);
  await page.evaluate((url) => document.querySelector('glass-object')!.setAttribute('texture', url), CHECKER);
  await expect.poll(async () => same(await capture(page), image), { timeout: 5000 }).toBe(true);
});

test('a failure\'s message comes with its chunk; without it, the error\'s own text', async ({ page, consoleLog }) => {
  await page.addInitScript(withoutWebGL2);
  for (const blocked of [false, true]) {
    if (blocked) await blockChunk(page, MESSAGES);
    await openPage(page);
    const text = await page.evaluate(() => new Promise<{ event: string; shown: string }>((resolve) => {
      const el = document.createElement('glass-plane-scene');
      el.setAttribute('renderer', 'webgl'); // auto would draw with the software renderer
      el.addEventListener('error', (e) => {
        const event = (e as CustomEvent<{ message: string }>).detail.message;
        setTimeout(() => resolve({ event, shown: el.shadowRoot!.querySelector('[part=message]')!.textContent ?? '' }), 300);
      });
      document.body.append(el);
    }));
    if (!blocked) expect(text.shown).toBe('WebGL2 is not available here, so the glass scene cannot be shown.');
    else expect(text.shown).toBe(text.event);
    expect(text.shown).toContain('WebGL2');
    // The parts' one policy: a chunk that cannot load is warned about once.
    if (blocked) expectOneWarning(consoleLog, 'the failure messages could not load');
    consoleLog.take('error'); // the blocked fetch
  }
});
