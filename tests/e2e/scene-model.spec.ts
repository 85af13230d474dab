// The WebGL renderer drawing scene values (docs/scene-model.md#one-scene-value) other than the default one, through the
// renderer page (no element): glass anywhere, objects placed by transforms, point lights,
// materials, opacity, image textures, no glass. Properties checked from geometry, not goldens.
import { test, expect, mount, openPage, capture } from './fixtures';
import { drawScene, openRendererPage } from './helpers/scene-json';
import { dominant, dominantPixels } from './helpers/pixels';
import { compareImages } from './helpers/golden';
import { project, type Vec3 } from './helpers/projection';
import { lookAt } from './helpers/stability';
import { note } from './helpers/bounds';
import { defaultScene, DEFAULT_LIGHT } from '../../src/scene/default-scene';
import { DEFAULT_CAMERA_POSITION, DEFAULT_CAMERA_ROTATION, DEFAULT_CUBE_DISTANCE } from '../../src/element/attributes';
import type { Light, Material, Scene, SceneObject } from '../../src/scene/scene';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from '../unit/helpers/frame-state';
import type { RgbaImage } from './helpers/golden';
import { clusterMesh } from '../../src/scene/geometry/cluster';
import { gaussianMesh } from '../../src/scene/geometry/gaussian';

const W = 320, H = 180;

function state(position: Vec3, target: Vec3, view: FrameState['view'] = 'final'): FrameState {
  const { yaw, pitch } = lookAt(position, target);
  return defaultFrameState({
    width: W, height: H, spin: 0, cameraPosition: position, yaw, pitch, colorSpace: 'none', view, samples: 0, tessellation: 64,
  });
}

const grey = (x: number): Vec3 => [x, x, x];
function material(diffuse: Vec3, extra: Partial<Material> = {}): Material {
  return {
    ambient: diffuse, diffuse, specular: grey(0), shininess: 32, opacity: 1, texture: { kind: 'procedural' }, mapping: 'uv', ...extra,
  };
}
function box(position: Vec3, diffuse: Vec3, extra: Partial<Material> = {}, size = 1): SceneObject {
  return {
    geometry: { kind: 'box', size },
    transform: { position, rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: material(diffuse, extra),
    bounds: { center: [0, 0, 0], radius: (Math.sqrt(3) / 2) * size },
  };
}
function scene(objects: SceneObject[], extra: Partial<Scene> = {}): Scene {
  return { glass: null, objects, lights: [DEFAULT_LIGHT], background: grey(0.1), ...extra };
}
const sum = (img: RgbaImage) => img.data.reduce((s, v, i) => (i % 4 === 3 ? s : s + v), 0);

test.beforeEach(async ({ page }) => {
  await openRendererPage(page);
});

test('the default scene value draws what the element draws', async ({ page }) => {
  const s: FrameState = {
    ...state(DEFAULT_CAMERA_POSITION, [0, 0, 0]), yaw: DEFAULT_CAMERA_ROTATION[0], pitch: DEFAULT_CAMERA_ROTATION[1],
    time: 1.25, spin: 0.8, samples: 4, tessellation: 'auto', colorSpace: 'srgb',
  };
  const fromValue = await drawScene(page, s, defaultScene(DEFAULT_CUBE_DISTANCE, 0.8));
  await openPage(page);
  await mount(page, { time: 1.25 }, { width: W, height: H });
  const { differing } = compareImages(fromValue, await capture(page));
  note(`default scene value vs the element: ${differing} px differ`);
  // Measured 0; the golden budget (0.1 %, helpers/golden.ts) for rasterization ties.
  expect(differing, 'pixels differing between the scene value and the element').toBeLessThanOrEqual(Math.floor(W * H * 0.001));
});

test('a glass floor reflects a cube above it: the reflection pass is the mirrored cube seen from the eye', async ({ page }) => {
  // Low over the floor: the glass at ~75° where F ≈ 0.25, and the cube's lit +Z face in the mirror.
  const eye: Vec3 = [0, 0.6, 6];
  const s = state(eye, [0, 0, 0]);
  const floor = scene([box([0, 1, 0], [0.8, 0.2, 0.2])], { glass: { center: [0, 0, 0], normal: [0, 1, 0], size: [8, 8] } });
  // The mirror identity, with the floor as the mirror: what the mirrored eye sees of the cube
  // (pass 1, screen-aligned) is where the eye sees the cube mirrored to (0, −1, 0).
  // Lighting differs (the mirrored cube is lit from the unmirrored light), so any red excess
  // counts: even an unlit face (ambient only) has red 4× its green.
  const RED = 5;
  const reflection = dominantPixels(await drawScene(page, { ...s, view: 'reflection' }, floor), 'r', RED);
  const mirrored = dominantPixels(await drawScene(page, { ...s, view: 'scene' }, scene([box([0, -1, 0], [0.8, 0.2, 0.2])])), 'r', RED);
  const a = new Set(reflection), both = mirrored.filter((p) => a.has(p)).length;
  note(`glass floor: ${reflection.length} red px in the reflection, ${mirrored.length} of the mirrored cube, IoU ${(both / (reflection.length + mirrored.length - both)).toFixed(4)}`);
  // Measured: 860 red px in both, intersection over union 1. Bounds: 10 % under the count, 1 %
  // under the overlap (edge pixels lit a little differently may fall either side of RED).
  expect(mirrored.length, 'red pixels of the mirrored cube').toBeGreaterThanOrEqual(0.9 * 860);
  expect(both / (reflection.length + mirrored.length - both), 'overlap (intersection over union)').toBeGreaterThanOrEqual(0.99);
  // And the final frame shows it where the mirrored cube projects: redder than with no reflection.
  const final = await drawScene(page, s, floor);
  const none = await drawScene(page, { ...s, ior: 1 }, floor);
  const m = project({ position: eye, yaw: s.yaw, pitch: s.pitch }, [0, -1, 0], W, H);
  const i = (Math.round(m.y) * W + Math.round(m.x)) * 4;
  note(`glass floor: red added where the reflection lands ${final.data[i] - none.data[i]}`);
  expect(final.data[i] - none.data[i], 'red the reflection adds where it lands (measured 9; 1 level for rounding)').toBeGreaterThanOrEqual(9 - 1);
});

test('a point light lights what faces it; a second light adds', async ({ page }) => {
  const eye: Vec3 = [0, 1, 6];
  const s = state(eye, [0, 0, 0]);
  const point = (p: Vec3): Light => ({ kind: 'point', vector: p, ambient: grey(0), diffuse: grey(0.9), specular: grey(0) });
  const dark = { background: grey(0) } as const;
  const one = await drawScene(page, s, scene([box([0, 0, 0], grey(0.8), {}, 2)], { ...dark, lights: [point([-3, 0, 4])] }));
  const both = await drawScene(page, s, scene([box([0, 0, 0], grey(0.8), {}, 2)], { ...dark, lights: [point([-3, 0, 4]), point([3, 0, 4])] }));
  // Front face (+Z) is lit by both at the same angle; pixel columns left and right of centre.
  const at = (img: RgbaImage, x: number) => img.data[(Math.round(H / 2) * W + x) * 4];
  // Symmetric lights on a symmetric view: twice the light (within rounding).
  note(`two point lights: ratio ${(sum(both) / sum(one)).toFixed(4)}; one light, left ${at(one, Math.round(W / 2) - 30)} vs right ${at(one, Math.round(W / 2) + 30)}`);
  // Measured 2.0000 (within ±0.005 here).
  expect(sum(both) / sum(one), 'two lights give twice the light of one').toBeCloseTo(2, 2);
  // A point light's direction varies over the face: the side nearer the light is brighter.
  // Measured 119 against 54 levels; bound 10 % under the difference.
  expect(at(one, Math.round(W / 2) - 30), 'nearer the left light').toBeGreaterThan(at(one, Math.round(W / 2) + 30) + 0.9 * (119 - 54));
});

test('tessellation auto: the reflection of a dense mesh draws a clustered copy, a number draws it whole', async ({ page }) => {
  const eye: Vec3 = [4, 2.2, 5];
  const gaussian = (resolution: number): SceneObject => ({
    geometry: { kind: 'gaussian', resolution }, transform: { position: [0, 0.4, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: material([0.2, 0.5, 0.9]), bounds: { center: [0, 0.5, 0], radius: 2.9 },
  });
  const floor = (o: SceneObject) => scene([o], { glass: { center: [0, 0, 0], normal: [0, 1, 0], size: [8, 8] } });
  const triangles = async (s: FrameState, sc: Scene) => {
    await drawScene(page, s, sc);
    return page.evaluate(() => (window as unknown as { __renderer: { stats(): { triangles: { scene: number; reflection: number } } } }).__renderer.stats().triangles);
  };
  const dense = await triangles({ ...state(eye, [0, 0.4, 0]), tessellation: 'auto' }, floor(gaussian(225)));
  note(`dense Gaussian: ${JSON.stringify(dense)}`);
  expect(dense.scene).toBe(100_352);
  // 320×180, the mesh 4 units wide ~7 units from the mirrored eye: ~22 px per unit, the 32 grid:
  // exactly its clustered copy (2,706 triangles).
  const clustered = (grid: number) => clusterMesh(gaussianMesh(225), grid).indices.length / 3;
  expect(dense.reflection, 'reflection triangles: the 32 grid\'s clustered copy').toBe(clustered(32));
  const whole = await triangles({ ...state(eye, [0, 0.4, 0]), tessellation: 64 }, floor(gaussian(225)));
  expect(whole).toEqual({ scene: 100_352, reflection: 100_352 });
  // A mesh already about as coarse as its cells: clustering would save too little, drawn whole.
  const coarse = await triangles({ ...state(eye, [0, 0.4, 0]), tessellation: 'auto' }, floor(gaussian(24)));
  expect(coarse.reflection).toBe(coarse.scene);
  // Nearer, larger on screen: a finer grid.
  const near = await triangles({ ...state([1.6, 1.2, 2], [0, 0.4, 0]), tessellation: 'auto' }, floor(gaussian(225)));
  note(`dense Gaussian, nearer: ${JSON.stringify(near)}`);
  expect(near.reflection, 'nearer: the 64 grid\'s copy (10,642 triangles)').toBe(clustered(64));
});

test('an object with opacity 0.5 blends over what is behind it', async ({ page }) => {
  const s = state([0, 0, 6], [0, 0, 0]);
  const flatLight: Light = { kind: 'directional', vector: [0, 0, 1], ambient: grey(0), diffuse: grey(1), specular: grey(0) };
  const uniform = { texture: { kind: 'image', url: 'white' } } as const;
  const white = { white: { width: 1, height: 1, rgba: [255, 255, 255, 255] } };
  const behind = box([0, 0, -2], [1, 0, 0], uniform, 3);
  const front = box([0, 0, 0], [0, 0, 1], { ...uniform, opacity: 0.5 }, 1);
  const img = await drawScene(page, s, scene([front, behind], { lights: [flatLight] }), white);
  const i = (Math.round(H / 2) * W + Math.round(W / 2)) * 4;
  // Listed first, drawn after the opaque one: blue·0.5 + red·0.5.
  expect(Math.abs(img.data[i] - 128), 'red half').toBeLessThanOrEqual(2);
  expect(Math.abs(img.data[i + 2] - 128), 'blue half').toBeLessThanOrEqual(2);
});

test('image textures follow the OBJ convention: v = 0 is the bottom row of the image', async ({ page }) => {
  const s = state([0, 0, 3], [0, 0, 0]);
  const flatLight: Light = { kind: 'directional', vector: [0, 0, 1], ambient: grey(0), diffuse: grey(1), specular: grey(0) };
  // Top row red, bottom row blue; the box's +Z face has v growing along +Y.
  const img = { rb: { width: 1, height: 2, rgba: [255, 0, 0, 255, 0, 0, 255, 255] } };
  const out = await drawScene(page, s, scene([box([0, 0, 0], grey(1), { texture: { kind: 'image', url: 'rb' } })], { lights: [flatLight] }), img);
  const px = (y: number) => out.data.subarray((y * W + W / 2) * 4, (y * W + W / 2) * 4 + 3);
  const upper = px(Math.round(H / 2) - 15), lower = px(Math.round(H / 2) + 15);
  note(`image texture: upper ${Array.from(upper)}, lower ${Array.from(lower)}`);
  // Measured: upper (246, 0, 9), lower (1, 0, 254). Bounds 10 % under the differences.
  expect(upper[0], 'upper half red').toBeGreaterThan(upper[2] + 0.9 * (246 - 9));
  expect(lower[2], 'lower half blue').toBeGreaterThan(lower[0] + 0.9 * (254 - 1));
});

test('with no glass the final image is the scene pass alone', async ({ page }) => {
  const s = state([2, 2, 5], [0, 0, 0]);
  const sc = scene([box([0, 0, 0], [0.2, 0.7, 0.3])]);
  const final = await drawScene(page, s, sc);
  const scenePass = await drawScene(page, { ...s, view: 'scene' }, sc);
  expect(compareImages(final, scenePass).differing).toBe(0);
  note(`no glass: ${dominant(final, 'g').count} green px`);
  expect(dominant(final, 'g').count, 'the object is drawn (measured 830 px)').toBeGreaterThanOrEqual(0.9 * 830);
});

test('flat shading lights each triangle once, from its face normal (a coarse Gaussian surface)', async ({ page }) => {
  // resolution 5: vertices every 1.0 over [−2, 2]²; triangle (0,0)-(0,1)-(1,0) of the grid's
  // centre cell: a = (0, 1, 0), c = (0, e⁻¹, 1), b = (1, e⁻¹, 0).
  const e1 = Math.exp(-1);
  const a: Vec3 = [0, 1, 0], b: Vec3 = [1, e1, 0], c: Vec3 = [0, e1, 1];
  const u = [c[0] - a[0], c[1] - a[1], c[2] - a[2]], v = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
  const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
  const nl = Math.hypot(n[0], n[1], n[2]);
  // A light from the side: the face normal and any vertex normal of this triangle light it very
  // differently (170 against 59 levels at vertex b), so per-vertex lighting cannot pass.
  const L = [0, 0.3, 1].map((x) => x / Math.hypot(0.3, 1));
  const expected = 255 * Math.max(0, (n[0] * L[0] + n[1] * L[1] + n[2] * L[2]) / nl);
  const centroid: Vec3 = [(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3];
  const eye: Vec3 = [0.3, 4, 0.4];
  const s = { ...state(eye, centroid), shading: 'flat' as const };
  const surface: SceneObject = {
    geometry: { kind: 'gaussian', resolution: 5 },
    transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: material(grey(1), { ambient: grey(0), texture: { kind: 'image', url: 'white' } }),
    bounds: { center: [0, 0.5, 0], radius: 3 },
  };
  const light: Light = { kind: 'directional', vector: [0, 0.3, 1], ambient: grey(0), diffuse: grey(1), specular: grey(0) };
  const white = { white: { width: 1, height: 1, rgba: [255, 255, 255, 255] } };
  const img = await drawScene(page, s, scene([surface], { lights: [light] }), white);
  const p = project({ position: eye, yaw: s.yaw, pitch: s.pitch }, centroid, W, H);
  // Every pixel around the centroid (well inside the triangle) has the face's one colour.
  for (const [dx, dy] of [[0, 0], [-3, 0], [3, 0], [0, -3], [0, 3]]) {
    const i = ((Math.round(p.y) + dy) * W + Math.round(p.x) + dx) * 4;
    expect(Math.abs(img.data[i] - expected), `pixel (${dx}, ${dy}) from the centroid: ${img.data[i]} vs ${expected.toFixed(1)}`).toBeLessThanOrEqual(1);
  }
});

test('meshes from files are drawn from both sides and lit on the side facing the viewer', async ({ page }) => {
  const s = state([0, 0, 3], [0, 0, 0]);
  // One big triangle wound clockwise seen from the camera, its normals pointing away (−Z).
  const tri: SceneObject = {
    geometry: {
      kind: 'mesh', key: 'test:back-facing-triangle',
      data: {
        positions: new Float32Array([-1, -1, 0, 0, 1, 0, 1, -1, 0]), normals: new Float32Array([0, 0, -1, 0, 0, -1, 0, 0, -1]),
        uvs: new Float32Array(6), indices: new Uint32Array([0, 1, 2]),
      },
    },
    transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: material(grey(1), { ambient: grey(0), texture: { kind: 'image', url: 'white' } }),
    bounds: { center: [0, 0, 0], radius: 1.5 },
  };
  const light: Light = { kind: 'directional', vector: [0, 0, 1], ambient: grey(0), diffuse: grey(1), specular: grey(0) };
  const white = { white: { width: 1, height: 1, rgba: [255, 255, 255, 255] } };
  const img = await drawScene(page, s, scene([tri], { lights: [light] }), white);
  const i = (Math.round(H / 2 + 10) * W + Math.round(W / 2)) * 4;
  // Not culled, and N turned towards the viewer: N·L = 1, full white (unlit it would be black).
  expect(img.data[i], 'the triangle, lit from the viewer\u2019s side').toBeGreaterThanOrEqual(254);
});

test('the page\'s scene value is frozen through and through: a change in place throws, and the element and both renderers draw on as before', async ({ page }) => {
  await openPage(page);
  for (const renderer of ['webgl', 'software']) {
    const { selector } = await mount(page, { time: 0, spin: 0, renderer, 'object-rotation': '' }, { width: 160, height: 90 });
    const before = await capture(page, undefined, selector);
    const tries = await page.evaluate((s) => {
      'use strict'; // assignments to frozen properties throw, as in a module
      const scene = (document.querySelector(s) as unknown as { scene: Scene }).scene;
      const attempts: [string, () => void][] = [
        ['an object\'s position', () => { (scene.objects[0].transform.position as unknown as number[])[1] = 5; }],
        ['a material', () => { (scene.objects[0].material as { opacity: number }).opacity = 0.2; }],
        ['the objects', () => { (scene.objects as SceneObject[]).pop(); }],
        ['a light', () => { (scene.lights[0].diffuse as unknown as number[])[0] = 9; }],
        ['the background', () => { (scene.background as unknown as number[])[0] = 1; }],
        ['the glass', () => { (scene as { glass: unknown }).glass = null; }],
      ];
      return attempts.map(([name, f]) => { try { f(); return `${name}: changed`; } catch (e) { return `${name}: ${(e as Error).name}`; } });
    }, selector);
    expect(tries, renderer).toEqual([
      'an object\'s position: TypeError', 'a material: TypeError', 'the objects: TypeError', 'a light: TypeError', 'the background: TypeError', 'the glass: TypeError',
    ]);
    await page.evaluate((s) => (document.querySelector(s) as unknown as { requestRender(): void }).requestRender(), selector);
    expect(compareImages(await capture(page, undefined, selector), before).differing, renderer).toBe(0);
  }
});
