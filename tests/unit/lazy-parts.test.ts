// The one mechanism for lazy parts (src/frame/lazy-parts.ts, ARCHITECTURE.md#lazy-parts): what a
// frame's one question starts and waits for, the failure policy, and no allocation when nothing
// is pending. The declarations themselves: render/parts.ts, element/parts.ts, and their chunks.
import fs from 'node:fs';
import { collections, instrumented } from './helpers/collections';
import { describe, expect, it } from 'vitest';
import { LazyParts, type LazyPartSpec, type PartListener } from '../../src/frame/lazy-parts';
import { CHUNKS } from '../../src/frame/chunks';
import { RENDER_PARTS, needsExtras } from '../../src/render/parts';
import { ELEMENT_PARTS } from '../../src/element/parts';
import { defaultScene } from '../../src/scene/default-scene';
import { defaultFrameState } from './helpers/frame-state';
import { chunkGroups } from '../../scripts/chunk-groups';

interface Host { wants: boolean; got: string[] }

function deferred<T>() {
  let resolve!: (v: T) => void, reject!: (e: unknown) => void;
  const promise = new Promise<T>((res, rej) => { resolve = res; reject = rej; });
  return { promise, resolve, reject };
}

function recorder(): PartListener & { warnings: string[]; settles: number } {
  const r = { warnings: [] as string[], settles: 0, warn: (m: string) => r.warnings.push(m), settled: () => { r.settles++; } };
  return r;
}

function part(name: string, holds: boolean, load: () => Promise<string>): LazyPartSpec<Host, string> {
  return {
    name, chunk: 'diagnostics', load, holds, instead: `drawn without ${name}`,
    needed: (h) => h.wants, arrived: (h, v) => h.got.push(v),
  };
}

describe('LazyParts', () => {
  it('starts nothing and answers null while no part is needed', () => {
    let fetches = 0;
    const host = { wants: false, got: [] };
    const parts = new LazyParts([part('a', true, () => { fetches++; return Promise.resolve('A'); })], host, recorder());
    expect(parts.request()).toBeNull();
    expect(fetches).toBe(0);
    expect(parts.loading).toBe(false);
  });

  it('a needed part that holds: one fetch, the same promise while it comes, handed over once, then null', async () => {
    let fetches = 0;
    const d = deferred<string>();
    const host = { wants: true, got: [] as string[] };
    const listener = recorder();
    const spec = part('a', true, () => { fetches++; return d.promise; });
    const parts = new LazyParts([spec], host, listener);
    const first = parts.request();
    expect(first).not.toBeNull();
    expect(parts.request()).toBe(first);
    expect(parts.loading).toBe(true);
    expect(parts.get(spec)).toBeNull();
    d.resolve('A');
    await first;
    expect(fetches).toBe(1);
    expect(host.got).toEqual(['A']);
    expect(parts.get(spec)).toBe('A');
    expect(parts.request()).toBeNull();
    expect(parts.loading).toBe(false);
    expect(listener.settles).toBe(1);
  });

  it('a part that does not hold starts loading, and the frame is drawn meanwhile', async () => {
    const d = deferred<string>();
    const host = { wants: true, got: [] as string[] };
    const spec = part('b', false, () => d.promise);
    const parts = new LazyParts([spec], host, recorder());
    expect(parts.request()).toBeNull();
    expect(parts.loading).toBe(true);
    d.resolve('B');
    await parts.fetch(spec);
    expect(host.got).toEqual(['B']);
  });

  it('waits for every held part at once, and a part started later makes a new promise', async () => {
    const da = deferred<string>(), db = deferred<string>();
    const host = { wants: true, got: [] as string[] };
    const a = part('a', true, () => da.promise);
    const b: LazyPartSpec<Host, string> = { ...part('b', true, () => db.promise), needed: (h) => h.got.length > 0 || h.wants };
    const parts = new LazyParts([a, b], host, recorder());
    const both = parts.request()!;
    let settled = false;
    void both.then(() => { settled = true; });
    da.resolve('A');
    await da.promise;
    await Promise.resolve();
    expect(settled).toBe(false); // b is still on its way
    db.resolve('B');
    await both;
    expect(host.got.sort()).toEqual(['A', 'B']);
  });

  it('a part that fails: one warning naming it and what is drawn instead, never asked for again', async () => {
    let fetches = 0;
    const host = { wants: true, got: [] as string[] };
    const listener = recorder();
    const spec = part('rough glass', true, () => { fetches++; return Promise.reject(new Error('offline')); });
    const parts = new LazyParts([spec], host, listener);
    const wait = parts.request()!;
    await expect(wait).resolves.toBeUndefined(); // never rejects
    expect(listener.warnings).toEqual(['rough glass could not load (Error: offline); drawn without rough glass']);
    expect(parts.request()).toBeNull();
    expect(parts.get(spec)).toBeNull();
    expect(await parts.fetch(spec)).toBeNull();
    expect(fetches).toBe(1);
    expect(listener.settles).toBe(1);
  });

  it('an owner that cannot take the module: the same policy as a failed fetch', async () => {
    const host = { wants: true, got: [] as string[] };
    const listener = recorder();
    const spec: LazyPartSpec<Host, string> = { ...part('c', true, () => Promise.resolve('C')), arrived: () => { throw new Error('bad'); } };
    const parts = new LazyParts([spec], host, listener);
    await parts.request();
    expect(listener.warnings).toHaveLength(1);
    expect(listener.warnings[0]).toContain('c could not load (Error: bad)');
    expect(parts.get(spec)).toBeNull();
  });

  it('a name read from the owner', async () => {
    const host = { wants: true, got: [] as string[] };
    const listener = recorder();
    const spec: LazyPartSpec<Host, string> = { ...part('x', true, () => Promise.reject(new Error('no'))), name: (h) => `wants=${h.wants}` };
    await new LazyParts([spec], host, listener).request();
    expect(listener.warnings[0]).toMatch(/^wants=true could not load/);
  });

  it('a module provided by another chunk: in at once, handed over, no fetch, and a fetch under way is not handed over twice', async () => {
    let fetches = 0;
    const host = { wants: true, got: [] as string[] };
    const spec = part('d', true, () => { fetches++; return Promise.resolve('fetched'); });
    const parts = new LazyParts([spec], host, recorder());
    parts.provide(spec, 'given');
    expect(parts.request()).toBeNull();
    expect(fetches).toBe(0);
    expect(host.got).toEqual(['given']);

    const late = new LazyParts([spec], { wants: true, got: [] as string[] }, recorder());
    const wait = late.request();
    late.provide(spec, 'given');
    await wait;
    expect(late.get(spec)).toBe('given');
    expect(fetches).toBe(1); // the fetch went on, and what it brought was left
  });
});

describe.skipIf(instrumented)('the frame\'s one question allocates nothing when nothing is pending', () => {
  const CALLS = 2_000_000;

  it('the check itself sees allocation: the same loop with 32 bytes a call collects', async () => {
    const sink: unknown[] = [null];
    expect(await collections(() => {
      for (let i = 0; i < CALLS; i++) sink[0] = { i, j: i };
    })).toBeGreaterThan(0);
  });

  it('the renderer\'s parts, none needed (the default scene, the default state)', async () => {
    const state = defaultFrameState(), scene = defaultScene(state.cubeDistance, state.spin);
    const host = { ctx: { state, scene } as never, checks: false, rough: null as never, counter: null as never };
    const parts = new LazyParts(RENDER_PARTS, host, recorder());
    let answers = 0;
    expect(await collections(() => {
      for (let i = 0; i < CALLS; i++) if (parts.request() !== null) answers++;
    })).toBe(0);
    expect(answers).toBe(0);
  });

  it('the element\'s parts, none needed (no controls, no turn, no children, no images, no camera-src, no environment URL)', async () => {
    const host = {
      values: { controls: null, cameraSrc: null, environment: 'neutral' },
      scenes: { turnSet: () => false },
      source: { hasChild: () => false, hasUndefinedChild: () => false },
      namesImages: () => false,
    } as never;
    const parts = new LazyParts(ELEMENT_PARTS, host, recorder());
    expect(await collections(() => {
      for (let i = 0; i < CALLS; i++) parts.request();
    })).toBe(0);
  });
});

describe('the declarations', () => {
  const all = [...RENDER_PARTS, ...ELEMENT_PARTS];

  it('every part names a chunk of the table, and every grouped chunk\'s files exist', () => {
    for (const p of all) expect(Object.keys(CHUNKS)).toContain(p.chunk);
    for (const [name, c] of Object.entries(CHUNKS)) {
      for (const m of 'modules' in c ? c.modules : []) {
        // A virtual module (virtual/…) is a build plugin's: the plugin under scripts/ must name it.
        if (m.startsWith('virtual/')) expect(fs.readdirSync('scripts').filter((f) => /\.(ts|mjs)$/.test(f)).some((f) => fs.readFileSync(`scripts/${f}`, 'utf8').includes(`/${m}`)), `${name}: ${m}`).toBe(true);
        else expect(fs.existsSync(m), `${name}: ${m}`).toBe(true);
      }
    }
  });

  it('each part says what is drawn without it', () => {
    for (const p of all) expect(p.instead.length).toBeGreaterThan(10);
  });

  it('the mesh extras are needed for flat shading, a Gaussian, or a mesh at tessellation auto; not for the default scene', () => {
    const s = defaultFrameState(), scene = defaultScene(s.cubeDistance, s.spin);
    expect(needsExtras(s, scene)).toBe(false);
    expect(needsExtras({ ...s, shading: 'flat' }, scene)).toBe(true);
    const gaussian = { ...scene, objects: [{ ...scene.objects[0], geometry: { kind: 'gaussian' } }] } as never;
    expect(needsExtras(s, gaussian)).toBe(true);
    const mesh = { ...scene, objects: [{ ...scene.objects[0], geometry: { kind: 'mesh' } }] } as never;
    expect(needsExtras(s, mesh)).toBe(true);
    expect(needsExtras({ ...s, tessellation: 64 }, mesh)).toBe(false);
  });
});

describe('the chunk groups vite.config.ts makes from the table', () => {
  const groups = chunkGroups();
  const grouped = Object.entries(CHUNKS).flatMap(([name, c]) => ('modules' in c ? c.modules.map((m) => [name, m] as const) : []));

  it('one group for each chunk that lists files, in the table\'s order', () => {
    expect(groups.map((g) => g.name)).toEqual(Object.entries(CHUNKS).filter(([, c]) => 'modules' in c).map(([n]) => n));
  });

  it('each listed file, by its absolute id with either separator, falls in its own group only', () => {
    for (const [name, m] of grouped) {
      for (const id of [`/work/repo/${m}`, `C:\\repo\\${m.replaceAll('/', '\\')}`]) {
        expect(groups.filter((g) => g.test.test(id)).map((g) => g.name), id).toEqual([name]);
      }
    }
  });

  it('no other file: a neighbour, a longer name, another extension, a core file', () => {
    for (const id of ['/r/src/element/xcamera-source.ts', '/r/xsrc/element/camera-source.ts', '/r/lib-src/frame/chunks-src/math/ggx.ts', '/r/src/element/camera-source.tsx', '/r/src/element/camera-sourcets',
      '/r/src/render/renderer.ts', '/r/src/element/children/child-elements.ts']) {
      expect(groups.filter((g) => g.test.test(id)), id).toEqual([]);
    }
  });
});

describe('LazyParts, edges', () => {
  it('fetch() starts a part no frame needs (a failure\'s texts), once', async () => {
    let fetches = 0;
    const host = { wants: false, got: [] as string[] };
    const spec = part('texts', false, () => { fetches++; return Promise.resolve('T'); });
    const parts = new LazyParts([spec], host, recorder());
    const [a, b] = await Promise.all([parts.fetch(spec), parts.fetch(spec)]);
    expect([a, b, fetches]).toEqual(['T', 'T', 1]);
    expect(await parts.fetch(spec)).toBe('T');
  });

  it('a part no longer needed while it loads does not hold the frame', () => {
    const host = { wants: true, got: [] as string[] };
    const parts = new LazyParts([part('e', true, () => new Promise<string>(() => {}))], host, recorder());
    expect(parts.request()).not.toBeNull();
    host.wants = false;
    expect(parts.request()).toBeNull();
    expect(parts.loading).toBe(true);
  });

  it('a declaration of another owner is refused', () => {
    const parts = new LazyParts([part('f', true, () => Promise.resolve('F'))], { wants: false, got: [] }, recorder());
    expect(() => parts.get(part('g', true, () => Promise.resolve('G')))).toThrow(/not a part/);
  });
});

describe('LazyParts: the edges of the question', () => {
  it('a part needed later gets a new promise that waits for it too, not the one already answered', async () => {
    const a = deferred<string>(), b = deferred<string>();
    const host = { wants: true, got: [] as string[] };
    const wantsB = { on: false };
    const specA = part('a', true, () => a.promise);
    const specB: LazyPartSpec<Host, string> = { ...part('b', true, () => b.promise), needed: () => wantsB.on };
    const parts = new LazyParts([specA, specB], host, recorder());
    const first = parts.request();
    wantsB.on = true;
    const second = parts.request();
    expect(second).not.toBe(first);
    expect(parts.request()).toBe(second);
    let done = false;
    void second!.then(() => { done = true; });
    a.resolve('A');
    await first;
    await Promise.resolve();
    expect(done).toBe(false); // b is still on its way
    b.resolve('B');
    await second;
    expect(host.got).toEqual(['A', 'B']);
  });

  it('waits only for parts that hold the frame: another part on its way does not delay the answer', async () => {
    const held = deferred<string>(), free = deferred<string>();
    const host = { wants: true, got: [] as string[] };
    const parts = new LazyParts([part('free', false, () => free.promise), part('held', true, () => held.promise)], host, recorder());
    const p = parts.request()!;
    held.resolve('H');
    await p; // settles though `free` never does
    expect(host.got).toEqual(['H']);
    expect(parts.loading).toBe(true);
  });

  it('a part without `arrived` loads, and is provided, without complaint', async () => {
    const listener = recorder();
    const host = { wants: true, got: [] as string[] };
    const plain = (name: string): LazyPartSpec<Host, string> => {
      const { arrived: _, ...rest } = part(name, true, () => Promise.resolve(name.toUpperCase()));
      return rest;
    };
    const a = plain('a'), b = plain('b');
    const parts = new LazyParts([a, b], host, listener);
    await parts.fetch(a);
    expect(parts.get(a)).toBe('A');
    parts.provide(b, 'given');
    expect(parts.get(b)).toBe('given');
    expect(listener.warnings).toEqual([]);
  });

  it('provided twice: the first value stays and is handed over once', () => {
    const host = { wants: false, got: [] as string[] };
    const spec = part('a', true, () => Promise.resolve('fetched'));
    const parts = new LazyParts([spec], host, recorder());
    parts.provide(spec, 'one');
    parts.provide(spec, 'two');
    expect(parts.get(spec)).toBe('one');
    expect(host.got).toEqual(['one']);
  });

  it('a failure\'s warning quotes at most 200 characters of the error', async () => {
    const listener = recorder();
    const host = { wants: true, got: [] as string[] };
    const long = 'x'.repeat(300);
    const parts = new LazyParts([part('a', true, () => Promise.reject(new Error(long)))], host, listener);
    await parts.request();
    expect(listener.warnings).toEqual([`a could not load (${`Error: ${long}`.slice(0, 200)}); drawn without a`]);
  });
});
