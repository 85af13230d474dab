// The reflection's level of detail in the element (SPEC §7, reflection-lod.ts): with tessellation
// 'auto' a dense mesh is drawn into the reflection as the clustered copy whose cells span at most
// REFLECTION_CELL_PX pixels of the reflection target at the object's centre, seen from the
// MIRRORED eye. The triangle counts the frame reports are checked against that rule computed here,
// in float64, from the camera, the glass and the target's size.
import { test, expect, openPage, setAttributes, type SceneElement } from './fixtures';
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
    host.innerHTML = `<glass-plane-scene id="lod" time="0" glass-center="0 -1 0" glass-normal="0 1 0" glass-size="8 8"
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
