// Without WebGL2 (docs/element.md#failure-behaviour): the element says so in its own box and fires `error`, and throws
// nothing. The browser here has WebGL2, so getContext('webgl2') is stubbed to return null.
import { test, expect, openPage, type SceneElement } from './fixtures';
import type { GlassPlaneSceneErrorDetail } from '../../src/element/types';
import { withoutWebGL2 } from './helpers/no-webgl2';

test.beforeEach(async ({ page }) => {
  await page.addInitScript(withoutWebGL2);
  await openPage(page);
});

// The element reports this failure through the `error` event and the message only: it logs
// nothing to the console (the fixture fails the test on any console error or warning).
test('renderer="webgl" shows a readable message, fires error webgl2-unavailable, throws nothing', async ({ page }) => {
  const result = await page.evaluate(
    () =>
      new Promise<{ errors: GlassPlaneSceneErrorDetail[]; ready: number; threw: string | null }>((resolve) => {
        const el = document.createElement('glass-plane-scene') as SceneElement;
        el.id = 'no-gl';
        el.setAttribute('renderer', 'webgl'); // auto would draw with the software renderer (software.spec.ts)
        el.style.width = '320px';
        el.style.height = '180px';
        const errors: GlassPlaneSceneErrorDetail[] = [];
        let ready = 0;
        el.addEventListener('error', (e) => errors.push((e as unknown as CustomEvent<GlassPlaneSceneErrorDetail>).detail));
        el.addEventListener('ready', () => ready++);
        document.body.append(el);
        let threw: string | null = null;
        try {
          // The public API stays callable: nothing to draw, but no exception either.
          el.requestRender();
          el.capture();
          void el.stats;
          el.setAttribute('transparency', '0.9');
        } catch (e) {
          threw = String(e);
        }
        // Give a frame or two for anything that would still try to render.
        setTimeout(() => resolve({ errors, ready, threw }), 300);
      }),
  );
  expect(result.threw).toBeNull();
  expect(result.ready, 'no ready event').toBe(0);
  expect(result.errors).toHaveLength(1);
  expect(result.errors[0].type).toBe('webgl2-unavailable');
  expect(result.errors[0].message).toMatch(/WebGL2/);

  const message = page.locator('#no-gl [part=message]');
  await expect(message).toBeVisible();
  await expect(message).toContainText('WebGL2');
  const [box, host] = await Promise.all([message.boundingBox(), page.locator('#no-gl').boundingBox()]);
  expect(box && host, 'message and element boxes').toBeTruthy();
  // In the element's own box.
  expect(box!.x).toBeGreaterThanOrEqual(host!.x);
  expect(box!.y).toBeGreaterThanOrEqual(host!.y);
  expect(box!.x + box!.width).toBeLessThanOrEqual(host!.x + host!.width + 0.5);
  expect(box!.y + box!.height).toBeLessThanOrEqual(host!.y + host!.height + 0.5);
});
