// Loads shared by URL (docs/scene-model.md#loading): one fetch for many asks while it is under
// way or once it has loaded; a load that failed is forgotten, by the cache and by the element, so
// asking again fetches again.
import { afterEach, describe, expect, it, vi } from 'vitest';
import { acquireModel } from '../../src/element/children/model-cache';
import { GlassObject } from '../../src/element/children/glass-object';
import { GlassLight } from '../../src/element/children/glass-light';
import { CameraSource } from '../../src/element/camera-source';
import { stubFetch } from './helpers/fetch-stub';

const OBJ = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n';

afterEach(() => {
  vi.unstubAllGlobals();
  vi.restoreAllMocks();
});

describe('the model cache', () => {
  it('fetches a model again after its fetch failed (HTTP 503), and a loaded one never again', async () => {
    vi.spyOn(console, 'error').mockImplementation(() => {});
    const url = 'http://x/cache/busy.obj';
    const { requests } = stubFetch({ [url]: [503, OBJ] });
    const first = acquireModel(url, () => {});
    await expect(first.promise).rejects.toThrow(/HTTP 503/);
    const second = acquireModel(url, () => {}); // the first still held: its failure is not shared
    expect((await second.promise).obj.indices.length).toBe(3);
    first.release();
    const third = acquireModel(url, () => {});
    expect(await third.promise).toBe(await second.promise);
    expect(requests).toEqual([url, url]);
  });
});

/** A child element without a DOM: connected, its events collected. */
function connected<T extends GlassObject | GlassLight>(el: T): { el: T; types: string[] } {
  const types: string[] = [];
  Object.assign(el, {
    isConnected: true,
    hasAttribute: () => false,
    dispatchEvent: (e: Event) => types.push(e.type) > 0,
  });
  return { el, types };
}

/**
 * A connected child's `src` set to `url`, which answers 503 then `body`, and set again to the same
 * URL once the error has fired: the requests made, once its `load` has fired too.
 */
async function srcAgainAfter503<T extends GlassObject | GlassLight>(child: T, url: string, body: string): Promise<{ el: T; requests: string[] }> {
  vi.spyOn(console, 'error').mockImplementation(() => {});
  vi.stubGlobal('document', { baseURI: 'http://x/page/' });
  const { requests } = stubFetch({ [url]: [503, body] });
  const { el, types } = connected(child);
  el.attributeChangedCallback('src', null, url);
  await vi.waitFor(() => expect(types).toContain('error'));
  el.attributeChangedCallback('src', url, url);
  await vi.waitFor(() => expect(types).toContain('load'));
  return { el, requests };
}

describe('<glass-object src> after a failed load', () => {
  it('fetches the model again when src is set again to the same URL', async () => {
    const url = 'http://x/element/busy.obj';
    const { el, requests } = await srcAgainAfter503(new GlassObject(), url, OBJ);
    expect(requests).toEqual([url, url]);
    expect(el.toSceneObjects()).toHaveLength(1);
  });
});

describe('the course\'s files after a failed load (docs/course-files.md#load-errors)', () => {
  const LIGHTING = '0 0 10\n0.2\n255 255 255\n0.8\n1 1 1\n0.5\n255 255 255\n8\n';

  it('<glass-light src> set again to the same URL fetches the lighting file again', async () => {
    const url = 'http://x/light/iluminacao.txt';
    const { requests } = await srcAgainAfter503(new GlassLight(), url, LIGHTING);
    expect(requests).toEqual([url, url]);
  });

  it('camera-src set again to the same URL fetches the camera file again', async () => {
    vi.spyOn(console, 'error').mockImplementation(() => {});
    vi.stubGlobal('document', { baseURI: 'http://x/page/' });
    const url = 'http://x/camera/busy.cfg';
    const { requests } = stubFetch({ [url]: [503, '0 0 10\n0 0 -1\n0 1 0\n1 1 1\n'] });
    const types: string[] = [];
    const element = { isConnected: true, dispatchEvent: (e: Event) => types.push(e.type) > 0 } as unknown as HTMLElement;
    const source = new CameraSource({ element, src: () => url, changed: () => {} });
    source.srcChanged();
    await vi.waitFor(() => expect(types).toContain('error'));
    source.srcChanged();
    await vi.waitFor(() => expect(source.camera).not.toBeNull());
    expect(requests).toEqual([url, url]);
  });
});
