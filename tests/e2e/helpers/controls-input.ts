// Input and camera helpers for the controls tests: drags through CDP with explicit timestamps,
// the element's box and camera pose, camera-change recording, and where a world point lands on
// the element (CSS px from its centre, y down) for a pose.
import type { CDPSession, Page } from '@playwright/test';
import type { SceneElement } from '../fixtures';
import { forwardFromYawPitch } from '../../../src/math/camera';

export const DEG = 180 / Math.PI;
export type Quat = [number, number, number, number];
export interface ControlsElement extends SceneElement { objectRotation: Quat }
export interface Pose { position: number[]; rotation: number[] }
export interface CameraChange { position: number[]; rotation: number[]; target?: number[] }

/** Angle in degrees between two unit quaternions' rotations. */
export const quatAngle = (a: Quat, b: Quat) => 2 * Math.acos(Math.min(1, Math.abs(a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3]))) * DEG;

export async function box(page: Page, selector: string) {
  return page.evaluate((s) => {
    const r = document.querySelector(s)!.getBoundingClientRect();
    return { x: r.left, y: r.top, width: r.width, height: r.height, cx: r.left + r.width / 2, cy: r.top + r.height / 2 };
  }, selector);
}

export const pose = (page: Page, s: string): Promise<Pose> => page.evaluate((s) => {
  const el = document.querySelector(s) as SceneElement & { cameraPosition: number[]; cameraRotation: number[] };
  return { position: [...el.cameraPosition], rotation: [...el.cameraRotation] };
}, s);

export const rotationOf = (page: Page, s: string) => page.evaluate((s) => (document.querySelector(s) as unknown as ControlsElement).objectRotation, s);

/**
 * CDP timestamps are seconds since the epoch; events before the page's time origin read 0. The
 * base is fixed when a worker first loads this file, and a worker's pages open later and later:
 * at +60 s, a page opened more than a minute on (the trackball inertia test, late in a full run)
 * got every drag's events at 0 — no time between them, no flick. Three hours outlasts any run.
 */
export const EPOCH = Date.now() / 1000 + 3 * 3600;

/**
 * Mouse drag through CDP: press at `from`, `steps` moves to `to`, `dtMs` apart, release `restMs`
 * after the last move; `t0` seconds after EPOCH (only differences matter to the element).
 */
export async function drag(cdp: CDPSession, from: { x: number; y: number }, to: { x: number; y: number }, o: { t0: number; steps: number; dtMs: number; restMs: number; button?: 'left' | 'right'; modifiers?: number; handledBy?: Page }) {
  const button = o.button ?? 'left', buttons = button === 'left' ? 1 : 2, modifiers = o.modifiers ?? 0;
  const handled = o.handledBy ? await pointerEventsHandled(o.handledBy) : async () => {};
  let t = EPOCH + o.t0;
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x: from.x, y: from.y, timestamp: t, modifiers });
  t += 0.01;
  await cdp.send('Input.dispatchMouseEvent', { type: 'mousePressed', x: from.x, y: from.y, button, buttons, clickCount: 1, timestamp: t, modifiers });
  await handled('pointerdown');
  for (let k = 1; k <= o.steps; k++) {
    t += o.dtMs / 1000;
    const x = from.x + ((to.x - from.x) * k) / o.steps, y = from.y + ((to.y - from.y) * k) / o.steps;
    await cdp.send('Input.dispatchMouseEvent', { type: 'mouseMoved', x, y, button, buttons, timestamp: t, modifiers });
    await handled('pointermove');
  }
  t += o.restMs / 1000;
  await cdp.send('Input.dispatchMouseEvent', { type: 'mouseReleased', x: to.x, y: to.y, button, buttons: 0, clickCount: 1, timestamp: t, modifiers });
  await handled('pointerup');
}

/**
 * For `drag`'s `handledBy`: resolves, for each event dispatched, once the page has handled it. A
 * page that cannot keep up (a slow frame, a loaded machine) would otherwise get moves that are
 * still queued when the next arrives coalesced into one pointermove, which turns at most 5° and
 * takes the flick's speed with it. Counted on the window in the capture phase: the element's own
 * listener runs later in the same dispatch.
 */
async function pointerEventsHandled(page: Page): Promise<(type: string) => Promise<void>> {
  const base = await page.evaluate(() => {
    const w = window as unknown as { __pointerEvents?: Record<string, number> };
    if (!w.__pointerEvents) {
      const n: Record<string, number> = (w.__pointerEvents = { pointerdown: 0, pointermove: 0, pointerup: 0 });
      // Moves with a button down only: the hover move before a press may come or not.
      for (const type of Object.keys(n)) window.addEventListener(type, (e) => { if (type !== 'pointermove' || (e as PointerEvent).buttons) n[type]++; }, true);
    }
    return { ...w.__pointerEvents };
  });
  return async (type) => {
    const n = ++base[type];
    await page.waitForFunction(([type, n]) => (window as unknown as { __pointerEvents: Record<string, number> }).__pointerEvents[type as string] >= (n as number), [type, n] as const, { polling: 5 });
  };
}

/** Collects camera-change details on the element from now on, each with performance.now() when it came. */
export async function recordCameraChanges(page: Page, s: string): Promise<() => Promise<(CameraChange & { at: number })[]>> {
  await page.evaluate((s) => {
    const w = window as unknown as { __changes: unknown[] };
    w.__changes = [];
    document.querySelector(s)!.addEventListener('camera-change', (e) => w.__changes.push({ ...(e as CustomEvent).detail, at: performance.now() }));
  }, s);
  return () => page.evaluate(() => (window as unknown as { __changes: (CameraChange & { at: number })[] }).__changes);
}

/**
 * Where world point `p` is drawn for camera `pose` (perspective, vertical field of view `fov`
 * degrees) on an element `height` CSS px tall: CSS px right of and below its centre. The view is
 * lookAt along forwardFromYawPitch with +Y up, as docs/default-scene.md#the-camera defines yaw and pitch.
 */
export function screenOffset(pose: Pose, p: ArrayLike<number>, fov: number, height: number): { x: number; y: number } {
  const f = forwardFromYawPitch([0, 0, 0], pose.rotation[0], pose.rotation[1]);
  const h = Math.hypot(f[0], f[2]);
  const right = [-f[2] / h, 0, f[0] / h];
  const up = [right[1] * f[2] - right[2] * f[1], right[2] * f[0] - right[0] * f[2], right[0] * f[1] - right[1] * f[0]];
  const rel = [0, 1, 2].map((i) => p[i] - pose.position[i]);
  const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const depth = dot(rel, f);
  const pxPerUnit = height / 2 / Math.tan(fov / 2 / DEG) / depth;
  return { x: dot(rel, right) * pxPerUnit, y: -dot(rel, up) * pxPerUnit };
}
