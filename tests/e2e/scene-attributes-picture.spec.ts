// Each attribute of the children's tables (docs/scene-model.md#glass-object, docs/scene-model.md#glass-light) (and the scene element's glass and background)
// changes the picture. One base scene; each change is applied alone, drawn, captured, compared
// with the base frame, and undone.
import { test, expect, openPage, capture } from './fixtures';
import { mountHtml } from './helpers/scene-children';
import { compareImages } from './helpers/golden';
import { note } from './helpers/bounds';

const BASE = `<glass-plane-scene refine="0" time="0" spin="0" samples="0" camera-position="2.2 2.2 4.5" camera-rotation="-115 -18"
    glass-normal="0 1 0" glass-center="0 0 0" glass-size="6 6">
  <glass-object id="o" shape="sphere" position="0 0.8 0" scale="1.2" shininess="32"></glass-object>
  <glass-object id="m" src="/tests/e2e/pages/models/ngon-textured.obj" position="-2 0.3 -1" scale="0.6"></glass-object>
  <glass-light id="l" direction="0.4 1 0.6"></glass-light>
</glass-plane-scene>`;

/**
 * [element id, attribute, value, pixels it changes as measured here]: every row must change the
 * frame, by at least 90 % of what it was measured to change (the same run after run; the margin
 * is for edge pixels a harmless change may flip), so a change that only half takes effect fails.
 */
// Measured in linear light (color-space srgb, the default). Ka 0.6 0.1 0.1 changes 65 px where
// it changed 146 as stored: the ambient term is a small share of the sphere's light, and
// encoding compresses small changes in the brights.
const CHANGES: [string, string, string, number][] = [
  ['o', 'shape', 'cube', 645], ['o', 'position', '0.5 1 0', 495], ['o', 'rotation', '30 20 10', 213], ['o', 'scale', '1.5 1 1', 284],
  ['o', 'ambient', '0.6 0.1 0.1', 65], ['o', 'diffuse', '0.1 0.9 0.2', 234], ['o', 'specular', '1 1 1', 56], ['o', 'shininess', '4', 282],
  ['o', 'opacity', '0.4', 280], ['o', 'texture', '/tests/e2e/pages/models/checker.png', 217], ['o', 'mapping', 'triplanar', 195],
  ['m', 'src', '/tests/e2e/pages/models/tetra.obj', 312], ['m', 'normalize', '', 359],
  ['l', 'direction', '-1 0.5 0.2', 510], ['l', 'position', '1 3 2', 294], ['l', 'ambient', '0.6 0.6 0.6', 367], ['l', 'diffuse', '0.2 0.3 1', 478],
  ['l', 'specular', '0 0 0', 58],
  ['scene', 'glass-center', '0 -0.5 0', 3838], ['scene', 'glass-normal', '0 1 0.3', 3632], ['scene', 'glass-size', '0 0', 4549],
  ['scene', 'background', '#335', 14008],
];

test('every attribute of the children (docs/scene-model.md#glass-object) changes the picture', async ({ page, consoleLog }) => {
  test.setTimeout(120_000);
  await openPage(page);
  await mountHtml(page, BASE);
  const settle = () => page.evaluate(() => new Promise((r) => setTimeout(() => requestAnimationFrame(() => requestAnimationFrame(() => r(null))), 300)));
  await settle();
  const base = await capture(page);
  const unchanged: string[] = [];
  for (const [id, name, value, measured] of CHANGES) {
    const target = id === 'scene' ? 'glass-plane-scene' : `#${id}`;
    const before = await page.evaluate(({ target, name, value }) => {
      const el = document.querySelector(target)!;
      const old = el.getAttribute(name);
      el.setAttribute(name, value);
      return old;
    }, { target, name, value });
    await settle(); // models and images load asynchronously
    const { differing } = compareImages(base, await capture(page));
    note(`${target} ${name}="${value}": ${differing} px`);
    if (differing < 0.9 * measured) unchanged.push(`${target} ${name}="${value}": ${differing} px (measured ${measured})`);
    await page.evaluate(({ target, name, before }) => {
      const el = document.querySelector(target)!;
      if (before === null) el.removeAttribute(name);
      else el.setAttribute(name, before);
    }, { target, name, before });
    await settle();
  }
  expect(unchanged, 'attributes whose change left the frame as it was, or changed it less than measured').toEqual([]);
  // Back to the base: the frame is the base frame again (nothing stuck).
  expect(compareImages(base, await capture(page)).differing).toBe(0);
  // position with direction set: a point light, and one warning saying so (docs/element.md#bad-values).
  expect(consoleLog.take('warning').filter((w) => !w.includes('position is set too'))).toEqual([]);
});

test('the reflection skips (docs/knobs.md#reflection-skips) hold for any glass placement: a glass floor out of view, seen edge-on, or absent', async ({ page }) => {
  await openPage(page);
  await mountHtml(page, `<glass-plane-scene refine="0" time="0" spin="0" glass-normal="0 1 0" glass-center="0 0 0" glass-size="6 6"
      camera-position="0 2 5" camera-rotation="-90 -20"><glass-object shape="cube" position="0 1 0"></glass-object></glass-plane-scene>`);
  const reflection = (attrs: Record<string, string>) => page.evaluate((attrs) => new Promise<{ ran: boolean; reason?: string }>((resolve) => {
    const el = document.querySelector('glass-plane-scene')!;
    el.addEventListener('frame', (e) => resolve((e as CustomEvent).detail.passes.reflection), { once: true });
    for (const [k, v] of Object.entries(attrs)) el.setAttribute(k, v);
  }), attrs);
  expect(await reflection({ 'camera-rotation': '-90 -21' }), 'looking down at the floor').toEqual({ ran: true, reason: undefined });
  expect((await reflection({ 'camera-rotation': '-90 60' })).reason, 'looking up, the floor out of view').toBe('glass off screen');
  expect((await reflection({ 'camera-position': '0 0 5', 'camera-rotation': '-90 0' })).reason, 'the eye in the floor plane').toBe('glass edge-on');
  expect((await reflection({ 'camera-position': '0 2 5', 'camera-rotation': '-90 -20', 'glass-size': '0 0' })).reason, 'no glass').toBe('no glass');
});
