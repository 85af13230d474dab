// environment="url" (docs/pbr.md#an-image): WebGL reads an image the way the CPU renderers do — a white mirror facing the camera
// reflects the texels three quarters across (+z), to the level — and the grid of spheres under a sky against the reference;
// through the element, a Radiance file and a PNG made by the tests are the light `ready` waits for, drawn as the reference draws
// the element's scene value; files that cannot be read fire `error` naming the file and the place, and the studio lights the
// model instead; the chunk is fetched only for a URL with a glTF material.
import { PNG } from 'pngjs';
import { test, expect, openPage, capture } from './fixtures';
import { drawScene, openRendererPage } from './helpers/scene-json';
import { mountHtml, requestedFrame } from './helpers/scene-children';
import { fetchedChunks } from './helpers/chunks';
import { productGlb } from './helpers/gltf-models';
import { elementScene } from './helpers/element-scene';
import { expectPsnr, note } from './helpers/bounds';
import { renderScene, compareImages } from '../../src/reference';
import { defaultFrameState } from '../unit/helpers/frame-state';
import { BOX_STATE, boxScene, imageEnvironment, pbrMaterial, skyImage, sphereGrid } from '../unit/helpers/pbr-scenes';
import { hdrFile } from '../unit/helpers/hdr-file';
import type { Scene } from '../../src/scene/scene';
import type { Page } from '@playwright/test';

const CENTRE = 4 * (16 * 33 + 16);

test('WebGL: a white mirror facing the camera reflects the image three quarters across (+z): (0.2, 0.4, 0.6) within a level', async ({ page }) => {
  await openRendererPage(page);
  const rgb = new Float32Array(16 * 8 * 3);
  for (let j = 0; j < 8; j++) for (let i = 0; i < 16; i++) rgb.set(i >= 10 && i <= 13 ? [0.2, 0.4, 0.6] : [0.9, 0.1, 0.1], 3 * (j * 16 + i));
  const scene: Scene = { ...boxScene(pbrMaterial({ baseColor: [1, 1, 1, 1], metallic: 1, roughness: 0 })), lights: [], environment: imageEnvironment({ width: 16, height: 8, rgb }, 1, 'https://example.test/quarters.hdr') };
  const got = [...(await drawScene(page, BOX_STATE, scene)).data.subarray(CENTRE, CENTRE + 3)];
  [0.2, 0.4, 0.6].forEach((want, k) => expect(Math.abs(got[k] - want * 255), `channel ${k}: ${got}`).toBeLessThanOrEqual(1));
});

test('WebGL: the grid of spheres under a sky with a sun, tone mapped, against the reference, within 2 dB of its measured PSNR', async ({ page }) => {
  await openRendererPage(page);
  const scene: Scene = { ...sphereGrid(), lights: [], environment: imageEnvironment(skyImage()) };
  const state = defaultFrameState({ width: 320, height: 180, cameraPosition: [0, 1.5, 3.3], yaw: -90, pitch: -8, time: 0, spin: 0, samples: 4, toneMapping: 'neutral' });
  const image = await drawScene(page, state, scene);
  const cmp = compareImages(renderScene(scene, state, null, { samplesPerAxis: 4, environmentSamples: 1024 }), image.data);
  const p = cmp.psnr;
  note(`PBR sphere grid under a sky image, WebGL against the reference: all ${p.all.toFixed(1)}, objects ${p.objects.toFixed(1)}, glass ${p.glass.toFixed(1)}, edges ${p.edges.toFixed(1)}, dark ${p.dark.toFixed(1)} dB`);
  // Measured here: all 30.1, objects 41.3, glass 53.1, edges 22.7, dark 49.5 dB (MSAA shades a pixel once, the reference 16 times).
  expectPsnr(cmp, { all: 30.1, objects: 41.3, glass: 53.1 }, 'PBR sphere grid under a sky image');
});

/** The sky as a PNG of sRGB bytes (its sun clipped at 1). */
function skyPng(): Buffer {
  const sky = skyImage(64), png = new PNG({ width: 64, height: 32 });
  const enc = (l: number) => Math.round(255 * (l <= 0.0031308 ? 12.92 * l : 1.055 * Math.min(1, l) ** (1 / 2.4) - 0.055));
  for (let k = 0; k < 64 * 32; k++) {
    png.data[4 * k] = enc(sky.rgb[3 * k]); png.data[4 * k + 1] = enc(sky.rgb[3 * k + 1]); png.data[4 * k + 2] = enc(sky.rgb[3 * k + 2]); png.data[4 * k + 3] = 255;
  }
  return PNG.sync.write(png);
}

async function routes(page: Page): Promise<void> {
  const glb = await productGlb();
  await page.route('**/wild/product.glb', (route) => route.fulfill({ status: 200, contentType: 'text/plain', body: Buffer.from(glb) }));
  const hdr = Buffer.from(hdrFile(skyImage(256)));
  await page.route('**/skies/sky%20at%20noon.hdr', (route) => route.fulfill({ status: 200, contentType: 'application/octet-stream', body: hdr }));
  await page.route('**/skies/cut.hdr', (route) => route.fulfill({ status: 200, body: hdr.subarray(0, hdr.length - 3000) }));
  await page.route('**/skies/page.hdr', (route) => route.fulfill({ status: 200, contentType: 'text/html', body: '<!doctype html><p>Not here</p>' }));
  await page.route('**/skies/missing.hdr', (route) => route.fulfill({ status: 404, body: 'not found' }));
  await page.route('**/skies/sky.png', (route) => route.fulfill({ status: 200, contentType: 'image/png', body: skyPng() }));
}

const mount = (page: Page, renderer: string, environment: string) => mountHtml(page, `<glass-plane-scene refine="0" renderer="${renderer}" environment="${environment}" time="0" spin="0" samples="4" camera-position="1.8 1.6 4.5" camera-rotation="-100 -12">
  <glass-object src="/wild/product.glb" position="0 0.3 1.2"></glass-object>
</glass-plane-scene>`);

const MEASURED = {
  // Measured here, against the reference at 1,024 directions a pixel (docs/pbr.md#an-image).
  'webgl hdr': { all: 42.9, objects: 40.3, glass: 52.4 },
  'software hdr': { all: 39.9, objects: 40.2, glass: 53.4 },
} as const;

for (const renderer of ['webgl', 'software'] as const) {
  test(`${renderer}: environment="skies/sky at noon.hdr" — ready waits for it, the scene value names it, drawn as the reference draws that value`, async ({ page, consoleLog }) => {
    await routes(page);
    await openPage(page);
    const seen = await mount(page, renderer, 'skies/sky at noon.hdr');
    expect(seen.filter((e) => e.type === 'error')).toEqual([]);
    for (let k = 0; k < 2; k++) await requestedFrame(page);
    const image = await capture(page);
    const { scene, state, images } = await elementScene(page, image.width, image.height, { toneMapping: 'neutral' });
    const env = scene.environment!;
    expect(env.kind).toBe('image');
    if (env.kind !== 'image') return;
    expect(env.url).toMatch(/\/skies\/sky%20at%20noon\.hdr$/);
    // 256 × 128 as written: not reduced (at most 512 × 256).
    expect([env.image.width, env.image.height]).toEqual([256, 128]);
    const cmp = compareImages(renderScene(scene, state, images, { samplesPerAxis: 4, environmentSamples: 1024 }), image.data);
    note(`${renderer}, environment a .hdr sky: GLB product PSNR ${cmp.psnr.all.toFixed(1)} dB (objects ${cmp.psnr.objects.toFixed(1)}, glass ${cmp.psnr.glass.toFixed(1)})`);
    expectPsnr(cmp, MEASURED[`${renderer} hdr`], `${renderer}, environment a .hdr sky`);
    expect(consoleLog.take('pageerror')).toEqual([]);
  });
}

test('a PNG sky lights the model as sRGB; files that cannot be read fire error naming the file and the place, and the studio lights it instead', async ({ page, consoleLog }) => {
  await routes(page);
  await openPage(page);
  const picture = async (environment: string) => {
    const seen = await mount(page, 'webgl', environment);
    const errors = seen.filter((e) => e.type === 'error').map((e) => e.detail);
    const env = await page.evaluate(() => {
      const e = ([...document.querySelectorAll('glass-plane-scene')].pop() as unknown as { scene: Scene }).scene.environment;
      return e ? { kind: e.kind, width: e.kind === 'image' ? e.image.width : 0 } : null;
    });
    return { errors, env };
  };
  const png = await picture('skies/sky.png');
  expect(png).toEqual({ errors: [], env: { kind: 'image', width: 64 } });
  // Its bytes taken as sRGB: the texels the scene value holds are the sky's linear light again, to the 8-bit step.
  const texels = await page.evaluate(() => {
    const e = ([...document.querySelectorAll('glass-plane-scene')].pop() as unknown as { scene: Scene }).scene.environment;
    return e?.kind === 'image' ? [...e.image.rgb.subarray(0, 3 * 64 * 32)] : [];
  });
  const sky = skyImage(64);
  for (const k of [3 * (5 * 64 + 10), 3 * (28 * 64 + 40) + 2]) expect(Math.abs(texels[k] - sky.rgb[k]), `texel value ${k}`).toBeLessThan(0.01 * Math.max(0.1, sky.rgb[k]) + 0.002);
  for (const [file, message] of [['missing.hdr', /404/], ['page.hdr', /HTML/], ['cut.hdr', /scanline \d+ of 128/]] as const) {
    const got = await picture(`skies/${file}`);
    expect(got.env, file).toEqual({ kind: 'studio', width: 0 });
    expect(got.errors.length, file).toBe(1);
    expect(got.errors[0].url, file).toMatch(new RegExp(`/skies/${file.replace('.', '\\.')}$`));
    expect(got.errors[0].message, file).toMatch(message);
  }
  // One message each, from the page's cache of loads (the browser adds its own line for the 404).
  const logged = consoleLog.take('error').filter((m) => m.includes('glass-plane-scene'));
  for (const file of ['missing.hdr', 'page.hdr', 'cut.hdr']) expect(logged.filter((m) => m.includes(`/skies/${file}`)).length, file).toBe(1);
  expect(consoleLog.take('pageerror')).toEqual([]);
});

test('the environment-files chunk is fetched only by a URL with a glTF material', async ({ page }) => {
  await routes(page);
  await openPage(page);
  await mountHtml(page, `<glass-plane-scene refine="0" time="0" spin="0" environment="skies/sky.png"></glass-plane-scene>`);
  await mountHtml(page, `<glass-plane-scene refine="0" time="0" spin="0"><glass-object src="/wild/product.glb"></glass-object></glass-plane-scene>`);
  expect(await fetchedChunks(page, ['environment-files'])).toEqual([]);
  await mountHtml(page, `<glass-plane-scene refine="0" time="0" spin="0" environment="skies/sky.png"><glass-object src="/wild/product.glb"></glass-object></glass-plane-scene>`);
  expect(await fetchedChunks(page, ['environment-files'])).toEqual(['environment-files']);
});
