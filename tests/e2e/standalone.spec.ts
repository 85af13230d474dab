// The self-contained build (dist/glass-plane-scene.standalone.js) in a page with only a
// <script type="module"> tag: it defines the element and renders. `npm test` builds first.
import fs from 'node:fs';
import path from 'node:path';
import { test, expect, openPage, mount, capture } from './fixtures';
import { note } from './helpers/bounds';
import { countUnlike } from './helpers/pixels';

const BUNDLE = path.resolve('dist/glass-plane-scene.standalone.js');

test('the standalone bundle defines the element, which renders', async ({ page }) => {
  expect(fs.existsSync(BUNDLE), `${path.relative(process.cwd(), BUNDLE)} is missing: run \`npm run build\``).toBe(true);
  await openPage(page, 'standalone');
  // The page loaded the bundle alone: no module from /src/ was requested.
  const scripts = await page.evaluate(() => performance.getEntriesByType('resource').map((e) => e.name));
  expect(scripts.some((s) => s.includes('/src/'))).toBe(false);
  const { ready } = await mount(page, { time: 1.25 }, { width: 320, height: 180 });
  expect([ready.width, ready.height]).toEqual([320, 180]);
  const image = await capture(page);
  // Background is 0.1 grey (26); the cube, glass and sphere make well over 1000 other pixels.
  note(`standalone: ${countUnlike(image, [26, 26, 26], 3)} px unlike the background`);
  expect(countUnlike(image, [26, 26, 26], 3), 'measured 27,657 px').toBeGreaterThanOrEqual(0.9 * 27_657);
});
