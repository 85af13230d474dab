// The renderer contract's images on the WebGL side (ARCHITECTURE.md, "How a frame flows"): the
// decoded images a scene names arrive with each frame, by URL; the Renderer uploads an image the
// first time a frame has it, nothing while the map is unchanged, again when the URL's image is
// replaced, and frees it when a frame naming it no longer finds it. On a stand-in context.
import { describe, expect, it } from 'vitest';
import { fakeGl } from './helpers/fake-gl';
import { defaultFrameState } from './helpers/frame-state';
import { Renderer } from '../../src/render/renderer';
import { BACKGROUND, DEFAULT_GLASS, DEFAULT_LIGHT } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import type { DecodedImage, SceneImages } from '../../src/scene/decoded-image';

const STATE = defaultFrameState({ width: 64, height: 36 });

/** One box textured with the image at `url`. */
const SCENE: Scene = {
  glass: DEFAULT_GLASS, lights: [DEFAULT_LIGHT], background: BACKGROUND,
  objects: [{
    geometry: { kind: 'box', size: 1 },
    material: {
      ambient: [0.2, 0.2, 0.2], diffuse: [0.8, 0.8, 0.8], specular: [0.5, 0.5, 0.5], shininess: 32, opacity: 1,
      texture: { kind: 'image', url: 'a.png' }, mapping: 'uv',
    },
    transform: { position: [0, 1, 1], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    bounds: { center: [0, 0, 0], radius: 1 },
  }],
};

const image = (): DecodedImage => ({ width: 2, height: 2, data: new Uint8Array(16).fill(255) });

describe('the WebGL renderer takes the decoded images with each frame', () => {
  it('uploads an image once, nothing more while the map is unchanged, again when replaced, and frees it when gone', () => {
    const { gl, calls } = fakeGl();
    const r = new Renderer(gl);
    const textures = () => r.stats.resources.textures;
    const count = (name: string) => calls.get(name) ?? 0;
    r.render(SCENE, STATE, null);
    const without = textures();
    const images = new Map([['a.png', image()]]);
    r.render(SCENE, STATE, images);
    expect(textures(), 'the image uploaded').toBe(without + 1);
    const uploads = count('texImage2D'), created = count('createTexture');
    for (let i = 0; i < 3; i++) r.render(SCENE, STATE, images);
    expect([count('texImage2D'), count('createTexture')], 'an unchanged map: no upload').toEqual([uploads, created]);
    const deleted = count('deleteTexture');
    images.set('a.png', image());
    r.render(SCENE, STATE, images);
    expect([count('createTexture'), count('deleteTexture')], 'a replaced image: the old freed, the new uploaded').toEqual([created + 1, deleted + 1]);
    expect(textures()).toBe(without + 1);
    images.delete('a.png');
    r.render(SCENE, STATE, images);
    expect(textures(), 'an image gone from the map is freed').toBe(without);
    r.read(SCENE, STATE, null, 'final'); // its off-screen target made
    const target = textures();
    r.read(SCENE, STATE, new Map([['a.png', image()]]) as SceneImages, 'final');
    expect(textures(), 'read() takes the same images').toBe(target + 1);
    r.read(SCENE, STATE, null, 'final');
    expect(textures()).toBe(target);
    r.dispose();
  });

  it('a null scene is the default scene for the state, kept between frames', () => {
    const { gl } = fakeGl();
    const r = new Renderer(gl);
    r.render(null, STATE);
    const buffers = r.stats.resources.buffers;
    r.render(null, { ...STATE, time: 1 });
    expect(r.stats.resources.buffers, 'no mesh rebuilt').toBe(buffers);
    r.dispose();
  });
});
