// Loads shared by URL (docs/scene-model.md#loading): one fetch for many asks while it is under
// way or once it has loaded; a load that failed is forgotten, by the cache and by the element, so
// asking again fetches again.
import { afterEach, describe, expect, it, vi } from 'vitest';
import { acquireModel } from '../../src/element/children/model-cache';
import { GlassObject } from '../../src/element/children/glass-object';
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

/** A <glass-object> without a DOM: connected, its events collected. */
function connectedObject(): { el: GlassObject; types: string[] } {
  const el = new GlassObject();
  const types: string[] = [];
  Object.assign(el, {
    isConnected: true,
    hasAttribute: () => false,
    dispatchEvent: (e: Event) => types.push(e.type) > 0,
  });
  return { el, types };
}

describe('<glass-object src> after a failed load', () => {
  it('fetches the model again when src is set again to the same URL', async () => {
    vi.spyOn(console, 'error').mockImplementation(() => {});
    vi.stubGlobal('document', { baseURI: 'http://x/page/' });
    const url = 'http://x/element/busy.obj';
    const { requests } = stubFetch({ [url]: [503, OBJ] });
    const { el, types } = connectedObject();
    el.attributeChangedCallback('src', null, url);
    await vi.waitFor(() => expect(types).toContain('error'));
    el.attributeChangedCallback('src', url, url);
    await vi.waitFor(() => expect(types).toContain('load'));
    expect(requests).toEqual([url, url]);
    expect(el.toSceneObjects()).toHaveLength(1);
  });
});
