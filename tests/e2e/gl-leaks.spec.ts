// GL objects freed on removal (docs/element.md#failure-behaviour), counted from the context itself: every create*/delete*
// call goes through a wrapped WebGL2RenderingContext (helpers/gl-census.ts). The element's own
// `stats.resources` are zeroed when it disposes its renderer, so a resource its dispose() forgets
// would still read 0 there; the census sees the object that was never deleted.
import type { Page } from '@playwright/test';
import { test, expect, mount, openPage, capture, setAttributes, type SceneElement } from './fixtures';
import { countGlObjects, glCensus, liveTotal, type Census } from './helpers/gl-census';
import { compareImages } from './helpers/golden';
import { mountHtml } from './helpers/scene-children';
import { mapsGlb } from './helpers/gltf-models';

const SIZE = { width: 160, height: 90 };

test.beforeEach(async ({ page }) => {
  await page.addInitScript(countGlObjects);
  await openPage(page);
});

/** Draws with every resource the renderer can own: MSAA targets, capture target, half-float reflection, more programs. */
async function exercise(page: Page, selector: string): Promise<void> {
  await capture(page, 'reflection', selector);
  await capture(page, 'scene', selector);
  await capture(page, undefined, selector);
  await setAttributes(page, selector, { 'debug-view': 'passes', fresnel: 'classic', shading: 'gouraud' });
  await setAttributes(page, selector, { 'debug-view': null, 'reflection-format': 'rgba16f', tessellation: 24 });
  await capture(page, 'reflection', selector);
}

async function remove(page: Page, selector: string): Promise<Census> {
  await page.evaluate((s) => document.querySelector(s)!.remove(), selector);
  // One frame later, so nothing deferred is missed.
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r(null))));
  return (await glCensus(page)).live;
}

const elementTotal = (page: Page, selector: string) =>
  page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.resources.total, selector);

test('an element removed from the page deletes every GL object it created, by the context\'s own count', async ({ page }) => {
  const before = await glCensus(page);
  expect(liveTotal(before.live), 'no GL object before the first element').toBe(0);
  const { selector } = await mount(page, { time: 1.25, samples: 4 }, SIZE);
  await exercise(page, selector);
  const { live, created } = await glCensus(page);
  console.log(`live while mounted: ${JSON.stringify(live)}; created: ${JSON.stringify(created)}`);
  // Not vacuous: the wrapper saw the renderer's objects, of every kind it owns…
  for (const kind of ['buffers', 'textures', 'framebuffers', 'renderbuffers', 'vertexArrays', 'programs', 'shaders']) {
    expect(live[kind], `live ${kind} while mounted`).toBeGreaterThan(0);
  }
  // …and agrees with the renderer's bookkeeping while it is alive; the one more is the backend's
  // fence on the last frame (webgl-backend.ts: a frame waits for the GPU to finish the one before).
  expect(live.syncs, 'the last frame\'s fence').toBeLessThanOrEqual(1);
  expect(liveTotal(live) - live.syncs, 'census = stats.resources.total while mounted').toBe(await elementTotal(page, selector));
  const after = await remove(page, selector);
  expect(after, 'live GL objects after removal, per kind').toEqual(before.live);
});

test('mount/remove cycles leave nothing behind; removing one of two elements frees only its own objects', async ({ page }) => {
  for (let i = 0; i < 3; i++) {
    const { selector } = await mount(page, { time: 1.25, samples: i % 2 ? 0 : 4 }, SIZE);
    await capture(page, 'reflection', selector);
    expect(liveTotal(await remove(page, selector)), `cycle ${i}: live GL objects after removal`).toBe(0);
  }
  const a = (await mount(page, { time: 1.25 }, SIZE)).selector;
  const onlyA = liveTotal((await glCensus(page)).live);
  const b = (await mount(page, { time: 2, samples: 0 }, SIZE)).selector;
  await capture(page, undefined, b);
  const bTotal = await elementTotal(page, b);
  const afterB = await remove(page, b);
  expect(liveTotal(afterB), 'after removing b: a\'s objects, no more, no fewer').toBe(onlyA);
  expect(bTotal).toBeGreaterThan(0);
  await capture(page, undefined, a);
  expect(liveTotal(await remove(page, a)), 'after removing both').toBe(0);
});

test('elements on one context share programs, the procedural texture and meshes: a second default element creates none of them', async ({ page }) => {
  const a = (await mount(page, { time: 1.25 }, SIZE)).selector;
  const one = (await glCensus(page)).created;
  const b = (await mount(page, { time: 1.5 }, SIZE)).selector;
  const two = (await glCensus(page)).created;
  // Per element: framebuffers, renderbuffers, its sphere LOD's buffers and VAO, and two textures:
  // the reflection and the frame in linear light (docs/colour.md#srgb). Shared: the 4 programs (8 shaders;
  // the 4th encodes the frame), the 512² texture (~1.4 MB with mipmaps), the cube's and glass's meshes.
  expect(two.programs - one.programs, 'programs compiled for the second element').toBe(0);
  expect(two.shaders - one.shaders, 'shaders compiled for the second element').toBe(0);
  expect(two.textures - one.textures, 'textures for the second element (its reflection and linear frame only)').toBe(2);
  const stats = await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats, b);
  expect(stats.programs, 'the second element still reports the 4 variants it uses').toBe(4);
  // Removing one keeps what the other uses; removing both frees everything.
  await remove(page, a);
  expect(await capture(page, undefined, b)).toBeTruthy();
  expect(liveTotal(await remove(page, b)), 'nothing left after both').toBe(0);
});

test('the clustered copies a dense mesh\'s reflection draws are freed with the element, at every grid it used', async ({ page }) => {
  // Another element keeps the context's shared resources alive: a copy left referenced would stay.
  const other = (await mount(page, { time: 1.25 }, SIZE)).selector;
  await capture(page, undefined, other);
  const onlyOther = liveTotal((await glCensus(page)).live);
  const { selector } = await mount(page, {
    time: 0, 'glass-center': '0 -1 0', 'glass-normal': '0 1 0', 'glass-size': '8 8', 'camera-position': '3 1.6 4', 'camera-rotation': '-126.87 -17.74',
  }, SIZE);
  const trianglesAt = async (position: string) => {
    await setAttributes(page, selector, { 'camera-position': position });
    await capture(page, undefined, selector);
    return page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.triangles, selector);
  };
  await page.evaluate((s) => {
    const o = document.createElement('glass-object');
    o.setAttribute('shape', 'gaussian');
    o.setAttribute('resolution', '225');
    document.querySelector(s)!.append(o);
  }, selector);
  const far = await trianglesAt('3 1.6 4');
  const near = await trianglesAt('1.5 0.8 2');
  // Not vacuous: two different clustered copies were drawn, both coarser than the mesh.
  expect(far.reflection).toBeLessThan(far.scene / 2);
  expect(near.reflection).toBeLessThan(near.scene);
  expect(near.reflection).not.toBe(far.reflection);
  expect(liveTotal(await remove(page, selector)), 'live GL objects after removal: the other element\'s only').toBe(onlyOther);
  expect(liveTotal(await remove(page, other)), 'after both').toBe(0);
});

test('an image texture is deleted with the element that drew it', async ({ page }) => {
  const before = (await glCensus(page)).live;
  const mountCube = (texture: string) => page.evaluate((texture) => new Promise<string>((resolve, reject) => {
    const host = document.createElement('div');
    host.innerHTML = `<glass-plane-scene refine="0" id="cube" time="0" spin="0" glass-size="0 0" camera-position="0 0 2.5" camera-rotation="-90 0"
      style="width: 160px; height: 90px"><glass-object shape="cube" ${texture}></glass-object></glass-plane-scene>`;
    const el = host.firstElementChild!;
    const t = setTimeout(() => reject(new Error('no ready event')), 30_000);
    el.addEventListener('ready', () => { clearTimeout(t); resolve('#cube'); }, { once: true });
    document.body.append(el);
  }), texture);
  const textures = async () => (await glCensus(page)).live.textures;
  // The same cube with the procedural texture: what it holds without an image.
  const plainCube = await mountCube('');
  const plain = await textures();
  await remove(page, plainCube);
  const selector = await mountCube('texture="/tests/e2e/pages/models/checker.png"');
  // The image (decoded after the first frame, or before it) is one more texture (not vacuous).
  await expect.poll(textures, { message: 'the image uploaded' }).toBe(plain + 1);
  expect(await remove(page, selector), 'live GL objects after removal, per kind').toEqual(before);
});

test('renderer webgl → software → webgl: every GL object freed while software draws, rebuilt after; the canvas shows each renderer\'s frame', async ({ page }) => {
  const before = (await glCensus(page)).live;
  const { selector } = await mount(page, { time: 1.25 }, SIZE);
  const gl = await capture(page, undefined, selector);
  const live = (await glCensus(page)).live;
  expect(liveTotal(live), 'GL objects while WebGL draws').toBeGreaterThan(0);
  // A software frame of the same state, drawn by an element that never used WebGL.
  const reference = (await mount(page, { time: 1.25, renderer: 'software' }, SIZE)).selector;
  const soft = await capture(page, undefined, reference);
  expect(compareImages(gl, soft).differing, 'the two renderers\' frames differ (the check is not vacuous)').toBeGreaterThan(0);

  await setAttributes(page, selector, { renderer: 'software' });
  expect(await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.renderer, selector)).toBe('software');
  expect((await glCensus(page)).live, 'live GL objects while the software renderer draws').toEqual(before);
  // The software frame reached the canvas that held WebGL's (no stale frame).
  expect(compareImages(await capture(page, undefined, selector), soft).differing, 'canvas after the switch to software').toBe(0);

  await setAttributes(page, selector, { renderer: 'webgl' });
  expect(await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.renderer, selector)).toBe('webgl');
  expect((await glCensus(page)).live, 'live GL objects after the switch back').toEqual(live);
  expect(compareImages(await capture(page, undefined, selector), gl).differing, 'canvas after the switch back to webgl').toBe(0);
  expect(await remove(page, selector)).toEqual(before);
});

test('a removed element takes no part in a later context loss and restore: no error event, no GL object rebuilt', async ({ page }) => {
  const a = (await mount(page, { time: 1.25 }, SIZE)).selector;
  const b = (await mount(page, { time: 2 }, SIZE)).selector;
  await page.evaluate((s) => {
    const w = window as unknown as { __removedErrors: number };
    w.__removedErrors = 0;
    document.querySelector(s)!.addEventListener('error', () => w.__removedErrors++);
  }, b);
  const onlyA = await remove(page, b);
  await page.evaluate((s) => new Promise<void>((resolve, reject) => {
    const gl = (globalThis as { __GLASS_PLANE_SCENE_GL__?: WebGL2RenderingContext }).__GLASS_PLANE_SCENE_GL__;
    const ext = gl?.getExtension('WEBGL_lose_context');
    if (!ext) return reject(new Error('WEBGL_lose_context unavailable'));
    const el = document.querySelector(s)!;
    const t = setTimeout(() => reject(new Error('no frame after the restore')), 15_000);
    el.addEventListener('error', () => {
      el.addEventListener('frame', () => { clearTimeout(t); resolve(); }, { once: true });
      setTimeout(() => ext.restoreContext(), 100); // not from within the loss's own dispatch
    }, { once: true });
    ext.loseContext();
  }), a);
  await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
  expect(await page.evaluate(() => (window as unknown as { __removedErrors: number }).__removedErrors), 'error events on the removed element').toBe(0);
  expect((await glCensus(page)).live, 'live GL objects after the restore: the remaining element\'s only').toEqual(onlyA);
});

test('a glTF material\'s maps and the environment\'s textures are counted and deleted with the element', async ({ page }) => {
  const before = (await glCensus(page)).live;
  const glb = await mapsGlb();
  await page.route('**/wild/maps.glb', (route) => route.fulfill({ status: 200, contentType: 'model/gltf-binary', body: Buffer.from(glb) }));
  await mountHtml(page, `<glass-plane-scene refine="0" id="maps" time="0" spin="0" style="width: 160px; height: 90px">
    <glass-object src="/wild/maps.glb"></glass-object></glass-plane-scene>`);
  await page.evaluate(() => new Promise((r) => {
    const el = document.querySelector('#maps') as unknown as HTMLElement & { requestRender(): void };
    el.addEventListener('frame', r, { once: true });
    el.requestRender();
  }));
  const { live } = await glCensus(page);
  // The three maps, the white texel that stands for a missing one, and the environment's two textures, at least.
  expect(live.textures, 'live textures while mounted').toBeGreaterThanOrEqual(6);
  expect(liveTotal(live) - live.syncs, 'census = stats.resources.total while mounted').toBe(await elementTotal(page, '#maps'));
  expect(await remove(page, '#maps'), 'live GL objects after removal, per kind').toEqual(before);
});
