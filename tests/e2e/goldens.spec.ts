// Golden images of every debug view at a fixed time and camera, compared with pixelmatch.
// The goldens are in linear light (`color-space="srgb"`, the default); goldens/none/ holds the
// frames as they were before color-space existed, which `none` must reproduce byte for byte.
// Pixels come from the element's capture() (read back from GL), not page.screenshot(), so fonts
// and compositing cannot interfere. Regenerate with `npm run goldens` after looking at the change.
import path from 'node:path';
import { test, expect, mount, openPage, capture, nextFrame, type RgbaImage } from './fixtures';
import { mountHtml } from './helpers/scene-children';
import { compareToGolden, GOLDEN_DIR, readPng } from './helpers/golden';
import { differingBytes } from '../unit/helpers/pixel-diff';
import { bunnyGlb } from './helpers/gltf-models';

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
  return differingBytes(golden.data, image.data);
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

// The README's rough glass (docs/rough-glass.md#roughness): the bench's floor — a cube resting on the glass, a sphere
// 1.5 above it — at roughness 0.3 and ior 10, where the glass shows mostly the reflection: sharp
// at the cube's contact, the sphere's light spread wide.
test('README picture: a rough glass floor at 640×360', async ({ page }) => {
  await openPage(page);
  await mountHtml(page, `<glass-plane-scene refine="0" time="0" spin="0" pixel-ratio="1" ior="10" roughness="0.3"
    glass-center="0 0 0" glass-normal="0 1 0" glass-size="8 8" background="0.1 0.1 0.12"
    camera-position="0.3 1.9 5.2" camera-target="0 0.6 0">
    <glass-object shape="cube" position="-0.9 0.5 0.2" rotation="0 25 0" diffuse="0.9 0.3 0.3" ambient="0.9 0.3 0.3"></glass-object>
    <glass-object shape="sphere" position="0.9 2 -0.2" diffuse="0.3 0.8 0.4" ambient="0.3 0.8 0.4"></glass-object>
  </glass-plane-scene>`);
  await nextFrame(page, 'glass-plane-scene', (el) => { el.style.width = '640px'; el.style.height = '360px'; });
  const image = await capture(page);
  expect([image.width, image.height]).toEqual([640, 360]);
  compareToGolden('readme-rough-floor', image);
});

// The README's glTF picture (docs/gltf.md): a GLB made by the tests — the Stanford bunny, gold, its
// node scaling and turning it — standing on a glass floor, its metallic-roughness material lit by the
// scene's light (docs/pbr.md#the-scenes-lights), tone mapped (PBR Neutral, tone-mapping="auto"); the environment's light is still to come.
test('README picture: a GLB on a glass floor at 640×360', async ({ page }) => {
  const glb = await bunnyGlb();
  await page.route('**/wild/bunny.glb', (route) => route.fulfill({ status: 200, contentType: 'model/gltf-binary', body: Buffer.from(glb) }));
  await openPage(page);
  await mountHtml(page, `<glass-plane-scene refine="0" time="0" spin="0" pixel-ratio="1" ior="1.5" samples="4"
    glass-center="0 0 0" glass-normal="0 1 0" glass-size="8 8" background="0.1 0.1 0.12"
    camera-position="0.2 1.5 3.4" camera-target="0 0.55 0">
    <glass-object src="/wild/bunny.glb"></glass-object>
    <glass-light direction="0.5 1 0.8"></glass-light>
  </glass-plane-scene>`);
  await nextFrame(page, 'glass-plane-scene', (el) => { el.style.width = '640px'; el.style.height = '360px'; });
  const image = await capture(page);
  expect([image.width, image.height]).toEqual([640, 360]);
  compareToGolden('readme-gltf-floor', image);
});
