// Two more parts the core leaves out (docs/package.md#chunks), each a chunk fetched when a scene first asks:
// the group rotation (scene/group-rotation.ts: what applies a turn to `scene` and finds the
// centre it turns about), wanted once `objectRotation` turns the objects or the trackball is in
// use; and the debug views (render/debug-views.ts) of debug-view reflection, fresnel and passes.
// A page that asks for neither fetches neither; a frame that needs one waits for it; a chunk
// that cannot load gives one warning, no `error`, and the stated fallback.
import type { Page } from '@playwright/test';
import { test, expect, openPage, capture, type RgbaImage } from './fixtures';
import { mountHtml } from './helpers/scene-children';
import { blockChunk, countFrames, expectFrameHeldFor, expectOneWarning, fetchedChunks, framesSeen, holdBack, samePixels as same, wait } from './helpers/chunks';

const TURN = 'group-rotation';
const VIEWS = 'debug-views';
/** A quarter turn about y: the box and the sphere change places on screen. */
const QUARTER: [number, number, number, number] = [0, Math.SQRT1_2, 0, Math.SQRT1_2];
const SCENE = (attrs = '') => `<glass-plane-scene refine="0" time="0" spin="0" ${attrs}></glass-plane-scene>`;

interface Turnable extends HTMLElement {
  objectRotation: number[];
  readonly scene: { objects: { transform: { position: number[]; rotation: number[] } }[] };
}

/** Sets objectRotation and reads `scene`'s first object in the same task. */
const turnNow = (page: Page, q: number[]) => page.evaluate((q) => {
  const el = document.querySelector('glass-plane-scene') as unknown as Turnable;
  el.objectRotation = q;
  return el.scene.objects[0].transform;
}, q);
const firstObject = (page: Page) => page.evaluate(() => (document.querySelector('glass-plane-scene') as unknown as Turnable).scene.objects[0].transform);

/**
 * The default scene turned a quarter, settled, with nothing held back: the picture and the first
 * object. With controls="trackball" (which changes no pixel): the group rotation is in before
 * the scene value is first built, so the turn's centre is found with it.
 */
async function turnedReference(page: Page): Promise<{ picture: RgbaImage; plain: RgbaImage; object: { position: number[]; rotation: number[] } }> {
  await openPage(page);
  await mountHtml(page, SCENE('controls="trackball"'));
  const plain = await capture(page);
  await turnNow(page, QUARTER);
  await wait(page, 300);
  return { picture: await capture(page), plain, object: await firstObject(page) };
}

test('the default scene fetches neither chunk; objectRotation fetches the group rotation, debug-view passes the debug views', async ({ page }) => {
  await openPage(page);
  await mountHtml(page, SCENE());
  await turnNow(page, [0, 0, 0, 1]); // the identity is no turn: nothing to fetch
  await wait(page, 200);
  expect([(await fetchedChunks(page, [TURN])).length > 0, (await fetchedChunks(page, [VIEWS])).length > 0]).toEqual([false, false]);
  await turnNow(page, QUARTER);
  await expect.poll(async () => (await fetchedChunks(page, [TURN])).length).toBe(1);
  expect((await fetchedChunks(page, [VIEWS])).length > 0).toBe(false);
  await page.evaluate(() => document.querySelector('glass-plane-scene')!.setAttribute('debug-view', 'passes'));
  await expect.poll(async () => (await fetchedChunks(page, [VIEWS])).length).toBe(1);
});

test('objectRotation without controls: frames wait for the group rotation (held 600 ms), `scene` is turned from the next frame on', async ({ page }) => {
  const ref = await turnedReference(page);
  expect(same(ref.picture, ref.plain), 'a quarter turn changes the picture').toBe(false);
  await holdBack(page, TURN, 600);
  await openPage(page);
  await mountHtml(page, SCENE());
  const before = await firstObject(page);
  await countFrames(page);
  // Before the chunk is in, `scene` leaves the turn out (README: it settles with the next frame).
  expect(await turnNow(page, QUARTER), 'scene before the chunk').toEqual(before);
  await wait(page, 400);
  expect(await framesSeen(page), 'frames drawn while the chunk is held back').toBe(0);
  await expect.poll(() => framesSeen(page), { timeout: 5000 }).toBeGreaterThan(0);
  expect(same(await capture(page), ref.picture), 'the first frame drawn is the turned picture').toBe(true);
  const after = await firstObject(page);
  expect(after).toEqual(ref.object);
  expect(after.position, 'the turn moved the first object').not.toEqual(before.position);
});

test('a scene value built after the group rotation is in turns about its own centre (the content moved, the turn kept)', async ({ page }) => {
  // A quarter turn of the scene with the cube at -2: set up so from the start, or moved there after
  // the turn or before it, the picture must be the same (the renderers turn about the centre
  // SceneValue finds for each value it builds; `scene` finds its own).
  const picture = async (attrs: string, steps: string[]) => {
    await openPage(page);
    await mountHtml(page, SCENE(`controls="trackball" ${attrs}`));
    for (const step of steps) {
      await page.evaluate((step) => new Function('el', step)(document.querySelector('glass-plane-scene')), step);
      await wait(page, 200); // a frame drawn, its value built, between the changes
    }
    return capture(page);
  };
  const turn = `el.objectRotation = ${JSON.stringify(QUARTER)};`, move = 'el.setAttribute("cube-distance", "-2");';
  const fromTheStart = await picture('cube-distance="-2"', [turn]);
  expect(same(await picture('', [move]), fromTheStart), 'the turn changes the picture').toBe(false);
  expect(same(await picture('', [turn, move]), fromTheStart), 'turned, then moved').toBe(true);
  expect(same(await picture('', [move, turn]), fromTheStart), 'moved, then turned').toBe(true);
});

test('with controls="trackball" the group rotation comes with the controls: `scene` is turned in the same task', async ({ page }) => {
  const ref = await turnedReference(page);
  await openPage(page);
  await mountHtml(page, SCENE('controls="trackball"'));
  expect((await fetchedChunks(page, [TURN])).length > 0, 'fetched with the controls').toBe(true);
  expect(await turnNow(page, QUARTER)).toEqual(ref.object);
  // The turned picture once a frame has drawn it (a loaded GPU may take longer than a fixed wait).
  await expect.poll(async () => same(await capture(page), ref.picture), { timeout: 10_000 }).toBe(true);
});

test('if the group rotation cannot load: one warning, no error, the objects turn about the origin and `scene` leaves the turn out', async ({ page, consoleLog }) => {
  const ref = await turnedReference(page);
  await blockChunk(page, TURN);
  await openPage(page);
  const seen = await mountHtml(page, SCENE());
  const before = await firstObject(page);
  await countFrames(page);
  await turnNow(page, [0, 0.5, 0, Math.sqrt(0.75)]);
  await turnNow(page, QUARTER); // a second turn: no second warning
  await expect.poll(() => framesSeen(page), { timeout: 5000 }).toBeGreaterThan(0);
  await wait(page, 300);
  expect(seen.filter((e) => e.type === 'error')).toEqual([]);
  expect(await firstObject(page)).toEqual(before);
  const shown = await capture(page);
  expect(same(shown, ref.plain), 'still turned').toBe(false);
  expect(same(shown, ref.picture), 'not about the objects\' centre').toBe(false);
  expectOneWarning(consoleLog, 'trackball\'s turn could not load');
});

test('debug-view="passes" with the debug views held back 600 ms: no frame until they are in, then the four passes', async ({ page }) => {
  await expectFrameHeldFor(page, VIEWS, 'debug-view', 'passes');
});

test('if the debug views cannot load: one warning, no error, the final image', async ({ page, consoleLog }) => {
  await openPage(page);
  await mountHtml(page, SCENE());
  const final = await capture(page);
  await blockChunk(page, VIEWS);
  await openPage(page);
  const seen = await mountHtml(page, SCENE('debug-view="fresnel"'));
  await page.evaluate(() => document.querySelector('glass-plane-scene')!.setAttribute('debug-view', 'reflection'));
  await wait(page, 300);
  expect(seen.filter((e) => e.type === 'error')).toEqual([]);
  expect(same(await capture(page), final)).toBe(true);
  expectOneWarning(consoleLog, 'debug-view could not load');
});
