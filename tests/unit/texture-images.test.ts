// The element's image textures (src/element/texture-images.ts): every image a scene's materials draw with — a texture, a glTF
// material's maps on TEXCOORD_0 — fetched and decoded once per page, handed to the renderer drawing; one whose decoding has
// settled is handed over at once by whoever asks after (the frame after a child's `load`, which waits for its images, has them).
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { stubFetch } from './helpers/fetch-stub';
import { TextureImages, decodeImage } from '../../src/element/texture-images';
import type { Scene } from '../../src/scene/scene';
import { boxScene, pbrMaterial, withPbr } from './helpers/pbr-scenes';
import { map } from './helpers/pbr-map-cases';

/** A decoded bitmap's size from its body: "w×h". */
beforeEach(() => {
  vi.stubGlobal('createImageBitmap', async (blob: Blob) => {
    const [w, h] = (await blob.text()).split('×').map(Number);
    return { width: w, height: h, close: () => undefined };
  });
  vi.stubGlobal('OffscreenCanvas', class {
    constructor(readonly width: number, readonly height: number) {}
    getContext(kind: string) {
      if (kind !== '2d') return null; // as a canvas does for a context it has not
      const { width, height } = this;
      return { drawImage: () => undefined, getImageData: () => ({ width, height, data: new Uint8ClampedArray(4 * width * height) }) };
    }
  });
});
afterEach(() => vi.unstubAllGlobals());

let n = 0;
/** URLs of their own per test: decoded images are kept for the page's life (the module's). */
const fresh = (name: string) => `https://example.com/${++n}/${name}.png`;

function scene(urls: { base?: string; mr?: string; ao?: string; em?: string; uv1?: string }): Scene {
  const pbr = pbrMaterial({
    metallicRoughnessTexture: urls.mr ? map(urls.mr) : null, occlusionTexture: urls.ao ? map(urls.ao) : null,
    emissiveTexture: urls.em ? map(urls.em) : urls.uv1 ? map(urls.uv1, 1) : null,
  });
  const s = boxScene(pbr);
  const material = withPbr(pbr, urls.base ? { kind: 'image', url: urls.base } : { kind: 'none' });
  return { ...s, objects: [{ ...s.objects[0], material }] };
}

function element() {
  const given: string[] = [];
  const host = { sink: () => ({ setImage: (url: string) => given.push(url) }), loaded: vi.fn() };
  return { images: new TextureImages(host), given, host };
}

describe('TextureImages', () => {
  it('asks for the texture and each map on TEXCOORD_0, once each, and hands each over when decoded', async () => {
    const u = { base: fresh('base'), mr: fresh('mr'), ao: fresh('ao'), em: fresh('em'), uv1: fresh('uv1') };
    const { requests } = stubFetch({ [u.base]: '2×2', [u.mr]: '1×1', [u.ao]: '4×4', [u.em]: '1×2', [u.uv1]: '1×1' });
    const a = element();
    const s = scene({ base: u.base, mr: u.mr, ao: u.ao });
    a.images.sync(s);
    a.images.sync({ ...s }); // a new value naming the same images: nothing asked again
    expect(a.given, 'nothing decoded yet').toEqual([]);
    await Promise.all([u.base, u.mr, u.ao].map(decodeImage));
    await Promise.resolve();
    expect(requests.sort()).toEqual([u.base, u.mr, u.ao].sort());
    expect(a.given.sort()).toEqual([u.base, u.mr, u.ao].sort());
    expect(a.host.loaded).toHaveBeenCalledTimes(3);
    // An emissive map on TEXCOORD_1 is not drawn, so not fetched.
    const b = element();
    b.images.sync(scene({ uv1: u.uv1 }));
    expect(requests).not.toContain(u.uv1);
  });

  it('hands over an image decoded already within sync itself, with no call for another frame', async () => {
    const url = fresh('em');
    stubFetch({ [url]: '1×1' });
    await decodeImage(url);
    const a = element();
    a.images.sync(scene({ em: url }));
    expect(a.given, 'before sync returned').toEqual([url]);
    await Promise.resolve();
    expect(a.host.loaded).not.toHaveBeenCalled();
  });

  it('hands over nothing for an image that failed, at once or later', async () => {
    const url = fresh('gone');
    stubFetch({ [url]: 404 });
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    expect(await decodeImage(url)).toBeNull();
    const a = element();
    a.images.sync(scene({ mr: url }));
    await Promise.resolve();
    expect(a.given).toEqual([]);
    expect(a.host.loaded).not.toHaveBeenCalled();
    expect(warn).toHaveBeenCalledTimes(1);
    expect(String(warn.mock.calls[0][0]), 'the warning names the image and the status').toMatch(new RegExp(`texture "${url}" could not be loaded \\(HTTP 404\\)`));
    warn.mockRestore();
  });

  it('hands over nothing for an image that fails after it was asked for, nor calls for a frame', async () => {
    const url = fresh('fails later');
    stubFetch({ [url]: 500 });
    const warn = vi.spyOn(console, 'warn').mockImplementation(() => undefined);
    const a = element();
    a.images.sync(scene({ ao: url }));
    expect(await decodeImage(url)).toBeNull();
    await Promise.resolve();
    expect(a.given).toEqual([]);
    expect(a.host.loaded).not.toHaveBeenCalled();
    warn.mockRestore();
  });

  it('keeps an image that arrives while no renderer draws, and calls for a frame all the same', async () => {
    const url = fresh('while none draws');
    stubFetch({ [url]: '1×1' });
    const loaded = vi.fn();
    const images = new TextureImages({ sink: () => null, loaded });
    images.sync(scene({ mr: url }));
    await decodeImage(url);
    await Promise.resolve();
    expect(loaded).toHaveBeenCalledTimes(1);
    // A renderer that starts later is given it.
    const given: string[] = [];
    images.feed({ setImage: (u) => given.push(u) });
    expect(given).toEqual([url]);
  });

  it('asks for nothing for a plain material, and for an OBJ material\'s texture alone', async () => {
    const url = fresh('obj texture');
    const { requests } = stubFetch({ [url]: '1×1' });
    const a = element();
    const plain = boxScene(pbrMaterial());
    const obj: Scene = { ...plain, objects: [{ ...plain.objects[0], material: { ...plain.objects[0].material, pbr: undefined, texture: { kind: 'image', url } } }] };
    a.images.sync(plain);
    a.images.sync(obj);
    await decodeImage(url);
    expect(requests).toEqual([url]);
  });
});
