// The course's files in the element (docs/course-files.md). Mesh and Bézier `.byu` through
// <glass-object src>, iluminacao.txt through <glass-light src>, the camera `.cfg` through
// camera-src; pixels checked where courseProject says, and against the float64 reference.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Page } from '@playwright/test';
import { test, expect, openPage, capture, type RgbaImage } from './fixtures';
import { installSummary, mountHtml, nextEvent, summary } from './helpers/scene-children';
import { parseCameraCfg } from '../../src/loaders/course/camera-cfg';
import { courseProject, type CourseCamera } from '../../src/math/course-camera';
import { renderScene, compareImages } from '../../src/reference';
import type { Scene, SceneObject } from '../../src/scene/scene';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from '../unit/helpers/frame-state';

const DATA = path.resolve(path.dirname(fileURLToPath(import.meta.url)), '../data/course');
const URL_BASE = '/tests/data/course/';
const W = 160, H = 90;
const BLACK = '#000';

function camera(name: string): CourseCamera {
  const { warnings: _w, ...cam } = parseCameraCfg(fs.readFileSync(path.join(DATA, name), 'utf8'), { url: name });
  return cam;
}

const pixel = (img: RgbaImage, x: number, y: number): number[] => {
  const i = 4 * (Math.floor(y) * img.width + Math.floor(x));
  return [img.data[i], img.data[i + 1], img.data[i + 2]];
};
const isBackground = (rgb: number[]): boolean => rgb.every((c) => c === 0);

async function settle(page: Page): Promise<void> {
  await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(() => r(null)))));
}

/** A point `t` of the way from a face's centroid to its vertex `k`, world space (tetra.byu scaled by `s`). */
const TETRA = [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1]];
const TETRA_FACES = [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]];
function inside(face: number[], s: number): number[] {
  const c = [0, 1, 2].map((a) => face.reduce((sum, v) => sum + TETRA[v][a], 0) / 3);
  return c.map((x) => x * s);
}

test.beforeEach(async ({ page }) => {
  await installSummary(page);
});

test('a mesh .byu loads (no texture, no order) and camera-src draws it where courseProject says', async ({ page }) => {
  await openPage(page);
  const events = await mountHtml(page, `<glass-plane-scene refine="0" time="0" glass-size="0 0" background="${BLACK}" camera-src="${URL_BASE}camera.cfg">
    <glass-object src="${URL_BASE}tetra.byu" scale="2"></glass-object></glass-plane-scene>`);
  const load = events.find((e) => e.type === 'load')!;
  expect(load.target).toBe('glass-object');
  expect(load.detail).toEqual({ url: expect.stringMatching(/\/tetra\.byu$/), warnings: [] });
  const s = await summary(page);
  expect(s.objects.map((o) => [o.kind, o.vertices, o.triangles, o.material.texture])).toEqual([['mesh', 4, 4, 'none']]);
  await settle(page);
  const img = await capture(page);
  expect([img.width, img.height]).toEqual([W, H]);
  const cam = camera('camera.cfg');
  // Faces seen edge-on (the planes x = 0 and y = 0 pass through C) have no pixels of their own.
  const seen = TETRA_FACES.filter((f) => {
    const [a, b, c] = f.map((v) => courseProject(cam, TETRA[v].map((x) => 2 * x), W, H));
    return Math.abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) > 20;
  });
  expect(seen).toHaveLength(2);
  for (const face of seen) {
    const p = courseProject(cam, inside(face, 2), W, H);
    expect(isBackground(pixel(img, p.x, p.y)), `face ${face} centroid at (${p.x.toFixed(1)}, ${p.y.toFixed(1)})`).toBe(false);
  }
  // Outside the tetrahedron's picture: left of the origin, and above its apex.
  for (const q of [[-1, 1, 0], [1, 2.2, 0], [2.5, 1.5, 0]]) {
    const p = courseProject(cam, q, W, H);
    expect(isBackground(pixel(img, p.x, p.y)), `outside at ${q}`).toBe(true);
  }
});

test('a Bézier .byu: load detail.order, E×E vertices, resolution re-evaluates without a new fetch', async ({ page }) => {
  await openPage(page);
  const requests: string[] = [];
  page.on('request', (r) => requests.push(r.url()));
  const events = await mountHtml(page, `<glass-plane-scene refine="0" time="0" glass-size="0 0" background="${BLACK}" camera-src="${URL_BASE}camera.cfg">
    <glass-object src="${URL_BASE}patch-2x5-first-fastest.byu" position="-4 -2 0" scale="1.5"></glass-object>
    <glass-object src="${URL_BASE}patch-3x3-second-fastest.byu" position="1 -1 0"></glass-object></glass-plane-scene>`);
  const loads = events.filter((e) => e.type === 'load').map((e) => [e.detail.url.split('/').pop(), e.detail.order]);
  expect(loads.sort()).toEqual([['patch-2x5-first-fastest.byu', 'first-fastest'], ['patch-3x3-second-fastest.byu', 'second-fastest']]);
  let s = await summary(page);
  expect(s.objects.map((o) => o.vertices)).toEqual([64, 100]); // E = 8 and E = 10 from the files
  await settle(page);
  const img = await capture(page);
  const cam = camera('camera.cfg');
  // The 3×3 patch's centre, P(0.5, 0.5) ≈ the net's centre in x, y: (1 + 1.5, −1 + 1.5).
  const c = courseProject(cam, [2.5, 0.5, 0], W, H);
  expect(isBackground(pixel(img, c.x, c.y))).toBe(false);

  const before = requests.filter((u) => u.endsWith('.byu')).length;
  await nextEvent(page, 'frame', `el.querySelectorAll('glass-object')[1].setAttribute('resolution', '5')`);
  s = await summary(page);
  expect(s.objects.map((o) => o.vertices)).toEqual([64, 25]);
  await nextEvent(page, 'frame', `el.querySelectorAll('glass-object')[1].removeAttribute('resolution')`);
  expect((await summary(page)).objects.map((o) => o.vertices)).toEqual([64, 100]);
  expect(requests.filter((u) => u.endsWith('.byu')).length).toBe(before);
});

test('content after the counts is one warning, once per URL, in the load detail and the console', async ({ page, consoleLog }) => {
  await openPage(page);
  const events = await mountHtml(page, `<glass-plane-scene refine="0" time="0" glass-size="0 0">
    <glass-object src="${URL_BASE}tetra-trailing.byu"></glass-object>
    <glass-object src="${URL_BASE}tetra-trailing.byu" position="2 0 0"></glass-object></glass-plane-scene>`);
  const loads = events.filter((e) => e.type === 'load');
  expect(loads).toHaveLength(2);
  for (const l of loads) {
    expect(l.detail.warnings).toHaveLength(1);
    expect(l.detail.warnings[0]).toMatch(/tetra-trailing\.byu line 11: /);
  }
  const warnings = consoleLog.take('warning').filter((w) => w.includes('tetra-trailing.byu'));
  expect(warnings).toHaveLength(1);
  expect((await summary(page)).objects.map((o) => o.triangles)).toEqual([4, 4]);
});

/** The file, the line its error names (undefined: some line; null: none, not a parse error), the message. */
const malformed: [string, number | null | undefined, RegExp][] = [
  ['mesh-bad-token.byu', 4, /not a number/],
  ['mesh-truncated.byu', undefined, /./],
  ['mesh-missing-count.byu', 1, /./],
  ['page.byu', null, /HTML/],
];

for (const [file, line, message] of malformed) {
  test(`${file} is a load error with file and line; the rest of the scene draws`, async ({ page, consoleLog }) => {
    await openPage(page);
    const events = await mountHtml(page, `<glass-plane-scene refine="0" time="0" glass-size="0 0" background="${BLACK}" camera-src="${URL_BASE}camera.cfg">
      <glass-object src="${URL_BASE}${file}"></glass-object><glass-object shape="sphere" scale="2"></glass-object></glass-plane-scene>`);
    const error = events.find((e) => e.type === 'error')!;
    expect(error.target).toBe('glass-object');
    expect(error.detail).toMatchObject({ type: 'load', url: expect.stringContaining(file) });
    if (line === undefined) expect(error.detail.line).toEqual(expect.any(Number));
    else if (line === null) expect(error.detail.line).toBeUndefined();
    else expect(error.detail.line).toBe(line);
    expect(error.detail.message).toMatch(message);
    expect((await summary(page)).objects.map((o) => o.kind)).toEqual(['sphere']);
    await settle(page);
    const img = await capture(page);
    const c = courseProject(camera('camera.cfg'), [0, 0, 0], W, H);
    expect(isBackground(pixel(img, c.x, c.y)), 'the sphere still draws').toBe(false);
    expect(consoleLog.take('error').filter((e) => e.includes(file))).toHaveLength(1);
  });
}

test('iluminacao.txt: a point light at Pl and the material of every object, attributes first', async ({ page }) => {
  await openPage(page);
  const events = await mountHtml(page, `<glass-plane-scene refine="0" time="0" glass-size="0 0">
    <glass-object src="${URL_BASE}tetra.byu"></glass-object>
    <glass-object shape="sphere" diffuse="0.1 0.9 0.1" shininess="3"></glass-object>
    <glass-light src="${URL_BASE}iluminacao.txt" specular="0.5 0.5 0.5"></glass-light></glass-plane-scene>`);
  expect(events.find((e) => e.type === 'load' && e.target === 'glass-light')?.detail).toEqual({ url: expect.stringMatching(/iluminacao\.txt$/), warnings: [] });
  const s = await summary(page);
  const [tetra, sphere] = s.objects.map((o) => o.material);
  // ka 0.2, kd·Od = 0.5·(0.7, 0.5, 0.8), ks 0.5, n 2 → Blinn 8.
  expect(tetra.ambient).toEqual([0.2, 0.2, 0.2]);
  expect(tetra.diffuse.map((x) => +x.toFixed(6))).toEqual([0.35, 0.25, 0.4]);
  expect(tetra.specular).toEqual([0.5, 0.5, 0.5]);
  expect(tetra.shininess).toBe(8);
  expect(tetra.texture).toBe('none');
  expect(sphere).toMatchObject({ diffuse: [0.1, 0.9, 0.1], shininess: 3, ambient: [0.2, 0.2, 0.2], texture: 'procedural' });
  expect(s.lights).toHaveLength(1);
  const l = s.lights[0];
  expect(l.kind).toBe('point');
  expect(l.vector).toEqual([-200, 50, 100]);
  expect(l.ambient.map((x) => Math.round(x * 255))).toEqual([100, 90, 80]);
  expect(l.diffuse).toEqual([1, 1, 1]);
  expect(l.specular).toEqual([0.5, 0.5, 0.5]); // the attribute wins over Il

  // Removing the file: default material and the default light again.
  await nextEvent(page, 'frame', `el.querySelector('glass-light').removeAttribute('src')`);
  const d = await summary(page);
  expect(d.objects[0].material.diffuse).toEqual([0.8, 0.8, 0.8]);
});

// docs/scene-model.md#material-precedence: attribute over MTL over lighting file over default, for an OBJ with its MTL in an
// element with a lighting file; a light's own position over the file's Pl; with two lighting
// files the first in document order gives the material, and each adds its light.
test('an MTL wins over the lighting file, a light\'s position over Pl, and the first of two files gives the material', async ({ page }) => {
  await openPage(page);
  // The second file: every value unlike the first's (Pl −200 50 100, ka 0.2, kd·Od 0.35 0.25 0.4, ks 0.5, n 2).
  await page.route('**/second/iluminacao.txt', (r) => r.fulfill({ status: 200, contentType: 'text/plain', body: '5 6 7\n0.4\n50 50 50\n1\n0.1 0.2 0.3\n0.9\n100 100 100\n5\n' }));
  await mountHtml(page, `<glass-plane-scene refine="0" time="0" glass-size="0 0">
    <glass-object src="/tests/e2e/pages/models/tetra.obj"></glass-object>
    <glass-object src="${URL_BASE}tetra.byu"></glass-object>
    <glass-light src="${URL_BASE}iluminacao.txt"></glass-light>
    <glass-light src="/second/iluminacao.txt"></glass-light></glass-plane-scene>`);
  const s = await summary(page);
  const [red, textured, byu] = s.objects.map((o) => o.material);
  // tetra.mtl's red: Ka 0.1 0 0, Kd 0.9 0.1 0.1, Ks 0.3, Ns 64 (the file's would be 0.2, 0.35 0.25 0.4, 0.5, 8).
  expect(red).toMatchObject({ ambient: [0.1, 0, 0], diffuse: [0.9, 0.1, 0.1], specular: [0.3, 0.3, 0.3], shininess: 64 });
  // textured has only Kd: the rest from the first lighting file, not the defaults (Ns 32) or the second file.
  expect(textured).toMatchObject({ ambient: [0.2, 0.2, 0.2], diffuse: [0.5, 0.5, 0.5], specular: [0.5, 0.5, 0.5], shininess: 8 });
  expect(byu.diffuse.map((x) => +x.toFixed(6))).toEqual([0.35, 0.25, 0.4]);
  expect(s.lights.map((l) => l.vector)).toEqual([[-200, 50, 100], [5, 6, 7]]);

  await nextEvent(page, 'frame', `el.querySelector('glass-light').setAttribute('position', '1 2 3')`);
  const moved = await summary(page);
  expect(moved.lights.map((l) => l.vector)).toEqual([[1, 2, 3], [5, 6, 7]]);
  expect(moved.lights[0].ambient.map((x) => Math.round(x * 255))).toEqual([100, 90, 80]); // still the file's Ia
});

test('a lighting file that fails adds no light (the default one is used) and fires error with its line', async ({ page, consoleLog }) => {
  await openPage(page);
  const events = await mountHtml(page, `<glass-plane-scene refine="0" time="0" glass-size="0 0">
    <glass-object src="${URL_BASE}tetra.byu"></glass-object>
    <glass-light src="${URL_BASE}iluminacao-bad-token.txt"></glass-light></glass-plane-scene>`);
  const error = events.find((e) => e.type === 'error')!;
  expect(consoleLog.take('error').filter((e) => e.includes('iluminacao-bad-token.txt line 6'))).toHaveLength(1);
  expect(error.target).toBe('glass-light');
  expect(error.detail).toMatchObject({ type: 'load', url: expect.stringContaining('iluminacao-bad-token.txt'), line: 6 });
  const s = await summary(page);
  expect(s.lights.map((l) => l.kind)).toEqual(['directional']);
  expect(s.objects[0].material.diffuse).toEqual([0.8, 0.8, 0.8]);
}, );

/** x mirrored: image b is image a flipped left to right, but for a few pixels on edges. */
function mirroredDifference(a: RgbaImage, b: RgbaImage): number {
  let differ = 0;
  for (let y = 0; y < a.height; y++) {
    for (let x = 0; x < a.width; x++) {
      const p = pixel(a, x, y), q = pixel(b, a.width - 1 - x, y);
      if (p.some((c, k) => Math.abs(c - q[k]) > 8)) differ++;
    }
  }
  return differ;
}

test('a negative hx mirrors the picture left to right (culled built-ins too)', async ({ page }) => {
  await openPage(page);
  await mountHtml(page, `<glass-plane-scene refine="0" time="0" glass-size="0 0" background="${BLACK}" camera-src="${URL_BASE}camera.cfg">
    <glass-object src="${URL_BASE}tetra.byu" scale="2"></glass-object>
    <glass-object shape="cube" position="-2 0 0" rotation="20 30 0"></glass-object></glass-plane-scene>`);
  const a = await capture(page); // mountHtml waited for ready, which waits for the camera file
  const covered = a.data.filter((_, i) => i % 4 === 0 && a.data[i] + a.data[i + 1] + a.data[i + 2] > 0).length;
  expect(covered).toBeGreaterThan(1000); // measured 1073
  await page.evaluate((url) => document.querySelector('glass-plane-scene')!.setAttribute('camera-src', url), `${URL_BASE}camera-negative-hx.cfg`);
  // The camera is in force once its file is in, frames later under load: wait for the picture it
  // means (15 s at most), not for a number of frames.
  await expect.poll(async () => mirroredDifference(a, await capture(page)), { timeout: 15_000 }).toBeLessThan(16);
  const differ = mirroredDifference(a, await capture(page));
  console.log(`negative hx: ${differ} of ${W * H} pixels differ from the mirrored picture (${covered} covered)`);
  // Measured 8 (edge pixels whose coverage rounds differently mirrored); an unmirrored picture differs in hundreds.
  expect(differ).toBeLessThan(16);
});

test('a camera-src that fails fires error (url, line) on the scene element and keeps the camera it had', async ({ page, consoleLog }) => {
  await openPage(page);
  await mountHtml(page, `<glass-plane-scene refine="0" time="0" glass-size="0 0" background="${BLACK}" camera-src="${URL_BASE}camera.cfg">
    <glass-object src="${URL_BASE}tetra.byu" scale="2"></glass-object></glass-plane-scene>`);
  await settle(page);
  const a = await capture(page);
  const detail = await nextEvent(page, 'error', `el.setAttribute('camera-src', '${URL_BASE}camera-truncated.cfg')`);
  expect(detail).toMatchObject({ type: 'load', url: expect.stringContaining('camera-truncated.cfg'), line: 3 });
  expect(consoleLog.take('error').filter((e) => e.includes('camera-truncated.cfg line 3'))).toHaveLength(1);
  await page.evaluate(() => (document.querySelector('glass-plane-scene') as unknown as { requestRender(): void }).requestRender());
  await settle(page);
  const b = await capture(page);
  expect(Buffer.from(b.data).equals(Buffer.from(a.data)), 'the course camera stays').toBe(true);
  // Removing camera-src gives the flyby camera back: another picture.
  await nextEvent(page, 'frame', `el.removeAttribute('camera-src')`);
  await settle(page);
  expect(Buffer.from((await capture(page)).data).equals(Buffer.from(a.data))).toBe(false);
});

/** The element's scene value with its typed arrays, rebuilt on this side. */
async function sceneOf(page: Page): Promise<Scene> {
  const json = await page.evaluate(() => {
    const s = (document.querySelector('glass-plane-scene') as unknown as { scene: Scene }).scene;
    return {
      ...s,
      objects: s.objects.map((o) => (o.geometry.kind !== 'mesh' ? o : {
        ...o, geometry: { ...o.geometry, data: { positions: [...o.geometry.data.positions], normals: [...o.geometry.data.normals], uvs: [...o.geometry.data.uvs], indices: [...o.geometry.data.indices] } },
      })),
    };
  });
  const objects = json.objects.map((o) => {
    if (o.geometry.kind !== 'mesh') return o as SceneObject;
    const d = o.geometry.data as unknown as Record<string, number[]>;
    return { ...o, geometry: { kind: 'mesh', key: o.geometry.key, data: {
      positions: new Float32Array(d.positions), normals: new Float32Array(d.normals), uvs: new Float32Array(d.uvs), indices: new Uint32Array(d.indices),
    } } } as SceneObject;
  });
  return { ...(json as unknown as Scene), objects };
}

for (const glass of [false, true]) {
  test(`a course scene (camera, lighting, mesh and Bézier .byu${glass ? ', glass' : ''}) matches the reference`, async ({ page }) => {
    await openPage(page);
    const glassAttrs = glass ? 'glass-center="0 0 -0.5" glass-normal="0 0 1" glass-size="8 5" transparency="0.4"' : 'glass-size="0 0"';
    await mountHtml(page, `<glass-plane-scene refine="0" time="0" spin="0" samples="4" ${glassAttrs} camera-src="${URL_BASE}camera.cfg">
      <glass-object src="${URL_BASE}tetra.byu" scale="2" rotation="0 -30 0"></glass-object>
      <glass-object src="${URL_BASE}patch-3x3-first-fastest.byu" position="-3.5 -1.5 0" diffuse="0.3 0.5 0.8"></glass-object>
      <glass-light src="${URL_BASE}iluminacao.txt"></glass-light></glass-plane-scene>`);
    await settle(page);
    const image = await capture(page);
    const scene = await sceneOf(page);
    const state: FrameState = defaultFrameState({
      width: image.width, height: image.height, spin: 0, transparency: 0.4, cameraPosition: [0, 0, 0], yaw: 0, pitch: 0, courseCamera: camera('camera.cfg'),
    });
    const ref = renderScene(scene, state, null, { samplesPerAxis: 4 });
    const cmp = compareImages(ref, image.data);
    const line = `course scene${glass ? ' with glass' : ''}: PSNR ${cmp.psnr.all.toFixed(1)} dB (objects ${cmp.psnr.objects.toFixed(1)}, glass ${cmp.psnr.glass.toFixed(1)}, edges ${cmp.psnr.edges.toFixed(1)}), max error ${cmp.maxError.toFixed(0)}`;
    console.log(line);
    test.info().annotations.push({ type: 'psnr', description: line });
    expect(cmp.pixels.objects).toBeGreaterThan(300);
    // Measured in linear light (SwiftShader, 4× MSAA against 4×4 reference samples): 43.0 / 42.5 dB
    // overall, objects 43.1 / 43.1, edges 33.9 / 38.2, glass 44.2 (with glass); as stored they were
    // 46.3 / 46.4, 45.6, 37.8 / 41.2 and 54.5: encoding steepens the errors of the dark glass body
    // and of the edges. (The glass, read anisotropically, is 46.8 dB with isotropic reads: the
    // reference shortens a footprint longer than 64 texels, as at this glass's grazing far end.)
    // Bounds 2 dB below.
    expect(cmp.psnr.all, line).toBeGreaterThanOrEqual((glass ? 42.5 : 43.0) - 2);
    expect(cmp.psnr.objects, line).toBeGreaterThanOrEqual(43.1 - 2);
    expect(cmp.psnr.edges, line).toBeGreaterThanOrEqual((glass ? 38.2 : 33.9) - 2);
    if (glass) expect(cmp.psnr.glass, line).toBeGreaterThanOrEqual(44.2 - 2);
  });
}
