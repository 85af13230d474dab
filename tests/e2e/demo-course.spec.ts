// The demo's course page (demo/course.html): a scene read from the course's files (docs/course-files.md), a switch between the
// two renderers, and the difference image between them.
import { test, expect, capture } from './fixtures';
import { MARGIN_DB, note } from './helpers/bounds';

test('the course page draws its files with either renderer and shows the difference image between them', async ({ page }) => {
  test.setTimeout(90_000);
  await page.setViewportSize({ width: 1000, height: 640 });
  await page.goto('/demo/course.html');
  // Both models loaded, and a frame drawn with them.
  await page.waitForFunction(() => [...document.querySelectorAll('glass-object')].every((o) => (o as unknown as { loading: boolean }).loading === false), undefined, { timeout: 30_000 });
  await page.evaluate(() => new Promise((r) => {
    const el = document.getElementById('scene') as unknown as HTMLElement & { requestRender(): void };
    el.addEventListener('frame', r, { once: true });
    el.requestRender();
  }));
  const shot = await capture(page, undefined, '#scene');
  let lit = 0;
  for (let i = 0; i < shot.data.length; i += 4) if (shot.data[i] + shot.data[i + 1] + shot.data[i + 2] > 3 * 40) lit++;
  note(`course page: ${lit} lit px`);
  expect(lit, 'pixels of the chalice and the bump (measured 36,485)').toBeGreaterThanOrEqual(0.9 * 36_485);
  await page.selectOption('select[data-attr="renderer"]', 'software');
  await expect.poll(() => page.evaluate(() => (document.getElementById('scene') as unknown as { stats: { renderer: string } }).stats.renderer)).toBe('software');
  await page.click('#compare');
  await expect(page.locator('#difference-caption')).toContainText('dB between the two renderers', { timeout: 30_000 });
  const caption = await page.locator('#difference-caption').textContent();
  const db = Number(/([\d.]+) dB/.exec(caption!)![1]);
  console.log(`course page: ${caption}`);
  expect(db, 'WebGL and software agree on the course scene (measured 49.1 dB)').toBeGreaterThanOrEqual(49.1 - MARGIN_DB);
  expect(await page.evaluate(() => (document.getElementById('difference') as HTMLCanvasElement).width)).toBeGreaterThan(100);
});
