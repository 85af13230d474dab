// No allocation in the frame loop during motion: the scene value is built when its
// content changes (an attribute that shapes it, a child, a model), never because a pose moved.
// The trackball's turn and the orbit camera travel in the frame state, so 60 and more frames of
// trackball inertia, and of an orbit drag with its write-back at the end, build it zero times.
// `stats.sceneBuilds` counts the builds; a content change still builds exactly once. The software
// renderer's worker is sent the scene once and then only the frame state, the turn in it.
import type { CDPSession, Page } from '@playwright/test';
import { test, expect, mount, openPage, nextFrame, capture, type SceneElement } from './fixtures';
import { compareImages } from './helpers/golden';
import { box, drag, EPOCH, recordCameraChanges, type ControlsElement } from './helpers/controls-input';

type Counted = SceneElement & ControlsElement & { stats: SceneElement['stats'] & { sceneBuilds: number } };

const builds = (page: Page, s: string) => page.evaluate((s) => (document.querySelector(s) as unknown as Counted).stats.sceneBuilds, s);

/** Counts `frame` events from now on; `frames()` reads the count. */
async function countFrames(page: Page, s: string): Promise<() => Promise<number>> {
  await page.evaluate((s) => {
    const w = window as unknown as { __frames: number };
    w.__frames = 0;
    document.querySelector(s)!.addEventListener('frame', () => { w.__frames++; });
  }, s);
  return () => page.evaluate(() => (window as unknown as { __frames: number }).__frames);
}

/** Waits until no frame has come for 600 ms (the motion has stopped). */
async function settled(frames: () => Promise<number>): Promise<void> {
  let last = -1;
  await expect.poll(async () => {
    const n = await frames();
    const still = n === last;
    last = n;
    return still;
  }, { timeout: 30_000, intervals: [600] }).toBe(true);
}

/** One mouse move through CDP, then the frame it causes. */
async function moveAndDraw(page: Page, cdp: CDPSession, s: string, x: number, y: number, t: number): Promise<void> {
  await page.evaluate((s) => {
    (window as unknown as { __next: Promise<void> }).__next = new Promise((r) => document.querySelector(s)!.addEventListener('frame', () => r(), { once: true }));
  }, s);
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x, y, button: 'left', buttons: 1, timestamp: t });
  await page.evaluate(() => (window as unknown as { __next: Promise<void> }).__next);
}

/**
 * A drag of 64 moves of 1 px through the middle of `b`, each drawn before the next (64 frames
 * whatever the machine's load), the pointer resting 200 ms before the release (no inertia).
 */
async function slowDrag(page: Page, cdp: CDPSession, selector: string, b: { cx: number; cy: number }): Promise<void> {
  let t = EPOCH + 200;
  const x0 = b.cx - 32;
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: x0, y: b.cy, timestamp: t });
  await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: x0, y: b.cy, button: 'left', buttons: 1, clickCount: 1, timestamp: (t += 0.01) });
  for (let k = 1; k <= 64; k++) await moveAndDraw(page, cdp, selector, x0 + k, b.cy, (t += 0.016));
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: x0 + 64, y: b.cy, button: 'left', buttons: 0, clickCount: 1, timestamp: (t += 0.2) });
}

test('trackball: 64 frames of a drag and the frames of a flick\'s inertia build the scene value zero times; the turn still shows', async ({ page }) => {
  await openPage(page);
  const { selector } = await mount(page, { time: 0, spin: 0, controls: 'trackball' }, { width: 160, height: 90 });
  const b = await box(page, selector);
  const cdp = await page.context().newCDPSession(page);
  const frames = await countFrames(page, selector);
  const before = await builds(page, selector);
  // 64 moves of 1 px, each drawn before the next (64 frames whatever the machine's load), the
  // pointer resting 200 ms before the release (no inertia) ...
  await slowDrag(page, cdp, selector, b);
  await settled(frames);
  const dragged = await frames();
  // ... then a flick: 8 moves 16 ms apart, released 8 ms after the last (as in inertia.spec.ts),
  // and its inertia (how many frames it draws depends on the machine's load; at least one).
  await drag(cdp, { x: b.cx - 20, y: b.cy + 5 }, { x: b.cx + 20, y: b.cy - 5 }, { t0: 20, steps: 8, dtMs: 16, restMs: 8 });
  await settled(frames);
  const n = await frames(), after = await builds(page, selector);
  const q = await page.evaluate((s) => (document.querySelector(s) as unknown as Counted).objectRotation, selector);
  console.log(`trackball: ${dragged} frames of a drawn drag, ${n - dragged} of a flick and its inertia, ${after - before} scene builds, objectRotation w ${q[3].toFixed(4)}`);
  expect(dragged, 'frames of the drawn drag').toBeGreaterThanOrEqual(64);
  expect(n - dragged, 'frames of the flick and its inertia').toBeGreaterThan(0);
  expect(q[3], 'the objects turned').toBeLessThan(0.999);
  expect(after - before, 'scene builds while the objects turned').toBe(0);
  // An attribute that does not shape the scene builds nothing; a content change builds it once.
  await nextFrame(page, selector, (el) => el.setAttribute('transparency', '0.3'));
  expect(await builds(page, selector) - after, 'builds after a transparency change').toBe(0);
  await nextFrame(page, selector, (el) => el.setAttribute('background', '0.2 0.1 0.1'));
  expect(await builds(page, selector) - after, 'builds after a background change').toBe(1);
});

test('orbit: 60+ frames of a drag and its write-back build the scene value zero times', async ({ page }) => {
  await openPage(page);
  const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, { width: 160, height: 90 });
  const b = await box(page, selector);
  const cdp = await page.context().newCDPSession(page);
  const changes = await recordCameraChanges(page, selector);
  const frames = await countFrames(page, selector);
  const before = await builds(page, selector);
  const yaw0 = await page.evaluate((s) => (document.querySelector(s) as unknown as Counted).cameraRotation[0], selector);
  // 64 moves of 1 px, each drawn before the next; the pointer rests 200 ms before the release,
  // so no inertia: the gesture ends at the release and writes the camera attributes back.
  await slowDrag(page, cdp, selector, b);
  await expect.poll(async () => (await changes()).length, { timeout: 10_000 }).toBe(1);
  await settled(frames);
  const n = await frames(), after = await builds(page, selector);
  const [change] = await changes();
  console.log(`orbit drag: ${n} frames, ${after - before} scene builds, yaw ${yaw0.toFixed(2)} → ${change.rotation[0].toFixed(2)}`);
  expect(n, 'frames of the drag').toBeGreaterThanOrEqual(60);
  expect(Math.abs(change.rotation[0] - yaw0), 'the camera turned 0.4° per px').toBeCloseTo(64 * 0.4, 0);
  expect(after - before, 'scene builds while the camera orbited and was written back').toBe(0);
});

test('software: turns reach the worker in the frame state alone; its frames are the turned picture, drawn without a rebuild', async ({ page }) => {
  await openPage(page);
  const { selector } = await mount(page, { time: 0, spin: 0, renderer: 'software' }, { width: 160, height: 90 });
  expect(await page.evaluate((s) => (document.querySelector(s) as unknown as Counted).stats.thread, selector)).toBe('worker');
  const plain = await capture(page, undefined, selector);
  const before = await builds(page, selector);
  const turns: [number, number, number, number][] = [[0, 0.2588, 0, 0.9659], [0.3, 0.4, -0.2, 0.8426], [0, 0.7071, 0, 0.7071]];
  for (const q of turns) {
    await nextFrame(page, selector, new Function('el', `el.objectRotation = ${JSON.stringify(q)};`) as (el: SceneElement) => void);
    // The worker's frame on the canvas, and the same state drawn now on the main thread from the scene as it is.
    const shown = await capture(page, undefined, selector);
    const drawnHere = await capture(page, 'final', selector);
    expect(compareImages(shown, drawnHere).differing, `turn ${q}: the worker drew what the main thread draws`).toBe(0);
    expect(compareImages(plain, shown).differing, `turn ${q}: the objects turned`).toBeGreaterThan(200);
  }
  expect(await builds(page, selector) - before, 'scene builds for three turns').toBe(0);
  // A new scene value reaches the worker (it does not keep drawing the one it holds).
  const turned = await capture(page, undefined, selector);
  await nextFrame(page, selector, (el) => el.setAttribute('background', '0.5 0.2 0.1'));
  const shown = await capture(page, undefined, selector);
  expect(compareImages(turned, shown).differing, 'the new background is drawn').toBeGreaterThan(1000);
  expect(compareImages(shown, await capture(page, 'final', selector)).differing, 'by the worker as on the main thread').toBe(0);
  expect(await builds(page, selector) - before, 'one build for the background').toBe(1);
});
