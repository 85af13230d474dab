// docs/knobs.md#many-elements: many elements on one page (more than Chromium's ~16 live WebGL contexts).
// 40 elements with different attributes in a scrolling grid (tests/e2e/pages/many.html): each
// renders what it would render alone, none loses its context, scrolling brings the rest in, and
// keys go to the focused element only.
import { test, expect, mount, openPage, capture, type SceneElement, type Attrs } from './fixtures';
import { note } from './helpers/bounds';
import type { Page } from '@playwright/test';
import { compareImages, DIFF_BUDGET, PIXEL_THRESHOLD } from './helpers/golden';
import { countUnlike } from './helpers/pixels';
import type { CameraChangeDetail, GlassPlaneSceneErrorDetail } from '../../src/element/types';

const COUNT = 40;
const SIZE = { width: 160, height: 90 }; // many.html's grid cells
const BACKGROUND = [26, 26, 26] as const;
const FRESNEL = ['exact', 'schlick', 'classic'] as const;
const TOO_MANY = /Too many active WebGL contexts/i;

/** Element i's attributes: every one different, all around the default view (cube, reflection, sphere in view). */
function attrsOf(i: number): Attrs {
  return {
    time: (1 + 0.05 * i).toFixed(2),
    transparency: (((i * 37) % 100) / 100).toFixed(2),
    'cube-distance': (1.5 + (i % 5) * 0.4).toFixed(1),
    ior: (1.2 + (i % 7) * 0.3).toFixed(1),
    fresnel: FRESNEL[i % 3],
    'camera-position': `${(5.25 - (i % 4) * 0.4).toFixed(2)} ${(3 - (i % 3) * 0.4).toFixed(2)} ${(1 + (i % 5) * 0.4).toFixed(2)}`,
    'camera-rotation': `${(-170.8 + ((i % 6) - 2) * 3).toFixed(1)} ${(-19.6 + (i % 4) * 2).toFixed(1)}`,
    controls: true,
  };
}

interface ManyLog {
  ready: boolean[];
  errors: string[];
}

/** Fills many.html's grid with COUNT elements (#many-1 … #many-40), logging ready and error. */
async function fill(page: Page): Promise<void> {
  await openPage(page, 'many');
  const all = Array.from({ length: COUNT }, (_, i) => attrsOf(i));
  await page.evaluate((all) => {
    const log: ManyLog = { ready: all.map(() => false), errors: [] };
    (window as unknown as { __many: ManyLog }).__many = log;
    const grid = document.getElementById('grid')!;
    all.forEach((attrs, i) => {
      const el = document.createElement('glass-plane-scene');
      el.id = `many-${i + 1}`;
      for (const [k, v] of Object.entries({ refine: '0', ...attrs } as Attrs)) if (v !== false) el.setAttribute(k, v === true ? '' : String(v));
      el.addEventListener('ready', () => { log.ready[i] = true; }, { once: true });
      el.addEventListener('error', (e) => {
        const d = (e as unknown as CustomEvent<GlassPlaneSceneErrorDetail>).detail;
        log.errors.push(`#${el.id}: ${d?.type}: ${d?.message}`);
      });
      grid.append(el);
    });
  }, all);
}

const manyLog = (page: Page) => page.evaluate(() => (window as unknown as { __many: ManyLog }).__many);

/** Indices of the elements that intersect the viewport now. */
const inView = (page: Page) =>
  page.evaluate(() =>
    [...document.querySelectorAll('glass-plane-scene')].flatMap((el, i) => {
      const r = el.getBoundingClientRect();
      return r.bottom > 0 && r.top < innerHeight && r.right > 0 && r.left < innerWidth ? [i] : [];
    }),
  );

/** Scrolls to `y` and waits until every element in view has fired ready. */
async function scrollAndWait(page: Page, y: number): Promise<void> {
  await page.evaluate((y) => window.scrollTo(0, y), y);
  const visible = await inView(page);
  await expect
    .poll(async () => {
      const log = await manyLog(page);
      expect(log.errors, 'error events').toEqual([]);
      return visible.filter((i) => !log.ready[i]).map((i) => `#many-${i + 1}`);
    }, { message: `elements in view at scrollY ${y} without ready`, timeout: 30_000 })
    .toEqual([]);
}

test.describe('forty elements', () => {
  test('each renders what it renders alone; scrolling brings in the rest; no context is lost', async ({ page, consoleLog }) => {
    test.setTimeout(180_000);
    await fill(page);
    await scrollAndWait(page, 0);
    const firstView = await inView(page);
    expect(firstView.length, 'elements in the first view').toBeLessThan(COUNT);

    // Those below the fold have not drawn (IntersectionObserver).
    const below = await page.evaluate(
      (n) => [...document.querySelectorAll('glass-plane-scene')].slice(-n).map((el) => (el as SceneElement).stats.frames),
      4,
    );
    expect(below, 'frames drawn by the last row, out of view').toEqual([0, 0, 0, 0]);

    // Scroll down through the page, a viewport at a time.
    const height = await page.evaluate(() => document.documentElement.scrollHeight - innerHeight);
    expect(height, 'the page scrolls').toBeGreaterThan(200);
    for (let y = 250; y < height + 250; y += 250) await scrollAndWait(page, Math.min(y, height));
    const log = await manyLog(page);
    expect(log.ready.filter((r) => !r).length, 'elements that never fired ready').toBe(0);
    expect(log.errors).toEqual([]);

    // Every element drew something like the scene, not a blank or lost canvas.
    const sample = [0, 1, 2, 3, 13, 22, 31, 39];
    const captures = new Map<number, Awaited<ReturnType<typeof capture>>>();
    const blank: string[] = [];
    for (let i = 0; i < COUNT; i++) {
      const selector = `#many-${i + 1}`;
      await page.evaluate((s) => document.querySelector(s)!.scrollIntoView({ block: 'center' }), selector);
      const img = await capture(page, undefined, selector);
      expect([img.width, img.height], `${selector} size`).toEqual([SIZE.width, SIZE.height]);
      // The scene: some background (0.1 grey), and the cube, the sphere or the glass over it
      // (the clearest glass in the set leaves ~750 other pixels). A black or empty canvas fails both.
      const drawn = countUnlike(img, BACKGROUND, 3);
      const background = img.width * img.height - drawn;
      if (drawn < 400 || background < 1000) blank.push(`${selector}: ${drawn} scene pixels, ${background} background pixels`);
      if (sample.includes(i)) captures.set(i, img);
    }
    expect(blank, 'elements that do not look like the scene').toEqual([]);
    expect(consoleLog.entries.filter((e) => TOO_MANY.test(e.text)).map((e) => e.text), '"Too many active WebGL contexts"').toEqual([]);

    // The same attributes alone on a fresh page give the same pixels.
    const rows: string[] = [];
    for (const i of sample) {
      await openPage(page);
      const { selector } = await mount(page, attrsOf(i), SIZE);
      const alone = await capture(page, undefined, selector);
      const { differing } = compareImages(captures.get(i)!, alone, PIXEL_THRESHOLD);
      rows.push(`#many-${i + 1}: ${differing}`);
      expect(differing, `#many-${i + 1} on the busy page vs alone (pixels differing)`).toBeLessThanOrEqual(
        Math.floor(DIFF_BUDGET * SIZE.width * SIZE.height),
      );
    }
    test.info().annotations.push({ type: 'differing pixels vs alone', description: rows.join(', ') });
  });

  test('keys go to the focused element only', async ({ page }) => {
    test.setTimeout(120_000);
    await fill(page);
    await scrollAndWait(page, 0);
    await page.evaluate(() => {
      const w = window as unknown as { __changes: Record<string, number> };
      w.__changes = {};
      for (const el of document.querySelectorAll('glass-plane-scene')) {
        w.__changes[el.id] = 0;
        el.addEventListener('camera-change', (e) => {
          void (e as CustomEvent<CameraChangeDetail>).detail;
          w.__changes[el.id]++;
        });
      }
    });
    const poses = () =>
      page.evaluate(() => [...document.querySelectorAll('glass-plane-scene')].map((el) => JSON.stringify((el as SceneElement).cameraPosition)));
    const start = await poses();
    await page.focus('#many-3');
    await page.keyboard.down('KeyW');
    await page.waitForTimeout(300);
    await page.keyboard.up('KeyW');
    await expect.poll(async () => (await poses())[2], { message: '#many-3 moved' }).not.toBe(start[2]);
    await page.waitForTimeout(300);
    const end = await poses();
    const moved = end.flatMap((p, i) => (p !== start[i] ? [`#many-${i + 1}`] : []));
    expect(moved, 'elements whose camera moved').toEqual(['#many-3']);
    const changes = await page.evaluate(() => (window as unknown as { __changes: Record<string, number> }).__changes);
    expect(Object.entries(changes).filter(([, n]) => n > 0).map(([id]) => id), 'elements that fired camera-change').toEqual(['many-3']);
  });
});

// Moved from properties.spec.ts (was test.fail there, while each element had its own context).
test("twenty elements on one page all render (more than the browser's live contexts)", async ({ page }) => {
  await openPage(page);
  const selectors: string[] = [];
  for (let i = 0; i < 20; i++) selectors.push((await mount(page, { time: 1.25 }, { width: 80, height: 45 })).selector);
  await page.waitForTimeout(300);
  for (const s of selectors) {
    const img = await capture(page, undefined, s);
    note(`${s}: ${countUnlike(img, [26, 26, 26], 3)} px unlike the background`);
    expect(countUnlike(img, [26, 26, 26], 3), `${s} rendered (measured 1,837 px each)`).toBeGreaterThanOrEqual(0.9 * 1837);
  }
});
