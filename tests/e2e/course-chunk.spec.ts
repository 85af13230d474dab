// camera-src's code is two chunks of its own (docs/package.md#chunks): the element's (element/camera-source.ts,
// which loads the file) and the renderer's (frame/course-projection.ts: the course's maths and
// the scene's depth range). A page without camera-src fetches neither; a page with it draws
// from the course camera once both are in, however slow; a chunk that cannot load leaves the
// view to the camera attributes, with one warning and no `error`.
import type { Page } from '@playwright/test';
import { test, expect, openPage, capture, type RgbaImage } from './fixtures';
import { samePixels as same } from './helpers/chunks';
import { mountHtml } from './helpers/scene-children';
import { drawScene, openRendererPage, sceneToJson } from './helpers/scene-json';
import { parseCameraCfg } from '../../src/loaders/course/camera-cfg';
import { defaultScene } from '../../src/scene/default-scene';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from '../unit/helpers/frame-state';
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const CFG = '/tests/data/course/camera.cfg';
const SCENE = (attrs: string) => `<glass-plane-scene refine="0" time="0" spin="0" ${attrs}></glass-plane-scene>`;
const CHUNKS = ['camera-source', 'course-projection'];

const fetched = (page: Page) =>
  page.evaluate((names) => names.filter((n) => performance.getEntriesByType('resource').some((e) => e.name.includes(n))), CHUNKS);
const settled = async (page: Page) => {
  await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
  return capture(page);
};

/** The default scene as the element draws it with and without camera-src (no chunk held back). */
async function pictures(page: Page): Promise<{ course: RgbaImage; flyby: RgbaImage }> {
  await openPage(page);
  await mountHtml(page, SCENE(`camera-src="${CFG}"`));
  const course = await settled(page);
  await openPage(page);
  await mountHtml(page, SCENE(''));
  const flyby = await settled(page);
  return { course, flyby };
}

test('a scene without camera-src fetches neither chunk; one with it fetches both', async ({ page }) => {
  await openPage(page);
  await mountHtml(page, SCENE(''));
  expect(await fetched(page)).toEqual([]);
  await mountHtml(page, SCENE(`camera-src="${CFG}"`));
  expect(await fetched(page)).toEqual(CHUNKS);
});

test('held back 600 ms each, the chunks still end in the course camera\'s picture', async ({ page }) => {
  const { course, flyby } = await pictures(page);
  expect(same(course, flyby), 'the course camera sees the scene otherwise than the default camera').toBe(false);
  for (const name of CHUNKS) {
    await page.route(`**/${name}*`, async (route) => {
      await new Promise((r) => setTimeout(r, 600));
      await route.continue();
    });
  }
  await openPage(page);
  await mountHtml(page, SCENE(`camera-src="${CFG}"`));
  await page.evaluate(() => new Promise((r) => setTimeout(r, 1000)));
  expect(same(await settled(page), course)).toBe(true);
});

test('`ready` waits for camera-src\'s reader (held back 600 ms): at `ready` the course camera is the view', async ({ page }) => {
  const { course, flyby } = await pictures(page);
  await page.route('**/camera-source*', async (route) => {
    await new Promise((r) => setTimeout(r, 600));
    await route.continue();
  });
  await openPage(page);
  await mountHtml(page, SCENE(`camera-src="${CFG}"`)); // resolves at `ready`
  const atReady = await capture(page);
  expect(same(atReady, flyby), 'not the camera attributes\' picture').toBe(false);
  expect(same(atReady, course)).toBe(true);
});

for (const name of CHUNKS) {
  test(`if ${name} cannot load, the camera attributes stay the view: one warning, no error`, async ({ page, consoleLog }) => {
    const { flyby } = await pictures(page);
    await page.route(`**/${name}*`, (route) => route.abort());
    await openPage(page);
    const seen = await mountHtml(page, SCENE(`camera-src="${CFG}"`));
    await page.evaluate(() => new Promise((r) => setTimeout(r, 500)));
    expect(seen.filter((e) => e.type === 'error')).toEqual([]);
    expect(same(await settled(page), flyby)).toBe(true);
    expect(consoleLog.take('warning').filter((w) => w.includes('camera-src could not load'))).toHaveLength(1);
    consoleLog.take('error'); // the browser's own report of the failed fetch
  });
}

test('the Renderer draws a course camera from the camera attributes until load(), from the course camera after', async ({ page }) => {
  // The projection's chunk comes 300 ms after the renderer's checks (the page runs with checks on):
  // load() must wait for every part a frame needs, not only the first.
  await page.route('**/course-projection*', async (route) => {
    await new Promise((r) => setTimeout(r, 300));
    await route.continue();
  });
  await openRendererPage(page);
  const text = fs.readFileSync(path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../data/course/camera.cfg'), 'utf8');
  const { warnings: _w, ...camera } = parseCameraCfg(text, { url: 'camera.cfg' });
  const base: FrameState = defaultFrameState({ width: 160, height: 90, spin: 0, samples: 0 });
  const withCamera = { ...base, courseCamera: camera };
  const scene = sceneToJson(defaultScene(0.75, 0));
  type Api = { __renderer: { drawNow(s: FrameState, sc: unknown): string } };
  const now = (s: FrameState) => page.evaluate(([s, sc]) => (window as unknown as Api).__renderer.drawNow(s, sc), [s, scene] as const);
  const flyby = await now(base);
  expect(await now(withCamera) === flyby, 'before load() the course camera is not used').toBe(true);
  await drawScene(page, withCamera, defaultScene(0.75, 0)); // loads the chunk
  expect(await now(withCamera) === flyby, 'after load() it is').toBe(false);
});
