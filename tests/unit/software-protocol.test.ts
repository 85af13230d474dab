// What crosses to the software renderer's worker (docs/software-renderer.md#worker): each mesh's
// arrays and each image's pixels once, the scene only when it is a new value; and the worker's
// side, which puts the arrays back and draws the band it is asked for.
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { defaultScene } from '../../src/scene/default-scene';
import { boxMesh } from '../../src/scene/geometry/box';
import type { MeshData } from '../../src/scene/geometry/mesh-data';
import type { DecodedImage } from '../../src/scene/decoded-image';
import type { Scene } from '../../src/scene/scene';
import { SentResources, unpackScene, type SoftwareRequest, type SoftwareResponse } from '../../src/software/protocol';
import { renderBand } from '../../src/software/bands';
import { SoftwareRenderer } from '../../src/software';
import { defaultFrameState } from './helpers/frame-state';
import { BOX_STATE, mirrorToKey } from './helpers/pbr-scenes';

/** The default scene with its first object made a mesh of `data` under `key`. */
function meshScene(key: string, data: MeshData): Scene {
  const scene = defaultScene(0.75, 0.8);
  return { ...scene, objects: scene.objects.map((o, i) => (i === 0 ? { ...o, geometry: { kind: 'mesh' as const, key, data } } : o)) };
}

const image = (n: number): DecodedImage => ({ width: 1, height: 1, data: new Uint8Array([n, n, n, 255]) });

describe('SentResources: each mesh and image crosses once', () => {
  it('a new scene goes with its meshes, their arrays stripped from the scene (null data)', () => {
    const data = boxMesh(1);
    const scene = meshScene('box', data);
    const sent = new SentResources().pack(scene, new Map());
    expect(sent.meshes).toEqual([['box', data]]);
    expect(sent.meshes[0][1]).toBe(data);
    expect(sent.scene).not.toBe(scene);
    const g = sent.scene!.objects[0].geometry;
    expect(g).toEqual({ kind: 'mesh', key: 'box', data: null });
    // Only the mesh object is rewritten; the others are the scene's own values.
    expect(sent.scene!.objects.slice(1)).toEqual(scene.objects.slice(1));
    expect(sent.scene!.objects[1]).toBe(scene.objects[1]);
    expect(sent.scene!.glass).toBe(scene.glass);
    // The caller's scene keeps its arrays.
    expect(scene.objects[0].geometry).toEqual({ kind: 'mesh', key: 'box', data });
  });

  it('the same scene value again: no scene, no meshes', () => {
    const scene = meshScene('box', boxMesh(1));
    const resources = new SentResources();
    resources.pack(scene, new Map());
    expect(resources.pack(scene, new Map())).toEqual({ scene: null, meshes: [], images: [] });
  });

  it('a new scene value with a mesh already held: the scene, stripped, without the mesh', () => {
    const data = boxMesh(1);
    const resources = new SentResources();
    resources.pack(meshScene('box', data), new Map());
    const again = resources.pack(meshScene('box', data), new Map());
    expect(again.meshes).toEqual([]);
    expect(again.scene!.objects[0].geometry).toEqual({ kind: 'mesh', key: 'box', data: null });
  });

  it('a key whose arrays changed crosses again', () => {
    const resources = new SentResources();
    resources.pack(meshScene('box', boxMesh(1)), new Map());
    const bigger = boxMesh(2);
    expect(resources.pack(meshScene('box', bigger), new Map()).meshes).toEqual([['box', bigger]]);
  });

  it('a scene without meshes goes as it is (the same value)', () => {
    const scene = defaultScene(0.75, 0.8);
    const sent = new SentResources().pack(scene, new Map());
    expect(sent.scene).toBe(scene);
    expect(sent.meshes).toEqual([]);
  });

  it('images: each URL once, whether or not the scene is new', () => {
    const scene = defaultScene(0.75, 0.8);
    const resources = new SentResources();
    const a = image(10), b = image(20);
    expect(resources.pack(scene, new Map([['a.png', a]])).images).toEqual([['a.png', a]]);
    expect(resources.pack(scene, new Map([['a.png', a], ['b.png', b]])).images).toEqual([['b.png', b]]);
    expect(resources.pack(defaultScene(0.5, 0.8), new Map([['a.png', a], ['b.png', b]])).images).toEqual([]);
  });
});

describe('unpackScene: the worker puts the arrays back', () => {
  it('from its store, by key; an object whose key it lacks stays as it came', () => {
    const data = boxMesh(1);
    const stripped = new SentResources().pack(meshScene('box', data), new Map()).scene!;
    const back = unpackScene(stripped, new Map([['box', data]]));
    expect(back.objects[0].geometry).toEqual({ kind: 'mesh', key: 'box', data });
    expect((back.objects[0].geometry as { data: MeshData }).data).toBe(data);
    expect(back.objects[1]).toBe(stripped.objects[1]);
    const missing = unpackScene(stripped, new Map());
    expect(missing.objects[0]).toBe(stripped.objects[0]);
  });

  it('a mesh that arrived with its arrays is left alone; a scene without meshes is the same value', () => {
    const data = boxMesh(1), other = boxMesh(3);
    const whole = meshScene('box', data);
    expect(unpackScene(whole, new Map([['box', other]])).objects[0]).toBe(whole.objects[0]);
    const plain = defaultScene(0.75, 0.8);
    expect(unpackScene(plain, new Map())).toBe(plain);
  });
});

describe('the worker (src/software/worker.ts) under a stand-in worker scope', () => {
  const posted: { message: SoftwareResponse; transfer?: Transferable[] }[] = [];
  let onmessage: (e: { data: SoftwareRequest }) => void;
  const hadSelf = 'self' in globalThis;
  const oldSelf = (globalThis as { self?: unknown }).self;

  beforeAll(async () => {
    const scope = { postMessage: (message: SoftwareResponse, transfer?: Transferable[]) => posted.push({ message, transfer }), onmessage: null };
    (globalThis as { self?: unknown }).self = scope;
    vi.resetModules();
    await import('../../src/software/worker');
    onmessage = scope.onmessage as unknown as typeof onmessage;
  });
  afterAll(() => {
    if (hadSelf) (globalThis as { self?: unknown }).self = oldSelf;
    else delete (globalThis as { self?: unknown }).self;
  });

  const state = defaultFrameState({ width: 40, height: 24, time: 0.5 });
  const request = (over: Partial<SoftwareRequest>): SoftwareRequest => ({
    id: 1, state, scene: null, meshes: [], images: [], samplesPerAxis: 1, band: null, ...over,
  });

  it('a request before any scene: an error response naming why, with its id', () => {
    onmessage({ data: request({ id: 7 }) });
    expect(posted.pop()).toEqual({ message: { id: 7, error: 'no scene sent yet' }, transfer: undefined });
  });

  it('draws the band asked for, as a renderer of its own would, and transfers the pixels', () => {
    const data = boxMesh(1);
    const scene = meshScene('box', data);
    const sent = new SentResources().pack(scene, new Map());
    const band = { top: 6, bottom: 15 };
    const before = performance.now();
    onmessage({ data: request({ id: 8, ...sent, band, samplesPerAxis: 2 }) });
    const took = performance.now() - before;
    const { message, transfer } = posted.pop()!;
    const expected = new SoftwareRenderer();
    expected.samplesPerAxis = 2;
    const want = renderBand(expected, scene, state, new Map(), band);
    expect(message).toMatchObject({ id: 8, width: 40, height: 24 });
    const ok = message as Extract<SoftwareResponse, { pixels: Uint8ClampedArray }>;
    expect(ok.pixels.length).toBe(4 * 40 * 9);
    expect(Buffer.from(ok.pixels).equals(Buffer.from(want))).toBe(true);
    expect(ok.ms).toBeGreaterThanOrEqual(0);
    expect(ok.ms).toBeLessThanOrEqual(took);
    expect(transfer).toEqual([ok.pixels.buffer]);

    // No scene this time: the one it holds, its mesh from the store; the whole frame.
    onmessage({ data: request({ id: 9, samplesPerAxis: 1 }) });
    const again = posted.pop()!.message as typeof ok;
    const whole = new SoftwareRenderer();
    expect(again.id).toBe(9);
    expect(Buffer.from(again.pixels).equals(Buffer.from(renderBand(whole, scene, state, new Map(), null)))).toBe(true);
  });

  it('a failure while drawing is an error response, not a thrown exception', () => {
    onmessage({ data: request({ id: 10, state: { ...state, width: Number.NaN, get height(): number { throw new Error('bad height'); } } }) });
    expect(posted.pop()!.message).toEqual({ id: 10, error: 'bad height' });
    // What a worker may meet: a thrown value that is not an Error.
    onmessage({ data: request({ id: 11, state: { ...state, get height(): number { throw 'plain words'; } } }) });
    expect(posted.pop()!.message).toEqual({ id: 11, error: 'plain words' });
  });

  it('a glTF material under an environment: the worker makes the maps first, and the requests after it wait their turn', async () => {
    // The mirror metal reflecting the key panel (environment-light.test.ts): 153 at the centre with the studio, 0 without.
    const sent = new SentResources().pack(mirrorToKey(), new Map());
    onmessage({ data: request({ id: 12, ...sent, state: BOX_STATE }) });
    onmessage({ data: request({ id: 13, state: BOX_STATE }) });
    // Neither is drawn yet: the maps are on their way.
    expect(posted).toEqual([]);
    await vi.waitFor(() => expect(posted.length).toBe(2), { timeout: 30_000 });
    const [first, second] = posted.splice(0).map((p) => p.message as Extract<SoftwareResponse, { pixels: Uint8ClampedArray }>);
    expect([first.id, second.id]).toEqual([12, 13]);
    const centre = 4 * (16 * 33 + 16);
    expect(first.pixels[centre]).toBe(153);
    expect(second.pixels[centre]).toBe(153);
    // Made once: the next scene with the studio is drawn at once.
    onmessage({ data: request({ id: 14, ...new SentResources().pack(mirrorToKey(), new Map()), state: BOX_STATE }) });
    expect((posted.pop()!.message as typeof first).pixels[centre]).toBe(153);
  });
});
