// The default scene's material and DefaultSceneCache (src/scene/default-scene.ts): what renderers
// called without a scene draw (docs/default-scene.md#material-and-lighting).
import { describe, expect, it } from 'vitest';
import { DefaultSceneCache, defaultMaterial, defaultScene } from '../../src/scene/default-scene';

describe('defaultMaterial', () => {
  it('Ka = Kd = albedo, Ks 0.5, shininess 32, opaque, the procedural texture mapped by UV', () => {
    expect(defaultMaterial([0.8, 0.3, 0.3])).toEqual({
      ambient: [0.8, 0.3, 0.3], diffuse: [0.8, 0.3, 0.3], specular: [0.5, 0.5, 0.5], shininess: 32,
      opacity: 1, texture: { kind: 'procedural' }, mapping: 'uv',
    });
  });
});

describe('DefaultSceneCache', () => {
  it('gives the same value while the cube distance and spin stay, a new one when either changes', () => {
    const cache = new DefaultSceneCache();
    const a = cache.get(0.75, 0.8);
    expect(a).toEqual(defaultScene(0.75, 0.8));
    expect(cache.get(0.75, 0.8)).toBe(a);
    const b = cache.get(1, 0.8);
    expect(b).not.toBe(a);
    expect(b.objects[0].transform.position[2]).toBe(1);
    const c = cache.get(1, 0);
    expect(c).not.toBe(b);
    expect(c.objects[0].transform.spin).toBe(0);
    expect(cache.get(1, 0)).toBe(c);
    // Object.is: −0 is another spin than 0 (a renderer may tell them apart), NaN the same NaN.
    expect(cache.get(1, -0)).not.toBe(c);
    const d = cache.get(NaN, 0);
    expect(cache.get(NaN, 0)).toBe(d);
  });
});
