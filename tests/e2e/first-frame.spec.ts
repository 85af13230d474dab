// The first frame never stalls (docs/element.md#events): on a fresh page an element of every kind
// is `ready` within 2 s whatever order and delay its lazy chunks arrive in, and the page's own
// animation frames keep coming meanwhile and after. The self-contained build (dist/), whose lazy
// chunks are files a route can hold back.
import type { Page } from '@playwright/test';
import { test, expect } from './fixtures';

const KINDS: Record<string, string> = {
  default: '<glass-plane-scene></glass-plane-scene>',
  children: '<glass-plane-scene><glass-object shape="sphere"></glass-object></glass-plane-scene>',
  orbit: '<glass-plane-scene controls="orbit"></glass-plane-scene>',
  trackball: '<glass-plane-scene controls="trackball"></glass-plane-scene>',
  software: '<glass-plane-scene renderer="software"></glass-plane-scene>',
  rough: '<glass-plane-scene roughness="0.3"></glass-plane-scene>',
};

interface Run { ready: number; twoFrames: number; longestGap: number }

/**
 * Mounts `html` in #stage once the element is defined and measures, on the page's clock: how long
 * until `ready` (null past `limit` ms), how long two animation frames then take, and the longest
 * wait between the page's own animation frames from the append until those two frames are in.
 */
function mountAndWatch(page: Page, html: string, limit: number): Promise<Run | null> {
  return page.evaluate(async ([html, limit]) => {
    await customElements.whenDefined('glass-plane-scene');
    let last = performance.now(), longestGap = 0, watching = true;
    const tick = (t: number) => {
      longestGap = Math.max(longestGap, t - last);
      last = t;
      if (watching) requestAnimationFrame(tick);
    };
    requestAnimationFrame(tick);
    const holder = document.createElement('div');
    holder.innerHTML = html;
    const el = holder.firstElementChild!;
    const start = performance.now();
    const ready = await new Promise<number | null>((resolve) => {
      const t = setTimeout(() => resolve(null), limit);
      el.addEventListener('ready', () => { clearTimeout(t); resolve(performance.now() - start); }, { once: true });
      document.getElementById('stage')!.append(el);
    });
    if (ready === null) return null;
    const before = performance.now();
    await new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)));
    const twoFrames = performance.now() - before;
    watching = false;
    return { ready, twoFrames, longestGap };
  }, [html, limit] as const);
}

/**
 * Holds back every lazy chunk of the build (not its entry) by 0–300 ms, from a seeded sequence:
 * the same delays in every run. Returns the delays, filled as the chunks are asked for.
 */
async function holdChunksAtRandom(page: Page, seed: number): Promise<number[]> {
  const random = () => ((seed = (seed * 1103515245 + 12345) % 2 ** 31) / 2 ** 31);
  const delays: number[] = [];
  await page.route(/\/dist\/(?!glass-plane-scene\.standalone\.js).*\.js$/, async (route) => {
    const ms = Math.floor(random() * 300);
    delays.push(ms);
    await new Promise((r) => setTimeout(r, ms));
    await route.continue();
  });
  return delays;
}

test('a sphere child on a page sized by a stylesheet: ready, then two animation frames at once (three fresh pages)', async ({ page }) => {
  await page.setViewportSize({ width: 700, height: 800 });
  for (let i = 0; i < 3; i++) {
    await page.goto('/tests/e2e/pages/first-frame.html');
    const run = await mountAndWatch(page, KINDS.children, 10_000);
    expect(run, 'ready').not.toBeNull();
    // Measured: two frames ≈ 17–35 ms on a quiet machine; 1,067 ms once with a StrykerJS run
    // holding one of the two cores (2026-11-28; 500 ms was the bound then). The stall this guards
    // against held them 25 s: 2 s tells the two apart with room for a loaded machine.
    expect(run!.twoFrames, JSON.stringify(run)).toBeLessThan(2000);
  }
});

test('every kind of element but rough glass, its lazy chunks each held back 0–300 ms at random: ready within 2 s and the page\'s frames never held up (50 fresh pages)', async ({ page }) => {
  test.setTimeout(240_000);
  await page.setViewportSize({ width: 700, height: 800 });
  const delays = await holdChunksAtRandom(page, 12345);
  // Rough glass has a test of its own below: its frames at 640×360 are seconds of SwiftShader's
  // time, still running in the browser's GPU process after the page is gone, and the next page's
  // first frame waited behind them (a default element after a rough one not ready within 2 s, in
  // two full runs of two).
  const names = Object.keys(KINDS).filter((k) => k !== 'rough'), lines: string[] = [];
  for (let i = 0; i < 50; i++) {
    const kind = names[i % names.length];
    await page.goto('/tests/e2e/pages/first-frame.html');
    const run = await mountAndWatch(page, KINDS[kind], 2000);
    const line = `run ${i} (${kind}): ${run ? `ready ${run.ready.toFixed(0)} ms, two frames ${run.twoFrames.toFixed(0)} ms, longest wait between frames ${run.longestGap.toFixed(0)} ms` : 'not ready within 2 s'}`;
    lines.push(line);
    expect(run, line).not.toBeNull();
    expect(run!.longestGap, line).toBeLessThan(1000);
  }
  console.log(lines.join('\n'));
  expect(delays.length, 'chunks held back').toBeGreaterThan(50);
});

test('rough glass, its chunks held back 0–300 ms at random: ready within 2 s on each of 6 fresh pages', async ({ page }) => {
  test.setTimeout(240_000);
  await page.setViewportSize({ width: 700, height: 800 });
  await holdChunksAtRandom(page, 777);
  for (let i = 0; i < 6; i++) {
    await page.goto('/tests/e2e/pages/first-frame.html');
    // The page's frames are not held to a bound here: its first rough frame at 640×360 is seconds
    // of SwiftShader's time (12 s with the machine loaded, 22.7 s of held frames measured), and
    // the browser holds the page's frames until it is shown.
    const ready = await page.evaluate(async (html) => {
      await customElements.whenDefined('glass-plane-scene');
      const holder = document.createElement('div');
      holder.innerHTML = html;
      const el = holder.firstElementChild!, start = performance.now();
      const ready = await new Promise<number | null>((resolve) => {
        const t = setTimeout(() => resolve(null), 2000);
        el.addEventListener('ready', () => { clearTimeout(t); resolve(performance.now() - start); }, { once: true });
        document.getElementById('stage')!.append(el);
      });
      // The next page starts with the GPU idle: this page's rough frames, seconds each, would
      // otherwise run on in the browser's GPU process ahead of the next page's first frame.
      el.remove();
      const gl = (globalThis as { __GLASS_PLANE_SCENE_GL__?: WebGL2RenderingContext }).__GLASS_PLANE_SCENE_GL__;
      gl?.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
      return ready;
    }, KINDS.rough);
    expect(ready, `run ${i}: ready (ms)`).not.toBeNull();
  }
});

test('one browser, two pages: an orbit element swiped with touch on one and removed; on the other, brought to the front, a new orbit element is ready at once', async ({ browser }) => {
  const touch = await browser.newContext({ hasTouch: true, viewport: { width: 700, height: 800 } });
  const plain = await browser.newContext({ viewport: { width: 700, height: 800 } });
  try {
    const a = await touch.newPage(), b = await plain.newPage();
    await b.goto('/tests/e2e/pages/first-frame.html');
    await a.goto('/tests/e2e/pages/first-frame.html');
    await a.bringToFront();
    expect(await mountAndWatch(a, KINDS.orbit, 10_000), 'the touch page\'s element').not.toBeNull();
    // A one-finger swipe across the element, as a phone sends it.
    const cdp = await touch.newCDPSession(a);
    const at = (x: number) => [{ x, y: 180, id: 1 }];
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(200) });
    for (let x = 220; x <= 440; x += 20) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(x) });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await a.evaluate(() => document.querySelector('glass-plane-scene')!.remove());
    await b.bringToFront();
    const run = await mountAndWatch(b, KINDS.orbit, 2000);
    expect(run, 'ready within 2 s on the page brought to the front').not.toBeNull();
    expect(run!.twoFrames, JSON.stringify(run)).toBeLessThan(500);
  } finally {
    await touch.close();
    await plain.close();
  }
});
