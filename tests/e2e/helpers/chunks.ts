// For the specs of the chunks the core leaves out (docs/package.md#chunks): which were fetched, holding one
// back or blocking it, counting the frames drawn meanwhile, and the one warning a failed chunk gives.
import type { Page } from '@playwright/test';
import { expect, openPage, capture, type ConsoleLog, type RgbaImage } from '../fixtures';
import { mountHtml } from './scene-children';

export const samePixels = (a: RgbaImage, b: RgbaImage): boolean => a.width === b.width && a.data.every((v, i) => v === b.data[i]);

/** Those of `names` that some resource the page fetched so far is named after. */
export const fetchedChunks = (page: Page, names: string[]): Promise<string[]> =>
  page.evaluate((ns) => ns.filter((n) => performance.getEntriesByType('resource').some((e) => e.name.includes(n))), names);

export const wait = (page: Page, ms: number): Promise<unknown> => page.evaluate((t) => new Promise((r) => setTimeout(r, t)), ms);

/** Holds back every request for the chunk `name` by `ms`. */
export async function holdBack(page: Page, name: string, ms: number): Promise<void> {
  await page.route(`**/*${name}*`, async (route) => {
    await new Promise((r) => setTimeout(r, ms));
    await route.continue();
  });
}

/** Fails every request for the chunk `name`. */
export async function blockChunk(page: Page, name: string): Promise<void> {
  await page.route(`**/*${name}*`, (route) => route.abort());
}

/** Counts the first scene element's `frame` events from now on (read them with framesSeen). */
export const countFrames = (page: Page): Promise<void> => page.evaluate(() => {
  const w = window as unknown as { __frames: number };
  w.__frames = 0;
  document.querySelector('glass-plane-scene')!.addEventListener('frame', () => w.__frames++);
});
export const framesSeen = (page: Page): Promise<number> => page.evaluate(() => (window as unknown as { __frames: number }).__frames);

/** Exactly one warning containing `text`; the browser's own error lines for the failed fetch are taken too. */
export function expectOneWarning(consoleLog: ConsoleLog, text: string): void {
  expect(consoleLog.take('warning').filter((w) => w.includes(text))).toHaveLength(1);
  consoleLog.take('error');
}

/**
 * An attribute that needs the chunk `name`, set on a default scene (160×90, time 0, spin 0) while
 * that chunk is held back 600 ms: no frame is drawn until it is in, and the first is the picture
 * the element draws with the attribute set from the start (which must differ from the plain one).
 */
export async function expectFrameHeldFor(page: Page, name: string, attribute: string, value: string): Promise<void> {
  const scene = (attrs: string) => `<glass-plane-scene refine="0" time="0" spin="0" ${attrs}></glass-plane-scene>`;
  await openPage(page);
  await mountHtml(page, scene(`${attribute}="${value}"`));
  await wait(page, 300);
  const wanted = await capture(page);
  await openPage(page);
  await mountHtml(page, scene(''));
  await wait(page, 300);
  expect(samePixels(wanted, await capture(page)), `${attribute}="${value}" changes the picture`).toBe(false);
  await holdBack(page, name, 600);
  await openPage(page);
  await mountHtml(page, scene(''));
  await countFrames(page);
  await page.evaluate(([a, v]) => document.querySelector('glass-plane-scene')!.setAttribute(a, v), [attribute, value]);
  await wait(page, 400);
  expect(await framesSeen(page), `frames drawn while ${name} is held back`).toBe(0);
  await expect.poll(() => framesSeen(page), { timeout: 5000 }).toBeGreaterThan(0);
  expect(samePixels(await capture(page), wanted), 'the first frame once it is in').toBe(true);
}
