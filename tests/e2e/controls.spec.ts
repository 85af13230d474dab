// docs/interaction.md#controls with real input: mouse and wheel through CDP Input.dispatchMouseEvent (with explicit
// timestamps, which become the events' timeStamps, so a release velocity is the same run after
// run), touch through CDP's synthesized gestures, keys through the keyboard. Checked numerically
// (camera pose, objectRotation), with direction: content follows the pointer (the trackball's
// objects, the orbit's near side, the point under a pan), and with pixels. Inertia by the wall
// clock at several frame rates: inertia.spec.ts.
import type { CDPSession, Page } from '@playwright/test';
import { test, expect, mount, openPage, capture, nextFrame, setAttributes, type SceneElement } from './fixtures';
import { compareImages } from './helpers/golden';
import { box, DEG, drag, pose, recordCameraChanges, rotationOf, screenOffset, type ControlsElement, type Quat } from './helpers/controls-input';
import { forwardFromYawPitch } from '../../src/math/camera';

const SIZE = { width: 320, height: 180 };

/** The camera's right and up (world), for camera-rotation [yaw, pitch]. */
function cameraAxes(rotation: number[]) {
  const f = forwardFromYawPitch([0, 0, 0], rotation[0], rotation[1]);
  const h = Math.hypot(f[0], f[2]);
  const right = [-f[2] / h, 0, f[0] / h];
  const up = [right[1] * f[2] - right[2] * f[1], right[2] * f[0] - right[0] * f[2], right[0] * f[1] - right[1] * f[0]];
  return { f, right, up };
}

test.describe('trackball', () => {
  test('a drag of N px from the centre turns the objects by the arcball angle asin(N/r), about the camera\'s up axis; pixels follow', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'trackball' }, SIZE);
    const b = await box(page, selector);
    const before = await capture(page, undefined, selector);
    const cdp = await page.context().newCDPSession(page);
    const N = 50, r = Math.min(b.width, b.height) / 2;
    // Resting 200 ms before release: no inertia, so the orientation is the drag's alone.
    await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + N, y: b.cy }, { t0: 10, steps: 10, dtMs: 16, restMs: 200, handledBy: page });
    const q = await rotationOf(page, selector);
    const angle = 2 * Math.acos(Math.min(1, Math.abs(q[3]))) * DEG;
    expect(angle, 'turn of a 50 px drag over a 90 px radius').toBeCloseTo(Math.asin(N / r) * DEG, 3);
    // About the camera's up (a drag right turns the front of the objects right).
    const { up } = cameraAxes((await pose(page, selector)).rotation);
    const s = Math.sin((angle / DEG) / 2);
    for (let i = 0; i < 3; i++) expect(q[i] / s).toBeCloseTo(up[i], 3);
    // Pixels: the picture moved, and it is the picture of that rotation set directly (a frame
    // drawn now: on a busy GPU the drag's last frame may still be on its way).
    await nextFrame(page, selector, new Function('el', 'el.requestRender();') as (el: SceneElement) => void);
    const after = await capture(page, undefined, selector);
    expect(compareImages(before, after).differing, 'pixels changed by the drag').toBeGreaterThan(500);
    await setAttributes(page, selector, { controls: null });
    // Each set rotation is in the next frame drawn (waited for as its `frame` event).
    await nextFrame(page, selector, new Function('el', 'el.objectRotation = [0, 0, 0, 1];') as (el: SceneElement) => void);
    expect(compareImages(before, await capture(page, undefined, selector)).differing, 'identity rotation: the first picture again').toBe(0);
    await nextFrame(page, selector, new Function('el', `el.objectRotation = ${JSON.stringify(q)};`) as (el: SceneElement) => void);
    expect(compareImages(after, await capture(page, undefined, selector)).differing, 'the dragged picture from objectRotation').toBe(0);
  });

  test('a drag up turns the objects\' front up (about the camera\'s −right axis), and the arrow keys turn them as a drag from the centre would', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'trackball' }, SIZE);
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    const N = 40, r = Math.min(b.width, b.height) / 2;
    await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx, y: b.cy - N }, { t0: 15, steps: 10, dtMs: 16, restMs: 200, handledBy: page });
    const { right, up } = cameraAxes((await pose(page, selector)).rotation);
    const axisOf = (q: Quat) => { const s = Math.hypot(q[0], q[1], q[2]); return { angle: 2 * Math.atan2(s, q[3]) * DEG, axis: [q[0] / s, q[1] / s, q[2] / s] }; };
    const dragged = axisOf(await rotationOf(page, selector));
    expect(dragged.angle, 'turn of a 40 px drag over a 90 px radius').toBeCloseTo(Math.asin(N / r) * DEG, 3);
    // The part facing the viewer (−forward) goes up: −forward × up = −right.
    for (let i = 0; i < 3; i++) expect(dragged.axis[i], `axis[${i}]`).toBeCloseTo(-right[i], 3);
    // ArrowRight: 5° about the camera's up, the front turning right, like a drag to the right.
    await page.evaluate((s) => { (document.querySelector(s) as unknown as ControlsElement).objectRotation = [0, 0, 0, 1]; }, selector);
    await page.focus(selector);
    await page.keyboard.press('ArrowRight');
    await expect.poll(async () => axisOf(await rotationOf(page, selector)).angle).toBeCloseTo(5, 6);
    const keyed = axisOf(await rotationOf(page, selector));
    for (let i = 0; i < 3; i++) expect(keyed.axis[i], `key axis[${i}]`).toBeCloseTo(up[i], 6);
  });

  test('turning the objects moves no camera: no camera-change and nothing written, after the inertia too; the wheel\'s dolly fires one', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'trackball' }, SIZE);
    const changes = await recordCameraChanges(page, selector);
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    // A flick (inertia after it), then a right-drag (the light).
    await drag(cdp, { x: b.cx - 20, y: b.cy }, { x: b.cx + 20, y: b.cy }, { t0: 17, steps: 8, dtMs: 16, restMs: 8, handledBy: page });
    await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + 30, y: b.cy }, { t0: 18, steps: 8, dtMs: 16, restMs: 200, button: 'right', handledBy: page });
    await expect.poll(() => page.evaluate((s) => { const el = document.querySelector(s)!; return new Promise((r) => { let n = 0; const f = () => n++; el.addEventListener('frame', f); setTimeout(() => { el.removeEventListener('frame', f); r(n); }, 300); }); }, selector), { message: 'the spin stopped' }).toBe(0);
    expect(await changes(), 'no camera-change for turning objects').toHaveLength(0);
    expect(await page.evaluate((s) => document.querySelector(s)!.hasAttribute('camera-position'), selector), 'camera-position not written').toBe(false);
    await page.mouse.move(b.cx, b.cy);
    await page.mouse.wheel(0, 100);
    await expect.poll(async () => (await changes()).length).toBe(1);
  });

  test('right-drag and Shift-drag turn the light, not the objects: the lighting changes', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'trackball' }, SIZE);
    const b = await box(page, selector);
    const before = await capture(page, undefined, selector);
    const cdp = await page.context().newCDPSession(page);
    await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + 60, y: b.cy + 20 }, { t0: 30, steps: 12, dtMs: 16, restMs: 200, button: 'right', handledBy: page });
    expect(await rotationOf(page, selector)).toEqual([0, 0, 0, 1]);
    const lit = await capture(page, undefined, selector);
    expect(compareImages(before, lit).differing, 'pixels relit by a right-drag').toBeGreaterThan(200);
    await drag(cdp, { x: b.cx + 60, y: b.cy + 20 }, { x: b.cx, y: b.cy }, { t0: 31, steps: 12, dtMs: 16, restMs: 200, modifiers: 8 /* Shift */, handledBy: page });
    expect(await rotationOf(page, selector)).toEqual([0, 0, 0, 1]);
    // Back along the same path: nearly the first lighting again.
    expect(compareImages(before, await capture(page, undefined, selector)).differing).toBeLessThan(compareImages(before, lit).differing / 4);
  });
});

test.describe('orbit', () => {
  test('a drag turns the camera about its target at a fixed distance (0.4° per px), the near side of the scene following the pointer; one camera-change at the end, attributes written once', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const changes = await recordCameraChanges(page, selector);
    const start = await pose(page, selector);
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    // 40 px right and 20 px up.
    await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + 40, y: b.cy - 20 }, { t0: 40, steps: 10, dtMs: 16, restMs: 200, handledBy: page });
    await expect.poll(async () => (await changes()).length).toBe(1);
    const end = await pose(page, selector);
    expect(end.rotation[0] - start.rotation[0], 'yaw turned right by 40 px × 0.4°').toBeCloseTo(16, 6);
    expect(end.rotation[1] - start.rotation[1], 'pitch turned up by 20 px × 0.4°').toBeCloseTo(8, 6);
    expect(Math.hypot(...end.position)).toBeCloseTo(Math.hypot(0, 1, 6), 6);
    // What the user sees: the scene turns with the pointer, as if grabbed. The point halfway
    // from the target to the camera, drawn at the centre before, is now right of and above it.
    const near = start.position.map((x) => x / 2);
    expect(screenOffset(start, near, 60, b.height).x).toBeCloseTo(0, 9);
    const moved = screenOffset(end, near, 60, b.height);
    // Measured (40.4, −20.8) px for the pointer's (40, −20).
    expect(moved.x, 'the near side moved right with the pointer (px)').toBeGreaterThan(30);
    expect(moved.y, 'and up (px, y down)').toBeLessThan(-15);
    const detail = (await changes())[0] as { position: number[]; rotation: number[]; target: number[] };
    expect(detail.target).toEqual([0, 0, 0]);
    expect(detail.position.map((x) => x.toFixed(9))).toEqual(end.position.map((x) => x.toFixed(9)));
    const attrs = await page.evaluate((s) => document.querySelector(s)!.getAttribute('camera-position'), selector);
    expect(attrs!.split(' ').map(Number)).toEqual(end.position);
  });

  test('a right-drag pans: the point under the pointer stays under it, and camera-target is written back once and announced', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const changes = await recordCameraChanges(page, selector);
    const start = await pose(page, selector);
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    // 30 px right and 20 px down, from the centre, where the target is drawn.
    await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + 30, y: b.cy + 20 }, { t0: 45, steps: 10, dtMs: 16, restMs: 200, button: 'right', handledBy: page });
    await expect.poll(async () => (await changes()).length).toBe(1);
    const end = await pose(page, selector);
    expect(end.rotation, 'a pan does not turn the camera').toEqual(start.rotation);
    // The old target, under the pointer when the drag began, is under it at the end.
    const under = screenOffset(end, [0, 0, 0], 60, b.height);
    expect(under.x, 'the grabbed point, px right of the centre').toBeCloseTo(30, 6);
    expect(under.y, 'px below the centre').toBeCloseTo(20, 6);
    // So the target moved against the drag: left along the camera's right (−X here), and up.
    const [change] = await changes();
    const target = await page.evaluate((s) => document.querySelector(s)!.getAttribute('camera-target')!.split(' ').map(Number), selector);
    expect(change.target, 'camera-change carries the new target').toEqual(target);
    const { f, right, up } = cameraAxes(start.rotation);
    const along = (v: number[]) => target[0] * v[0] + target[1] * v[1] + target[2] * v[2];
    const unitsPerPx = (2 * Math.hypot(0, 1, 6) * Math.tan(30 / DEG)) / b.height;
    expect(along(right), 'target moved left by 30 px at its depth').toBeCloseTo(-30 * unitsPerPx, 9);
    expect(along(up), 'and up by 20 px').toBeCloseTo(20 * unitsPerPx, 9);
    expect(along(f), 'not along the view').toBeCloseTo(0, 9);
    // The camera moved with it, still looking at it from the same distance.
    const written = await page.evaluate((s) => document.querySelector(s)!.getAttribute('camera-position')!.split(' ').map(Number), selector);
    expect(written).toEqual(change.position);
    for (let i = 0; i < 3; i++) expect(written[i] - target[i]).toBeCloseTo(start.position[i], 9);
    await page.waitForTimeout(200);
    expect(await changes(), 'the write-back fired no second camera-change').toHaveLength(1);
  });

  test('the wheel dollies towards the target and ends its gesture 150 ms after its last event', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const changes = await recordCameraChanges(page, selector);
    const b = await box(page, selector);
    // Three notches up in one task, so that no pause on a busy machine splits them into two
    // gestures (the gesture ends 150 ms after the last one).
    await page.evaluate(([s, x, y]) => {
      const canvas = document.querySelector(s as string)!.shadowRoot!.querySelector('canvas')!;
      for (let i = 0; i < 3; i++) canvas.dispatchEvent(new WheelEvent('wheel', { deltaY: -100, deltaMode: 0, clientX: x as number, clientY: y as number, bubbles: true, cancelable: true, composed: true }));
    }, [selector, b.cx, b.cy] as const);
    await expect.poll(async () => (await changes()).length).toBe(1);
    const end = await pose(page, selector);
    expect(Math.hypot(...end.position), 'distance × e^(−3·100·0.0015)').toBeCloseTo(Math.hypot(0, 1, 6) * Math.exp(-0.45), 6);
    await page.waitForTimeout(300);
    expect((await changes()).length, 'one camera-change for the whole wheel gesture').toBe(1);
  });

  test('wheel events in lines (deltaMode 1) dolly as 16 px a line, in pages (deltaMode 2) as the canvas height a page', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const changes = await recordCameraChanges(page, selector);
    const b = await box(page, selector);
    /** The camera's distance after one wheel event from the start, as its camera-change tells it. */
    const dolly = async (deltaY: number, deltaMode: number) => {
      const n = (await changes()).length + 2; // the page's camera-position, then the wheel's gesture
      await page.evaluate((s) => document.querySelector(s)!.setAttribute('camera-position', '0 1 6'), selector);
      await page.evaluate(([s, x, y, deltaY, deltaMode]) => {
        const canvas = document.querySelector(s as string)!.shadowRoot!.querySelector('canvas')!;
        canvas.dispatchEvent(new WheelEvent('wheel', { deltaY: deltaY as number, deltaMode: deltaMode as number, clientX: x as number, clientY: y as number, bubbles: true, cancelable: true, composed: true }));
      }, [selector, b.cx, b.cy, deltaY, deltaMode] as const);
      await expect.poll(async () => (await changes()).length).toBe(n);
      return Math.hypot(...(await changes())[n - 1].position);
    };
    const lines = await dolly(3, 1), pixels = await dolly(48, 0);
    expect(pixels, 'the pixel event dollied').not.toBeCloseTo(Math.hypot(0, 1, 6), 3);
    expect(lines, '3 lines = 48 px').toBeCloseTo(pixels, 9);
    // A quarter page of a 180 px canvas: 45 px.
    expect(await dolly(0.25, 2), '¼ page = 45 px').toBeCloseTo(await dolly(45, 0), 9);
  });

  test('with camera-target the camera looks at it: "0 1 6" alone shows nothing of the scene, with a target it does', async ({ page }) => {
    await openPage(page);
    const bg = (img: { data: Uint8Array }) => { let n = 0; for (let i = 0; i < img.data.length; i += 4) if (Math.abs(img.data[i] - 26) > 8 || Math.abs(img.data[i + 2] - 26) > 8) n++; return n; };
    const a = await mount(page, { time: 0, spin: 0, 'camera-position': '0 1 6' }, SIZE);
    const b = await mount(page, { time: 0, spin: 0, 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const without = bg(await capture(page, undefined, a.selector)), withTarget = bg(await capture(page, undefined, b.selector));
    expect(withTarget, 'pixels other than the background, looking at the target').toBeGreaterThan(SIZE.width * SIZE.height * 0.2);
    expect(without).toBeLessThan(withTarget / 4);
  });
});

/** One finger through CDP (touch emulation on): down at (x, y), ten moves of (dx, dy), up. */
async function swipe(page: Page, cdp: CDPSession, x: number, y: number, dx: number, dy: number) {
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: [{ x, y }] });
  for (let k = 1; k <= 10; k++) {
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: [{ x: x + dx * k, y: y + dy * k }] });
    await page.waitForTimeout(16);
  }
  await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
}

test.describe('touch, focus and jumps', () => {
  test('without controls a touch swipe over the element scrolls the page; with controls it orbits instead', async ({ page }) => {
    await openPage(page);
    await page.evaluate(() => { document.body.style.height = '3000px'; });
    const { selector } = await mount(page, { time: 0, spin: 0 }, { width: 320, height: 400 });
    const cdp = await page.context().newCDPSession(page);
    await cdp.send('Emulation.setTouchEmulationEnabled', { enabled: true, maxTouchPoints: 5 });
    const b = await box(page, selector);
    const touchAction = (s: string) => page.evaluate((s) => {
      const el = document.querySelector(s)!;
      return [getComputedStyle(el).touchAction, getComputedStyle(el.shadowRoot!.querySelector('canvas')!).touchAction];
    }, s);
    expect(await touchAction(selector)).toEqual(['auto', 'auto']);
    await swipe(page, cdp, b.cx, b.cy, 0, -20);
    await expect.poll(() => page.evaluate(() => window.scrollY), { message: 'page scrolled by the swipe' }).toBeGreaterThan(100);
    // Let the swipe's fling run out before scrolling back, or it carries on scrolling after.
    let last = -1;
    await expect.poll(async () => { const y = await page.evaluate(() => window.scrollY); const still = y === last; last = y; return still; }, { intervals: [200] }).toBe(true);
    await page.evaluate(() => window.scrollTo(0, 0));
    await setAttributes(page, selector, { controls: 'orbit' });
    expect(await touchAction(selector)).toEqual(['none', 'none']);
    const start = await pose(page, selector);
    await swipe(page, cdp, b.cx, b.cy, -8, -12);
    await page.waitForTimeout(200);
    expect(await page.evaluate(() => window.scrollY), 'no scroll with controls').toBe(0);
    const end = await pose(page, selector);
    // The finger went left and up: the camera turns left (yaw wrapped into ±180°) and up, as a
    // mouse drag would (5° per event at most: 27.7° and 41.6° for the swipe, more with the
    // inertia after it).
    const yaw = ((end.rotation[0] - start.rotation[0] + 540) % 360) - 180;
    expect(yaw, 'the finger turned the camera left').toBeLessThan(-27);
    expect(end.rotation[1] - start.rotation[1], 'and up').toBeGreaterThan(41);
  });

  test('two-finger pinch-out dollies in by the ratio of the finger spans; a two-finger drag pans with the fingers', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    const at = (d: number) => [{ x: b.cx - d, y: b.cy, id: 1 }, { x: b.cx + d, y: b.cy, id: 2 }];
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(20) });
    for (const d of [25, 30, 35, 40]) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(d) });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    // Spread from 40 to 80 px: half the distance. The fingers' events come one finger at a time,
    // so the midpoint wobbles by half a step; the zoom is about the midpoint, so the target stays.
    await expect.poll(async () => Math.hypot(...(await pose(page, selector)).position)).toBeCloseTo(Math.hypot(0, 1, 6) / 2, 9);
    const start = await pose(page, selector);
    const target = await page.evaluate((s) => document.querySelector(s)!.getAttribute('camera-target')!.split(' ').map(Number), selector);
    for (const x of target) expect(x, 'the target stayed under the fingers\' midpoint').toBeCloseTo(0, 9);
    expect(screenOffset(start, target, 60, b.height).x, 'the target, at the centre').toBeCloseTo(0, 6);
    // Both fingers 30 px right and 15 px up, together.
    const moved = (k: number) => [{ x: b.cx - 20 + 5 * k, y: b.cy - 2.5 * k, id: 1 }, { x: b.cx + 20 + 5 * k, y: b.cy - 2.5 * k, id: 2 }];
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: moved(0) });
    for (let k = 1; k <= 6; k++) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: moved(k) });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    await expect.poll(async () => (await pose(page, selector)).position[0]).not.toBeCloseTo(start.position[0], 6);
    const end = await pose(page, selector);
    const under = screenOffset(end, target, 60, b.height);
    expect(end.rotation, 'a pan does not turn the camera').toEqual(start.rotation);
    expect(under.x, 'the point under the fingers went right with them (px)').toBeCloseTo(30, 6);
    expect(under.y, 'and up (px, y down)').toBeCloseTo(-15, 6);
  });

  test('keys act only while the element has focus: arrows orbit by 5° (right turns right, up turns up), + dollies in', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const start = await pose(page, selector);
    await page.keyboard.press('ArrowRight');
    expect(await pose(page, selector), 'unfocused: nothing').toEqual(start);
    await page.focus(selector);
    await page.keyboard.press('ArrowRight');
    await expect.poll(async () => (await pose(page, selector)).rotation[0] - start.rotation[0]).toBeCloseTo(5, 6);
    await page.keyboard.press('ArrowUp');
    await expect.poll(async () => (await pose(page, selector)).rotation[1] - start.rotation[1]).toBeCloseTo(5, 6);
    await page.keyboard.press('+');
    await expect.poll(async () => Math.hypot(...(await pose(page, selector)).position)).toBeCloseTo(Math.hypot(0, 1, 6) / 1.1, 6);
  });

  test('flyby keys move the way they say: D right, W forward, Space up, ArrowRight turns right; one camera-change each, at rest', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: true, 'camera-position': '0 1 6', 'camera-rotation': '-90 0' }, SIZE);
    const changes = await recordCameraChanges(page, selector);
    await page.focus(selector);
    /** Holds `key` about 150 ms; returns the pose change once the camera-change for it came. */
    const hold = async (key: string, n: number) => {
      const before = await pose(page, selector);
      await page.keyboard.down(key);
      await page.waitForTimeout(150);
      await page.keyboard.up(key);
      await expect.poll(async () => (await changes()).length).toBe(n);
      const after = await pose(page, selector);
      return { d: after.position.map((x, i) => x - before.position[i]), yaw: after.rotation[0] - before.rotation[0], pitch: after.rotation[1] - before.rotation[1] };
    };
    // Looking down −Z: the camera's right is +X.
    const d = await hold('KeyD', 1);
    expect(d.d[0], 'D: right (+X)').toBeGreaterThan(0.1);
    expect(Math.abs(d.d[1]) + Math.abs(d.d[2]), 'D: only along X').toBeLessThan(1e-9);
    const w = await hold('KeyW', 2);
    expect(w.d[2], 'W: forward (−Z)').toBeLessThan(-0.1);
    expect(Math.abs(w.d[0]) + Math.abs(w.d[1]), 'W: only along Z').toBeLessThan(1e-9);
    const up = await hold('Space', 3);
    expect(up.d[1], 'Space: up (+Y)').toBeGreaterThan(0.1);
    const turn = await hold('ArrowRight', 4);
    expect(turn.yaw, 'ArrowRight: yaw grows (towards +X)').toBeGreaterThan(1);
    expect(turn.pitch).toBe(0);
    const last = (await changes())[3];
    expect(last.position).toEqual((await pose(page, selector)).position);
  });

  test('flyby: the first movement after pointer lock is dropped and no event turns the camera more than 5°', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: true }, SIZE);
    // Pointer lock, as the page sees it: the shadow root reports the canvas locked, then a
    // real lock change is announced. (Headless Chromium refuses the real request.)
    await page.evaluate((s) => {
      const el = document.querySelector(s)!;
      const canvas = el.shadowRoot!.querySelector('canvas')!;
      Object.defineProperty(el.shadowRoot!, 'pointerLockElement', { get: () => canvas });
      document.dispatchEvent(new Event('pointerlockchange'));
    }, selector);
    const start = await pose(page, selector);
    const move = (dx: number, dy: number) => page.evaluate(([s, dx, dy]) => {
      const canvas = document.querySelector(s as string)!.shadowRoot!.querySelector('canvas')!;
      canvas.dispatchEvent(new MouseEvent('mousemove', { movementX: dx as number, movementY: dy as number, bubbles: true }));
    }, [selector, dx, dy] as const);
    await move(-528, -377);
    await page.waitForTimeout(50);
    expect(await pose(page, selector), 'the lock-entry movement turned nothing').toEqual(start);
    await move(-528, -377);
    await page.waitForTimeout(50);
    const turned = await pose(page, selector);
    const yaw = turned.rotation[0] - start.rotation[0], pitch = turned.rotation[1] - start.rotation[1];
    expect(Math.hypot(yaw, pitch), 'a huge movement later: one step of 5° at most').toBeLessThanOrEqual(5 + 1e-9);
    expect(Math.hypot(yaw, pitch)).toBeGreaterThan(4.9);
  });
});

test('camera-change: one per batch of camera attributes set by the page, none for the element\'s own write-back', async ({ page }) => {
  await openPage(page);
  const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit' }, SIZE);
  const changes = await recordCameraChanges(page, selector);
  await page.evaluate((s) => {
    const el = document.querySelector(s)!;
    el.setAttribute('camera-position', '0 1 6');
    el.setAttribute('camera-target', '0 0 0');
  }, selector);
  await expect.poll(async () => (await changes()).length).toBe(1);
  const [d] = (await changes()) as { position: number[]; rotation: number[]; target: number[] }[];
  expect(d.position).toEqual([0, 1, 6]);
  expect(d.target).toEqual([0, 0, 0]);
  expect(d.rotation[0]).toBeCloseTo(-90, 9); // looking at the target: down −Z
  expect(d.rotation[1]).toBeCloseTo(-Math.atan2(1, 6) * DEG, 9);
  // A gesture: its write-back sets the attributes, and only the gesture's own event is fired.
  await page.focus(selector);
  await page.keyboard.press('ArrowLeft');
  await expect.poll(async () => (await changes()).length).toBe(2);
  await page.waitForTimeout(100);
  expect((await changes()).length).toBe(2);
});

test('camera-change details a listener keeps are never changed by later camera changes (attributes, a pan, an orbit)', async ({ page }) => {
  await openPage(page);
  const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
  await page.evaluate((s) => {
    const w = window as unknown as { __kept: { detail: unknown; json: string }[] };
    w.__kept = [];
    document.querySelector(s)!.addEventListener('camera-change', (e) => {
      const detail = (e as CustomEvent).detail;
      w.__kept.push({ detail, json: JSON.stringify(detail) });
    });
  }, selector);
  const kept = () => page.evaluate(() => (window as unknown as { __kept: { detail: unknown; json: string }[] }).__kept
    .map((k) => ({ now: JSON.stringify(k.detail), then: k.json })));
  // 1: the page sets the camera; 2: a right-drag pans (position and target move); 3: a key orbits.
  await setAttributes(page, selector, { 'camera-position': '1 2 7', 'camera-target': '0 0.5 0' });
  await expect.poll(async () => (await kept()).length).toBe(1);
  const b = await box(page, selector);
  const cdp = await page.context().newCDPSession(page);
  await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + 30, y: b.cy + 10 }, { t0: 35, steps: 6, dtMs: 16, restMs: 200, button: 'right', handledBy: page });
  await expect.poll(async () => (await kept()).length).toBe(2);
  await page.focus(selector);
  await page.keyboard.press('ArrowLeft');
  await expect.poll(async () => (await kept()).length).toBe(3);
  const details = await kept();
  expect(new Set(details.map((d) => d.then)).size, 'three different cameras announced').toBe(3);
  for (const [i, d] of details.entries()) expect(d.now, `detail ${i + 1}, read after the later changes`).toBe(d.then);
});

// orbit and trackball are a chunk of their own (controls/pointer-controls.ts), loaded the first
// time `controls` asks for them: the frame after that waits for it, so a drag after the next
// frame is never lost — even when the chunk is slow to come (held back 600 ms here).
test('controls set on a drawn element: after the next frame a drag turns the camera, however slow the controls\' chunk', async ({ page }) => {
  await page.route('**/pointer-controls*', async (route) => {
    await new Promise((r) => setTimeout(r, 600));
    await route.continue();
  });
  await openPage(page);
  const { selector } = await mount(page, { time: 0, spin: 0, 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
  await setAttributes(page, selector, { controls: 'orbit' });
  const start = await pose(page, selector);
  const b = await box(page, selector);
  const cdp = await page.context().newCDPSession(page);
  await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + 40, y: b.cy }, { t0: 40, steps: 10, dtMs: 16, restMs: 200, handledBy: page });
  await expect.poll(async () => (await pose(page, selector)).rotation[0] - start.rotation[0], { message: 'yaw turned by 40 px × 0.4°' }).toBeCloseTo(16, 6);
});

// The flyby is in the same chunk (controls/controls.ts): a page without `controls` fetches none of
// it; `controls="flyby"` set on a drawn element holds the next frame until the keys listen.
const controlsFetched = (page: Page) =>
  page.evaluate(() => performance.getEntriesByType('resource').some((e) => /controls\/(controls|flyby-|pointer-)/.test(e.name)));

test('a page without controls never fetches their chunk', async ({ page }) => {
  await openPage(page);
  await mount(page, { time: 0, spin: 0 }, SIZE);
  expect(await controlsFetched(page)).toBe(false);
});

test('controls="flyby" set on a drawn element: after the next frame a held key turns the camera, however slow the chunk', async ({ page }) => {
  await page.route('**/flyby-input*', async (route) => {
    await new Promise((r) => setTimeout(r, 600));
    await route.continue();
  });
  await openPage(page);
  const { selector } = await mount(page, { time: 0, spin: 0 }, SIZE);
  await setAttributes(page, selector, { controls: 'flyby' });
  expect(await controlsFetched(page)).toBe(true);
  const start = await pose(page, selector);
  await page.focus(selector);
  await page.keyboard.down('ArrowRight');
  await page.waitForTimeout(200);
  await page.keyboard.up('ArrowRight');
  // 90°/s for ~0.2 s: the yaw grows by about 18° (from −169°: no wrap).
  await expect.poll(async () => (await pose(page, selector)).rotation[0] - start.rotation[0], { message: 'yaw turned right' }).toBeGreaterThan(5);
});

test('if the controls\' chunk cannot load, the scene is drawn without input: one warning, no error', async ({ page, consoleLog }) => {
  await page.route('**/controls/controls*', (route) => route.abort());
  await openPage(page);
  const { selector } = await mount(page, { time: 0, spin: 0, controls: 'flyby' }, SIZE);
  await page.waitForTimeout(300);
  const img = await capture(page, undefined, selector);
  expect(img.data.some((v, i) => i % 4 !== 3 && v > 40), 'something is drawn').toBe(true);
  expect(consoleLog.take('warning').filter((w) => w.includes('controls="flyby" could not load'))).toHaveLength(1);
  consoleLog.take('error'); // the browser's own report of the failed fetch
});
