// Golden images of every debug view at a fixed time and camera, compared with pixelmatch.
// The goldens are in linear light (`color-space="srgb"`, the default); goldens/none/ holds the
// frames as they were before color-space existed, which `none` must reproduce byte for byte.
// Pixels come from the element's capture() (read back from GL), not page.screenshot(), so fonts
// and compositing cannot interfere. Regenerate with `npm run goldens` after looking at the change.
import path from 'node:path';
import { test, expect, mount, openPage, capture, type RgbaImage } from './fixtures';
import { compareToGolden, GOLDEN_DIR, readPng } from './helpers/golden';

const SIZE = { width: 320, height: 180 };
const VIEWS = ['none', 'reflection', 'scene', 'fresnel', 'passes'] as const;
const CAMERAS = {
  // No camera attributes: the element's default view (cube, its reflection, sphere through the glass).
  default: {},
  // Off to the right, looking back across the glass at a steeper angle: more Fresnel reflection.
  oblique: { 'camera-position': '2.5 1.6 5', 'camera-rotation': '-115 -8' },
} as const;

/** Bytes that differ between `image` and goldens/none/<name>.png (0: the same frame). */
function bytesDifferingFromNone(name: string, image: RgbaImage): number {
  const golden = readPng(path.join(GOLDEN_DIR, 'none', `${name}.png`));
  expect([image.width, image.height]).toEqual([golden.width, golden.height]);
  let n = 0;
  for (let i = 0; i < golden.data.length; i++) if (golden.data[i] !== image.data[i]) n++;
  return n;
}

for (const [cameraName, cameraAttrs] of Object.entries(CAMERAS)) {
  test.describe(`camera ${cameraName}`, () => {
    for (const view of VIEWS) {
      test(`debug-view ${view}`, async ({ page }) => {
        await openPage(page);
        await mount(page, { time: 1.25, 'debug-view': view, ...cameraAttrs }, SIZE);
        compareToGolden(`${cameraName}-${view}`, await capture(page));
      });

      test(`debug-view ${view}, color-space none: today's frame byte for byte`, async ({ page }) => {
        await openPage(page);
        await mount(page, { time: 1.25, 'debug-view': view, 'color-space': 'none', ...cameraAttrs }, SIZE);
        expect(bytesDifferingFromNone(`${cameraName}-${view}`, await capture(page))).toBe(0);
      });
    }
  });
}

// The README's picture is this golden: what the element draws by default, at 640×360, kept
// true by the same comparison.
test('README picture: the default view at 640×360', async ({ page }) => {
  await openPage(page);
  await mount(page, { time: 1.25 }, { width: 640, height: 360 });
  compareToGolden('readme-default-view', await capture(page));
});

test('README picture with color-space none: the frame before color-space, byte for byte', async ({ page }) => {
  await openPage(page);
  await mount(page, { time: 1.25, 'color-space': 'none' }, { width: 640, height: 360 });
  expect(bytesDifferingFromNone('readme-default-view', await capture(page))).toBe(0);
});
