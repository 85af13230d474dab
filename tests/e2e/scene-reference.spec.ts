// The accuracy bar (docs/knobs.md#bars-the-tests-hold): for scenes beyond the default one, the WebGL renderer's image matches
// the float64 reference's (renderScene) at ≥ 35 dB PSNR. Each scene is drawn by the Renderer
// (renderer page) at samples 4 and reflection-scale 1, against the reference at 4×4 samples per
// pixel; the figure of each is printed and annotated. Each case's bounds sit MARGIN_DB (2 dB)
// under the figures measured here (SwiftShader, 320×180, the same to 0.1 dB from run to run),
// over the whole image and each region; the bar's 35 dB is below all of them. Measured in linear
// light (color-space srgb), where textures are read anisotropically: 1.5–4 dB under the figures
// as stored (48.3 → 44.9 on the Gaussian; 43.9 with isotropic reads), since encoding steepens
// the GPU's errors in the darks (×12.92 at black): edges (MSAA 4 against 16 samples) most.
import { test, expect } from './fixtures';
import { drawScene, openRendererPage, type Images } from './helpers/scene-json';
import { lookAt } from './helpers/stability';
import { expectPsnr, note } from './helpers/bounds';
import { renderScene, compareImages } from '../../src/reference';
import { DEFAULT_LIGHT } from '../../src/scene/default-scene';
import type { Light, Material, Scene, SceneObject, Vec3 } from '../../src/scene/scene';
import type { FrameState, Shading } from '../../src/frame/types';
import { defaultFrameState } from '../unit/helpers/frame-state';
import { bezierPatchMesh } from '../../src/scene/geometry/bezier';
import { FIFTH, FOUR, litBy } from '../unit/helpers/lights';

const W = 320, H = 180;
const ISSUE_BAR_DB = 35;

function state(position: Vec3, target: Vec3, shading: Shading = 'phong'): FrameState {
  const { yaw, pitch } = lookAt(position, target);
  return defaultFrameState({ width: W, height: H, spin: 0, cameraPosition: position, yaw, pitch, shading });
}

const grey = (x: number): Vec3 => [x, x, x];
const mat = (diffuse: Vec3, extra: Partial<Material> = {}): Material => ({
  ambient: [diffuse[0] * 0.25, diffuse[1] * 0.25, diffuse[2] * 0.25], diffuse, specular: grey(0.5), shininess: 32, opacity: 1,
  texture: { kind: 'procedural' }, mapping: 'uv', ...extra,
});
const at = (position: Vec3, extra: Partial<SceneObject['transform']> = {}): SceneObject['transform'] =>
  ({ position, rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0, ...extra });
const box = (position: Vec3, diffuse: Vec3, extra: Partial<Material> = {}): SceneObject =>
  ({ geometry: { kind: 'box', size: 1 }, transform: at(position), material: mat(diffuse, extra), bounds: { center: [0, 0, 0], radius: Math.sqrt(3) / 2 } });
const gaussian = (resolution: number, position: Vec3 = [0, 0, 0]): SceneObject =>
  ({ geometry: { kind: 'gaussian', resolution }, transform: at(position), material: mat([0.2, 0.5, 0.9]), bounds: { center: [0, 0.5, 0], radius: 2.9 } });
const floor = { center: [0, 0, 0] as Vec3, normal: [0, 1, 0] as Vec3, size: [8, 8] as const };
const point = (p: Vec3, c: Vec3): Light => ({ kind: 'point', vector: p, ambient: grey(0.05), diffuse: c, specular: c });

type Measured = { all: number; objects: number; glass?: number; edges: number };

interface Case {
  name: string; scene: Scene; state: FrameState; images?: Images;
  /** PSNR measured here (dB), whole image and regions: the bounds sit MARGIN_DB under them. */
  measured: Measured;
}

const CASES: Case[] = [
  {
    name: 'a glass floor under objects (the Gaussian at 40, a box)',
    scene: { glass: floor, objects: [gaussian(40, [0, 0.3, 0]), box([2.2, 0.8, 0.5], [0.8, 0.3, 0.3])], lights: [DEFAULT_LIGHT], background: grey(0.1) },
    state: state([4, 2.2, 5], [0.5, 0.3, 0]),
    measured: { all: 46.0, objects: 46.2, glass: 51.0, edges: 36.9 },
  },
  {
    // Tessellation 'auto': the reflection draws a vertex-clustered copy (~2.7k of 100k triangles here).
    name: 'a dense Gaussian (225², 100k triangles) over a glass floor, its reflection from the clustered copy',
    scene: { glass: floor, objects: [gaussian(225, [0, 0.4, 0])], lights: [DEFAULT_LIGHT], background: grey(0.1) },
    state: state([4, 2.2, 5], [0, 0.4, 0]),
    measured: { all: 45.9, objects: 44.2, glass: 51.6, edges: 35.7 },
  },
  {
    // A Bézier surface (docs/software-renderer.md#bezier-surfaces): a bicubic bump at E = 40, as the course's .byu loader makes it.
    name: 'a bicubic Bézier surface (E = 40) over a glass floor',
    scene: {
      glass: floor, lights: [DEFAULT_LIGHT], background: grey(0.1),
      objects: [{
        geometry: { kind: 'mesh', key: 'bezier-bump', data: bezierPatchMesh({ degreeU: 3, degreeV: 3, points: (() => {
          const p: number[] = [];
          for (let i = 0; i <= 3; i++) for (let j = 0; j <= 3; j++) p.push(-1.2 + 0.8 * i, i > 0 && i < 3 && j > 0 && j < 3 ? 1.6 : (i + j) % 2 ? 0.3 : 0, -1.2 + 0.8 * j);
          return p;
        })() }, 40) },
        transform: at([0, 0.3, 0]), material: mat([0.9, 0.6, 0.3]), bounds: { center: [0, 0.6, 0], radius: 1.8 },
      }],
    },
    state: state([3, 2.2, 4], [0, 0.5, 0]),
    measured: { all: 46.5, objects: 43.8, glass: 51.5, edges: 35.8 },
  },
  {
    name: 'two point lights',
    scene: {
      glass: null, objects: [box([-0.8, 0, 0], grey(0.8)), box([0.8, 0, 0], [0.3, 0.8, 0.3])],
      lights: [point([-3, 2, 3], [0.9, 0.6, 0.5]), point([3, 1, 2], [0.4, 0.5, 0.9])], background: grey(0.1),
    },
    state: state([0.5, 1.5, 4], [0, 0, 0]),
    measured: { all: 46.3, objects: 45.7, edges: 32.6 },
  },
  {
    name: 'a half-transparent object over another',
    scene: {
      glass: null, objects: [box([0, 0, 0.6], [0.2, 0.3, 0.9], { opacity: 0.5 }), box([0.3, 0.2, -0.6], [0.9, 0.3, 0.2])],
      lights: [DEFAULT_LIGHT], background: grey(0.1),
    },
    state: state([1.5, 1.5, 4], [0, 0, 0]),
    measured: { all: 49.5, objects: 50.3, edges: 36.9 },
  },
];
/** The Gaussian alone, by resolution and shading: PSNR measured here (dB). */
const GAUSSIAN_MEASURED: Record<number, Record<Shading, Measured>> = {
  40: {
    phong: { all: 44.9, objects: 44.5, edges: 31.3 },
    gouraud: { all: 44.8, objects: 43.9, edges: 31.3 },
    flat: { all: 43.9, objects: 39.4, edges: 31.4 },
  },
  400: {
    phong: { all: 44.8, objects: 44.0, edges: 31.3 },
    gouraud: { all: 44.8, objects: 43.9, edges: 31.3 },
    flat: { all: 44.8, objects: 43.9, edges: 31.3 },
  },
};
for (const resolution of [40, 400]) {
  for (const shading of ['phong', 'gouraud', 'flat'] as const) {
    CASES.push({
      name: `the Gaussian at ${resolution}², ${shading}`,
      scene: { glass: null, objects: [gaussian(resolution)], lights: [DEFAULT_LIGHT], background: grey(0.1) },
      state: state([3, 3, 4], [0, 0.3, 0], shading),
      measured: GAUSSIAN_MEASURED[resolution][shading],
    });
  }
}

// The texture mappings (docs/scene-model.md#texture-mappings) with the procedural checker (src/scene/mapping.ts on both sides).
const sphere = (position: Vec3, material: Material): SceneObject =>
  ({ geometry: { kind: 'sphere', radius: 0.8 }, transform: at(position), material, bounds: { center: [0, 0, 0], radius: 0.8 } });
CASES.push({
  name: 'mappings: triplanar on the Gaussian, cylindrical on a sphere, spherical on a box',
  scene: {
    glass: null, lights: [DEFAULT_LIGHT], background: grey(0.1),
    objects: [
      { ...gaussian(40, [0, 0, -1]), material: mat([0.9, 0.9, 0.9], { mapping: 'triplanar' }) },
      sphere([-1.6, 0.8, 1], mat([0.9, 0.6, 0.3], { mapping: 'cylindrical' })),
      { ...box([1.6, 0.6, 1], [0.4, 0.8, 0.9], { mapping: 'spherical' }) },
    ],
  },
  state: state([0, 2.5, 5.5], [0, 0.3, 0]),
  // With triplanar's X and Z projections swapped the objects fall to 34.8 dB, with every mapping read as uv 16.5.
  measured: { all: 43.7, objects: 41.3, edges: 31.1 },
});

test.beforeEach(async ({ page }) => {
  await openRendererPage(page);
});

for (const c of CASES) {
  test(`${c.name}: within 2 dB of its measured PSNR against the reference (≥ ${ISSUE_BAR_DB} dB)`, async ({ page }) => {
    const image = await drawScene(page, c.state, c.scene, c.images);
    const ref = renderScene(c.scene, c.state, null, { samplesPerAxis: 4 });
    const cmp = compareImages(ref, image.data);
    const line = `${c.name}: PSNR ${cmp.psnr.all.toFixed(1)} dB (objects ${cmp.psnr.objects.toFixed(1)}, glass ${cmp.psnr.glass.toFixed(1)}, edges ${cmp.psnr.edges.toFixed(1)}), max error ${cmp.maxError.toFixed(0)}`;
    note(line);
    expect(cmp.psnr.all, line).toBeGreaterThanOrEqual(ISSUE_BAR_DB);
    expectPsnr(cmp, c.measured, c.name);
  });
}

test('a fifth light is left out, as by the software renderer and the reference (docs/scene-model.md#lights)', async ({ page }) => {
  const st = defaultFrameState({ width: 96, height: 54, spin: 0 });
  const four = await drawScene(page, st, litBy(FOUR)), five = await drawScene(page, st, litBy([...FOUR, FIFTH]));
  const other = await drawScene(page, st, litBy([...FOUR.slice(1), FIFTH]));
  const differing = (a: Uint8Array, b: Uint8Array) => a.reduce((n, v, i) => n + (v !== b[i] ? 1 : 0), 0);
  expect(differing(other.data, four.data)).toBeGreaterThan(1000); // the fifth light shows where it is used
  expect(differing(five.data, four.data)).toBe(0);
});
