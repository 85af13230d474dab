// Playwright fixtures and helpers for the browser tests: the pinned SwiftShader Chromium, a page
// that fails its test on any console error/warning or page error, and element helpers
// (mount, wait for a frame, capture pixels).
import { test as base, expect, type Browser, type ConsoleMessage, type Page } from '@playwright/test';
import type { CapturePass, FrameReport, GlassPlaneSceneErrorDetail, RenderStats } from '../../src/element/types';
import type { RgbaImage } from './helpers/golden';

export { expect };
export type { FrameReport, RgbaImage };

/**
 * Flags for a closed network and WebGL2 on the CPU. `--use-angle=swiftshader` also makes the
 * result independent of any GPU the machine might have; `--enable-unsafe-swiftshader` is needed
 * since Chromium stopped falling back to SwiftShader for WebGL on its own.
 */
export const CHROMIUM_ARGS = [
  '--no-sandbox',
  '--use-angle=swiftshader',
  '--enable-unsafe-swiftshader',
  '--headless=shell',
  '--disable-background-networking',
  '--disable-component-update',
  '--disable-sync',
  '--no-first-run',
  '--disable-quic',
];

/** $PLAYWRIGHT_CHROMIUM (e.g. /usr/bin/chromium), else the Chromium inside @sparticuz/chromium. */
async function chromiumExecutable(): Promise<string> {
  const override = process.env.PLAYWRIGHT_CHROMIUM;
  if (override) return override;
  const { default: sparticuz } = await import('@sparticuz/chromium');
  return sparticuz.executablePath();
}

type Entry = { type: string; text: string };

/**
 * Browser notices that say nothing about the element's correctness. Chromium's GPU process
 * posts "GPU stall due to ReadPixels" as a console warning whenever gl.readPixels has to wait
 * for the GPU, which a synchronous capture() must do by contract (the tests call it on purpose).
 * Only that Performance-category message is ignored: WebGL errors ("WebGL: INVALID_OPERATION: …")
 * arrive the same way and must still fail the test.
 */
const IGNORED = [/^\[\.WebGL-0x[0-9a-f]+\]GL Driver Message \(OpenGL, Performance, [A-Z_]+, \w+\): GPU stall due to ReadPixels/];

/**
 * Everything the page printed. Errors, warnings and uncaught exceptions fail the test at
 * teardown unless the test took them with `take()` (and, presumably, asserted on them).
 */
export class ConsoleLog {
  readonly entries: Entry[] = [];

  attach(page: Page): void {
    page.on('console', (m: ConsoleMessage) => {
      const loc = m.location();
      const where = loc.url ? ` (${loc.url}:${loc.lineNumber})` : '';
      if (IGNORED.some((re) => re.test(m.text()))) return;
      this.entries.push({ type: m.type(), text: m.text() + where });
    });
    page.on('pageerror', (e: Error) => this.entries.push({ type: 'pageerror', text: e.stack ?? String(e) }));
  }

  /** Removes and returns the entries of `type` ('warning', 'error', 'pageerror', 'log', …). */
  take(type: string): string[] {
    const out: string[] = [];
    for (let i = 0; i < this.entries.length; ) {
      if (this.entries[i].type === type) out.push(this.entries.splice(i, 1)[0].text);
      else i++;
    }
    return out;
  }

  /** Count of entries of `type` not yet taken. */
  count(type: string): number {
    return this.entries.filter((e) => e.type === type).length;
  }

  problems(): Entry[] {
    return this.entries.filter((e) => e.type === 'error' || e.type === 'warning' || e.type === 'pageerror');
  }
}

type TestFixtures = { consoleLog: ConsoleLog };
type WorkerFixtures = { browser: Browser };

export const test = base.extend<TestFixtures, WorkerFixtures>({
  browser: [
    async ({ playwright }, use) => {
      const executablePath = await chromiumExecutable();
      const browser = await playwright.chromium.launch({ executablePath, args: CHROMIUM_ARGS });
      await use(browser);
      await browser.close();
    },
    { scope: 'worker', timeout: 60_000 },
  ],

  page: async ({ page }, use) => {
    // Before any module loads: the renderer then checks gl.getError() after every frame and
    // reports errors with console.error, which consoleLog turns into a test failure.
    await page.addInitScript(() => {
      (globalThis as { __GLASS_PLANE_SCENE_CHECKS__?: boolean }).__GLASS_PLANE_SCENE_CHECKS__ = true;
    });
    await use(page);
  },

  consoleLog: [
    async ({ page }, use) => {
      const log = new ConsoleLog();
      log.attach(page);
      await use(log);
      // One more round trip, so messages posted just before the test ended have arrived.
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => r(null)))).catch(() => {});
      const problems = log.problems();
      if (problems.length) {
        throw new Error(
          `the page logged ${problems.length} unexpected console error(s)/warning(s)/page error(s):\n` +
            problems.map((p) => `  [${p.type}] ${p.text}`).join('\n'),
        );
      }
    },
    { auto: true },
  ],
});

/** The element as tests see it; typed here so page.evaluate callbacks typecheck. */
export interface SceneElement extends HTMLElement {
  /** Null while nothing can be drawn. */
  capture(pass?: CapturePass): ImageData | null;
  requestRender(): void;
  whenRefined(): Promise<void>;
  readonly stats: RenderStats;
  transparency: number;
  cubeDistance: number;
  ior: number;
  cameraPosition: [number, number, number];
  cameraRotation: [number, number];
}

export type Attrs = Record<string, string | number | boolean>;

export interface Mounted {
  /** CSS selector of the element (an id). */
  selector: string;
  /** detail of its `ready` event. */
  ready: FrameReport;
}

/** Opens a test page from tests/e2e/pages/ and waits until the element is defined. */
export async function openPage(page: Page, name = 'element'): Promise<void> {
  await page.goto(`/tests/e2e/pages/${name}.html`);
  await page.waitForFunction(() => customElements.get('glass-plane-scene') !== undefined, undefined, { timeout: 30_000 });
}

/**
 * Creates <glass-plane-scene> with `attrs` (true → present, false → absent), at `size` CSS px
 * when given (else the element's own default), appends it to the body and resolves with its
 * `ready` detail. Rejects on an `error` event or when ready has not come within 30 s.
 *
 * `refine` is 0 unless `attrs` sets it (so does mountHtml): a test of anything else captures the picture a frame draws
 * as the knobs say, the same one whenever it reads the canvas after `ready`; with the element's default a still view
 * would go on refining for a few frames after it (docs/refinement.md). tests/e2e/refinement.spec.ts tests the default.
 */
export async function mount(page: Page, attrs: Attrs = {}, size?: { width: number; height: number }): Promise<Mounted> {
  attrs = { refine: 0, ...attrs };
  return page.evaluate(
    ({ attrs, size }) =>
      new Promise<Mounted>((resolve, reject) => {
        const w = window as unknown as { __gpsCount?: number };
        w.__gpsCount = (w.__gpsCount ?? 0) + 1;
        const id = `gps-${w.__gpsCount}`;
        const el = document.createElement('glass-plane-scene');
        el.id = id;
        for (const [k, v] of Object.entries(attrs)) {
          if (v === false) continue;
          el.setAttribute(k, v === true ? '' : String(v));
        }
        if (size) {
          el.style.width = `${size.width}px`;
          el.style.height = `${size.height}px`;
        }
        const timer = setTimeout(() => reject(new Error(`#${id}: no ready event within 30 s`)), 30_000);
        el.addEventListener('ready', (e) => {
          clearTimeout(timer);
          resolve({ selector: `#${id}`, ready: (e as CustomEvent<FrameReport>).detail });
        }, { once: true });
        el.addEventListener('error', (e) => {
          clearTimeout(timer);
          const d = (e as unknown as CustomEvent<GlassPlaneSceneErrorDetail>).detail;
          reject(new Error(`#${id}: error event ${d?.type}: ${d?.message}`));
        }, { once: true });
        document.body.append(el);
      }),
    { attrs, size },
  );
}

/**
 * Runs `change` on the element in the page and resolves with the detail of the next `frame`
 * event it causes (the listener is in place before the change). `change` is serialized into
 * the page: it may only use its argument.
 */
export async function nextFrame(
  page: Page,
  selector: string,
  change: (el: SceneElement) => void = (el) => el.requestRender(),
  timeoutMs = 20_000,
): Promise<FrameReport> {
  return page.evaluate(
    ({ selector, changeSrc, timeoutMs }) =>
      new Promise<FrameReport>((resolve, reject) => {
        const el = document.querySelector(selector) as SceneElement | null;
        if (!el) return reject(new Error(`${selector} not found`));
        const timer = setTimeout(() => reject(new Error(`${selector}: no frame event within ${timeoutMs} ms`)), timeoutMs);
        el.addEventListener('frame', (e) => {
          clearTimeout(timer);
          resolve((e as CustomEvent<FrameReport>).detail);
        }, { once: true });
        (new Function('el', `(${changeSrc})(el)`) as (el: SceneElement) => void)(el);
      }),
    { selector, changeSrc: change.toString(), timeoutMs },
  );
}

/** Sets attributes (string → setAttribute, null/false → remove, true → present) and waits for the frame. */
export async function setAttributes(page: Page, selector: string, attrs: Record<string, string | number | boolean | null>): Promise<FrameReport> {
  return nextFrame(page, selector, new Function('el', `
    const attrs = ${JSON.stringify(attrs)};
    for (const [k, v] of Object.entries(attrs)) {
      if (v === null || v === false) el.removeAttribute(k);
      else el.setAttribute(k, v === true ? '' : String(v));
    }`) as (el: SceneElement) => void);
}

/** The element's capture(pass) as an RGBA image in Node (bytes travel as base64). */
export async function capture(page: Page, pass?: CapturePass, selector = 'glass-plane-scene'): Promise<RgbaImage> {
  const { width, height, b64 } = await page.evaluate(
    ({ selector, pass }) => {
      const el = document.querySelector(selector) as SceneElement | null;
      if (!el) throw new Error(`${selector} not found`);
      const img = pass === undefined ? el.capture() : el.capture(pass);
      if (!img) throw new Error(`${selector}.capture(${pass ?? ''}) returned ${String(img)}`);
      const bytes = new Uint8Array(img.data.buffer, img.data.byteOffset, img.data.byteLength);
      let s = '';
      for (let i = 0; i < bytes.length; i += 0x8000) s += String.fromCharCode(...bytes.subarray(i, i + 0x8000));
      return { width: img.width, height: img.height, b64: btoa(s) };
    },
    { selector, pass },
  );
  const buf = Buffer.from(b64, 'base64');
  expect(buf.length, 'capture() returned width × height × 4 bytes').toBe(width * height * 4);
  return { width, height, data: new Uint8Array(buf.buffer, buf.byteOffset, buf.length) };
}

/** The drawing buffer size of the element's canvas (in its open shadow root). */
export async function canvasSize(page: Page, selector = 'glass-plane-scene'): Promise<{ width: number; height: number }> {
  return page.evaluate((selector) => {
    const c = document.querySelector(selector)?.shadowRoot?.querySelector('canvas');
    if (!c) throw new Error(`${selector}: no canvas in the shadow root`);
    return { width: c.width, height: c.height };
  }, selector);
}
