// Property checks that need no golden: what each pass may and may not contain, how the image
// responds to attributes, sizes, events, and the attribute/property contract (docs/element.md, docs/rendering.md).
// Every test runs with the renderer's GL error checks on and fails on any console error or
// warning it did not expect (fixtures.ts).
import { PNG } from 'pngjs';
import { test, expect, mount, openPage, capture, canvasSize, nextFrame, setAttributes, type SceneElement } from './fixtures';
import { compareImages, PIXEL_THRESHOLD } from './helpers/golden';
import { dominant, dominantPixels, countUnlike } from './helpers/pixels';
import { project, mirrorZ, forward, type Camera, type Vec3 } from './helpers/projection';
import type { CameraChangeDetail, GlassPlaneSceneErrorDetail } from '../../src/element/types';
import { note } from './helpers/bounds';

const SIZE = { width: 320, height: 180 };
const W = SIZE.width;
const H = SIZE.height;
const CUBE = (d: number): Vec3 => [-1, 1, d];
const SPHERE: Vec3 = [1, 1, -1.5];
const BACKGROUND = [25.5, 25.5, 25.5] as const;

const cameraAttrs = (c: Camera) => ({
  'camera-position': c.position.join(' '),
  'camera-rotation': `${c.yaw} ${c.pitch}`,
});

test.beforeEach(async ({ page }) => {
  await openPage(page);
});

test.describe('reflection pass', () => {
  // High, in front of the glass, looking down at it: the mirrored cube lands in the upper left
  // quarter, so a flipped or unmirrored reflection would land far from where it should.
  const camera: Camera = { position: [2, 4, 6], yaw: -95, pitch: -30 };
  const d = 2.5;

  test('holds no trace of the sphere behind the glass, though the scene pass shows it', async ({ page }) => {
    // The test can only fail if the sphere's mirror image would be in view, inside the glass.
    const m = mirrorZ(SPHERE);
    const p = project(camera, m, W, H);
    expect(p.inFront && p.x > 0 && p.x < W && p.y > 0 && p.y < H, 'mirrored sphere centre in view').toBe(true);
    const t = camera.position[2] / (camera.position[2] - m[2]); // ray eye → mirrored sphere meets z = 0
    const hit = camera.position.map((c, i) => c + (m[i] - c) * t);
    expect(Math.abs(hit[0]) < 4 && hit[1] > -1 && hit[1] < 3, 'seen through the glass rectangle').toBe(true);

    await mount(page, { time: 1.25, 'cube-distance': d, ...cameraAttrs(camera) }, SIZE);
    const reflection = await capture(page, 'reflection');
    const scene = await capture(page, 'scene');
    expect(reflection.width * reflection.height).toBeGreaterThan(0);
    note(`sphere behind the glass: green px in the scene pass ${dominant(scene, 'g').count}, in the reflection ${dominant(reflection, 'g').count}`);
    // Measured 514 green px; 10 % under it at most (the sphere's edge pixels).
    expect(dominant(scene, 'g').count, 'green sphere pixels in the scene pass (the detector works)').toBeGreaterThanOrEqual(0.9 * 514);
    expect(dominant(reflection, 'g').count, 'green pixels in the reflection pass').toBe(0);
  });

  test('shows the cube mirrored, registered with the screen', async ({ page }) => {
    const expected = project(camera, mirrorZ(CUBE(d)), W, H);
    const direct = project(camera, CUBE(d), W, H);
    const tol = 0.05 * W;
    // Sensitivity: an upside-down FBO, a left-right flip or a missing mirror would all miss by > 2 tol.
    expect(Math.abs(expected.y - (H - expected.y))).toBeGreaterThan(2 * tol);
    expect(Math.abs(expected.x - (W - expected.x))).toBeGreaterThan(2 * tol);
    expect(Math.hypot(expected.x - direct.x, expected.y - direct.y)).toBeGreaterThan(2 * tol);

    await mount(page, { time: 1.25, 'cube-distance': d, ...cameraAttrs(camera) }, SIZE);
    const reflection = await capture(page, 'reflection');
    // Compared in units of the image, so a reflection FBO smaller than the screen still fits.
    const sx = W / reflection.width;
    const sy = H / reflection.height;
    const red = dominant(reflection, 'r');
    note(`mirrored cube: ${(red.count * sx * sy).toFixed(0)} red px, centroid (${(red.cx * sx).toFixed(1)}, ${(red.cy * sy).toFixed(1)}) vs (${expected.x.toFixed(1)}, ${expected.y.toFixed(1)})`);
    // Measured: 99 red px, the centroid 1.3 px from the cube centre's mirror image in x and 8.3 px
    // in y (the red blob is the cube's faces that face the mirrored eye, not its centre). Bounds:
    // the count 10 % under, each offset 2 px over the measured one.
    expect(red.count * sx * sy, 'red cube pixels in the reflection pass').toBeGreaterThanOrEqual(0.9 * 99);
    expect(Math.abs(red.cx * sx - expected.x), `red centroid x ${(red.cx * sx).toFixed(1)} vs ${expected.x.toFixed(1)}`).toBeLessThan(1.3 + 2);
    expect(Math.abs(red.cy * sy - expected.y), `red centroid y ${(red.cy * sy).toFixed(1)} vs ${expected.y.toFixed(1)}`).toBeLessThan(8.3 + 2);
  });

  test('clips an object that crosses the glass: only its near part is reflected', async ({ page }) => {
    // spin 0: the cube stays axis-aligned, its faces at z = d ± 0.5. At d = +0.45 almost all
    // of it is in front of the glass, at d = −0.45 only a 0.05 slab is; without the clip plane
    // both would reflect a whole cube. reflection-scale 1 keeps the pixel counts comparable.
    await mount(page, { time: 0, spin: 0, 'cube-distance': 0.45, 'reflection-scale': 1, ...cameraAttrs(camera) }, SIZE);
    const front = dominant(await capture(page, 'reflection'), 'r').count;
    await setAttributes(page, 'glass-plane-scene', { 'cube-distance': -0.45 });
    const crossing = dominant(await capture(page, 'reflection'), 'r').count;
    note(`clipped cube: ${front} red px in front, ${crossing} crossing`);
    // Measured: 305 red px in front, 18 crossing (the 0.05 slab's sliver). Bounds: 10 % under
    // the first; the second 1.5× the measured (a whole cube would be ~300).
    expect(front, 'cube in front: its reflection').toBeGreaterThanOrEqual(0.9 * 305);
    expect(crossing, 'cube mostly behind: a sliver at most').toBeLessThanOrEqual(1.5 * 18);
  });
});

test.describe('final image', () => {
  // Straight at the sphere through the glass: near-normal incidence, F ≈ R0 = 0.04. The cube
  // is put behind the glass off to the left, so nothing is reflected over the sphere.
  const camera: Camera = { position: [1, 1, 5], yaw: -90, pitch: 0 };
  const attrs = { time: 1.25, 'cube-distance': -3, ...cameraAttrs(camera) };

  test('more transparency shows more of the sphere; at 1 the sphere comes through nearly unchanged', async ({ page }) => {
    await mount(page, { ...attrs, transparency: 0.2 }, SIZE);
    const green: number[] = [dominant(await capture(page), 'g').excess];
    for (const t of [0.8, 1]) {
      await setAttributes(page, 'glass-plane-scene', { transparency: t });
      green.push(dominant(await capture(page), 'g').excess);
    }
    note(`green excess at T 0.2, 0.8, 1: ${green.map((g) => g.toFixed(0)).join(', ')}`);
    // Measured excess 4,578, 24,013 and 33,838 in linear light: ratios 5.25 and 1.41 (3,666,
    // 27,647, 35,919 as stored). Bounds 10 % under each.
    expect(green[0], 'some green at T 0.2').toBeGreaterThanOrEqual(0.9 * 4578);
    expect(green[1], 'T 0.8 vs 0.2').toBeGreaterThan(green[0] * 0.9 * 5.25);
    expect(green[2], 'T 1 vs 0.8').toBeGreaterThan(green[1] * 0.9 * 1.41);

    // T = 1: out = F·R + (1 − F)·B with R the background (nothing reflected here), F ≤ ~0.05.
    const final = await capture(page);
    const scene = await capture(page, 'scene');
    const sphere = dominantPixels(scene, 'g');
    expect(sphere.length).toBeGreaterThan(300);
    let worst = 0;
    let sum = 0;
    for (const p of sphere) {
      for (let c = 0; c < 3; c++) {
        const b = scene.data[p * 4 + c];
        // 0.06·|R − B|: F up to 0.06 at these angles; + 2 levels for 8-bit rounding of B and the blend.
        const excess = Math.abs(final.data[p * 4 + c] - b) - (0.06 * Math.abs(BACKGROUND[c] - b) + 2);
        worst = Math.max(worst, excess);
        sum += Math.abs(final.data[p * 4 + c] - b);
      }
    }
    note(`T 1 over the sphere (${sphere.length} px): worst excess ${worst.toFixed(2)}, mean |final − scene| ${(sum / (sphere.length * 3)).toFixed(2)}`);
    expect(worst, 'largest deviation beyond F·|R − B| + 2 on a sphere pixel').toBeLessThanOrEqual(0);
    // Measured 1.44 levels; bound 1.5× that.
    expect(sum / (sphere.length * 3), 'mean |final − scene| over the sphere').toBeLessThan(1.5 * 1.44);
  });

  test('moving cube-distance moves the cube, and it grows as it comes closer', async ({ page }) => {
    // spin 0: an axis-aligned cube shows its lit front face (N·L = 0.48) to this camera.
    const cam: Camera = { position: [0, 1.5, 8], yaw: -90, pitch: -5 };
    await mount(page, { time: 0, spin: 0, 'cube-distance': 1, ...cameraAttrs(cam) }, SIZE);
    const far = dominant(await capture(page), 'r');
    await setAttributes(page, 'glass-plane-scene', { 'cube-distance': 4 });
    const near = dominant(await capture(page), 'r');
    const pFar = project(cam, CUBE(1), W, H);
    const pNear = project(cam, CUBE(4), W, H);
    note(`cube at d 1: ${far.count} px, centroid (${far.cx.toFixed(1)}, ${far.cy.toFixed(1)}) vs (${pFar.x.toFixed(1)}, ${pFar.y.toFixed(1)}); at d 4: ${near.count} px, (${near.cx.toFixed(1)}, ${near.cy.toFixed(1)}) vs (${pNear.x.toFixed(1)}, ${pNear.y.toFixed(1)})`);
    // Measured: 570 px at d 1, 2,058 at d 4 (3.61×); the centroids within 3.4 px of the projected
    // centres. Bounds: 10 % under the counts and the ratio, 2 px over the offsets.
    expect(far.count).toBeGreaterThanOrEqual(0.9 * 570);
    expect(near.count, `apparent size, d 4 (${near.count} px) vs d 1 (${far.count} px)`).toBeGreaterThan(far.count * 0.9 * 3.61);
    // Closer to the camera, x = −1 lands further left of the centre.
    expect(pNear.x).toBeLessThan(pFar.x - 10);
    expect(near.cx, 'centroid moves left').toBeLessThan(far.cx - 0.5 * (pFar.x - pNear.x));
    for (const [blob, p] of [[far, pFar], [near, pNear]] as const) {
      expect(Math.abs(blob.cx - p.x)).toBeLessThan(3.4 + 2);
      expect(Math.abs(blob.cy - p.y)).toBeLessThan(3.4 + 2);
    }
  });

  test('capture() is what the page shows', async ({ page }) => {
    const { selector } = await mount(page, { time: 1.25 }, SIZE);
    const shot = PNG.sync.read(await page.locator(`${selector} canvas`).screenshot());
    const screen = { width: shot.width, height: shot.height, data: new Uint8Array(shot.data) };
    const pixels = await capture(page, undefined, selector);
    expect([screen.width, screen.height]).toEqual([pixels.width, pixels.height]);
    // The canvas is opaque (alpha: false) and no colour management applies to it in headless
    // Chromium, so the compositor copies the bytes: the tight golden threshold, no budget.
    const { differing } = compareImages(screen, pixels, PIXEL_THRESHOLD);
    expect(differing).toBe(0);
    note(`capture(): ${countUnlike(pixels, [26, 26, 26], 3)} px unlike the background`);
    expect(countUnlike(pixels, [26, 26, 26], 3), 'not a blank frame (measured 27,657 px)').toBeGreaterThanOrEqual(0.9 * 27_657);
  });
});

test.describe('glass', () => {
  // debug-view fresnel shows F as grey (F, F, F) on glass pixels. Looking at the glass point
  // (0, 1, 0) from 3 units away at incidence θ puts that point at the centre of the image, so
  // the centre's grey is 255·F(cos θ) computed by hand: a check of the Fresnel models and of the
  // glass brightening towards grazing angles. The cube is moved behind the glass, out of the way.
  const exact = (c: number, n: number) => {
    const st = Math.sqrt(1 - c * c) / n;
    const ct = Math.sqrt(1 - st * st);
    const rs = (c - n * ct) / (c + n * ct);
    const rp = (ct - n * c) / (ct + n * c);
    return (rs * rs + rp * rp) / 2;
  };
  const schlick = (c: number, n: number) => {
    const r0 = ((n - 1) / (n + 1)) ** 2;
    return r0 + (1 - r0) * (1 - c) ** 5;
  };
  const classic = (c: number) => (1 - c) ** 3;
  const MODELS = { exact, schlick, classic } as const;

  test('F in the fresnel view follows the chosen model and grows towards grazing incidence', async ({ page }) => {
    expect(exact(Math.cos((56.31 * Math.PI) / 180), 1.5)).toBeCloseTo(0.07396, 4); // Brewster: the formula is right
    const { selector } = await mount(page, { time: 1.25, 'cube-distance': -3, 'debug-view': 'fresnel' }, SIZE);
    const rows: string[] = [];
    for (const [model, f] of Object.entries(MODELS)) {
      let previous = -1;
      for (const theta of [0, 56.31, 80]) {
        const t = (theta * Math.PI) / 180;
        const yaw = (Math.atan2(-Math.cos(t), -Math.sin(t)) * 180) / Math.PI;
        await setAttributes(page, selector, {
          fresnel: model,
          'camera-position': `${3 * Math.sin(t)} 1 ${3 * Math.cos(t)}`,
          'camera-rotation': `${yaw} 0`,
        });
        const img = await capture(page, undefined, selector);
        // Mean of the 2×2 pixels around the centre (F varies by < 0.5 level across them).
        let grey = 0;
        for (const [x, y] of [[W / 2 - 1, H / 2 - 1], [W / 2, H / 2 - 1], [W / 2 - 1, H / 2], [W / 2, H / 2]]) {
          const i = (y * W + x) * 4;
          expect(Math.abs(img.data[i] - img.data[i + 1]) + Math.abs(img.data[i] - img.data[i + 2]), 'grey').toBeLessThanOrEqual(2);
          grey += img.data[i] / 4;
        }
        const expected = 255 * f(Math.cos(t), 1.5);
        rows.push(`${model} θ=${theta}: ${grey.toFixed(1)} (expected ${expected.toFixed(1)})`);
        expect(Math.abs(grey - expected), rows.at(-1)).toBeLessThanOrEqual(2);
        expect(grey, `${model}: brighter at ${theta}° than before`).toBeGreaterThan(previous);
        previous = grey;
      }
    }
    test.info().annotations.push({ type: 'fresnel', description: rows.join('; ') });
  });
});

test.describe('size', () => {
  // reflection-scale 1 (docs/knobs.md#the-knobs): the reflection FBO is then the drawing buffer's size too.
  test('captures are the drawing buffer, which follows the CSS size', async ({ page }) => {
    const { selector } = await mount(page, { time: 1.25, 'reflection-scale': 1 }, SIZE);
    expect(await canvasSize(page, selector)).toEqual(SIZE);
    for (const pass of [undefined, 'final', 'scene', 'reflection'] as const) {
      const img = await capture(page, pass, selector);
      expect([img.width, img.height], `capture(${pass ?? ''})`).toEqual([W, H]);
    }
    // Resizing the element resizes the drawing buffer (ResizeObserver) and draws at once.
    const report = await nextFrame(page, selector, (el) => {
      el.style.width = '200px';
      el.style.height = '100px';
    });
    expect([report.width, report.height]).toEqual([200, 100]);
    expect(await canvasSize(page, selector)).toEqual({ width: 200, height: 100 });
    for (const pass of [undefined, 'scene', 'reflection'] as const) {
      const img = await capture(page, pass, selector);
      expect([img.width, img.height], `capture(${pass ?? ''}) after resize`).toEqual([200, 100]);
    }
  });

  test('an element with no CSS size is 300×150 CSS px', async ({ page }) => {
    const { selector, ready } = await mount(page, { time: 1.25 });
    const box = await page.evaluate((s) => {
      const r = document.querySelector(s)!.getBoundingClientRect();
      return { width: r.width, height: r.height };
    }, selector);
    expect(box).toEqual({ width: 300, height: 150 });
    expect([ready.width, ready.height]).toEqual([300, 150]);
  });

  test.describe('at devicePixelRatio 2', () => {
    test.use({ deviceScaleFactor: 2 });
    test('the drawing buffer is the CSS size × 2', async ({ page }) => {
      const { selector, ready } = await mount(page, { time: 1.25, 'reflection-scale': 1 }, SIZE);
      expect(await page.evaluate(() => devicePixelRatio)).toBe(2);
      expect([ready.width, ready.height]).toEqual([2 * W, 2 * H]);
      expect(await canvasSize(page, selector)).toEqual({ width: 2 * W, height: 2 * H });
      for (const pass of [undefined, 'scene', 'reflection'] as const) {
        const img = await capture(page, pass, selector);
        expect([img.width, img.height], `capture(${pass ?? ''})`).toEqual([2 * W, 2 * H]);
      }
    });
  });
});

test.describe('attributes and properties', () => {
  test('a bad value warns once, falls back, and rendering goes on', async ({ page, consoleLog }) => {
    const { selector } = await mount(page, { time: 1.25, transparency: 0.8 }, SIZE);
    await setAttributes(page, selector, { transparency: 'abc' });
    await expect.poll(() => consoleLog.count('warning')).toBe(1);
    const [warning] = consoleLog.take('warning');
    expect(warning).toMatch(/^glass-plane-scene:/);
    expect(warning).toContain('transparency');
    expect(warning).toContain('abc');
    expect(await page.evaluate((s) => (document.querySelector(s) as SceneElement).transparency, selector)).toBe(0.5);

    // The same bad value again: no second warning; a frame still follows.
    const report = await nextFrame(page, selector, (el) => {
      el.setAttribute('transparency', 'abc');
      el.requestRender();
    });
    expect(report.passes.glass.ran).toBe(true);
    await page.evaluate(() => new Promise((r) => setTimeout(r, 200)));
    expect(consoleLog.count('warning'), 'no second warning').toBe(0);
    expect(await page.evaluate((s) => (document.querySelector(s) as SceneElement).transparency, selector)).toBe(0.5);
  });

  test('properties and attributes reflect each other', async ({ page }) => {
    const { selector } = await mount(page, { time: 1.25 }, SIZE);
    const r = await page.evaluate((s) => {
      const el = document.querySelector(s) as SceneElement;
      const before = { ior: el.ior, cubeDistance: el.cubeDistance, transparency: el.transparency };
      el.cubeDistance = 1;
      const attr = el.getAttribute('cube-distance');
      el.setAttribute('ior', '2');
      return { before, attr, cubeDistance: el.cubeDistance, ior: el.ior };
    }, selector);
    expect(r.before).toEqual({ ior: 1.5, cubeDistance: 0.75, transparency: 0.5 });
    expect(r.attr).toBe('1');
    expect(r.cubeDistance).toBe(1);
    expect(r.ior).toBe(2);
  });
});

test.describe('properties set before the element is defined', () => {
  // What the page sets first: the camera's fov (over a markup fov="40" on the one in the
  // document), a frame-state attribute, a scene attribute, and the trackball's rotation.
  const SET = { fov: 30, transparency: 0.9, cubeDistance: 1.2 };
  const TURN = [0, Math.sin(Math.PI / 12), 0, Math.cos(Math.PI / 12)];

  test('survive the upgrade: in the document, upgraded before it is connected, and upgraded when appended; the frames use them', async ({ page }) => {
    await page.goto('/tests/e2e/pages/undefined.html');
    const r = await page.evaluate(async ({ set, turn }) => {
      type El = HTMLElement & Record<string, unknown>;
      const make = (id: string) => {
        const el = document.createElement('glass-plane-scene') as unknown as El;
        el.id = id;
        el.setAttribute('time', '1.25');
        el.setAttribute('spin', '0');
        el.setAttribute('refine', '0'); // as mount() sets it
        el.style.width = '160px';
        el.style.height = '90px';
        return el;
      };
      const ready = (el: El) => new Promise((r) => el.addEventListener('ready', r, { once: true }));
      const setAll = (el: El) => { Object.assign(el, set); el.objectRotation = turn; };
      const inDoc = make('in-doc'), early = make('early'), late = make('late');
      inDoc.setAttribute('fov', '40');
      document.body.append(inDoc);
      for (const el of [inDoc, early, late]) setAll(el);
      const inDocReady = ready(inDoc);
      await import('/src/index.ts' as string);
      await customElements.whenDefined('glass-plane-scene');
      customElements.upgrade(early); // upgraded, not connected
      const read = (el: El) => ({
        values: { fov: el.fov, transparency: el.transparency, cubeDistance: el.cubeDistance },
        attrs: [el.getAttribute('fov'), el.getAttribute('transparency'), el.getAttribute('cube-distance')],
        rotation: el.objectRotation,
        own: ['fov', 'transparency', 'cubeDistance', 'objectRotation'].filter((p) => Object.prototype.hasOwnProperty.call(el, p)),
      });
      const beforeConnected = read(early);
      const readies = [inDocReady, ready(early), ready(late)];
      document.body.append(early, late);
      await Promise.all(readies);
      return { beforeConnected, inDoc: read(inDoc), early: read(early), late: read(late) };
    }, { set: SET, turn: TURN });
    const expected = { values: SET, attrs: ['30', '0.9', '1.2'], rotation: TURN.map((x) => expect.closeTo(x, 12)), own: [] };
    expect(r.beforeConnected, 'upgraded, not yet connected').toEqual(expected);
    expect(r.inDoc, 'in the document when defined').toEqual(expected);
    expect(r.early, 'upgraded, then connected').toEqual(expected);
    expect(r.late, 'upgraded when connected').toEqual(expected);
    // Their frames are those of an element given the same values once defined.
    const { selector } = await mount(page, { time: 1.25, spin: 0, fov: 30, transparency: 0.9, 'cube-distance': 1.2 }, { width: 160, height: 90 });
    await nextFrame(page, selector, new Function('el', `el.objectRotation = ${JSON.stringify(TURN)};`) as (el: SceneElement) => void);
    const reference = await capture(page, undefined, selector);
    for (const id of ['#in-doc', '#early', '#late']) {
      await nextFrame(page, id);
      expect(compareImages(reference, await capture(page, undefined, id)).differing, `${id}: pixels unlike the reference`).toBe(0);
    }
  });
});

test.describe('events', () => {
  test('frame reports which passes ran, and why one was skipped', async ({ page }) => {
    const { selector, ready } = await mount(page, { time: 1.25, 'debug-view': 'scene' }, SIZE);
    expect(ready.passes.scene.ran).toBe(true);
    expect(ready.passes.reflection.ran).toBe(false);
    expect(typeof ready.passes.reflection.reason).toBe('string');
    expect(ready.passes.reflection.reason!.length).toBeGreaterThan(0);
    expect(ready.drawCalls).toBeGreaterThan(0);

    const report = await setAttributes(page, selector, { 'debug-view': null });
    expect(report.frame).toBeGreaterThan(ready.frame);
    for (const pass of ['reflection', 'scene', 'glass'] as const) expect(report.passes[pass].ran, pass).toBe(true);
    const stats = await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats, selector);
    expect(stats.frames).toBe(report.frame);
    expect(stats.passesSkipped.reflection).toBeGreaterThanOrEqual(1);
    expect(stats.passesRun.reflection).toBeGreaterThanOrEqual(1);
    expect(stats.resources.total).toBeGreaterThan(0);
  });

  test('flying with the keyboard fires camera-change, only on the focused element', async ({ page }) => {
    const a = await mount(page, { time: 1.25, controls: true }, SIZE);
    const b = await mount(page, { time: 1.25, controls: true }, SIZE);
    type Log = Record<string, { count: number; last: CameraChangeDetail | null }>;
    await page.evaluate(() => {
      const w = window as unknown as { __cameraChanges: Log };
      w.__cameraChanges = {};
      for (const el of document.querySelectorAll('glass-plane-scene')) {
        const entry = (w.__cameraChanges[el.id] = { count: 0, last: null as CameraChangeDetail | null });
        el.addEventListener('camera-change', (e) => {
          entry.count++;
          entry.last = (e as CustomEvent<CameraChangeDetail>).detail;
        });
      }
    });
    const poses = () =>
      page.evaluate(() =>
        [...document.querySelectorAll('glass-plane-scene')].map((el) => ({
          id: el.id,
          tabIndex: (el as HTMLElement).tabIndex,
          position: (el as SceneElement).cameraPosition,
          rotation: (el as SceneElement).cameraRotation,
        })),
      );
    const changes = () => page.evaluate(() => (window as unknown as { __cameraChanges: Log }).__cameraChanges);
    const before = await poses();
    expect(before.map((p) => p.tabIndex), 'focusable').toEqual([0, 0]);
    expect(before[0].position).toEqual(before[1].position);

    for (const [moving, still] of [[b, a], [a, b]] as const) {
      const i = moving === a ? 0 : 1;
      const m = moving.selector.slice(1);
      const s = still.selector.slice(1);
      await page.focus(moving.selector);
      const start = await poses();
      const startChanges = await changes();
      await page.keyboard.down('KeyW');
      await page.waitForTimeout(300);
      await page.keyboard.up('KeyW');
      await expect.poll(async () => (await changes())[m].count).toBeGreaterThan(startChanges[m].count);
      // Wait for the flyby to come to rest (it may glide on after the key is released).
      let settled = await poses();
      await expect
        .poll(async () => {
          const previous = settled;
          await page.waitForTimeout(150);
          settled = await poses();
          return JSON.stringify(settled) === JSON.stringify(previous);
        })
        .toBe(true);
      const moved = settled[i];
      expect(moved.position, `${moving.selector} moved`).not.toEqual(start[i].position);
      // W flies forward: the displacement points along the view direction.
      const f = forward(start[i].rotation[0], start[i].rotation[1]);
      const delta = moved.position.map((x, k) => x - start[i].position[k]);
      expect(delta[0] * f[0] + delta[1] * f[1] + delta[2] * f[2], 'moved forward').toBeGreaterThan(0);
      const log = await changes();
      expect(log[m].last?.position, 'last camera-change detail is the final pose').toEqual(moved.position);
      expect(log[m].last?.rotation).toEqual(moved.rotation);
      // The other element neither moved nor heard anything.
      expect(settled[1 - i].position, `${still.selector} stayed`).toEqual(start[1 - i].position);
      expect(log[s].count, `${still.selector} camera-change events`).toBe(startChanges[s].count);
    }
  });
});

test.describe('lifecycle', () => {
  test('an idle element draws nothing (docs/knobs.md#idle-elements)', async ({ page }) => {
    const { selector } = await mount(page, { time: 1.25 }, SIZE);
    const frames = () => page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.frames, selector);
    const before = await frames();
    await page.waitForTimeout(500); // ~30 animation frames
    expect(await frames()).toBe(before);
  });

  test('removed from the DOM, it frees every GL resource (docs/element.md#failure-behaviour)', async ({ page }) => {
    const { selector } = await mount(page, { time: 1.25 }, SIZE);
    const resources = await page.evaluate((s) => {
      const el = document.querySelector(s) as SceneElement;
      const live = el.stats.resources.total;
      el.remove();
      return { live, after: el.stats.resources };
    }, selector);
    expect(resources.live).toBeGreaterThan(0);
    expect(resources.after).toEqual({
      buffers: 0, textures: 0, framebuffers: 0, renderbuffers: 0, vertexArrays: 0, programs: 0, shaders: 0, total: 0,
    });
  });

  test('after a lost context it reports the loss, then rebuilds and draws the same frame (docs/element.md#failure-behaviour)', async ({ page, consoleLog }) => {
    const { selector } = await mount(page, { time: 1.25 }, SIZE);
    const before = await capture(page, undefined, selector);
    const resourcesBefore = await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.resources, selector);
    const lost = await page.evaluate(
      (s) =>
        new Promise<GlassPlaneSceneErrorDetail>((resolve, reject) => {
          const el = document.querySelector(s) as SceneElement;
          // Every element renders through one shared context, exposed in checks mode for tests.
          const gl = (window as unknown as { __GLASS_PLANE_SCENE_GL__: WebGL2RenderingContext }).__GLASS_PLANE_SCENE_GL__;
          const ext = gl.getExtension('WEBGL_lose_context');
          if (!ext) return reject(new Error('WEBGL_lose_context unavailable'));
          (window as unknown as { __loseContext: WEBGL_lose_context }).__loseContext = ext;
          el.addEventListener('error', (e) => resolve((e as unknown as CustomEvent<GlassPlaneSceneErrorDetail>).detail), { once: true });
          ext.loseContext();
        }),
      selector,
    );
    expect(lost.type).toBe('context-lost');
    await nextFrame(page, selector, () => (window as unknown as { __loseContext: WEBGL_lose_context }).__loseContext.restoreContext());
    // docs/element.md#failure-behaviour asks for the error event only; a console error about the loss is allowed (at most
    // one, with the prefix). The element currently logs none.
    const logged = consoleLog.take('error');
    expect(logged.length).toBeLessThanOrEqual(1);
    for (const line of logged) expect(line).toMatch(/^glass-plane-scene:/);
    const after = await capture(page, undefined, selector);
    expect(compareImages(after, before).differing, 'same frame after the rebuild').toBe(0);
    const resourcesAfter = await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.resources, selector);
    expect(resourcesAfter).toEqual(resourcesBefore);
  });
});
