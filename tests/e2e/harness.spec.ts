// The test browser itself: WebGL2 on SwiftShader with what the renderer relies on. When this
// fails, every other browser test would fail for a reason that has nothing to do with the element.
import { test, expect, openPage } from './fixtures';

test('the test browser gives WebGL2 on SwiftShader with WEBGL_clip_cull_distance', async ({ page }) => {
  await page.goto('/tests/e2e/pages/webgl2-probe.html');
  const info = await page.evaluate(() => {
    const gl = document.createElement('canvas').getContext('webgl2');
    if (!gl) return null;
    const dbg = gl.getExtension('WEBGL_debug_renderer_info');
    return {
      renderer: dbg ? String(gl.getParameter(dbg.UNMASKED_RENDERER_WEBGL)) : '',
      clip: gl.getExtension('WEBGL_clip_cull_distance') !== null,
      samples: Number(gl.getParameter(gl.MAX_SAMPLES)),
    };
  });
  expect(info, 'webgl2 context').not.toBeNull();
  expect(info!.renderer).toContain('SwiftShader');
  expect(info!.clip).toBe(true);
  expect(info!.samples).toBeGreaterThanOrEqual(4);
});

test('the element page loads the element from source', async ({ page }) => {
  await openPage(page);
  expect(await page.evaluate(() => typeof customElements.get('glass-plane-scene'))).toBe('function');
});

test('the fixture turns on GL checks and sees WebGL errors as console warnings', async ({ page, consoleLog }) => {
  await page.goto('/tests/e2e/pages/webgl2-probe.html');
  expect(await page.evaluate(() => (globalThis as { __GLASS_PLANE_SCENE_CHECKS__?: boolean }).__GLASS_PLANE_SCENE_CHECKS__)).toBe(true);
  const glError = await page.evaluate(() => {
    const gl = document.createElement('canvas').getContext('webgl2')!;
    gl.drawArrays(gl.TRIANGLES, 0, 3); // no program bound: INVALID_OPERATION
    return gl.getError();
  });
  expect(glError).not.toBe(0);
  // Chromium reports it on the console; the fixture would fail the test had we not taken it.
  await expect.poll(() => consoleLog.count('warning')).toBeGreaterThan(0);
  expect(consoleLog.take('warning').join('\n')).toMatch(/INVALID_OPERATION/);
});
