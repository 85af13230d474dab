// SPEC §10 with real input: mouse and wheel through CDP Input.dispatchMouseEvent (with explicit
// timestamps, which become the events' timeStamps, so a release velocity is the same run after
// run), touch through CDP's synthesized gestures, and frames through a manual
// requestAnimationFrame clock where the frame rate matters. Checked numerically (camera pose,
// objectRotation) and with pixels.
import type { CDPSession, Page } from '@playwright/test';
import { test, expect, mount, openPage, capture, setAttributes, type SceneElement } from './fixtures';
import { compareImages } from './helpers/golden';
import { forwardFromYawPitch } from '../../src/math/camera';

const SIZE = { width: 320, height: 180 };
const DEG = 180 / Math.PI;
type Quat = [number, number, number, number];
interface ControlsElement extends SceneElement { objectRotation: Quat }

/** Angle in degrees between two unit quaternions' rotations. */
const quatAngle = (a: Quat, b: Quat) => 2 * Math.acos(Math.min(1, Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]))) * DEG;

/** A manual animation-frame clock: frames come only when the test ticks (after `manual`), with the time it says. */
function fakeFrames(): void {
  const queue = new Map<number, FrameRequestCallback>();
  let id = 0;
  const raf = { manual: false, now: 0, tick(ms: number): number {
    raf.now += ms;
    const cbs = [...queue.values()];
    queue.clear();
    for (const cb of cbs) cb(raf.now);
    return cbs.length;
  }, pending: () => queue.size };
  (window as unknown as { __raf: typeof raf }).__raf = raf;
  window.requestAnimationFrame = (cb) => {
    queue.set(++id, cb);
    if (!raf.manual) setTimeout(() => raf.tick(16), 16);
    return id;
  };
  window.cancelAnimationFrame = (i) => { queue.delete(i); };
}

async function box(page: Page, selector: string) {
  return page.evaluate((s) => {
    const r = document.querySelector(s)!.getBoundingClientRect();
    return { x: r.left, y: r.top, width: r.width, height: r.height, cx: r.left + r.width / 2, cy: r.top + r.height / 2 };
  }, selector);
}

const pose = (page: Page, s: string) => page.evaluate((s) => {
  const el = document.querySelector(s) as SceneElement & { cameraPosition: number[]; cameraRotation: number[] };
  return { position: [...el.cameraPosition], rotation: [...el.cameraRotation] };
}, s);

const rotationOf = (page: Page, s: string) => page.evaluate((s) => (document.querySelector(s) as unknown as ControlsElement).objectRotation, s);

/** CDP timestamps are seconds since the epoch; events before the page's time origin read 0. */
const EPOCH = Date.now() / 1000 + 60;

/**
 * Mouse drag through CDP: press at `from`, `steps` moves to `to`, `dtMs` apart, release `restMs`
 * after the last move; `t0` seconds after EPOCH (only differences matter to the element).
 */
async function drag(cdp: CDPSession, from: { x: number; y: number }, to: { x: number; y: number }, o: { t0: number; steps: number; dtMs: number; restMs: number; button?: 'left' | 'right'; modifiers?: number }) {
  const button = o.button ?? 'left', buttons = button === 'left' ? 1 : 2, modifiers = o.modifiers ?? 0;
  let t = EPOCH + o.t0;
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: from.x, y: from.y, timestamp: t, modifiers });
  t += 0.01;
  await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: from.x, y: from.y, button, buttons, clickCount: 1, timestamp: t, modifiers });
  for (let k = 1; k <= o.steps; k++) {
    t += o.dtMs / 1000;
    const x = from.x + ((to.x - from.x) * k) / o.steps, y = from.y + ((to.y - from.y) * k) / o.steps;
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x, y, button, buttons, timestamp: t, modifiers });
  }
  t += o.restMs / 1000;
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: to.x, y: to.y, button, buttons: 0, clickCount: 1, timestamp: t, modifiers });
}

/** Collects camera-change details on the element from now on. */
async function recordCameraChanges(page: Page, s: string): Promise<() => Promise<unknown[]>> {
  await page.evaluate((s) => {
    const w = window as unknown as { __changes: unknown[] };
    w.__changes = [];
    document.querySelector(s)!.addEventListener('camera-change', (e) => w.__changes.push((e as CustomEvent).detail));
  }, s);
  return () => page.evaluate(() => (window as unknown as { __changes: unknown[] }).__changes);
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
    await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + N, y: b.cy }, { t0: 10, steps: 10, dtMs: 16, restMs: 200 });
    const q = await rotationOf(page, selector);
    const angle = 2 * Math.acos(Math.min(1, Math.abs(q[3]))) * DEG;
    expect(angle, 'turn of a 50 px drag over a 90 px radius').toBeCloseTo(Math.asin(N / r) * DEG, 3);
    // About the camera's up (a drag right turns the front of the objects right).
    const { rotation } = await pose(page, selector);
    const f = forwardFromYawPitch([0, 0, 0], rotation[0], rotation[1]);
    const h = Math.hypot(f[0], f[2]);
    const right = [-f[2] / h, 0, f[0] / h];
    const up = [right[1] * f[2] - right[2] * f[1], right[2] * f[0] - right[0] * f[2], right[0] * f[1] - right[1] * f[0]];
    const s = Math.sin((angle / DEG) / 2);
    for (let i = 0; i < 3; i++) expect(q[i] / s).toBeCloseTo(up[i], 3);
    // Pixels: the picture moved, and it is the picture of that rotation set directly.
    const after = await capture(page, undefined, selector);
    expect(compareImages(before, after).differing, 'pixels changed by the drag').toBeGreaterThan(500);
    await setAttributes(page, selector, { controls: null });
    await page.evaluate((s) => { (document.querySelector(s) as unknown as ControlsElement).objectRotation = [0, 0, 0, 1]; }, selector);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    expect(compareImages(before, await capture(page, undefined, selector)).differing, 'identity rotation: the first picture again').toBe(0);
    await page.evaluate(([s, q]) => { (document.querySelector(s as string) as unknown as ControlsElement).objectRotation = q as Quat; }, [selector, q] as const);
    await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
    expect(compareImages(after, await capture(page, undefined, selector)).differing, 'the dragged picture from objectRotation').toBe(0);
  });

  test('after release the inertia at 30 Hz and at 144 Hz ends in the same orientation (within 0.5°), then frames stop', async ({ page }) => {
    await page.addInitScript(fakeFrames);
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'trackball' }, { width: 160, height: 90 });
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    const results: { hz: number; release: Quat; final: Quat; frames: number; pending: number }[] = [];
    for (const [i, hz] of [30, 144].entries()) {
      await page.evaluate((s) => {
        (window as unknown as { __raf: { manual: boolean } }).__raf.manual = true;
        (document.querySelector(s) as unknown as ControlsElement).objectRotation = [0, 0, 0, 1];
      }, selector);
      // A flick: 8 moves 16 ms apart, released 8 ms after the last.
      await drag(cdp, { x: b.cx - 20, y: b.cy + 5 }, { x: b.cx + 20, y: b.cy - 5 }, { t0: 20 + 10 * i, steps: 8, dtMs: 16, restMs: 8 });
      const release = await rotationOf(page, selector);
      const frames = await page.evaluate((hz) => {
        const raf = (window as unknown as { __raf: { tick(ms: number): number } }).__raf;
        let n = 0;
        for (let k = 0; k < hz * 4.5; k++) n += raf.tick(1000 / hz) > 0 ? 1 : 0;
        return n;
      }, hz);
      const pending = await page.evaluate(() => (window as unknown as { __raf: { pending(): number } }).__raf.pending());
      results.push({ hz, release, final: await rotationOf(page, selector), frames, pending });
    }
    await page.evaluate(() => { (window as unknown as { __raf: { manual: boolean; tick(ms: number): number } }).__raf.manual = false; });
    const [a, c] = results;
    console.log(`inertia: 30 Hz ${a.frames} frames, +${quatAngle(a.release, a.final).toFixed(2)}°; 144 Hz ${c.frames} frames, +${quatAngle(c.release, c.final).toFixed(2)}°; ` +
      `final orientations ${quatAngle(a.final, c.final).toFixed(4)}° apart`);
    expect(quatAngle(a.release, c.release), 'the same flick, the same release orientation').toBeLessThan(1e-6);
    expect(quatAngle(a.release, a.final), 'inertia turned the objects after release').toBeGreaterThan(5);
    // Measured 0.11°: not the frame rate (the steps telescope exactly) but the events' timeStamps,
    // which Chromium coarsens to 0.1 ms, so the two flicks' release rates differ by ~0.1 %.
    expect(quatAngle(a.final, c.final), '30 Hz against 144 Hz').toBeLessThan(0.5);
    expect(a.pending + c.pending, 'no frame requested once the spin stopped').toBe(0);
    expect(c.frames, 'it stopped before 4.5 s').toBeLessThan(144 * 4.5);
  });

  test('right-drag and Shift-drag turn the light, not the objects: the lighting changes', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'trackball' }, SIZE);
    const b = await box(page, selector);
    const before = await capture(page, undefined, selector);
    const cdp = await page.context().newCDPSession(page);
    await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + 60, y: b.cy + 20 }, { t0: 30, steps: 12, dtMs: 16, restMs: 200, button: 'right' });
    expect(await rotationOf(page, selector)).toEqual([0, 0, 0, 1]);
    const lit = await capture(page, undefined, selector);
    expect(compareImages(before, lit).differing, 'pixels relit by a right-drag').toBeGreaterThan(200);
    await drag(cdp, { x: b.cx + 60, y: b.cy + 20 }, { x: b.cx, y: b.cy }, { t0: 31, steps: 12, dtMs: 16, restMs: 200, modifiers: 8 /* Shift */ });
    expect(await rotationOf(page, selector)).toEqual([0, 0, 0, 1]);
    // Back along the same path: nearly the first lighting again.
    expect(compareImages(before, await capture(page, undefined, selector)).differing).toBeLessThan(compareImages(before, lit).differing / 4);
  });
});

test.describe('orbit', () => {
  test('a drag turns the camera about its target at a fixed distance (0.4° per px); one camera-change at the end, attributes written once', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const changes = await recordCameraChanges(page, selector);
    const start = await pose(page, selector);
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    await drag(cdp, { x: b.cx, y: b.cy }, { x: b.cx + 40, y: b.cy }, { t0: 40, steps: 10, dtMs: 16, restMs: 200 });
    await expect.poll(async () => (await changes()).length).toBe(1);
    const end = await pose(page, selector);
    expect(end.rotation[0] - start.rotation[0], 'yaw turned by 40 px × 0.4°').toBeCloseTo(16, 6);
    expect(Math.hypot(...end.position)).toBeCloseTo(Math.hypot(0, 1, 6), 6);
    const detail = (await changes())[0] as { position: number[]; rotation: number[]; target: number[] };
    expect(detail.target).toEqual([0, 0, 0]);
    expect(detail.position.map((x) => x.toFixed(9))).toEqual(end.position.map((x) => x.toFixed(9)));
    const attrs = await page.evaluate((s) => document.querySelector(s)!.getAttribute('camera-position'), selector);
    expect(attrs!.split(' ').map(Number)).toEqual(end.position);
  });

  test('the wheel dollies towards the target and ends its gesture 150 ms after its last event', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const changes = await recordCameraChanges(page, selector);
    const b = await box(page, selector);
    await page.mouse.move(b.cx, b.cy);
    for (let i = 0; i < 3; i++) await page.mouse.wheel(0, -100);
    await expect.poll(async () => (await changes()).length).toBe(1);
    const end = await pose(page, selector);
    expect(Math.hypot(...end.position), 'distance × e^(−3·100·0.0015)').toBeCloseTo(Math.hypot(0, 1, 6) * Math.exp(-0.45), 6);
    await page.waitForTimeout(300);
    expect((await changes()).length, 'one camera-change for the whole wheel gesture').toBe(1);
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
    expect(Math.abs(end.rotation[0] - start.rotation[0]), 'the finger turned the camera').toBeGreaterThan(10);
    expect(Math.abs(end.rotation[1] - start.rotation[1]), 'and tilted it').toBeGreaterThan(10);
  });

  test('two-finger pinch dollies by the ratio of the finger spans', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    const at = (d: number) => [{ x: b.cx - d, y: b.cy, id: 1 }, { x: b.cx + d, y: b.cy, id: 2 }];
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchStart', touchPoints: at(20) });
    for (const d of [25, 30, 35, 40]) await cdp.send('Input.dispatchTouchEvent', { type: 'touchMove', touchPoints: at(d) });
    await cdp.send('Input.dispatchTouchEvent', { type: 'touchEnd', touchPoints: [] });
    // The fingers' events come one finger at a time, so the midpoint wobbles by half a step
    // between them and pans a little while the distance changes: the target drifts by ~1e-4.
    await expect.poll(async () => Math.hypot(...(await pose(page, selector)).position)).toBeCloseTo(Math.hypot(0, 1, 6) / 2, 3);
  });

  test('keys act only while the element has focus: arrows orbit by 5°, + dollies', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, SIZE);
    const start = await pose(page, selector);
    await page.keyboard.press('ArrowRight');
    expect(await pose(page, selector), 'unfocused: nothing').toEqual(start);
    await page.focus(selector);
    await page.keyboard.press('ArrowRight');
    await expect.poll(async () => (await pose(page, selector)).rotation[0] - start.rotation[0]).toBeCloseTo(5, 6);
    await page.keyboard.press('+');
    await expect.poll(async () => Math.hypot(...(await pose(page, selector)).position)).toBeCloseTo(Math.hypot(0, 1, 6) / 1.1, 6);
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
