// capture(): with no argument, the pixels presented for the last frame, read back without drawing;
// capture(pass) draws that pass off screen from the last frame's state.
import { test, expect, mount, openPage, capture, nextFrame, type SceneElement } from './fixtures';
import { compareImages } from './helpers/golden';

const SIZE = { width: 160, height: 90 };

/** Counts every draw call the page makes on any WebGL2 context from now on. */
function countDrawCalls(): void {
  const w = window as unknown as { __draws: number };
  w.__draws = 0;
  const proto = WebGL2RenderingContext.prototype as unknown as Record<string, (...a: unknown[]) => unknown>;
  for (const name of ['drawArrays', 'drawElements', 'drawArraysInstanced', 'drawElementsInstanced', 'drawRangeElements']) {
    const native = proto[name];
    proto[name] = function (this: unknown, ...args: unknown[]) {
      w.__draws++;
      return native.apply(this, args);
    };
  }
}

const draws = (page: import('@playwright/test').Page) => page.evaluate(() => (window as unknown as { __draws: number }).__draws);

test.beforeEach(async ({ page }) => {
  await page.addInitScript(countDrawCalls);
  await openPage(page);
});

for (const view of ['none', 'passes'] as const) {
  test(`debug-view ${view}: capture() draws nothing and returns the frame a fresh draw of the same state gives`, async ({ page }) => {
    const { selector } = await mount(page, { time: 1.25, 'debug-view': view }, SIZE);
    const frames0 = await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.frames, selector);
    const d0 = await draws(page);
    const shown = await capture(page, undefined, selector);
    expect(await draws(page), 'draw calls made by capture()').toBe(d0);
    expect(await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.frames, selector)).toBe(frames0);

    // The same state drawn again (a requested frame) gives the same pixels.
    await nextFrame(page, selector); // requestRender()
    const again = await capture(page, undefined, selector);
    expect(compareImages(again, shown, 0).differing, 'capture() vs the next frame of the same state').toBe(0);
    if (view === 'none') {
      expect(compareImages(await capture(page, 'final', selector), shown, 0).differing, "capture() vs capture('final')").toBe(0);
    }
  });
}

test('capture() is what is on screen: a change not yet drawn does not show, and it draws nothing', async ({ page }) => {
  const { selector } = await mount(page, { time: 1.25 }, SIZE);
  const before = await capture(page, undefined, selector);
  const result = await page.evaluate((s) => {
    const el = document.querySelector(s) as SceneElement;
    const w = window as unknown as { __draws: number };
    const d0 = w.__draws;
    el.setAttribute('transparency', '1'); // drawn on the next animation frame, not now
    const img = el.capture()!;
    return { draws: w.__draws - d0, data: Array.from(img.data), width: img.width, height: img.height };
  }, selector);
  expect(result.draws).toBe(0);
  const now = { width: result.width, height: result.height, data: Uint8Array.from(result.data) };
  expect(compareImages(now, before, 0).differing, 'the frame on screen is still the old one').toBe(0);
});

test('without OffscreenCanvas (frames copied to a 2D canvas) capture() is the presented frame too', async ({ page }) => {
  await page.addInitScript(() => {
    delete (globalThis as { OffscreenCanvas?: unknown }).OffscreenCanvas;
  });
  await page.reload();
  await page.waitForFunction(() => customElements.get('glass-plane-scene') !== undefined);
  const { selector } = await mount(page, { time: 1.25 }, SIZE);
  expect(await page.evaluate(() => typeof OffscreenCanvas)).toBe('undefined');
  const d0 = await draws(page);
  const shown = await capture(page, undefined, selector);
  expect(await draws(page), 'draw calls made by capture()').toBe(d0);
  // The fallback's 2D copy of the GL canvas rounds a few channels by one level; capture() returns
  // what that copy shows, so against a GL readback of the same frame it may differ by that much.
  const fin = await capture(page, 'final', selector);
  let max = 0;
  for (let i = 0; i < fin.data.length; i++) max = Math.max(max, Math.abs(fin.data[i] - shown.data[i]));
  expect(max, "capture() vs capture('final'): largest channel difference").toBeLessThanOrEqual(1);
});
