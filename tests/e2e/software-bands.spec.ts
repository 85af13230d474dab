// The software renderer's frame split across workers, a band of rows each
// (element/software-host.ts). The element drawing with 2 or 3 workers puts on its canvas the
// pixels it puts there with one, which are the main thread's whole frame (capture()); rough glass
// (drawn whole by one worker) too; every worker is terminated when the element goes.
import { test, expect, mount, openPage, type SceneElement } from './fixtures';
import { differingBytes } from '../unit/helpers/pixel-diff';

const SIZE = { width: 320, height: 180 };

/** Records each software worker started and terminated (an init script: before the element runs). */
function countWorkers() {
  const w = window as unknown as { __softwareWorkers: { started: number; terminated: number } };
  w.__softwareWorkers = { started: 0, terminated: 0 };
  const Native = window.Worker;
  window.Worker = class extends Native {
    private readonly software: boolean;
    constructor(url: string | URL, options?: WorkerOptions) {
      super(url, options);
      this.software = options?.name === 'glass-plane-scene software renderer';
      if (this.software) w.__softwareWorkers.started++;
    }
    terminate(): void {
      if (this.software) w.__softwareWorkers.terminated++;
      super.terminate();
    }
  };
}

type Page = import('@playwright/test').Page;
const workers = (page: Page) => page.evaluate(() => (window as unknown as { __softwareWorkers: { started: number; terminated: number } }).__softwareWorkers);

/** New hosts start `n` workers (the element's SoftwareHost, the same module the element loads). */
async function useWorkers(page: Page, n: number): Promise<void> {
  await page.evaluate(async (n) => {
    const url = '/src/element/software-host.ts'; // served by Vite, the module the element loads
    const m = (await import(/* @vite-ignore */ url)) as { SoftwareHost: { workerCount: number | null } };
    m.SoftwareHost.workerCount = n;
  }, n);
}

/** The canvas as the workers' frame left it, and the same frame drawn whole on the main thread (capture()). */
async function canvasAndCapture(page: Page, selector: string) {
  return page.evaluate(async (s) => {
    const el = document.querySelector(s) as SceneElement;
    // A frame after ready, with nothing in flight: the canvas holds the last state's frame.
    await new Promise<void>((resolve) => { el.addEventListener('frame', () => resolve(), { once: true }); el.requestRender(); });
    const canvas = el.shadowRoot!.querySelector('canvas')!;
    const ctx = canvas.getContext('2d')!;
    const shown = ctx.getImageData(0, 0, canvas.width, canvas.height).data;
    const whole = el.capture()!.data;
    return { shown: Array.from(shown), whole: Array.from(whole), thread: el.stats.thread };
  }, selector);
}

function differing(a: number[], b: number[]): number {
  expect(a.length).toBe(b.length);
  return differingBytes(a, b);
}

for (const [name, attrs] of [
  ['default scene, samples 0', { samples: 0 }], ['default scene, samples 4, color-space none', { 'color-space': 'none' }],
  ['orthographic', { projection: 'orthographic', samples: 0 }], ['roughness 0.3', { roughness: 0.3 }],
] as const) {
  test(`${name}: 1, 2 and 3 workers put the same pixels on the canvas, the main thread's whole frame`, async ({ page }) => {
    await page.addInitScript(countWorkers);
    await openPage(page);
    let first: number[] | null = null;
    let started = 0;
    for (const n of [1, 2, 3]) {
      await useWorkers(page, n);
      const { selector } = await mount(page, { renderer: 'software', time: 1.25, ...attrs }, SIZE);
      const got = await canvasAndCapture(page, selector);
      expect(got.thread).toBe('worker');
      started += n;
      expect((await workers(page)).started, `${n} workers started`).toBe(started);
      expect(differing(got.shown, got.whole), `${n} workers: bytes that differ from the main thread's whole frame`).toBe(0);
      if (first) expect(differing(got.shown, first), `${n} workers: bytes that differ from 1 worker's frame`).toBe(0);
      first ??= got.shown;
      await page.evaluate((s) => document.querySelector(s)!.remove(), selector);
    }
  });
}

test('every worker is terminated when the element goes, and when it switches to WebGL', async ({ page }) => {
  await page.addInitScript(countWorkers);
  await openPage(page);
  await useWorkers(page, 3);
  const a = await mount(page, { renderer: 'software', samples: 0 }, SIZE);
  const b = await mount(page, { renderer: 'software', samples: 0 }, SIZE);
  expect(await workers(page)).toEqual({ started: 6, terminated: 0 });
  await page.evaluate((s) => document.querySelector(s)!.remove(), a.selector);
  await expect.poll(() => workers(page)).toEqual({ started: 6, terminated: 3 });
  await page.evaluate((s) => document.querySelector(s)!.setAttribute('renderer', 'webgl'), b.selector);
  await expect.poll(() => workers(page)).toEqual({ started: 6, terminated: 6 });
});

test('a frame in flight when the element goes is dropped, not drawn again on the main thread', async ({ page }) => {
  await openPage(page);
  await useWorkers(page, 2);
  await page.evaluate(async () => {
    const url = '/src/element/software-host.ts';
    const m = (await import(/* @vite-ignore */ url)) as { SoftwareHost: { prototype: { renderNow(...a: unknown[]): unknown } } };
    const w = window as unknown as { __mainThreadFrames: number };
    w.__mainThreadFrames = 0;
    const renderNow = m.SoftwareHost.prototype.renderNow;
    m.SoftwareHost.prototype.renderNow = function (this: unknown, ...a: unknown[]) {
      w.__mainThreadFrames++;
      return renderNow.apply(this, a);
    };
  });
  // Spinning: the next worker frame is asked for as soon as the last lands, so one is always in flight.
  const { selector } = await mount(page, { renderer: 'software', samples: 4, spin: 2 }, SIZE);
  await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
  await page.evaluate((s) => document.querySelector(s)!.remove(), selector);
  await page.evaluate(() => new Promise((r) => setTimeout(r, 500)));
  expect(await page.evaluate(() => (window as unknown as { __mainThreadFrames: number }).__mainThreadFrames)).toBe(0);
});
