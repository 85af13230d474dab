// `<glass-object reflect="false">` (docs/scene-model.md#glass-object) through the element and WebGL:
// the object is drawn but not reflected — the reflection pass is the one drawn without it — and the
// attribute reaches the scene value as `reflected: false`.
import { test, expect, openPage, capture } from './fixtures';
import { mountHtml } from './helpers/scene-children';
import { differingBytes } from '../unit/helpers/pixel-diff';
import type { Scene } from '../../src/scene/scene';

const scene = (cube: string) => `<glass-plane-scene refine="0" time="0" spin="0" debug-view="reflection" style="width:160px;height:90px">
  ${cube}<glass-object shape="sphere" position="0.6 1 -1.2"></glass-object></glass-plane-scene>`;
const CUBE = '<glass-object shape="cube" position="-0.8 1 0.9" rotation="0 30 0"';

test('WebGL: reflect="false" keeps the cube out of the reflection, and the scene value says so', async ({ page }) => {
  await openPage(page);
  const frames = [];
  for (const markup of [`${CUBE} reflect="false"></glass-object>`, '', `${CUBE}></glass-object>`]) {
    await page.evaluate(() => document.body.replaceChildren());
    await mountHtml(page, scene(markup));
    frames.push(await capture(page));
  }
  const [unreflected, without, reflected] = frames;
  expect(differingBytes(unreflected.data, without.data), 'the reflection drawn without the cube').toBe(0);
  expect(differingBytes(reflected.data, without.data), 'by default the cube is reflected').toBeGreaterThan(100);
  // The property and the scene value.
  const values = await page.evaluate(() => {
    const el = document.querySelector('glass-plane-scene') as unknown as { scene: Scene };
    const cube = document.querySelector('glass-object') as unknown as { reflect: boolean };
    const before = [cube.reflect, el.scene.objects[0].reflected];
    cube.reflect = false;
    return new Promise<unknown[]>((r) => requestAnimationFrame(() => r([...before, (cube as unknown as Element).getAttribute('reflect'), el.scene.objects[0].reflected])));
  });
  expect(values).toEqual([true, undefined, 'false', false]);
});
