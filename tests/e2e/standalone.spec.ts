// The self-contained build (dist/glass-plane-scene.standalone.js) in a page with only a
// <script type="module"> tag: it defines the element and renders. `npm test` builds first.
import fs from 'node:fs';
import path from 'node:path';
import { test, expect, openPage, mount, capture } from './fixtures';
import { note } from './helpers/bounds';
import { countUnlike } from './helpers/pixels';
import { differingBytes } from '../unit/helpers/pixel-diff';

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

// The build minifies the shaders (scripts/glsl-minify.ts) and splits rough glass and the software
// renderer into chunks: the standalone file must draw what the sources draw, pixel for pixel.
for (const [name, attrs] of [
  ['the default scene', { time: 1.25 }],
  ['rough glass (its chunk)', { time: 1.25, roughness: 0.4 }],
  ['the software renderer (its chunks)', { time: 1.25, renderer: 'software' }],
] as const) {
  test(`the standalone bundle draws ${name} as the sources do, byte for byte`, async ({ page }) => {
    const frames = [];
    for (const which of ['standalone', 'element']) {
      await openPage(page, which);
      await mount(page, attrs, { width: 160, height: 90 });
      await page.evaluate(() => new Promise((r) => setTimeout(r, 300)));
      frames.push(await capture(page));
    }
    const [built, sources] = frames;
    expect(differingBytes(built.data, sources.data), `bytes that differ between the standalone bundle and the sources (${name})`).toBe(0);
    expect(countUnlike(built, [26, 26, 26], 3), 'not an empty frame').toBeGreaterThan(2000);
  });
}
