// The `frame` and `ready` events' detail: one frozen report per frame, never changed afterwards,
// and not a structuredClone of the renderer's report (no deep copy per frame).
import { test, expect, mount, openPage, nextFrame, type SceneElement } from './fixtures';
import type { FrameReport } from '../../src/element/types';

const SIZE = { width: 160, height: 90 };

test('frame details are frozen, kept ones never change, and no frame calls structuredClone', async ({ page }) => {
  await page.addInitScript(() => {
    const w = window as unknown as { __clones: number };
    w.__clones = 0;
    const native = globalThis.structuredClone;
    globalThis.structuredClone = function (value: unknown, options?: StructuredSerializeOptions) {
      w.__clones++;
      return native(value, options);
    } as typeof structuredClone;
  });
  await openPage(page);
  const { selector } = await mount(page, { time: 1.25 }, SIZE);
  const result = await page.evaluate(async (selector) => {
    const el = document.querySelector(selector) as SceneElement;
    const w = window as unknown as { __clones: number };
    const kept: FrameReport[] = [];
    const atEvent: string[] = [];
    el.addEventListener('frame', (e) => {
      const d = (e as CustomEvent<FrameReport>).detail;
      kept.push(d);
      atEvent.push(JSON.stringify(d));
    });
    const clones0 = w.__clones;
    // Frames that differ in every field a report has: time, size, passes run and skipped.
    const changes: Array<(el: SceneElement) => void> = [
      (el) => el.setAttribute('time', '2'),
      (el) => el.setAttribute('camera-rotation', '90 0'), // glass behind the camera: reflection skipped
      (el) => el.setAttribute('debug-view', 'scene'),
      (el) => { el.removeAttribute('debug-view'); el.removeAttribute('camera-rotation'); el.style.width = '170px'; },
    ];
    for (const change of changes) {
      const n = kept.length;
      change(el);
      await new Promise<void>((resolve) => {
        const poll = () => (kept.length > n ? resolve() : requestAnimationFrame(poll));
        poll();
      });
    }
    return {
      clones: w.__clones - clones0,
      frozen: kept.map((d) => Object.isFrozen(d) && Object.isFrozen(d.passes) && Object.values(d.passes).every(Object.isFrozen)),
      distinct: new Set(kept).size,
      unchanged: kept.map((d, i) => JSON.stringify(d) === atEvent[i]),
      reflection: kept.map((d) => d.passes.reflection.ran),
      frames: kept.map((d) => d.frame),
    };
  }, selector);
  expect(result.clones, 'structuredClone calls while drawing frames').toBe(0);
  expect(result.frozen).toEqual([true, true, true, true]);
  expect(result.distinct, 'one detail object per frame').toBe(4);
  expect(result.unchanged, 'each kept detail, read after the later frames').toEqual([true, true, true, true]);
  expect(result.reflection).toEqual([true, false, false, true]);
  expect(new Set(result.frames).size).toBe(4);
});

test('the ready detail is the first frame\'s', async ({ page }) => {
  await openPage(page);
  const { selector, ready } = await mount(page, { time: 1.25 }, SIZE);
  expect(ready.frame).toBe(1);
  expect(ready.passes.reflection.ran).toBe(true);
  const next = await nextFrame(page, selector);
  expect(next.frame).toBe(2);
});
