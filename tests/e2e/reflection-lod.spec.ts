// The reflection's level of detail in the element (docs/knobs.md#level-of-detail, reflection-lod.ts): with tessellation
// 'auto' a dense mesh is drawn into the reflection as the clustered copy whose cells span at most
// REFLECTION_CELL_PX pixels of the reflection target at the object's centre, seen from the
// MIRRORED eye. The triangle counts the frame reports are checked against that rule computed here,
// in float64, from the camera, the glass and the target's size.
import { test, expect, openPage, setAttributes, capture, type SceneElement } from './fixtures';
import { mountFirstFrame } from './helpers/scene-children';
import { gaussianMesh, GAUSSIAN_EXTENT } from '../../src/scene/geometry/gaussian';
import { clusterMesh } from '../../src/scene/geometry/cluster';
import { REFLECTION_CELL_PX, REFLECTION_GRIDS, REFLECTION_MAX_FRACTION } from '../../src/frame/reflection-lod';

const SIZE = { width: 160, height: 90 };
const FOV = 60;
const RESOLUTION = 225;
/** The glass is a floor at y = −1; the Gaussian (y from e^−8 to 1) stands on the origin above it. */
const FLOOR_Y = -1;
const CENTRE = [0, (1 + Math.exp(-8)) / 2, 0];

/** The grid the rule asks for at `camera`: cells of the mesh's 4-unit side at most 4 px of the target. */
function expectedGrid(camera: number[]): number {
  const mirrored = [camera[0], 2 * FLOOR_Y - camera[1], camera[2]];
  const d = Math.hypot(CENTRE[0] - mirrored[0], CENTRE[1] - mirrored[1], CENTRE[2] - mirrored[2]);
  // Pixels per unit at distance d under a vertical field of view FOV over the target's height.
  const ppu = SIZE.height / (2 * Math.tan((FOV / 2) * (Math.PI / 180)) * d);
  const cells = (2 * GAUSSIAN_EXTENT * ppu) / REFLECTION_CELL_PX;
  return REFLECTION_GRIDS.find((g) => g >= cells) ?? 0;
}

test('a dense mesh\'s reflection draws the clustered copy its size in the reflection asks for, seen from the mirrored eye', async ({ page }) => {
  await openPage(page);
  await page.evaluate((size) => new Promise<void>((resolve, reject) => {
    const host = document.createElement('div');
    host.innerHTML = `<glass-plane-scene refine="0" id="lod" time="0" glass-center="0 -1 0" glass-normal="0 1 0" glass-size="8 8"
      camera-target="0 0.5 0" style="width: ${size.width}px; height: ${size.height}px"><glass-object shape="gaussian" resolution="225"></glass-object></glass-plane-scene>`;
    const el = host.firstElementChild!;
    const t = setTimeout(() => reject(new Error('no ready event')), 30_000);
    el.addEventListener('ready', () => { clearTimeout(t); resolve(); }, { once: true });
    document.body.append(el);
  }), SIZE);
  const fine = gaussianMesh(RESOLUTION);
  const full = fine.indices.length / 3;
  const rows: string[] = [];
  // Two cameras: at the first the real eye's distance would ask for a finer grid than the
  // mirrored eye's; at the second, tan(fov) in place of tan(fov / 2) would ask for a coarser one.
  for (const [camera, grid] of [[[0, 2, 3], 16], [[1.5, 0.8, 2], 32]] as const) {
    expect(expectedGrid([...camera]), `the rule's grid at ${camera.join(' ')} (this test's own arithmetic)`).toBe(grid);
    const clustered = clusterMesh(fine, grid).indices.length / 3;
    expect(clustered, 'the clustered copy saves enough to be used').toBeLessThanOrEqual(REFLECTION_MAX_FRACTION * full);
    const frame = await setAttributes(page, '#lod', { 'camera-position': camera.join(' ') });
    expect(frame.passes.reflection.ran, `${camera.join(' ')}: reflection ran`).toBe(true);
    const triangles = await page.evaluate(() => (document.querySelector('#lod') as SceneElement).stats.triangles);
    rows.push(`camera ${camera.join(' ')}: grid ${grid}, reflection ${triangles.reflection} of ${triangles.scene} triangles`);
    expect(triangles.scene, 'the scene pass draws the full mesh').toBe(full);
    expect(triangles.reflection, `camera ${camera.join(' ')}: reflection triangles (the ${grid} grid's copy)`).toBe(clustered);
  }
  console.log(rows.join('; '));
});

// The clustering is in a chunk of its own with flat shading and the Gaussian (render/mesh-extras.ts),
// fetched by the renderer the first time a frame needs one of them; that frame waits for it.
const GAUSSIAN = `<glass-plane-scene refine="0" time="0" glass-center="0 -1 0" glass-normal="0 1 0" glass-size="8 8" camera-position="0 2 3"
  camera-target="0 0.5 0" style="width: 160px; height: 90px"><glass-object shape="gaussian" resolution="225"></glass-object></glass-plane-scene>`;

/** Mounts `html`; the triangles the element reports in its first `frame` event, and every warning text. */
async function firstFrameTriangles(page: import('@playwright/test').Page, html: string): Promise<{ scene: number; reflection: number }> {
  return page.evaluate((html) => new Promise((resolve, reject) => {
    const host = document.createElement('div');
    host.innerHTML = html;
    const el = host.firstElementChild as SceneElement;
    const t = setTimeout(() => reject(new Error('no frame')), 30_000);
    el.addEventListener('frame', () => { clearTimeout(t); resolve({ ...el.stats.triangles }); }, { once: true });
    document.body.append(el);
  }), html);
}

const clusterFetched = (page: import('@playwright/test').Page) =>
  page.evaluate(() => performance.getEntriesByType('resource').some((e) => e.name.includes('mesh-extras')));

test('a scene with nothing to cluster, no Gaussian and smooth shading never fetches the mesh extras', async ({ page }) => {
  await openPage(page);
  await firstFrameTriangles(page, '<glass-plane-scene refine="0" time="0" style="width: 160px; height: 90px"></glass-plane-scene>');
  await page.waitForTimeout(200);
  expect(await clusterFetched(page)).toBe(false);
});

test('the first frame of a dense mesh\'s reflection is clustered, however slow the chunk (held back 600 ms)', async ({ page }) => {
  await page.route('**/mesh-extras*', async (route) => {
    await new Promise((r) => setTimeout(r, 600));
    await route.continue();
  });
  await openPage(page);
  const t = await firstFrameTriangles(page, GAUSSIAN);
  expect(await clusterFetched(page)).toBe(true);
  expect(t.scene).toBe(gaussianMesh(RESOLUTION).indices.length / 3);
  expect(t.reflection, 'the 16 grid\'s copy, as in the test above').toBe(clusterMesh(gaussianMesh(RESOLUTION), 16).indices.length / 3);
});

test('if the mesh extras cannot load, the Gaussian is not drawn and the scene goes on: one warning, no error', async ({ page, consoleLog }) => {
  await page.route('**/mesh-extras*', (route) => route.abort());
  await openPage(page);
  const t = await firstFrameTriangles(page, GAUSSIAN);
  expect([t.scene, t.reflection]).toEqual([0, 0]);
  expect(consoleLog.take('warning').filter((w) => w.includes('clustering could not load'))).toHaveLength(1);
  consoleLog.take('error'); // the browser's own report of the failed fetch
});

test('shading="flat": the first frame is flat, however slow the mesh extras (held back 600 ms)', async ({ page }) => {
  const html = (shading: string) => `<glass-plane-scene refine="0" time="0" spin="0" shading="${shading}" style="width: 160px; height: 90px"></glass-plane-scene>`;
  await page.route('**/mesh-extras*', async (route) => {
    await new Promise((r) => setTimeout(r, 600));
    await route.continue();
  });
  await openPage(page);
  const first = await mountFirstFrame(page, html('flat'));
  expect(await clusterFetched(page)).toBe(true);
  await page.waitForTimeout(300);
  const settled = await capture(page);
  const same = (a: { data: Uint8Array }, b: { data: Uint8Array }) => Buffer.compare(Buffer.from(a.data), Buffer.from(b.data)) === 0;
  expect(same(first, settled), 'the first frame is the settled (flat) one').toBe(true);
  await openPage(page);
  const smooth = await mountFirstFrame(page, html('phong'));
  expect(same(first, smooth), 'flat differs from phong').toBe(false);
});
