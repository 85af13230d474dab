// <glass-object> and <glass-light> children (docs/scene-model.md#children) become the element's scene value.
// Attributes parse, reflect and fall back with one warning; adding, removing, reordering and
// changing children updates el.scene and draws a frame; late and never-upgraded children.
import { test, expect, openPage, nextFrame, type SceneElement } from './fixtures';
import { installSummary, mountHtml, summary } from './helpers/scene-children';

test.beforeEach(async ({ page }) => {
  await installSummary(page);
});

test('child attributes parse, reflect to properties and fall back with one warning per value', async ({ page, consoleLog }) => {
  await openPage(page);
  await mountHtml(page, `<glass-plane-scene refine="0" time="1">
    <glass-object id="a" shininess="abc" diffuse="0.1 0.2 0.3" scale="2" shape="sphere"></glass-object>
    <glass-object id="b" shininess="abc" opacity="7"></glass-object>
    <glass-light id="l" direction="0 0 0" ambient="2 2 2"></glass-light>
  </glass-plane-scene>`);
  const r = await page.evaluate(() => {
    const a = document.getElementById('a') as any, b = document.getElementById('b') as any, l = document.getElementById('l') as any;
    const before = { shininess: a.shininess, diffuse: a.diffuse, scale: a.scale, shape: a.shape, opacity: b.opacity, direction: l.direction, ambient: l.ambient };
    a.position = [1, 2, 3];
    a.normalizeModel = true;
    a.mapping = 'TRIPLANAR';
    l.position = '4 5 6';
    return {
      before,
      attrs: { position: a.getAttribute('position'), normalize: a.getAttribute('normalize'), mapping: a.mapping },
      light: l.toLight(),
    };
  });
  expect(r.before).toEqual({ shininess: null, diffuse: [0.1, 0.2, 0.3], scale: [2, 2, 2], shape: 'sphere', opacity: 1, direction: null, ambient: [2, 2, 2] });
  expect(r.attrs).toEqual({ position: '1 2 3', normalize: '', mapping: 'triplanar' });
  expect(r.light).toEqual({ kind: 'point', vector: [4, 5, 6], ambient: [2, 2, 2], diffuse: [0.85, 0.85, 0.85], specular: [1, 1, 1] });
  const warnings = consoleLog.take('warning');
  // shininess="abc" on two elements: one warning; opacity="7" and direction="0 0 0": one each.
  expect(warnings.filter((w) => w.includes('<glass-object> shininess="abc"'))).toHaveLength(1);
  expect(warnings.filter((w) => w.includes('<glass-object> opacity="7"'))).toHaveLength(1);
  expect(warnings.filter((w) => w.includes('<glass-light> direction="0 0 0"'))).toHaveLength(1);
  expect(warnings.every((w) => w.startsWith('glass-plane-scene: '))).toBe(true);
  expect(warnings).toHaveLength(3);
});

test('no children: the default scene; objects and lights replace the defaults', async ({ page }) => {
  await openPage(page);
  await mountHtml(page, '<glass-plane-scene refine="0" time="1" cube-distance="0.5"></glass-plane-scene>');
  const d = await summary(page);
  expect(d.objects.map((o) => o.kind)).toEqual(['box', 'sphere']);
  expect(d.objects[0].position).toEqual([-1, 1, 0.5]);
  expect(d.lights).toHaveLength(1);
  expect(d.glass).toEqual({ center: [0, 1, 0], normal: [0, 0, 1], size: [8, 4] });
  expect(d.background).toEqual([0.1, 0.1, 0.1]);

  await nextFrame(page, 'glass-plane-scene', (el) => {
    const o = document.createElement('glass-object');
    o.setAttribute('shape', 'gaussian');
    o.setAttribute('resolution', '12');
    o.setAttribute('position', '0 1 0');
    el.append(o);
  });
  const s = await summary(page);
  expect(s.objects.map((o) => [o.kind, o.resolution])).toEqual([['gaussian', 12]]);
  expect(s.objects[0].material).toEqual({
    ambient: [0.2, 0.2, 0.2], diffuse: [0.8, 0.8, 0.8], specular: [0.5, 0.5, 0.5], shininess: 32, opacity: 1, texture: 'procedural', mapping: 'uv',
  });
  expect(s.lights).toEqual(d.lights); // still the default light

  await nextFrame(page, 'glass-plane-scene', (el) => el.append(document.createElement('glass-light')));
  const l = await summary(page);
  // A bare <glass-light> is the default light.
  expect(l.lights).toEqual(d.lights);
});

test('adding, removing, reordering and changing children updates el.scene, each with a frame', async ({ page }) => {
  await openPage(page);
  await mountHtml(page, `<glass-plane-scene refine="0" time="1">
    <glass-object id="c"></glass-object><glass-object id="s" shape="sphere"></glass-object>
    <glass-light id="l1" direction="0 1 0"></glass-light>
  </glass-plane-scene>`);
  const kinds = async () => (await summary(page)).objects.map((o) => o.kind);
  expect(await kinds()).toEqual(['box', 'sphere']);
  const sel = 'glass-plane-scene';
  const frameAfter = (f: (el: SceneElement) => void) => nextFrame(page, sel, f);

  await frameAfter((el) => el.prepend(el.querySelector('#s')!)); // reorder
  expect(await kinds()).toEqual(['sphere', 'box']);
  await frameAfter((el) => el.querySelector('#c')!.setAttribute('shape', 'gaussian')); // change
  expect(await kinds()).toEqual(['sphere', 'gaussian']);
  await frameAfter((el) => { (el.querySelector('#s') as any).position = '3 2 1'; });
  expect((await summary(page)).objects[0].position).toEqual([3, 2, 1]);
  await frameAfter((el) => el.querySelector('#c')!.remove()); // remove
  expect(await kinds()).toEqual(['sphere']);
  await frameAfter((el) => el.querySelector('#l1')!.setAttribute('diffuse', '0.5 0.25 2'));
  expect((await summary(page)).lights[0].diffuse).toEqual([0.5, 0.25, 2]);
  await frameAfter((el) => el.querySelector('#s')!.remove());
  await frameAfter((el) => el.querySelector('#l1')!.remove());
  const back = await summary(page);
  expect(back.objects.map((o) => o.kind)).toEqual(['box', 'sphere']); // the defaults again
  expect(back.lights[0].vector[1]).toBeCloseTo(1 / Math.hypot(0.4, 1, 0.6), 12);

  // A grandchild is not a child: not part of the scene.
  await frameAfter((el) => { const d = document.createElement('div'); d.append(document.createElement('glass-object')); el.append(d); });
  expect(await kinds()).toEqual(['box', 'sphere']);
});

test('at most 4 lights: the fifth is ignored with one warning', async ({ page, consoleLog }) => {
  await openPage(page);
  await mountHtml(page, `<glass-plane-scene refine="0" time="1">${'<glass-light></glass-light>'.repeat(5)}</glass-plane-scene>`);
  expect((await summary(page)).lights).toHaveLength(4);
  await nextFrame(page, 'glass-plane-scene', (el) => el.append(document.createElement('glass-light')));
  expect((await summary(page)).lights).toHaveLength(4);
  const w = consoleLog.take('warning');
  expect(w).toHaveLength(1);
  expect(w[0]).toMatch(/^glass-plane-scene: at most 4 <glass-light>/);
});

test('glass and background come from the attributes; "0 0" removes the glass', async ({ page, consoleLog }) => {
  await openPage(page);
  await mountHtml(page, '<glass-plane-scene refine="0" time="1" glass-normal="0 2 0" glass-center="0 0 0" glass-size="6 5" background="red"></glass-plane-scene>');
  const s = await summary(page);
  expect(s.glass).toEqual({ center: [0, 0, 0], normal: [0, 1, 0], size: [6, 5] });
  expect(s.background).toEqual([1, 0, 0]); // a named colour, through the canvas
  const el = 'glass-plane-scene';
  await nextFrame(page, el, (e) => { e.setAttribute('glass-size', '0 0'); e.setAttribute('background', 'hsl(120 100% 25%)'); });
  const t = await summary(page);
  expect(t.glass).toBeNull();
  expect(t.background[0]).toBe(0);
  expect(t.background[1]).toBeCloseTo(0.5, 2);
  const props = await page.evaluate(() => {
    const e = document.querySelector('glass-plane-scene') as any;
    e.glassNormal = [0, 0, 0];
    return { normal: e.glassNormal, size: e.glassSize, center: e.glassCenter };
  });
  expect(props).toEqual({ normal: [0, 0, 1], size: [0, 0], center: [0, 0, 0] });
  const w = consoleLog.take('warning');
  expect(w).toEqual([expect.stringMatching(/^glass-plane-scene: glass-normal="0 0 0": /)]);
});

// The scene element loads the children's chunk itself (children-loader.ts); here that load is
// blocked, as for a page whose children come from elsewhere (another copy of the package).
test('children defined after the scene element join the scene when they upgrade', async ({ page, consoleLog }) => {
  await page.route('**/child-elements*', (route) => route.abort());
  await openPage(page, 'parent-only');
  await mountHtml(page, `<glass-plane-scene refine="0" time="1">
    <glass-object shape="sphere" position="1 2 3"></glass-object><glass-light position="0 5 0"></glass-light>
  </glass-plane-scene>`);
  // Not upgraded: nothing to describe yet, so the default scene, and no crash.
  expect((await summary(page)).objects.map((o) => o.kind)).toEqual(['box', 'sphere']);
  expect((await summary(page)).objects[0].position).toEqual([-1, 1, 0.75]);
  await nextFrame(page, 'glass-plane-scene', () => {
    void (async () => {
      const { GlassObject } = await import('/src/element/children/glass-object.ts' as string);
      const { GlassLight } = await import('/src/element/children/glass-light.ts' as string);
      customElements.define('glass-object', GlassObject);
      customElements.define('glass-light', GlassLight);
    })();
  });
  await expect.poll(async () => (await summary(page)).objects.map((o) => [o.kind, ...o.position])).toEqual([['sphere', 1, 2, 3]]);
  expect((await summary(page)).lights.map((l) => l.kind)).toEqual(['point']);
  expect(consoleLog.take('warning').filter((w) => w.includes('could not load'))).toHaveLength(1);
  consoleLog.take('error'); // the browser's report of the blocked fetch
});

test('children never upgraded (their chunk blocked): the scene element renders its default scene', async ({ page, consoleLog }) => {
  await page.route('**/child-elements*', (route) => route.abort());
  await openPage(page, 'parent-only');
  await mountHtml(page, '<glass-plane-scene refine="0" time="1"><glass-object src="models/tetra.obj"></glass-object><glass-light></glass-light></glass-plane-scene>');
  const f = await nextFrame(page, 'glass-plane-scene');
  expect(f.passes.scene.ran).toBe(true);
  expect((await summary(page)).objects.map((o) => o.kind)).toEqual(['box', 'sphere']);
  expect(consoleLog.take('warning').filter((w) => w.includes('could not load'))).toHaveLength(1);
  consoleLog.take('error');
});
