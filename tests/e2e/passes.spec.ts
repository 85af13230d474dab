// Each pass checked against the float64 reference renderer, tightly enough that a wrong pass
// fails: the reflection in the final image, the glass seen from the −Z side, the
// clip of an object straddling the glass, the `discard` clip fallback, the `classic` composite.
// Masks come from the reference's geometry (keys, regions), never from colours.
//
// Each bound sits 2 dB under the figure measured here (SwiftShader, 320×180, deterministic: the
// same to 0.1 dB run after run; helpers/bounds.ts), far above the figures under the mutations of
// `npm run test:mutations:browser` (scripts/mutations/glass.mjs); the comments give both.
import type { Page } from '@playwright/test';
import { test, expect, mount, openPage, capture, type Attrs, type RgbaImage } from './fixtures';
import { renderReference, regionOfKey, REGION_CUBE, REGION_EDGE, type ReferenceImage } from '../../src/reference';
import type { FrameState } from '../../src/frame/types';
import { DEFAULT_CAMERA_POSITION, DEFAULT_CAMERA_ROTATION, DEFAULT_CUBE_DISTANCE } from '../../src/element/attributes';
import { cameraAttrs, diffImages, formatDiff, lookAt } from './helpers/stability';
import { dominantPixels } from './helpers/pixels';
import { formatError, glassMask, interiorMask, maskedError, reflectsCubeMask, type MaskedError } from './helpers/reference-match';
import { withoutClipDistance } from './helpers/without-clip-distance';
import type { Vec3 } from './helpers/projection';
import { MARGIN_DB } from './helpers/bounds';

const SIZE = { width: 320, height: 180 };
const TIME = 1.25;
/** The element at its closest to the reference: MSAA 4 against 4×4 samples, a full-size reflection. */
// Values as stored (color-space none): these tests guard the passes' geometry and the glass
// equation, and their figures under each mutation were measured so; linear light is tested
// against the reference in scene-reference, orthographic, stability and course-files.
const QUALITY: Attrs = { time: TIME, samples: 4, 'reflection-scale': 1, shading: 'phong', tessellation: 'auto', 'color-space': 'none' };
const SPP = 4;

interface Pose { position: Vec3; yaw: number; pitch: number }
const DEFAULT_POSE: Pose = { position: DEFAULT_CAMERA_POSITION as Vec3, yaw: DEFAULT_CAMERA_ROTATION[0], pitch: DEFAULT_CAMERA_ROTATION[1] };
const poseAttrs = (p: Pose) => cameraAttrs(p.position, p.yaw, p.pitch);

type Scene = Pick<FrameState, 'cubeDistance' | 'transparency' | 'ior' | 'fresnel'>;
const DEFAULT_SCENE: Scene = { cubeDistance: DEFAULT_CUBE_DISTANCE, transparency: 0.5, ior: 1.5, fresnel: 'exact' };
const sceneAttrs = (s: Scene): Attrs => ({ 'cube-distance': s.cubeDistance, transparency: s.transparency, ior: s.ior, fresnel: s.fresnel });

function reference(view: 'final' | 'reflection', pose: Pose, scene: Scene): ReferenceImage {
  return renderReference({
    ...SIZE, time: TIME, spin: 0.8, fov: 60, colorSpace: 'none', view, cameraPosition: pose.position, yaw: pose.yaw, pitch: pose.pitch, ...scene,
  }, { samplesPerAxis: SPP });
}

/** Mounts the element for `pose` and `scene` and returns `pass` with the reference of the same view. */
async function renderBoth(page: Page, pose: Pose, scene: Scene, pass: 'final' | 'reflection'): Promise<[RgbaImage, ReferenceImage]> {
  const { selector } = await mount(page, { ...QUALITY, ...sceneAttrs(scene), ...poseAttrs(pose) }, SIZE);
  return [await capture(page, pass === 'final' ? undefined : pass, selector), reference(pass, pose, scene)];
}

/** Records a measured figure where the report and the mutation script's log show it. */
function note(what: string, figure: MaskedError | string): void {
  const line = `${what}: ${typeof figure === 'string' ? figure : formatError(figure)}`;
  console.log(line);
  test.info().annotations.push({ type: 'figure', description: line });
}

function expectAtLeast(e: MaskedError, boundDb: number, what: string): void {
  note(what, e);
  expect(e.psnr, `${what}: ${formatError(e)}, bound ${boundDb} dB`).toBeGreaterThanOrEqual(boundDb);
}

test.beforeEach(async ({ page }) => {
  await openPage(page);
});

test('final image, default view: where the glass reflects the cube it matches the reference', async ({ page }) => {
  // Measured over the ~1,100 px where the glass reflects the cube (edge band left out): 49.1 dB.
  // Reflection from the unmirrored camera: 29.4 dB; clip plane flipped (nothing reflected):
  // 29.4 dB; F forced to 0: 26.4 dB. Bound 47.1 dB.
  const [image, ref] = await renderBoth(page, DEFAULT_POSE, DEFAULT_SCENE, 'final');
  const mask = reflectsCubeMask(ref);
  const e = maskedError(ref, image, mask);
  expect(e.pixels, 'the glass reflects the cube over enough pixels to judge').toBeGreaterThan(500);
  expectAtLeast(e, 49.1 - MARGIN_DB, 'default view, glass reflecting the cube');
});

// From behind the glass (z < 0) looking back at it, 30–50° off its normal: the glass reflects the
// sphere's side and N·V is negative for the +Z normal. Without |N·V| the clamped cosθ is 0 and
// F = 1: a full mirror instead of the dark glass.
const BACK_EYE: Vec3 = [2.5, 2.2, -4.5];
const BACK_POSE: Pose = { position: BACK_EYE, ...lookAt(BACK_EYE, [0, 1, 0]) };

test('final image from the −Z side: the glass matches the reference', async ({ page }) => {
  // Measured on the glass (~24,000 px): 52.1 dB; abs() dropped from cosθ: 24.9 dB. Bound 50.1 dB.
  const [image, ref] = await renderBoth(page, BACK_POSE, DEFAULT_SCENE, 'final');
  const e = maskedError(ref, image, glassMask(ref));
  expect(e.pixels, 'the glass fills much of the view').toBeGreaterThan(10_000);
  expectAtLeast(e, 52.1 - MARGIN_DB, '−Z side, glass');
});

// cube-distance 0: the cube's centre is on the glass, so culling (by bounds) cannot drop it from
// the reflection pass; only the GPU clip keeps its far half out. Unclipped, the far half lies
// between the mirrored eye and the glass and covers the near half's mirror image.
const STRADDLING: Scene = { ...DEFAULT_SCENE, cubeDistance: 0 };

test('cube straddling the glass (cube-distance 0): the reflection pass holds its near half only', async ({ page }) => {
  // Measured over the whole pass (edge band left out): 53.7 dB, and 0 of 853 red pixels where the
  // reference reflects nothing. Far-side clip removed: 38.7 dB, 257 of 1,190; clip plane flipped:
  // 35.7 dB, 257 of 337; unmirrored camera: 38.0 dB, 190 of 190. Bounds 51.7 dB and 10 px (a
  // margin for pixels on the cut, where a tie in rasterizing the clipped edge may leave some red).
  const [image, ref] = await renderBoth(page, DEFAULT_POSE, STRADDLING, 'reflection');
  expect(ref.keys.filter((k) => regionOfKey(k) === REGION_CUBE).length, 'the reference reflects the cube').toBeGreaterThan(300);
  expectAtLeast(maskedError(ref, image, interiorMask(ref)), 53.7 - MARGIN_DB, 'straddling, reflection pass');
  const red = dominantPixels(image, 'r');
  const stray = red.filter((p) => ref.keys[p] === 0 && ref.regions[p] !== REGION_EDGE).length;
  note('straddling, red px where the reference reflects nothing', `${stray} of ${red.length}`);
  expect(stray, `red pixels where the reference reflects nothing (of ${red.length} red)`).toBeLessThanOrEqual(10);
});

test('the discard clip fallback draws what gl_ClipDistance draws', async ({ page }) => {
  // Same straddling cube, MSAA off so both clip paths rasterise the same samples. Measured: 16 px
  // (0.03 %) beyond 8 levels, on the cut, where the two ways of clipping round the edge apart.
  // Discard removed: 942 px (1.6 %), max 97; discard inverted: 1,803 px (3.1 %). Bound 24 px
  // (1.5× the measured: ties on the cut).
  const straddling = async () => {
    const { selector } = await mount(page, { ...QUALITY, samples: 0, ...sceneAttrs(STRADDLING), ...poseAttrs(DEFAULT_POSE) }, SIZE);
    return capture(page, 'reflection', selector);
  };
  const clipped = await straddling();
  await page.addInitScript(withoutClipDistance);
  await openPage(page);
  const discarded = await straddling();
  const refused = await page.evaluate(() => (globalThis as { __clipDistanceRefused__?: number }).__clipDistanceRefused__);
  expect(refused, 'the renderer asked for WEBGL_clip_cull_distance and was refused').toBeGreaterThan(0);
  const d = diffImages(clipped, discarded);
  note('discard vs clip distance', formatDiff(d));
  expect(d.changed, `discard vs clip distance: ${formatDiff(d)}`).toBeLessThanOrEqual(24);
});

test('classic Fresnel: the final image matches the reference on the glass', async ({ page }) => {
  // The default view, where the glass shows its body, the sphere behind and the cube's
  // reflection. Measured: glass 49.4 dB, where it reflects the cube 52.8 dB. Alpha without its
  // (1 − T): 36.0 / 32.9 dB; colour not premultiplied: 19.5 / 18.7 dB. Bounds 47.4 / 50.8 dB.
  const classic: Scene = { ...DEFAULT_SCENE, fresnel: 'classic' };
  const [image, ref] = await renderBoth(page, DEFAULT_POSE, classic, 'final');
  expectAtLeast(maskedError(ref, image, glassMask(ref)), 49.4 - MARGIN_DB, 'classic, glass');
  expectAtLeast(maskedError(ref, image, reflectsCubeMask(ref)), 52.8 - MARGIN_DB, 'classic, glass reflecting the cube');
});
