// Golden images of every debug view at a fixed time and camera, compared with pixelmatch.
// Pixels come from the element's capture() (read back from GL), not page.screenshot(), so fonts
// and compositing cannot interfere. Regenerate with `npm run goldens` after looking at the change.
import { test, mount, openPage, capture } from './fixtures';
import { compareToGolden } from './helpers/golden';

const SIZE = { width: 320, height: 180 };
const VIEWS = ['none', 'reflection', 'scene', 'fresnel', 'passes'] as const;
const CAMERAS = {
  // No camera attributes: the element's default view (cube, its reflection, sphere through the glass).
  default: {},
  // Off to the right, looking back across the glass at a steeper angle: more Fresnel reflection.
  oblique: { 'camera-position': '2.5 1.6 5', 'camera-rotation': '-115 -8' },
} as const;

for (const [cameraName, cameraAttrs] of Object.entries(CAMERAS)) {
  test.describe(`camera ${cameraName}`, () => {
    for (const view of VIEWS) {
      test(`debug-view ${view}`, async ({ page }) => {
        await openPage(page);
        await mount(page, { time: 1.25, 'debug-view': view, ...cameraAttrs }, SIZE);
        compareToGolden(`${cameraName}-${view}`, await capture(page));
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
