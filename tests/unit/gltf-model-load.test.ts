// A glTF model's load after its file is fetched (src/element/children/gltf-model.ts, docs/gltf.md#loading): its external
// buffers fetched relative to the model's URL (fetchBytes stubbed), each failure an error naming the buffer, its URL and its
// JSON path; a file with its buffers past 256 kB offered to a worker (a stub Worker: its answer, its error, its failure to
// start), read here otherwise; embedded images as blob: URLs, external ones resolved.
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { gltfOf, newDocument, primitive } from './helpers/gltf';

const fetched: string[] = [];
let resources: Record<string, Uint8Array> = {};
vi.mock('../../src/element/children/model-fetch', () => ({
  fetchBytes: vi.fn(async (url: string) => {
    fetched.push(url);
    const name = decodeURIComponent(url.slice(url.lastIndexOf('/') + 1));
    if (!(name in resources)) throw new Error(`HTTP 404 for ${url}`);
    return resources[name];
  }),
}));
const { loadGltfModel, GLTF_WORKER_THRESHOLD } = await import('../../src/element/children/gltf-model');
const { LoadError } = await import('../../src/loaders/load-error');

const URL_BASE = 'https://example.com/models/chair.gltf';

async function triangleModel(): Promise<Uint8Array> {
  const { doc, root } = newDocument();
  root.setMesh(doc.createMesh().addPrimitive(primitive(doc, [0, 0, 0, 1, 0, 0, 0, 1, 0], [0, 1, 2])));
  const made = await gltfOf(doc);
  resources = made.resources;
  return made.json;
}

beforeEach(() => { fetched.length = 0; });
afterEach(() => { vi.unstubAllGlobals(); });

describe('loadGltfModel', () => {
  it('fetches each external buffer relative to the model, and reads the model', async () => {
    const json = await triangleModel();
    const model = await loadGltfModel(json, URL_BASE, new AbortController().signal);
    expect(fetched).toEqual(Object.keys(resources).map((k) => `https://example.com/models/${k}`));
    expect(model.gltf).toBe(true);
    expect(model.url).toBe(URL_BASE);
    expect([...model.obj.indices]).toEqual([0, 1, 2]);
  });

  it('a buffer that cannot be fetched: an error naming the model, the buffer, its URL and buffers[i].uri', async () => {
    const json = await triangleModel();
    resources = {};
    const e = await loadGltfModel(json, URL_BASE, new AbortController().signal).catch((x) => x);
    expect(e).toBeInstanceOf(LoadError);
    expect(e.message).toContain('chair.gltf');
    expect(e.message).toMatch(/buffers\[0\] \(https:\/\/example\.com\/models\/[^)]+\) could not be loaded: HTTP 404/);
    expect(e.detail.path).toBe('buffers[0].uri');
  });

  it('a buffer URI that is no URL: an error at buffers[i].uri, nothing fetched', async () => {
    const text = JSON.parse(new TextDecoder().decode(await triangleModel()));
    text.buffers[0].uri = 'http://[::1';
    const e = await loadGltfModel(new TextEncoder().encode(JSON.stringify(text)), URL_BASE, new AbortController().signal).catch((x) => x);
    expect(e).toBeInstanceOf(LoadError);
    expect(e.message).toContain('buffers[0].uri "http://[::1" is not a usable URL');
    expect(fetched).toEqual([]);
  });

  it('aborted while a buffer is fetched: the abort itself, not a load error', async () => {
    const json = await triangleModel();
    const controller = new AbortController();
    const abort = new DOMException('gone', 'AbortError');
    const { fetchBytes } = await import('../../src/element/children/model-fetch');
    vi.mocked(fetchBytes).mockImplementationOnce(async () => { controller.abort(abort); throw abort; });
    await expect(loadGltfModel(json, URL_BASE, controller.signal)).rejects.toBe(abort);
  });

  it('aborted after the read: rejects with the signal\'s reason', async () => {
    const json = await triangleModel();
    const controller = new AbortController();
    const { fetchBytes } = await import('../../src/element/children/model-fetch');
    vi.mocked(fetchBytes).mockImplementationOnce(async (u) => { controller.abort('late'); fetched.push(u); return Object.values(resources)[0]; });
    await expect(loadGltfModel(json, URL_BASE, controller.signal)).rejects.toBe('late');
  });
});

describe('the worker', () => {
  /** A stub Worker that answers with `reply` (or fails to start, or reports an error), recording what it was sent. */
  function stubWorker(behaviour: 'throw' | 'error' | ((req: { url: string }) => unknown)) {
    const sent: unknown[] = [];
    const made: string[] = [];
    class FakeWorker {
      onmessage: ((e: { data: unknown }) => void) | null = null;
      onerror: ((e: { preventDefault(): void }) => void) | null = null;
      terminated = false;
      constructor(url: URL) {
        if (behaviour === 'throw') throw new Error('no workers here');
        made.push(String(url));
      }
      postMessage(req: { url: string }) {
        sent.push(req);
        queueMicrotask(() => {
          if (behaviour === 'error') this.onerror?.({ preventDefault() {} });
          else if (typeof behaviour === 'function') this.onmessage?.({ data: behaviour(req) });
        });
      }
      terminate() { this.terminated = true; }
    }
    vi.stubGlobal('Worker', FakeWorker);
    return { sent, made };
  }

  /** The triangle model padded past the threshold with an unused buffer of its own. */
  async function bigModel(): Promise<Uint8Array> {
    const json = JSON.parse(new TextDecoder().decode(await triangleModel()));
    json.buffers.push({ uri: 'pad.bin', byteLength: GLTF_WORKER_THRESHOLD });
    resources['pad.bin'] = new Uint8Array(GLTF_WORKER_THRESHOLD);
    return new TextEncoder().encode(JSON.stringify(json));
  }

  it('a small file is read here: no worker made', async () => {
    const { made } = stubWorker(() => ({ ok: false, error: { url: 'x', message: 'must not be asked' } }));
    await loadGltfModel(await triangleModel(), URL_BASE, new AbortController().signal);
    expect(made).toEqual([]);
  });

  it('past the threshold its answer is the model; its error is the load\'s error, at its place', async () => {
    const json = await bigModel();
    const here = await loadGltfModel(json, URL_BASE, new AbortController().signal);
    // The worker's answer: a result of its own making (one triangle more), to tell it from a read here.
    const { parse } = await import('./helpers/gltf');
    const theirs = parse(json, URL_BASE, resources);
    const { sent, made } = stubWorker(() => ({ ok: true, result: { ...theirs, indices: new Uint32Array([2, 1, 0]) } }));
    const model = await loadGltfModel(json, URL_BASE, new AbortController().signal);
    expect(made).toHaveLength(1);
    expect(made[0]).toContain('gltf-worker');
    expect((sent[0] as { url: string }).url).toBe(URL_BASE);
    expect([...model.obj.indices]).toEqual([2, 1, 0]);
    expect([...here.obj.indices]).toEqual([0, 1, 2]);
    stubWorker(() => ({ ok: false, error: { url: URL_BASE, message: 'accessors[0].count: too many', path: 'accessors[0].count' } }));
    const e = await loadGltfModel(json, URL_BASE, new AbortController().signal).catch((x) => x);
    expect(e).toBeInstanceOf(LoadError);
    expect(e.detail.path).toBe('accessors[0].count');
    expect(e.message).toContain('accessors[0].count: too many');
  });

  it('a worker that cannot start or fails: the file is read here', async () => {
    const json = await bigModel();
    for (const b of ['throw', 'error'] as const) {
      stubWorker(b);
      const model = await loadGltfModel(json, URL_BASE, new AbortController().signal);
      expect([...model.obj.indices], b).toEqual([0, 1, 2]);
    }
  });
});
