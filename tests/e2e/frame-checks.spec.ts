// The renderer's checks (`checks: true`, the element's __GLASS_PLANE_SCENE_CHECKS__: gl.getError()
// after each frame, every uniform finite) are a chunk of their own (render/frame-checks.ts),
// fetched by Renderer.load: frames before it go unchecked, frames after it are checked.
import { test, expect } from './fixtures';
import { drawScene, openRendererPage, sceneToJson } from './helpers/scene-json';
import { defaultScene } from '../../src/scene/default-scene';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from '../unit/helpers/frame-state';

const STATE: FrameState = defaultFrameState({ width: 160, height: 90, spin: 0, samples: 0 });

test('the checks report a non-finite uniform once Renderer.load has brought them, not before', async ({ page, consoleLog }) => {
  await openRendererPage(page);
  // A NaN transparency reaches the glass's uniforms as it is (the element never passes one).
  const bad = { ...STATE, transparency: Number.NaN };
  type Api = { __renderer: { drawNow(s: FrameState, sc: unknown): string } };
  await page.evaluate(([s, sc]) => (window as unknown as Api).__renderer.drawNow(s, sc), [bad, sceneToJson(defaultScene(0.75, 0))] as const);
  expect(consoleLog.take('error').filter((e) => e.includes('non-finite uniform')), 'unchecked before load()').toHaveLength(0);
  await drawScene(page, bad, defaultScene(0.75, 0));
  expect(consoleLog.take('error').filter((e) => e.includes('non-finite uniform')).length, 'checked after load()').toBeGreaterThan(0);
});
