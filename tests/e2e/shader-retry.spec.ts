// A shader that fails to compile is not the end: the element retries when an attribute change
// selects another variant, and after a context restore.
import { test, expect, mount, openPage, nextFrame, type SceneElement } from './fixtures';
import type { Page } from '@playwright/test';
import type { GlassPlaneSceneErrorDetail } from '../../src/element/types';

const SIZE = { width: 160, height: 90 };

/** Makes every shader whose source has `#define FRESNEL_SCHLICK` fail to compile while window.__breakSchlick is true. */
function breakSchlick(): void {
  const w = window as unknown as { __breakSchlick: boolean };
  w.__breakSchlick = true;
  const sources = new WeakMap<WebGLShader, string>();
  const proto = WebGL2RenderingContext.prototype;
  const shaderSource = proto.shaderSource;
  const getShaderParameter = proto.getShaderParameter;
  const getShaderInfoLog = proto.getShaderInfoLog;
  const broken = (s: WebGLShader) => w.__breakSchlick && (sources.get(s) ?? '').includes('#define FRESNEL_SCHLICK');
  proto.shaderSource = function (this: WebGL2RenderingContext, s: WebGLShader, src: string) {
    sources.set(s, src);
    return shaderSource.call(this, s, src);
  };
  proto.getShaderParameter = function (this: WebGL2RenderingContext, s: WebGLShader, p: GLenum) {
    if (p === this.COMPILE_STATUS && broken(s)) return false;
    return getShaderParameter.call(this, s, p);
  };
  proto.getShaderInfoLog = function (this: WebGL2RenderingContext, s: WebGLShader) {
    return broken(s) ? 'ERROR: 0:3: injected by the test' : getShaderInfoLog.call(this, s);
  };
}

/** Records the element's error events and frame count into window.__errors / __frames. */
async function watch(page: Page, selector: string): Promise<void> {
  await page.evaluate((s) => {
    const w = window as unknown as { __errors: GlassPlaneSceneErrorDetail[]; __frames: number };
    w.__errors = [];
    w.__frames = 0;
    const el = document.querySelector(s)!;
    el.addEventListener('error', (e) => w.__errors.push((e as unknown as CustomEvent<GlassPlaneSceneErrorDetail>).detail));
    el.addEventListener('frame', () => w.__frames++);
  }, selector);
}

const errors = (page: Page) => page.evaluate(() => (window as unknown as { __errors: GlassPlaneSceneErrorDetail[] }).__errors.map((e) => e.type));
const messageShown = (page: Page, selector: string) =>
  page.evaluate((s) => !(document.querySelector(s)!.shadowRoot!.querySelector('[part=message]') as HTMLElement).hidden, selector);

test.beforeEach(async ({ page }) => {
  await page.addInitScript(breakSchlick);
  await openPage(page);
});

test('after a shader error, an attribute that selects another variant draws again', async ({ page, consoleLog }) => {
  const { selector } = await mount(page, { time: 1.25 }, SIZE); // fresnel exact: compiles
  await watch(page, selector);

  await page.evaluate((s) => document.querySelector(s)!.setAttribute('fresnel', 'schlick'), selector);
  await expect.poll(() => errors(page)).toEqual(['shader']);
  expect(await messageShown(page, selector), 'the message box is shown').toBe(true);
  const logged = consoleLog.take('error');
  expect(logged.length, 'one console error with the compile log').toBe(1);
  expect(logged[0]).toMatch(/^glass-plane-scene: .*injected by the test/s);
  expect(logged[0], 'the prefix once, not twice').not.toMatch(/^glass-plane-scene: glass-plane-scene:/);

  // A change that keeps the broken variant: still failed, and not reported again.
  await page.evaluate((s) => document.querySelector(s)!.setAttribute('transparency', '0.7'), selector);
  await page.waitForTimeout(300);
  expect(await errors(page)).toEqual(['shader']);
  expect(await messageShown(page, selector)).toBe(true);
  expect(consoleLog.take('error')).toEqual([]);

  // Another variant: it draws again and the message goes away.
  const frame = await nextFrame(page, selector, (el) => el.setAttribute('fresnel', 'exact'));
  expect(frame.passes.glass.ran).toBe(true);
  expect(await messageShown(page, selector), 'the message box is hidden again').toBe(false);
  expect(await page.evaluate((s) => (document.querySelector(s) as SceneElement).capture() !== null, selector)).toBe(true);
  expect(await errors(page)).toEqual(['shader']);
});

test('after a shader error, a context restore retries the same variant', async ({ page, consoleLog }) => {
  const { selector } = await mount(page, { time: 1.25 }, SIZE);
  await watch(page, selector);
  await page.evaluate((s) => document.querySelector(s)!.setAttribute('fresnel', 'schlick'), selector);
  await expect.poll(() => errors(page)).toEqual(['shader']);
  expect(consoleLog.take('error').length).toBe(1);

  // The driver is "fixed" while the context is away; restored, the element compiles schlick again.
  await page.evaluate(() => {
    const gl = (globalThis as { __GLASS_PLANE_SCENE_GL__?: WebGL2RenderingContext }).__GLASS_PLANE_SCENE_GL__!;
    const ext = gl.getExtension('WEBGL_lose_context')!;
    (window as unknown as { __ext: WEBGL_lose_context }).__ext = ext;
    ext.loseContext();
  });
  await expect.poll(() => errors(page)).toEqual(['shader', 'context-lost']);
  const frame = await nextFrame(page, selector, () => {
    (window as unknown as { __breakSchlick: boolean }).__breakSchlick = false;
    (window as unknown as { __ext: WEBGL_lose_context }).__ext.restoreContext();
  });
  expect(frame.passes.glass.ran).toBe(true);
  expect(await messageShown(page, selector)).toBe(false);
  expect(await page.evaluate((s) => document.querySelector(s)!.getAttribute('fresnel'), selector)).toBe('schlick');
  expect(await errors(page)).toEqual(['shader', 'context-lost']);
});
