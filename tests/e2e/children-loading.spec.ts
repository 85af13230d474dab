// Loading (docs/scene-model.md#loading): <glass-object src> fetches with progress, sniffs, parses (in a worker
// for big files), applies its MTL, and reports load / error; a changed src aborts the old load;
// one fetch per URL; `ready` waits for the models present at connection.
import fs from 'node:fs';
import path from 'node:path';
import { fileURLToPath } from 'node:url';
import type { Page, Route } from '@playwright/test';
import { test, expect, openPage } from './fixtures';
import { installSummary, mountHtml, nextEvent, summary } from './helpers/scene-children';

const MODELS = path.resolve(path.dirname(fileURLToPath(import.meta.url)), 'pages/models');

test.beforeEach(async ({ page }) => {
  await installSummary(page);
});

/** Holds requests for `pattern` until release() (then serves them from disk as usual). */
async function hold(page: Page, pattern: string): Promise<{ release: () => Promise<void>; count: () => number }> {
  const waiting: Route[] = [];
  let n = 0;
  await page.route(pattern, (route) => {
    n++;
    waiting.push(route);
  });
  return {
    release: async () => {
      await page.unroute(pattern);
      for (const r of waiting.splice(0)) await r.continue().catch(() => {});
    },
    count: () => n,
  };
}

test('a model: progress, then load; its MTL materials, one part per material, attributes win', async ({ page }) => {
  await openPage(page);
  const events = await mountHtml(page, `<glass-plane-scene refine="0" time="1">
    <glass-object src="models/tetra.obj" shininess="5"></glass-object></glass-plane-scene>`);
  const types = events.map((e) => e.type);
  expect(types.indexOf('progress')).toBeGreaterThanOrEqual(0);
  expect(types.indexOf('progress')).toBeLessThan(types.indexOf('load'));
  expect(types.indexOf('load')).toBeLessThan(types.indexOf('ready'));
  const progress = events.filter((e) => e.type === 'progress').at(-1)!.detail;
  expect(progress.loaded).toBe(246);
  const load = events.find((e) => e.type === 'load')!;
  expect(load.target).toBe('glass-object');
  expect(load.detail).toEqual({ url: expect.stringMatching(/\/models\/tetra\.obj$/), warnings: [] });

  const s = await summary(page);
  expect(s.objects.map((o) => [o.kind, o.triangles, o.vertices])).toEqual([['mesh', 2, 4], ['mesh', 2, 4]].map(([k, t]) => [k, t, expect.any(Number)]));
  const [red, textured] = s.objects.map((o) => o.material);
  expect(red).toEqual({ ambient: [0.1, 0, 0], diffuse: [0.9, 0.1, 0.1], specular: [0.3, 0.3, 0.3], shininess: 5, opacity: 0.75, texture: 'procedural', mapping: 'uv' });
  expect(textured.texture).toMatch(/\/models\/checker\.png$/);
  expect(textured.diffuse).toEqual([0.5, 0.5, 0.5]);
  expect(textured.ambient).toEqual([0.2, 0.2, 0.2]); // no Ka: the default
  expect(s.objects[0].bounds.radius).toBeGreaterThan(0.8);

  // normalize: longest side 2, centred; nothing refetched.
  await nextEvent(page, 'frame', `el.querySelector('glass-object').setAttribute('normalize', '')`);
  const n = await summary(page);
  expect(n.objects[0].key).toMatch(/#normalized#0$/);
  expect(n.objects[0].bounds.center.map((x) => Math.abs(x) < 1e-6)).toEqual([true, true, true]);
});

// docs/scene-model.md#material-precedence: attribute over MTL over default, nothing written back. tetra.mtl's `red` has Ka, Kd,
// Ks, Ns 64 and d 0.75; `textured` only Kd and map_Kd checker.png.
test('attributes win over the MTL (opacity, diffuse, texture), and the MTL over the defaults', async ({ page }) => {
  await openPage(page);
  const checker = fs.readFileSync(path.join(MODELS, 'checker.png'));
  await page.route('**/own/texture.png', (r) => r.fulfill({ status: 200, contentType: 'image/png', body: checker }));
  await mountHtml(page, `<glass-plane-scene refine="0" time="1">
    <glass-object src="models/tetra.obj" opacity="1" diffuse="0 0 1" texture="/own/texture.png"></glass-object></glass-plane-scene>`);
  const [red, textured] = (await summary(page)).objects.map((o) => o.material);
  const own = expect.stringMatching(/\/own\/texture\.png$/);
  expect(red).toEqual({ ambient: [0.1, 0, 0], diffuse: [0, 0, 1], specular: [0.3, 0.3, 0.3], shininess: 64, opacity: 1, texture: own, mapping: 'uv' });
  expect(textured).toEqual({ ambient: [0.2, 0.2, 0.2], diffuse: [0, 0, 1], specular: [0.5, 0.5, 0.5], shininess: 32, opacity: 1, texture: own, mapping: 'uv' });
  // Nothing written back: the element's attributes are what the page set.
  expect(await page.evaluate(() => document.querySelector('glass-object')!.getAttribute('opacity'))).toBe('1');
});

test('a material named in two MTL files is the first file\'s', async ({ page }) => {
  await openPage(page);
  const files: Record<string, string> = {
    'model.obj': 'mtllib first.mtl second.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl paint\nf 1 2 3\n',
    'first.mtl': 'newmtl paint\nKd 1 0 0\n',
    'second.mtl': 'newmtl paint\nKd 0 1 0\nKs 0 0 1\n',
  };
  await page.route('**/two-libs/*', (r) => r.fulfill({ status: 200, contentType: 'text/plain', body: files[r.request().url().split('/').pop()!] }));
  await mountHtml(page, '<glass-plane-scene refine="0" time="1"><glass-object src="/two-libs/model.obj"></glass-object></glass-plane-scene>');
  const [m] = (await summary(page)).objects.map((o) => o.material);
  expect(m.diffuse).toEqual([1, 0, 0]);
  // Per material, not per value: the second file's Ks is not merged in.
  expect(m.specular).toEqual([0.5, 0.5, 0.5]);
});

test('a changed src aborts the old load, which never appears', async ({ page }) => {
  await openPage(page);
  const slow = await hold(page, '**/models/tetra-copy.obj');
  const failed: string[] = [];
  page.on('requestfailed', (r) => failed.push(r.url()));
  await page.evaluate(() => {
    document.body.innerHTML = '<glass-plane-scene refine="0" time="1" style="width:160px;height:90px"><glass-object src="models/tetra-copy.obj"></glass-object></glass-plane-scene>';
    const loads: string[] = [];
    (window as any).__loads = loads;
    document.body.addEventListener('load', (e) => loads.push((e as CustomEvent).detail.url), true);
  });
  await expect.poll(slow.count).toBe(1);
  const load = await nextEvent(page, 'load', `el.querySelector('glass-object').src = 'models/tetra.obj'`);
  expect(load.url).toMatch(/\/tetra\.obj$/);
  await expect.poll(() => failed.some((u) => u.endsWith('/tetra-copy.obj'))).toBe(true); // aborted
  await slow.release();
  await page.waitForTimeout(300);
  const s = await summary(page);
  expect(s.objects.map((o) => o.key)).toEqual([expect.stringMatching(/\/tetra\.obj#0$/), expect.stringMatching(/\/tetra\.obj#1$/)]);
  expect(await page.evaluate(() => (window as any).__loads)).toEqual([expect.stringMatching(/\/tetra\.obj$/)]);
});

test('removing a loading object aborts its fetch; ready does not wait for it', async ({ page }) => {
  await openPage(page);
  const slow = await hold(page, '**/models/tetra-copy.obj');
  const failed: string[] = [];
  page.on('requestfailed', (r) => failed.push(r.url()));
  const ready = page.evaluate(() => new Promise<void>((resolve) => {
    document.body.innerHTML = '<glass-plane-scene refine="0" time="1" style="width:160px;height:90px"><glass-object src="models/tetra-copy.obj"></glass-object></glass-plane-scene>';
    const el = document.querySelector('glass-plane-scene')!;
    el.addEventListener('ready', () => resolve(), { once: true });
  }));
  await expect.poll(slow.count).toBe(1);
  await page.evaluate(() => document.querySelector('glass-object')!.remove());
  await ready;
  await expect.poll(() => failed.some((u) => u.endsWith('/tetra-copy.obj'))).toBe(true);
  await slow.release();
});

const failures: [string, string, RegExp][] = [
  ['an HTML page (a dev server fallback)', 'models/fallback.obj', /HTML/],
  ['a 404', 'models/missing.obj', /HTTP 404/],
  ['binary garbage', 'models/garbage.obj', /binary/],
];

for (const [what, src, message] of failures) {
  test(`${what} is a load error with the URL; the rest of the scene stays`, async ({ page, consoleLog }) => {
    await openPage(page);
    await page.route('**/models/fallback.obj', (r) => r.fulfill({ status: 200, contentType: 'text/html', body: '<!doctype html><html><body>Not found</body></html>' }));
    const events = await mountHtml(page, `<glass-plane-scene refine="0" time="1">
      <glass-object src="${src}"></glass-object><glass-object shape="sphere"></glass-object></glass-plane-scene>`);
    const error = events.find((e) => e.type === 'error')!;
    expect(error.target).toBe('glass-object');
    expect(error.detail).toMatchObject({ type: 'load', url: expect.stringContaining(src) });
    expect(error.detail.message).toMatch(message);
    expect(events.some((e) => e.type === 'load')).toBe(false);
    expect((await summary(page)).objects.map((o) => o.kind)).toEqual(['sphere']);
    const errors = consoleLog.take('error');
    expect(errors.filter((e) => e.startsWith('glass-plane-scene: ') && e.includes(src))).toHaveLength(1);
    // Chromium's own "Failed to load resource" line for the 404.
    expect(errors.length).toBe(src.includes('missing') ? 2 : 1);
  });
}

test('a missing MTL and a bad face are warnings: load carries them, the console shows each once', async ({ page, consoleLog }) => {
  await openPage(page);
  const events = await mountHtml(page, '<glass-plane-scene refine="0" time="1"><glass-object src="models/no-mtl.obj"></glass-object></glass-plane-scene>');
  const load = events.find((e) => e.type === 'load')!;
  expect(load.detail.warnings).toHaveLength(2);
  expect(load.detail.warnings[0]).toMatch(/^glass-plane-scene: http:\/\/\S+\/models\/no-mtl\.obj line 7: /);
  expect(load.detail.warnings[1]).toMatch(/^glass-plane-scene: http:\/\/\S+\/models\/missing\.mtl: material library not loaded \(HTTP 404/);
  const warnings = consoleLog.take('warning');
  expect(warnings.map((w) => w.replace(/ \(http.*$/, ''))).toEqual(load.detail.warnings);
  consoleLog.take('error'); // Chromium's "Failed to load resource" for missing.mtl
  expect((await summary(page)).objects).toHaveLength(1);
});

test('the same URL on 5 elements is fetched once', async ({ page }) => {
  await openPage(page);
  const requests: string[] = [];
  page.on('request', (r) => requests.push(r.url()));
  const children = '<glass-object src="models/tetra.obj"></glass-object>'.repeat(3);
  await mountHtml(page, `<glass-plane-scene refine="0" time="1">${children}</glass-plane-scene>`);
  await mountHtml(page, '<glass-plane-scene refine="0" time="1"><glass-object src="./models/tetra.obj"></glass-object><glass-object src="models/tetra.obj" normalize></glass-object></glass-plane-scene>');
  expect(requests.filter((u) => u.endsWith('/models/tetra.obj'))).toHaveLength(1);
  expect(requests.filter((u) => u.endsWith('/models/tetra.mtl'))).toHaveLength(1);
  const counts = await page.evaluate(() => [...document.querySelectorAll('glass-plane-scene')].map((e) => (e as any).scene.objects.length));
  expect(counts).toEqual([6, 4]);
});

test('a file of 256 KB or more is parsed in a worker', async ({ page }) => {
  await page.addInitScript(() => {
    const Native = Worker;
    (window as any).__workers = [];
    (window as any).Worker = class extends Native {
      constructor(url: string | URL, options?: WorkerOptions) {
        super(url, options);
        (window as any).__workers.push(String(url));
      }
    };
  });
  await openPage(page);
  // A 40×40-quad grid per row block, repeated until past 256 KB.
  const lines: string[] = [];
  const n = 120;
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) lines.push(`v ${i / n} ${Math.sin(i * j) * 0.01} ${j / n}`);
  for (let j = 0; j < n - 1; j++) for (let i = 0; i < n - 1; i++) {
    const a = j * n + i + 1;
    lines.push(`f ${a} ${a + 1} ${a + n + 1} ${a + n}`);
  }
  const body = lines.join('\n');
  expect(body.length).toBeGreaterThanOrEqual(256 * 1024);
  await page.route('**/models/big.obj', (r) => r.fulfill({ status: 200, contentType: 'text/plain', body }));
  const events = await mountHtml(page, '<glass-plane-scene refine="0" time="1"><glass-object src="models/big.obj"></glass-object></glass-plane-scene>');
  expect(events.find((e) => e.type === 'load')).toBeTruthy();
  const workers = await page.evaluate(() => (window as any).__workers as string[]);
  expect(workers).toHaveLength(1);
  expect(workers[0]).toMatch(/obj-worker/);
  const [o] = (await summary(page)).objects;
  expect([o.vertices, o.triangles]).toEqual([n * n, (n - 1) * (n - 1) * 2]);
  // The small model is parsed on the main thread.
  await mountHtml(page, '<glass-plane-scene refine="0" time="1"><glass-object src="models/tetra.obj"></glass-object></glass-plane-scene>');
  expect(await page.evaluate(() => (window as any).__workers.length)).toBe(1);
});

test('ready waits for the models in the markup, loaded or failed', async ({ page, consoleLog }) => {
  const slow = await hold(page, '**/models/slow.obj');
  await page.goto('/tests/e2e/pages/with-model.html');
  await expect.poll(slow.count).toBe(1);
  await page.waitForTimeout(500); // frames would have been drawn by now
  expect(await page.evaluate(() => (window as any).__events.map((e: any) => e.type))).toEqual([]);
  expect(await page.evaluate(() => (document.querySelector('glass-plane-scene') as any).stats.frames)).toBeGreaterThan(0);
  await slow.release(); // served from disk: there is no slow.obj, so a 404
  await expect.poll(() => page.evaluate(() => (window as any).__events.map((e: any) => e.type))).toEqual(['error', 'ready']);
  consoleLog.take('error');
});
