// Faults and lifecycle (docs/element.md#failure-behaviour). Adding and removing an element many times leaves no
// GL resource, listener, observer or animation-frame loop behind; an element moved in the DOM
// carries on; a lost (shared) WebGL context stops every element, and after the restore each one
// draws the same frame as before the loss.
import { test, expect, mount, openPage, capture, type SceneElement } from './fixtures';
import type { Page } from '@playwright/test';
import { compareImages } from './helpers/golden';
import { mountHtml } from './helpers/scene-children';
import type { FrameReport, GlassPlaneSceneErrorDetail } from '../../src/element/types';

const SIZE = { width: 160, height: 90 };

interface LeakReport {
  /** Net listeners on window, document and MediaQueryList objects, one line per target/type/phase. */
  listeners: string[];
  /** Net observed targets per observer kind (observe − unobserve − disconnected). */
  observations: Record<string, number>;
  /** requestAnimationFrame calls so far. */
  rafCalls: number;
}

/**
 * Init script (runs before any page script, so before the element's module): counts, without
 * changing behaviour, every listener registration on window, document and MediaQueryList objects
 * (with addEventListener's own dedup rules, `once` and `signal`), every target observed by a
 * ResizeObserver, IntersectionObserver or MutationObserver, and requestAnimationFrame calls.
 * Self-contained: it is serialized into the page.
 */
function installLeakProbes(): void {
  type Key = string; // "type|capture"
  const live = new Map<EventTarget, Map<Key, Set<unknown>>>();
  const names = new Map<EventTarget, string>();
  const watched = (t: unknown): t is EventTarget =>
    t === window || t === document || (typeof MediaQueryList !== 'undefined' && t instanceof MediaQueryList);
  const nameOf = (t: EventTarget): string => {
    if (t === window) return 'window';
    if (t === document) return 'document';
    let n = names.get(t);
    if (!n) names.set(t, (n = `MediaQueryList(${(t as MediaQueryList).media})#${names.size}`));
    return n;
  };
  const captureOf = (o: unknown): boolean => (typeof o === 'boolean' ? o : !!(o && (o as AddEventListenerOptions).capture));
  const nativeAdd = EventTarget.prototype.addEventListener;
  const nativeRemove = EventTarget.prototype.removeEventListener;
  const forget = (t: EventTarget, key: Key, l: unknown) => live.get(t)?.get(key)?.delete(l);
  const remember = (t: EventTarget, type: string, l: unknown, options: unknown) => {
    if (!l) return;
    const key = `${type}|${captureOf(options)}`;
    let byKey = live.get(t);
    if (!byKey) live.set(t, (byKey = new Map()));
    let set = byKey.get(key);
    if (!set) byKey.set(key, (set = new Set()));
    if (set.has(l)) return; // a duplicate registration is a no-op
    const o = typeof options === 'object' && options ? (options as AddEventListenerOptions) : {};
    if (o.signal?.aborted) return;
    set.add(l);
    // `once`: the browser drops the listener when it first fires; a companion once-listener of the
    // same type and phase fires at the same dispatch and forgets it.
    if (o.once) nativeAdd.call(t, type, () => forget(t, key, l), { once: true, capture: captureOf(options) });
    if (o.signal) nativeAdd.call(o.signal, 'abort', () => forget(t, key, l), { once: true });
  };
  EventTarget.prototype.addEventListener = function (this: EventTarget, type: string, l: EventListenerOrEventListenerObject | null, options?: boolean | AddEventListenerOptions) {
    if (watched(this)) remember(this, type, l, options);
    return nativeAdd.call(this, type, l, options);
  };
  EventTarget.prototype.removeEventListener = function (this: EventTarget, type: string, l: EventListenerOrEventListenerObject | null, options?: boolean | EventListenerOptions) {
    if (watched(this)) forget(this, `${type}|${captureOf(options)}`, l);
    return nativeRemove.call(this, type, l, options);
  };
  if (typeof MediaQueryList !== 'undefined') {
    // The legacy addListener/removeListener do not go through addEventListener.
    const proto = MediaQueryList.prototype as MediaQueryList & { addListener: (l: unknown) => void; removeListener: (l: unknown) => void };
    const add = proto.addListener;
    const remove = proto.removeListener;
    proto.addListener = function (this: MediaQueryList, l: unknown) {
      remember(this, 'change', l, false);
      return add.call(this, l);
    };
    proto.removeListener = function (this: MediaQueryList, l: unknown) {
      forget(this, 'change|false', l);
      return remove.call(this, l);
    };
  }

  const observations: Record<string, number> = {};
  for (const kind of ['ResizeObserver', 'IntersectionObserver', 'MutationObserver'] as const) {
    const Native = (window as unknown as Record<string, unknown>)[kind] as
      | (new (...a: unknown[]) => { observe(t: unknown, o?: unknown): void; unobserve?(t: unknown): void; disconnect(): void })
      | undefined;
    if (!Native) continue;
    const targets = new WeakMap<object, Set<unknown>>();
    const all = new Set<Set<unknown>>();
    const count = () => {
      let n = 0;
      for (const set of all) n += set.size;
      observations[kind] = n;
    };
    const Probe = class extends Native {
      constructor(...args: unknown[]) {
        super(...args);
        const set = new Set<unknown>();
        targets.set(this, set);
        all.add(set);
      }
      observe(t: unknown, o?: unknown) {
        targets.get(this)!.add(t);
        count();
        return super.observe(t, o);
      }
      unobserve(t: unknown) {
        targets.get(this)!.delete(t);
        count();
        return super.unobserve!(t);
      }
      disconnect() {
        targets.get(this)!.clear();
        count();
        return super.disconnect();
      }
    };
    if (kind === 'MutationObserver') delete (Probe.prototype as { unobserve?: unknown }).unobserve;
    Object.defineProperty(Probe, 'name', { value: kind });
    (window as unknown as Record<string, unknown>)[kind] = Probe;
    observations[kind] = 0;
  }

  let rafCalls = 0;
  const nativeRaf = window.requestAnimationFrame;
  window.requestAnimationFrame = function (cb: FrameRequestCallback) {
    rafCalls++;
    return nativeRaf.call(window, cb);
  };

  (window as unknown as { __leaks: () => LeakReport }).__leaks = () => {
    const listeners: string[] = [];
    for (const [t, byKey] of live) {
      for (const [key, set] of byKey) if (set.size) listeners.push(`${nameOf(t)} ${key} ×${set.size}`);
    }
    return { listeners: listeners.sort(), observations: { ...observations }, rafCalls };
  };
}

const leaks = (page: Page) => page.evaluate(() => (window as unknown as { __leaks: () => LeakReport }).__leaks());

test.describe('adding and removing', () => {
  test('100 add/remove cycles: resources back to zero each time; no listener, observer or frame loop left', async ({ page }) => {
    test.setTimeout(120_000);
    await page.addInitScript(installLeakProbes);
    await openPage(page);
    const baseline = await leaks(page);

    const result = await page.evaluate(async (size) => {
      const problems: string[] = [];
      const live: number[] = [];
      let errors = 0;
      for (let i = 0; i < 100; i++) {
        const el = document.createElement('glass-plane-scene') as SceneElement;
        el.style.width = `${size.width}px`;
        el.style.height = `${size.height}px`;
        el.setAttribute('time', String(1 + i / 100));
        el.addEventListener('error', () => errors++);
        // Most cycles draw first; some are removed before the first frame, or one frame in.
        const mode = i % 10 === 7 ? 'at once' : i % 10 === 8 ? 'next animation frame' : 'after ready';
        const ready = new Promise<boolean>((resolve) => {
          const t = setTimeout(() => resolve(false), 15_000);
          el.addEventListener('ready', () => { clearTimeout(t); resolve(true); }, { once: true });
        });
        document.body.append(el);
        if (mode === 'after ready') {
          if (!(await ready)) problems.push(`cycle ${i}: no ready within 15 s`);
          live.push(el.stats.resources.total);
        } else if (mode === 'next animation frame') {
          await new Promise((r) => requestAnimationFrame(r));
        }
        el.remove();
        const after = el.stats.resources;
        if (after.total !== 0) problems.push(`cycle ${i} (${mode}): resources after removal ${JSON.stringify(after)}`);
      }
      // Anything still scheduled would show up here.
      await new Promise((r) => setTimeout(r, 300));
      return { problems, live, errors };
    }, SIZE);

    expect(result.problems).toEqual([]);
    expect(result.errors, 'error events').toBe(0);
    expect(Math.min(...result.live), 'live GL resources while on the page').toBeGreaterThan(0);

    const before = await leaks(page);
    await page.waitForTimeout(500);
    const after = await leaks(page);
    expect(after.listeners, 'listeners on window, document and MediaQueryList: same as before the first element').toEqual(baseline.listeners);
    expect(after.observations, 'observed targets: same as before the first element').toEqual(baseline.observations);
    expect(after.rafCalls - before.rafCalls, 'requestAnimationFrame calls in 500 ms with no element on the page').toBe(0);
  });

  test('the probes see what a mounted element observes, and a leaked listener (the leak test is not vacuous)', async ({ page }) => {
    await page.addInitScript(installLeakProbes);
    await openPage(page);
    const baseline = await leaks(page);
    const { selector } = await mount(page, { time: 1.25 }, SIZE);
    const during = await leaks(page);
    // Connected, an element observes at least its own size (ResizeObserver) and visibility.
    const observed = Object.values(during.observations).reduce((a, b) => a + b, 0);
    expect(observed, `observations while mounted: ${JSON.stringify(during.observations)}`).toBeGreaterThan(
      Object.values(baseline.observations).reduce((a, b) => a + b, 0),
    );
    // A deliberate leak is counted.
    await page.evaluate(() => window.addEventListener('resize', () => {}));
    expect((await leaks(page)).listeners).toContain('window resize|false ×1');
    await page.evaluate((s) => document.querySelector(s)!.remove(), selector);
  });

  test('an element moved in the DOM draws the same frame again', async ({ page }) => {
    await openPage(page);
    const { selector } = await mount(page, { time: 1.25 }, SIZE);
    const before = await capture(page, undefined, selector);
    for (let i = 0; i < 5; i++) {
      const report = await page.evaluate(
        (s) =>
          new Promise<FrameReport>((resolve, reject) => {
            const el = document.querySelector(s) as SceneElement;
            const t = setTimeout(() => reject(new Error('no frame after re-inserting the element')), 15_000);
            el.addEventListener('frame', (e) => { clearTimeout(t); resolve((e as CustomEvent<FrameReport>).detail); }, { once: true });
            const holder = document.createElement('div');
            document.body.append(holder);
            el.remove();
            holder.append(el); // disconnected then connected again, in one task
          }),
        selector,
      );
      expect([report.width, report.height]).toEqual([SIZE.width, SIZE.height]);
      expect(await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.resources.total, selector)).toBeGreaterThan(0);
    }
    const after = await capture(page, undefined, selector);
    expect(compareImages(after, before).differing, 'same frame after five moves').toBe(0);
  });
});

test.describe('context loss', () => {
  test('losing the shared context stops every element; after the restore each draws the frame it drew before', async ({ page, consoleLog }) => {
    await openPage(page);
    const a = (await mount(page, { time: 1.25 }, SIZE)).selector;
    const b = (await mount(page, { time: 2, transparency: 0.8, 'cube-distance': 1.5 }, SIZE)).selector;
    const beforeA = await capture(page, undefined, a);
    const beforeB = await capture(page, undefined, b);
    const resources = async () => [
      await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.resources, a),
      await page.evaluate((s) => (document.querySelector(s) as SceneElement).stats.resources, b),
    ];
    const resourcesBefore = await resources();

    const lost = await page.evaluate(
      ([a, b]) =>
        new Promise<GlassPlaneSceneErrorDetail[]>((resolve, reject) => {
          const gl = (globalThis as { __GLASS_PLANE_SCENE_GL__?: WebGL2RenderingContext }).__GLASS_PLANE_SCENE_GL__;
          if (!(gl instanceof WebGL2RenderingContext)) return reject(new Error('globalThis.__GLASS_PLANE_SCENE_GL__ is not a WebGL2RenderingContext'));
          const ext = gl.getExtension('WEBGL_lose_context');
          if (!ext) return reject(new Error('WEBGL_lose_context unavailable'));
          (window as unknown as { __loseContext: WEBGL_lose_context }).__loseContext = ext;
          const w = window as unknown as { __frames: number };
          w.__frames = 0;
          const details: GlassPlaneSceneErrorDetail[] = [];
          const t = setTimeout(() => reject(new Error(`error events: ${JSON.stringify(details)}`)), 10_000);
          for (const s of [a, b]) {
            const el = document.querySelector(s)!;
            el.addEventListener('frame', () => w.__frames++);
            el.addEventListener('error', (e) => {
              details.push((e as unknown as CustomEvent<GlassPlaneSceneErrorDetail>).detail);
              if (details.length === 2) { clearTimeout(t); resolve(details); }
            }, { once: true });
          }
          ext.loseContext();
        }),
      [a, b],
    );
    expect(lost.map((d) => d.type)).toEqual(['context-lost', 'context-lost']);

    // Drawing stops: neither a requested frame nor attribute changes draw while the context is lost.
    const frames = await page.evaluate(async ([a, b]) => {
      const ea = document.querySelector(a) as SceneElement;
      const eb = document.querySelector(b) as SceneElement;
      const f = [ea.stats.frames, eb.stats.frames];
      ea.requestRender();
      ea.setAttribute('transparency', '0.9');
      ea.setAttribute('transparency', '0.5'); // back to the value of the frame before the loss
      eb.requestRender();
      await new Promise((r) => setTimeout(r, 500));
      return { before: f, after: [ea.stats.frames, eb.stats.frames], events: (window as unknown as { __frames: number }).__frames };
    }, [a, b]);
    expect(frames.after, 'stats.frames while the context is lost').toEqual(frames.before);
    expect(frames.events, 'frame events while the context is lost').toBe(0);

    // Restore: both rebuild and draw.
    await page.evaluate(
      ([a, b]) =>
        new Promise<void>((resolve, reject) => {
          const t = setTimeout(() => reject(new Error('no frame from both elements after the restore')), 15_000);
          let pending = 2;
          for (const s of [a, b]) {
            document.querySelector(s)!.addEventListener('frame', () => {
              if (--pending === 0) { clearTimeout(t); resolve(); }
            }, { once: true });
          }
          (window as unknown as { __loseContext: WEBGL_lose_context }).__loseContext.restoreContext();
        }),
      [a, b],
    );
    // docs/element.md#failure-behaviour asks for the error event only; a console error about the loss is allowed (at most
    // one per element, with the prefix).
    const logged = consoleLog.take('error');
    expect(logged.length).toBeLessThanOrEqual(2);
    for (const line of logged) expect(line).toMatch(/^glass-plane-scene:/);

    expect(compareImages(await capture(page, undefined, a), beforeA).differing, `${a}: same frame after the restore`).toBe(0);
    expect(compareImages(await capture(page, undefined, b), beforeB).differing, `${b}: same frame after the restore`).toBe(0);
    expect(await resources(), 'live GL resources rebuilt to the same counts').toEqual(resourcesBefore);
  });

  test('an image texture survives the loss: after the restore a textured object draws the pixels it drew before', async ({ page }) => {
    await openPage(page);
    const cube = (texture: string) => `<glass-plane-scene refine="0" time="0" spin="0" glass-size="0 0" camera-position="0 0 2.5" camera-rotation="-90 0"
      style="width: 160px; height: 90px"><glass-object shape="cube" ${texture}></glass-object></glass-plane-scene>`;
    await mountHtml(page, cube(''));
    const procedural = await capture(page);
    await page.evaluate(() => document.querySelector('glass-plane-scene')!.remove());
    await mountHtml(page, cube('texture="/tests/e2e/pages/models/checker.png"'));
    // The image decodes after the first frame; its arrival draws once more.
    // 1,226 px differ once it is (texture-images.spec.ts).
    await expect.poll(async () => compareImages(procedural, await capture(page)).differing, { message: 'the image texture is drawn' }).toBeGreaterThanOrEqual(0.9 * 1226);
    const before = await capture(page);

    await page.evaluate(() => new Promise<void>((resolve, reject) => {
      const gl = (globalThis as { __GLASS_PLANE_SCENE_GL__?: WebGL2RenderingContext }).__GLASS_PLANE_SCENE_GL__;
      const ext = gl?.getExtension('WEBGL_lose_context');
      if (!ext) return reject(new Error('WEBGL_lose_context unavailable'));
      const el = document.querySelector('glass-plane-scene')!;
      const t = setTimeout(() => reject(new Error('no frame after the restore')), 15_000);
      el.addEventListener('error', () => {
        el.addEventListener('frame', () => { clearTimeout(t); resolve(); }, { once: true });
        setTimeout(() => ext.restoreContext(), 100); // not from within the loss's own dispatch
      }, { once: true });
      ext.loseContext();
    }));
    const after = await capture(page);
    // Not the procedural texture again: the decoded image was handed to the new renderer.
    expect(compareImages(after, before).differing, 'pixels changed by the loss and restore').toBe(0);
  });
});

test('an element switched from WebGL to the software renderer draws on when the shared context is lost, at the CPU\'s size limit', async ({ page, consoleLog }) => {
  await openPage(page);
  const webgl = (await mount(page, { time: 0, spin: 0 }, SIZE)).selector;
  // 5000 px wide: within WebGL's limit here, past the CPU renderer's 4096.
  const wide = (await mount(page, { renderer: 'webgl', time: 0, spin: 0 }, { width: 5000, height: 8 })).selector;
  const switched = await page.evaluate((s) => new Promise<{ renderer: string | null | undefined; width: number }>((resolve, reject) => {
    const el = document.querySelector(s) as SceneElement;
    const t = setTimeout(() => reject(new Error('no software frame')), 15_000);
    const drawn = () => {
      if (el.stats.renderer !== 'software') return;
      el.removeEventListener('frame', drawn);
      clearTimeout(t);
      resolve({ renderer: el.stats.renderer, width: el.shadowRoot!.querySelector('canvas')!.width });
    };
    el.addEventListener('frame', drawn);
    el.setAttribute('renderer', 'software');
  }), wide);
  expect(switched.renderer).toBe('software');
  expect(switched.width, 'the CPU renderer\'s canvas limit').toBeLessThanOrEqual(4096);

  const after = await page.evaluate(([webgl, wide]) => new Promise<{ errors: string[]; frames: number }>((resolve, reject) => {
    const gl = (globalThis as { __GLASS_PLANE_SCENE_GL__?: WebGL2RenderingContext }).__GLASS_PLANE_SCENE_GL__!;
    const ext = gl.getExtension('WEBGL_lose_context');
    if (!ext) return reject(new Error('WEBGL_lose_context unavailable'));
    const errors: string[] = [];
    let frames = 0;
    document.querySelector(webgl)!.addEventListener('error', (e) => errors.push(`${webgl}: ${(e as unknown as CustomEvent<{ type: string }>).detail.type}`));
    const el = document.querySelector(wide) as SceneElement;
    el.addEventListener('error', (e) => errors.push(`${wide}: ${(e as unknown as CustomEvent<{ type: string }>).detail.type}`));
    el.addEventListener('frame', () => frames++);
    ext.loseContext();
    // After the loss: the software element draws what is asked of it.
    setTimeout(() => {
      el.setAttribute('time', '1');
      const t = setTimeout(() => resolve({ errors, frames }), 10_000);
      el.addEventListener('frame', () => { clearTimeout(t); resolve({ errors, frames }); }, { once: true });
    }, 300);
  }), [webgl, wide]);
  expect(after.errors, 'only the WebGL element loses its context').toEqual([`${webgl}: context-lost`]);
  expect(after.frames, 'the software element drew after the loss').toBeGreaterThan(0);
  consoleLog.take('error');
});
