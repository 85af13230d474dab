// What a person sees while models load (docs/element.md#loading-a-person-can-see): the progress
// bar while a child's model is on its way, filled by its bytes, gone when it has loaded or failed;
// the poster until `ready`, then removed.
import { test, expect, openPage } from './fixtures';
import { productGlb } from './helpers/gltf-models';

/** Mounts a scene of `srcs` and logs the bar's state at each child event, until `ready`. */
const barLog = (page: import('@playwright/test').Page, srcs: string[]) => page.evaluate((srcs) => new Promise<string[]>((resolve) => {
  const log: string[] = [];
  const host = document.createElement('div');
  host.innerHTML = `<glass-plane-scene refine="0" time="0" spin="0" style="width:160px;height:90px">${srcs.map((s, i) => `<glass-object src="${s}" position="${i} 0 0"></glass-object>`).join('')}</glass-plane-scene>`;
  const el = host.firstElementChild as HTMLElement;
  const bar = () => el.shadowRoot!.querySelector('[part=progress]') as HTMLElement;
  const shown = () => (bar().hidden ? 'hidden' : 'shown');
  const fill = () => (el.shadowRoot!.querySelector('[part=progress-bar]') as HTMLElement).style.width;
  log.push(`start ${shown()}`);
  el.addEventListener('progress', () => log.push(`progress ${shown()} ${bar().getAttribute('aria-valuenow')} ${fill()}`));
  el.addEventListener('load', () => log.push(`load ${shown()}`));
  el.addEventListener('error', (e) => { if (e.target !== el) log.push(`error ${shown()}`); });
  el.addEventListener('ready', () => resolve(log));
  document.body.append(host);
}), srcs);

test('the progress bar shows a model from its request, filled by its bytes, and goes when it has loaded', async ({ page }) => {
  const glb = await productGlb();
  await page.route('**/slow/product.glb', async (route) => {
    await new Promise((r) => setTimeout(r, 400));
    await route.fulfill({ status: 200, contentType: 'model/gltf-binary', body: Buffer.from(glb) });
  });
  await openPage(page);
  // The request (0 bytes, no total yet: indeterminate), the body whole (100 %), the load.
  expect(await barLog(page, ['/slow/product.glb'])).toEqual(['start hidden', 'progress shown null ', 'progress shown 100 100%', 'load hidden']);
});

test('with two models the bar stays until the last has ended, a failed one too', async ({ page, consoleLog }) => {
  const glb = await productGlb();
  await page.route('**/slow/product.glb', async (route) => {
    await new Promise((r) => setTimeout(r, 400));
    await route.fulfill({ status: 200, contentType: 'model/gltf-binary', body: Buffer.from(glb) });
  });
  await page.route('**/slow/missing.glb', async (route) => {
    await new Promise((r) => setTimeout(r, 400));
    await route.fulfill({ status: 404, body: 'not found' });
  });
  await openPage(page);
  const seen = await barLog(page, ['/slow/product.glb', '/slow/missing.glb']);
  const ends = seen.filter((l) => /^(load|error)/.test(l));
  expect(ends.sort()).toEqual(expect.arrayContaining([expect.stringMatching(/^load/), expect.stringMatching(/^error/)]));
  // Whichever ends first leaves the bar up (the other is on its way); the last takes it down.
  expect(seen.filter((l) => /^(load|error)/.test(l)).map((l) => l.split(' ')[1])).toEqual(['shown', 'hidden']);
  // The 404: the browser's line and the element's one error naming the file.
  expect(consoleLog.take('error').some((e) => e.includes('missing.glb'))).toBe(true);
});

test('the poster covers the canvas until ready, then is removed; set after ready it shows nothing', async ({ page }) => {
  const glb = await productGlb();
  await page.route('**/slow/product.glb', async (route) => {
    await new Promise((r) => setTimeout(r, 500));
    await route.fulfill({ status: 200, contentType: 'model/gltf-binary', body: Buffer.from(glb) });
  });
  await openPage(page);
  const seen = await page.evaluate(() => new Promise<string[]>((resolve) => {
    const poster = 'data:image/svg+xml,' + encodeURIComponent('<svg xmlns="http://www.w3.org/2000/svg" width="4" height="4"><rect width="4" height="4" fill="red"/></svg>');
    const host = document.createElement('div');
    host.innerHTML = `<glass-plane-scene refine="0" time="0" spin="0" style="width:160px;height:90px" poster="${poster}">
      <glass-object src="/slow/product.glb"></glass-object></glass-plane-scene>`;
    const el = host.firstElementChild as HTMLElement;
    const img = () => el.shadowRoot!.querySelector('[part=poster]') as HTMLImageElement;
    const state = () => `${img().hidden ? 'hidden' : 'shown'} ${img().hasAttribute('src') ? 'src' : 'no-src'} ${getComputedStyle(img()).display}`;
    document.body.append(host);
    const log = [`connected ${state()}`];
    el.addEventListener('load', () => log.push(`model loaded ${state()}`));
    el.addEventListener('ready', () => {
      log.push(`ready ${state()}`);
      el.setAttribute('poster', poster);
      log.push(`set again ${state()}`);
      resolve(log);
    });
  }));
  expect(seen).toEqual(['connected shown src block', 'model loaded shown src block', 'ready hidden no-src none', 'set again hidden no-src none']);
});
