// docs/interaction.md#inertia: the motion after a release is timed by the wall clock. Frames come at 13, 30 and 144
// per second from a paced requestAnimationFrame (setTimeout on the wall clock; each frame is
// handed the time it was due, as a display's vsync would be), and the decay is measured in real
// time, performance.now() at each frame, from objectRotation (trackball) and from the camera's
// yaw (orbit): the angle still to turn decays as e^(−t/τ), τ ≤ 0.5 s at every rate, and the
// whole turn after release is the same at every rate. The orbit's inertia is in one unit: a
// flick turns on at its own rate (not 6.3°/s), and its camera-change comes when the rate falls
// below 0.05°/s, at τ·ln(r₀ / 0.05°/s) after the release. A press, held without moving, stops a
// trackball's spin where it finds it (seen red without the stop in onDown: 13° more by the next frame).
import type { Page } from '@playwright/test';
import { test, expect, mount, openPage } from './fixtures';
import { box, drag, EPOCH, pose, quatAngle, recordCameraChanges, rotationOf, type ControlsElement, type Quat } from './helpers/controls-input';
import { INERTIA_TAU } from '../../src/element/controls/inertia';

interface Pace { fps: number; tickAt: number; idle(): boolean }
interface Sample { t: number; q: Quat; yaw: number }
interface Recording { releaseAt: number; releaseQ: Quat; releaseYaw: number; samples: Sample[] }

/** requestAnimationFrame paced at `__pace.fps` on the wall clock (installed before any module loads). */
function pacedFrames(): void {
  const queue = new Map<number, FrameRequestCallback>();
  let id = 0, timer = 0, due = 0;
  const pace = { fps: 60, tickAt: 0, idle: () => queue.size === 0 };
  (window as unknown as { __pace: typeof pace }).__pace = pace;
  const tick = () => {
    timer = 0;
    pace.tickAt = performance.now();
    const cbs = [...queue.values()];
    queue.clear();
    for (const cb of cbs) cb(due);
  };
  window.requestAnimationFrame = (cb) => {
    queue.set(++id, cb);
    if (timer === 0) {
      const now = performance.now();
      due = Math.max(now, due + 1000 / pace.fps);
      timer = setTimeout(tick, due - now) as unknown as number;
    }
    return id;
  };
  window.cancelAnimationFrame = (i) => { queue.delete(i); };
}

/** From now on: each frame's wall-clock time, objectRotation and yaw; the same at the release (pointerup). */
async function startRecording(page: Page, s: string, fps: number): Promise<void> {
  await page.evaluate(([s, fps]) => {
    const w = window as unknown as { __pace: Pace; __rec: Recording; __recOff?: () => void };
    const el = document.querySelector(s as string) as unknown as ControlsElement & { cameraRotation: number[] };
    w.__recOff?.();
    w.__pace.fps = fps as number;
    const rec: Recording = w.__rec = { releaseAt: -1, releaseQ: [0, 0, 0, 1], releaseYaw: 0, samples: [] };
    const onFrame = () => { if (rec.releaseAt >= 0) rec.samples.push({ t: w.__pace.tickAt, q: el.objectRotation, yaw: el.cameraRotation[0] }); };
    const onUp = () => { rec.releaseAt = performance.now(); rec.releaseQ = el.objectRotation; rec.releaseYaw = el.cameraRotation[0]; };
    el.addEventListener('frame', onFrame);
    window.addEventListener('pointerup', onUp, true); // capture: before the element's own handler
    w.__recOff = () => { el.removeEventListener('frame', onFrame); window.removeEventListener('pointerup', onUp, true); };
  }, [s, fps] as const);
}

/** Waits until the motion has stopped (no frame asked for) and returns the recording. */
async function motionRecorded(page: Page): Promise<Recording> {
  await expect.poll(() => page.evaluate(() => {
    const w = window as unknown as { __pace: Pace; __rec: Recording };
    return w.__rec.samples.length > 0 && w.__pace.idle();
  }), { timeout: 20_000, intervals: [250] }).toBe(true);
  return page.evaluate(() => (window as unknown as { __rec: Recording }).__rec);
}

/**
 * τ from the angle still to turn at each frame, φᵢ = φ(tᵢ): least squares of ln φ on t over the
 * frames with φ at least 2 % of φ at the release (below that the stop threshold shows). Also the
 * frames used, the mean frame interval and the longest one, in ms.
 */
function fitTau(times: number[], remaining: number[], atRelease: number) {
  const xs: number[] = [], ys: number[] = [];
  for (let i = 0; i < times.length; i++) if (remaining[i] >= 0.02 * atRelease) { xs.push(times[i] / 1000); ys.push(Math.log(remaining[i])); }
  const n = xs.length, mx = xs.reduce((a, b) => a + b, 0) / n, my = ys.reduce((a, b) => a + b, 0) / n;
  let sxy = 0, sxx = 0;
  for (let i = 0; i < n; i++) { sxy += (xs[i] - mx) * (ys[i] - my); sxx += (xs[i] - mx) ** 2; }
  const gaps = times.slice(1).map((t, i) => t - times[i]);
  return { tau: -sxx / sxy, frames: n, meanMs: gaps.reduce((a, b) => a + b, 0) / gaps.length, maxMs: Math.max(...gaps) };
}

const RATES = [13, 30, 144];

/**
 * Frames as cheap as they were before linear light: the timing is what is measured here, and on
 * SwiftShader a frame in srgb costs several times more (its multisampled sRGB resolve); with a
 * bench or mutation run beside the tests, the trackball's 20 s wait for the motion's end ran out
 * twice that way (alone it passed, τ 0.349 s).
 */
const CHEAP = { 'color-space': 'none' } as const;

type DecayRun = { fps: number; tau: number; turn: number; frames: number; meanMs: number; maxMs: number };

/** The decay measured at each paced rate: τ ≤ 0.5 s in real time, the element's own τ, and the same turn as at 144 fps. */
function expectWallClockDecay(what: string, runs: DecayRun[]): void {
  console.log(`${what} inertia: ` + runs.map((r) => `${r.fps} fps (frames ${r.meanMs.toFixed(1)} ms, longest ${r.maxMs.toFixed(0)}): τ ${r.tau.toFixed(3)} s over ${r.frames} frames, turned ${r.turn.toFixed(2)}°`).join('; '));
  for (const r of runs) {
    expect(r.meanMs, `${r.fps} fps: the frames came at the paced rate or slower`).toBeGreaterThan(1000 / r.fps - 1);
    expect(r.frames, `${r.fps} fps: frames in the fit`).toBeGreaterThanOrEqual(5);
    expect(r.tau, `${r.fps} fps: τ in real time`).toBeLessThanOrEqual(0.5);
    expect(r.tau, `${r.fps} fps: τ is the element's own`).toBeCloseTo(INERTIA_TAU, 1);
    expect(r.turn, `${r.fps} fps: the turn after release, against 144 fps`).toBeCloseTo(runs[2].turn, 0);
  }
}

test.describe('trackball inertia', () => {
  test('trackball: after a flick the objects\' turn decays with τ ≤ 0.5 s in real time at 13, 30 and 144 frames/s, and turns as far at each', async ({ page }) => {
    await page.addInitScript(pacedFrames);
    await openPage(page);
    const { selector } = await mount(page, { ...CHEAP, time: 0, spin: 0, controls: 'trackball' }, { width: 160, height: 90 });
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    const runs: DecayRun[] = [];
    for (const [i, fps] of RATES.entries()) {
      await page.evaluate((s) => { (document.querySelector(s) as unknown as ControlsElement).objectRotation = [0, 0, 0, 1]; }, selector);
      await startRecording(page, selector, fps);
      // A flick: 8 moves 16 ms apart, released 8 ms after the last; each sent once the page has
      // handled the one before (at 13 frames/s on a loaded machine, moves still queued were
      // coalesced into one, which turns 5° at most: the flick was sometimes lost).
      await drag(cdp, { x: b.cx - 20, y: b.cy + 5 }, { x: b.cx + 20, y: b.cy - 5 }, { t0: 20 + 10 * i, steps: 8, dtMs: 16, restMs: 8, handledBy: page });
      const rec = await motionRecorded(page);
      const final = rec.samples[rec.samples.length - 1].q;
      const fit = fitTau(rec.samples.map((x) => x.t - rec.releaseAt), rec.samples.map((x) => quatAngle(x.q, final)), quatAngle(rec.releaseQ, final));
      runs.push({ fps, ...fit, turn: quatAngle(rec.releaseQ, final) });
    }
    expectWallClockDecay('trackball', runs);
  });

  test('trackball: a press (held, not moved) on objects still spinning after a flick stops them; they stay where the press found them', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { ...CHEAP, time: 0, spin: 0, controls: 'trackball' }, { width: 160, height: 90 });
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    // The rotation as the press arrives (capture: before the element's own handler, in the same task).
    await page.evaluate((s) => {
      const el = document.querySelector(s) as unknown as ControlsElement;
      const w = window as unknown as { __atPress: Quat | null };
      w.__atPress = null;
      window.addEventListener('pointerdown', () => { w.__atPress = el.objectRotation; }, true);
    }, selector);
    await drag(cdp, { x: b.cx - 20, y: b.cy + 5 }, { x: b.cx + 20, y: b.cy - 5 }, { t0: 50, steps: 8, dtMs: 16, restMs: 8, handledBy: page });
    const released = await rotationOf(page, selector);
    // Still spinning: a frame after the release has turned the objects further.
    await page.evaluate((s) => new Promise((r) => document.querySelector(s)!.addEventListener('frame', r, { once: true })), selector);
    expect(quatAngle(released, await rotationOf(page, selector)), 'turned on after the release').toBeGreaterThan(0.5);
    await page.evaluate(() => { (window as unknown as { __atPress: Quat | null }).__atPress = null; });
    const t = EPOCH + 51;
    await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: b.cx, y: b.cy, button: 'left', buttons: 1, clickCount: 1, timestamp: t });
    await page.waitForFunction(() => (window as unknown as { __atPress: Quat | null }).__atPress !== null, undefined, { polling: 5 });
    const atPress = await page.evaluate(() => (window as unknown as { __atPress: Quat }).__atPress);
    // Held: frames asked for and drawn, and the objects have not moved since the press.
    const held = await page.evaluate(async (s) => {
      const el = document.querySelector(s) as unknown as ControlsElement;
      const seen: Quat[] = [];
      for (let i = 0; i < 3; i++) {
        const frame = new Promise((r) => el.addEventListener('frame', r, { once: true }));
        el.requestRender();
        await frame;
        seen.push(el.objectRotation);
      }
      return seen;
    }, selector);
    // At most a rounding (2.4e-6° seen once under load); a spin the press did not stop turns degrees a frame.
    for (const [i, q] of held.entries()) expect(quatAngle(atPress, q), `frame ${i + 1} while held: turned since the press (°)`).toBeLessThan(1e-3);
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: b.cx, y: b.cy, button: 'left', buttons: 0, clickCount: 1, timestamp: t + 0.3 });
  });
});

test('orbit: after a flick the camera\'s turn decays with τ ≤ 0.5 s in real time at 13, 30 and 144 frames/s, and turns as far at each', async ({ page }) => {
  await page.addInitScript(pacedFrames);
  await openPage(page);
  const { selector } = await mount(page, { ...CHEAP, time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, { width: 160, height: 90 });
  const b = await box(page, selector);
  const cdp = await page.context().newCDPSession(page);
  const runs: DecayRun[] = [];
  for (const [i, fps] of RATES.entries()) {
    await page.evaluate((s) => { const el = document.querySelector(s)!; el.setAttribute('camera-position', '0 1 6'); el.setAttribute('camera-target', '0 0 0'); }, selector);
    await startRecording(page, selector, fps);
    // 40 px right in 10 moves 16 ms apart: 0.4°/px × 4 px / 16 ms = 100°/s at the release.
    await drag(cdp, { x: b.cx - 20, y: b.cy }, { x: b.cx + 20, y: b.cy }, { t0: 60 + 10 * i, steps: 10, dtMs: 16, restMs: 8, handledBy: page });
    const rec = await motionRecorded(page);
    const final = rec.samples[rec.samples.length - 1].yaw;
    const left = (yaw: number) => ((final - yaw + 540) % 360) - 180;
    const fit = fitTau(rec.samples.map((x) => x.t - rec.releaseAt), rec.samples.map((x) => left(x.yaw)), left(rec.releaseYaw));
    runs.push({ fps, ...fit, turn: left(rec.releaseYaw) });
  }
  expectWallClockDecay('orbit', runs);
});

test('orbit: a flick turns on at its release rate (no 6.3°/s cap), and its one camera-change comes as the rate falls below 0.05°/s, τ·ln(r₀ ÷ 0.05°/s) after release', async ({ page }) => {
  await openPage(page);
  const { selector } = await mount(page, { ...CHEAP, time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, { width: 160, height: 90 });
  const changes = await recordCameraChanges(page, selector);
  await page.evaluate((s) => {
    const el = document.querySelector(s) as unknown as ControlsElement & { cameraRotation: number[] };
    const w = window as unknown as { __release: { at: number; yaw: number }; __frames: number[] };
    w.__frames = [];
    window.addEventListener('pointerup', () => { w.__release = { at: performance.now(), yaw: el.cameraRotation[0] }; }, true);
    el.addEventListener('frame', () => w.__frames.push(performance.now()));
  }, selector);
  const b = await box(page, selector);
  const cdp = await page.context().newCDPSession(page);
  // 40 px right in 10 moves 16 ms apart, released 8 ms after the last: the rate over the last
  // 80 ms is 0.4°/px × 4 px / 16 ms = 100°/s.
  const r0 = 100;
  await drag(cdp, { x: b.cx - 20, y: b.cy }, { x: b.cx + 20, y: b.cy }, { t0: 90, steps: 10, dtMs: 16, restMs: 8, handledBy: page });
  await expect.poll(async () => (await changes()).length, { timeout: 20_000 }).toBe(1);
  await page.waitForTimeout(500);
  const [change] = await changes();
  const { release, frames } = await page.evaluate(() => {
    const w = window as unknown as { __release: { at: number; yaw: number }; __frames: number[] };
    return { release: w.__release, frames: w.__frames };
  });
  expect(await changes(), 'one camera-change for the drag and its inertia').toHaveLength(1);
  // The turn after release: r₀·τ, less the r_stop·τ = 0.0175° it would still have turned.
  const turn = change.rotation[0] - release.yaw;
  console.log(`orbit flick: turned ${turn.toFixed(3)}° after release (r₀·τ = ${(r0 * INERTIA_TAU).toFixed(3)}°)`);
  expect(turn, 'turned r₀·τ after release').toBeCloseTo(r0 * INERTIA_TAU, 0);
  // The motion stops at the first frame at or after T, when r₀·e^(−t/τ) falls below 0.05°/s;
  // camera-change is fired in that frame. Margin: 10 ms early (timestamp rounding), 250 ms late
  // (a frame or a few late on a loaded 2-core machine); a threshold in the wrong unit is more
  // than 1.4 s away either side.
  const T = INERTIA_TAU * Math.log(r0 / 0.05) * 1000;
  const at = change.at - release.at;
  console.log(`camera-change ${at.toFixed(0)} ms after release; expected from ${T.toFixed(0)} ms`);
  expect(at, 'camera-change at the stop, not before').toBeGreaterThan(T - 10);
  expect(at, 'camera-change at the stop, not long after').toBeLessThan(T + 250);
  // camera-change is fired as the last step is taken, before that frame is drawn: its `frame`
  // event is the only one after it.
  expect(frames.filter((t) => t > change.at).length, 'no frame after the stop but the one drawing it').toBeLessThanOrEqual(1);
  const attrs = await page.evaluate((s) => document.querySelector(s)!.getAttribute('camera-rotation'), selector);
  expect(attrs!.split(' ').map(Number), 'the written camera-rotation is the one announced').toEqual(change.rotation);
});

for (const next of [null, 'trackball'] as const) {
  test(`orbit: controls changed to ${next ?? 'none'} while a flick's inertia runs ends the gesture there: the camera written back and one camera-change`, async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { ...CHEAP, time: 0, spin: 0, controls: 'orbit', 'camera-position': '0 1 6', 'camera-target': '0 0 0' }, { width: 160, height: 90 });
    const changes = await recordCameraChanges(page, selector);
    const start = await pose(page, selector);
    const b = await box(page, selector);
    const cdp = await page.context().newCDPSession(page);
    await drag(cdp, { x: b.cx - 20, y: b.cy }, { x: b.cx + 20, y: b.cy }, { t0: 95, steps: 10, dtMs: 16, restMs: 8, handledBy: page });
    // A frame of the inertia, then the change: the pose then is what is written and announced.
    const live = await page.evaluate(([s, next]) => new Promise<{ position: number[]; rotation: number[] }>((resolve) => {
      const el = document.querySelector(s as string) as unknown as ControlsElement & { cameraPosition: number[]; cameraRotation: number[] };
      el.addEventListener('frame', () => {
        const at = { position: el.cameraPosition, rotation: el.cameraRotation };
        if (next === null) el.removeAttribute('controls');
        else el.setAttribute('controls', next as string);
        resolve(at);
      }, { once: true });
    }), [selector, next] as const);
    expect(Math.abs(live.rotation[0] - start.rotation[0]), 'the inertia had turned the camera (°)').toBeGreaterThan(1);
    await expect.poll(async () => (await changes()).length, { message: 'the gesture ended' }).toBe(1);
    const [change] = await changes();
    expect(change.rotation, 'announced: the pose at the change').toEqual(live.rotation);
    expect(change.position).toEqual(live.position);
    const attrs = await page.evaluate((s) => ['camera-position', 'camera-rotation'].map((a) => document.querySelector(s)!.getAttribute(a)), selector);
    expect(attrs[0]!.split(' ').map(Number), 'camera-position written back').toEqual(live.position);
    expect(attrs[1]!.split(' ').map(Number), 'camera-rotation written back').toEqual(live.rotation);
    // Nothing moves on, and no second event comes.
    await page.evaluate((s) => new Promise((r) => { const el = document.querySelector(s) as unknown as ControlsElement; el.addEventListener('frame', r, { once: true }); el.requestRender(); }), selector);
    await page.waitForTimeout(300);
    expect(await changes(), 'one camera-change').toHaveLength(1);
    expect((await pose(page, selector)).rotation, 'the camera stopped').toEqual(live.rotation);
  });
}

/**
 * A busy page: from the release on, the page's own requestAnimationFrame loop works 20 ms in
 * every frame, and the element is big enough (640×360, linear light) that SwiftShader takes
 * longer to draw a frame than the page takes to ask for one. objectRotation is read on a timer,
 * as a page would read it, and its turn since the release follows the exponential
 * r₀·τ·(1 − e^(−t/τ)) (docs/interaction.md#inertia) to its end.
 */
test('trackball on a busy page (20 ms of page work in each frame): the turn after a flick follows r₀·τ·(1 − e^(−t/τ)) to its end', async ({ page }) => {
  await openPage(page);
  const size = { width: 640, height: 360 };
  const { selector } = await mount(page, { time: 0, spin: 0, controls: 'trackball' }, size);
  await page.evaluate((s) => {
    const el = document.querySelector(s) as unknown as ControlsElement;
    const w = window as unknown as { __busy: { at: number; q: Quat; samples: [number, Quat][]; rafs: number[] } };
    const busy = w.__busy = { at: -1, q: [0, 0, 0, 1] as Quat, samples: [] as [number, Quat][], rafs: [] as number[] };
    window.addEventListener('pointerup', () => {
      busy.at = performance.now();
      busy.q = el.objectRotation;
      const work = () => {
        const t = performance.now();
        busy.rafs.push(t);
        while (performance.now() - t < 20) { /* the page's own work */ }
        if (t - busy.at < 3500) requestAnimationFrame(work);
      };
      requestAnimationFrame(work);
      const timer = setInterval(() => {
        busy.samples.push([performance.now(), el.objectRotation]);
        if (performance.now() - busy.at > 3500) clearInterval(timer);
      }, 25);
    }, { capture: true, once: true });
  }, selector);
  const b = await box(page, selector);
  const cdp = await page.context().newCDPSession(page);
  // A flick through the centre along a line: 8 moves of 20 px, 16 ms apart, each turning by the
  // 5° cap (the arcball's radius is 180 px), released 8 ms after the last: the rate over the last
  // 80 ms is 6·5° over the 96 ms since the move before them, 312.5°/s about one axis.
  await drag(cdp, { x: b.cx - 80, y: b.cy }, { x: b.cx + 80, y: b.cy }, { t0: 200, steps: 8, dtMs: 16, restMs: 8, handledBy: page });
  const r0 = 6 * 5 / 0.096;
  await expect.poll(() => page.evaluate(() => (window as unknown as { __busy: { samples: unknown[]; at: number } }).__busy.samples.length > 0
    && performance.now() - (window as unknown as { __busy: { at: number } }).__busy.at > 3600), { timeout: 20_000 }).toBe(true);
  const busy = await page.evaluate(() => (window as unknown as { __busy: { at: number; q: Quat; samples: [number, Quat][]; rafs: number[] } }).__busy);
  const curve = (t: number) => r0 * INERTIA_TAU * (1 - Math.exp(-t / 1000 / INERTIA_TAU));
  const turns = busy.samples.map(([t, q]) => ({ t: t - busy.at, turn: quatAngle(busy.q, q) }));
  const gaps = busy.rafs.slice(1).map((t, i) => t - busy.rafs[i]);
  const final = turns[turns.length - 1].turn;
  console.log(`busy page: turned ${final.toFixed(2)}° (r₀·τ = ${(r0 * INERTIA_TAU).toFixed(2)}°); page frames every ${(gaps.reduce((a, b) => a + b, 0) / gaps.length).toFixed(0)} ms, the longest ${Math.max(...gaps).toFixed(0)} ms; at 0.7 s ${turns.find((x) => x.t >= 700)?.turn.toFixed(1)}° (curve ${curve(700).toFixed(1)}°)`);
  // The element never holds the page up: its frames wait for the GPU instead of queuing behind
  // it. Before, the page's frames stopped for 0.27 to 2.3 s in five runs of six (its main thread
  // blocked while SwiftShader worked through the queue), and a step after such a stall turns over
  // at most 0.25 s: the turn ended at 86–107° of 109.4°. Measured since: 79 and 118 ms at most.
  expect(Math.max(...gaps), 'the longest wait between the page\'s frames (ms)').toBeLessThan(250);
  // On the curve all along. Never ahead: the element steps on the wall clock before each
  // sample; event timestamps are coarsened to 0.1 ms, so the 96 ms the rate is measured over is
  // known to 0.2 % (109.47° was measured for 109.38°). Never behind the curve at the frame before
  // the last one before the sample: the element stepped after it.
  for (const x of turns) {
    expect(x.turn, `${x.t.toFixed(0)} ms after release: not ahead`).toBeLessThanOrEqual(curve(x.t) * 1.002 + 0.01);
    const before = busy.rafs.filter((t) => t - busy.at < x.t);
    if (before.length >= 2) expect(x.turn, `${x.t.toFixed(0)} ms after release: not behind`).toBeGreaterThanOrEqual(curve(before[before.length - 2] - busy.at) * 0.998 - 0.01);
  }
  expect(final, 'the whole turn after release').toBeCloseTo(r0 * INERTIA_TAU, 0);
});
