// For the specs of the chunks the core leaves out (issue 22): which were fetched, holding one
// back or blocking it, counting the frames drawn meanwhile, and the one warning a failed chunk gives.
import type { Page } from '@playwright/test';
import { expect, type ConsoleLog, type RgbaImage } from '../fixtures';

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
