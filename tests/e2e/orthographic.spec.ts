// projection="orthographic" (docs/interaction.md#orthographic-projection): the default view drawn orthographically matches the
// float64 reference, its reflection is still there for a viewer to see, switching back leaves
// perspective exactly as it was, and a bad value warns once and falls back.
import { test, expect, mount, openPage, capture, setAttributes, nextFrame, type RgbaImage, type SceneElement } from './fixtures';
import { renderReference, compareImages, glassReflectsCube, type ReferenceImage } from '../../src/reference';
import type { Projection } from '../../src/frame/types';
import { defaultFrameState } from '../unit/helpers/frame-state';
import { DEFAULT_CAMERA_ROTATION } from '../../src/element/attributes';
import { formatError, maskedError, reflectsCubeMask } from './helpers/reference-match';
import { LEVEL, pair, visibility } from './helpers/reflection-visibility';
import { differingPixels } from '../unit/helpers/pixel-diff';
import { expectPsnr, MARGIN_DB } from './helpers/bounds';

const TIME = 1.25;

/** The default scene and camera at `time`, through `projection`, as the reference draws it. */
function reference(width: number, height: number, time: number, projection: Projection, samplesPerAxis = 1): ReferenceImage {
  return renderReference(defaultFrameState({ width, height, time, colorSpace: 'none', projection }), { samplesPerAxis });
}

function note(line: string): void {
  console.log(line);
  test.info().annotations.push({ type: 'figure', description: line });
}

test.beforeEach(async ({ page }) => {
  await openPage(page);
});

// Measured (SwiftShader, 320×180): 48.3 dB overall (objects 42.3, glass 51.2, edges 40.5), 50.2 dB
// where the glass reflects the cube; the bounds sit 2 dB under each. Broken on purpose: glass.frag's
// cosθ from the perspective V (normalize(−relPos)) gives 42.1 dB overall and 30.9 dB on the
// reflection; the specular from the perspective V gives 37.7 dB overall (objects 26.7).
test('orthographic default view: within 2 dB of its measured PSNR against the float64 reference, the cube\'s reflection included', async ({ page }) => {
  const size = { width: 320, height: 180 };
  // The element at its closest to the reference: MSAA 4 against 4×4 samples, a full-size reflection.
  const { selector } = await mount(page, {
    time: TIME, projection: 'orthographic', samples: 4, 'reflection-scale': 1, shading: 'phong', tessellation: 'auto',
    // As stored, as its figures (and those under the mutations) were measured; linear light is
    // judged against the reference in scene-reference.spec.ts.
    'color-space': 'none',
  }, size);
  const image = await capture(page, undefined, selector);
  const ref = reference(size.width, size.height, TIME, 'orthographic', 4);
  const cmp = compareImages(ref, image.data);
  note(`orthographic default view: PSNR ${cmp.psnr.all.toFixed(1)} dB (objects ${cmp.psnr.objects.toFixed(1)}, glass ${cmp.psnr.glass.toFixed(1)}, edges ${cmp.psnr.edges.toFixed(1)}), max error ${cmp.maxError.toFixed(0)}`);
  expect(cmp.psnr.all).toBeGreaterThanOrEqual(40);
  expectPsnr(cmp, { all: 48.3, objects: 42.3, glass: 51.2, edges: 40.5 }, 'orthographic default view');
  // The whole image's figure could hide a wrong reflection (it covers few pixels): judge it alone.
  const mirrored = maskedError(ref, image, reflectsCubeMask(ref));
  note(`orthographic, glass reflecting the cube: ${formatError(mirrored)}`);
  expect(mirrored.pixels, 'the glass reflects the cube over enough pixels to judge').toBeGreaterThan(300);
  expect(mirrored.psnr, 'measured 50.2 dB').toBeGreaterThanOrEqual(50.2 - MARGIN_DB);
});

// reflection-visibility.spec.ts's measure (helpers/reflection-visibility.ts): the final image with the default ior
// against ior 1 (F = 0, no reflection), per pixel the largest |Δ| over RGB.
const cubeMask = (ref: ReferenceImage) => Uint8Array.from(ref.keys, (k) => (glassReflectsCube(k) ? 1 : 0));
const count = (mask: Uint8Array) => mask.reduce((n, m) => n + m, 0);

test('orthographic default view at 640×360: the reflection differs plainly from no reflection where it shows the cube', async ({ page }) => {
  // The visibility bar for the perspective view at 640×360 (reflection-visibility.spec.ts): max ≥ 40
  // levels, ≥ 1,000 px ≥ 15 overall and ≥ 500 px ≥ 15 where the glass reflects the cube. The
  // orthographic view shows the cube's reflection over a different area, so the pixel counts
  // are scaled by the ratio of the two areas (from the reference's geometry, per clock): the
  // same share of the reflection must stand out. The levels stay: what a viewer sees plainly.
  // Measured here, per clock: pixels ≥ 15 levels overall and where the glass reflects the cube
  // (max 43 levels at every clock). The counts may fall 10 % under these (edge pixels of the
  // reflection flipping on a harmless change), the largest difference 3 levels.
  const MEASURED: Record<number, { atLeast15: number; cubeAtLeast15: number }> = {
    0: { atLeast15: 1894, cubeAtLeast15: 1888 },
    1.25: { atLeast15: 2997, cubeAtLeast15: 2993 },
    2.5: { atLeast15: 1747, cubeAtLeast15: 1743 },
    3.75: { atLeast15: 2718, cubeAtLeast15: 2711 },
  };
  const { selector } = await mount(page, { time: 0, projection: 'orthographic' }, { width: 640, height: 360 });
  for (const time of [0, 1.25, 2.5, 3.75]) {
    const [on, off] = await pair(page, selector, time);
    const mask = cubeMask(reference(on.width, on.height, time, 'orthographic'));
    const ratio = count(mask) / count(cubeMask(reference(on.width, on.height, time, 'perspective')));
    const bar = { pixels: Math.round(1000 * ratio), cubePixels: Math.round(500 * ratio) };
    const v = visibility(on, off, mask);
    note(`orthographic 640×360, time ${time}: max ${v.max}, ${v.atLeast15} px ≥ ${LEVEL} (bar ${bar.pixels}); where the glass reflects the cube (${v.cubePixels} px, ${ratio.toFixed(2)}× the perspective view's): max ${v.cubeMax}, ${v.cubeAtLeast15} px ≥ ${LEVEL} (bar ${bar.cubePixels})`);
    expect(v.max).toBeGreaterThanOrEqual(43 - 3);
    expect(v.atLeast15).toBeGreaterThanOrEqual(Math.max(bar.pixels, 0.9 * MEASURED[time].atLeast15));
    expect(v.cubeMax).toBeGreaterThanOrEqual(43 - 3);
    expect(v.cubeAtLeast15).toBeGreaterThanOrEqual(Math.max(bar.cubePixels, 0.9 * MEASURED[time].cubeAtLeast15));
  }
});

test('perspective is unchanged: back from orthographic the same pixels, and switching compiles nothing', async ({ page }) => {
  const { selector } = await mount(page, { time: TIME }, { width: 320, height: 180 });
  const programs = () => page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.programs, selector);
  const before = await capture(page, undefined, selector);
  const compiled = await programs();
  await setAttributes(page, selector, { projection: 'orthographic' });
  const ortho = await capture(page, undefined, selector);
  expect(await programs(), 'the orthographic view needs no other shader variant').toBe(compiled);
  await setAttributes(page, selector, { projection: 'perspective' });
  const explicit = await capture(page, undefined, selector);
  await setAttributes(page, selector, { projection: null });
  const after = await capture(page, undefined, selector);
  const differing = (a: RgbaImage, b: RgbaImage) => differingPixels(a.data, b.data);
  note(`perspective vs orthographic: ${differing(before, ortho)} px differ`);
  expect(differing(before, ortho), 'orthographic draws another picture (measured 37,675 px)').toBeGreaterThan(0.9 * 37_675);
  expect(differing(before, explicit), 'projection="perspective" is the default').toBe(0);
  expect(differing(before, after)).toBe(0);
});

test('a bad projection warns once, falls back to perspective, and rendering goes on', async ({ page, consoleLog }) => {
  const { selector } = await mount(page, { time: TIME, projection: 'orthographic' }, { width: 160, height: 90 });
  const property = () => page.evaluate((s) => (document.querySelector(s) as unknown as { projection: string }).projection, selector);
  expect(await property()).toBe('orthographic');
  await setAttributes(page, selector, { projection: 'isometric' });
  await expect.poll(() => consoleLog.count('warning')).toBe(1);
  const [warning] = consoleLog.take('warning');
  expect(warning).toMatch(/^glass-plane-scene:/);
  expect(warning).toContain('projection');
  expect(warning).toContain('isometric');
  expect(await property()).toBe('perspective');
  const report = await nextFrame(page, selector, (el) => {
    el.setAttribute('projection', 'isometric');
    el.requestRender();
  });
  expect(report.passes.glass.ran).toBe(true);
  await page.evaluate(() => new Promise((r) => setTimeout(r, 200)));
  expect(consoleLog.count('warning'), 'no second warning').toBe(0);
  // The property takes the keyword too (case-insensitive, like the other keywords).
  await page.evaluate((s) => { (document.querySelector(s) as unknown as { projection: string }).projection = 'Orthographic'; }, selector);
  expect(await property()).toBe('orthographic');
});

// Broken on purpose (edge-on judged by the eye's distance from the plane in orthographic too): fails.
test('skip rules (docs/knobs.md#reflection-skips) in orthographic: edge-on is the view direction in the glass plane, not the eye on it', async ({ page }) => {
  // The eye exactly on the glass plane, looking at the glass 80° off its normal: a perspective
  // eye sees the glass as a line (edge-on); an orthographic camera sees it at that angle.
  const onPlane = { 'camera-position': '3.6 2.4 0', 'camera-rotation': DEFAULT_CAMERA_ROTATION.join(' '), time: TIME };
  const { selector } = await mount(page, onPlane, { width: 160, height: 90 });
  const perspective = await setAttributes(page, selector, { projection: 'perspective' });
  expect(perspective.passes.reflection).toEqual({ ran: false, reason: 'glass edge-on' });
  const ortho = await setAttributes(page, selector, { projection: 'orthographic' });
  expect(ortho.passes.reflection.ran, 'an orthographic eye on the plane still sees the glass').toBe(true);
  expect(ortho.passes.glass.ran).toBe(true);
  // Looking along −X from 3 in front of the glass: the view direction lies in the glass plane.
  const along = await setAttributes(page, selector, { 'camera-position': '6 1 3', 'camera-rotation': '180 0' });
  expect(along.passes.reflection).toEqual({ ran: false, reason: 'glass edge-on' });
  const perspectiveAlong = await setAttributes(page, selector, { projection: 'perspective' });
  expect(perspectiveAlong.passes.reflection.ran, 'the same pose in perspective sees the glass beside it').toBe(true);
});
