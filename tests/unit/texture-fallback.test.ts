// An image texture that is missing (not yet decoded, or failed): drawn with the procedural checker
// by default, plain (white, as `kind: 'none'`) with `fallback: 'none'` — a glTF model's or a course
// file's, which never show the checker (docs/gltf.md#images) — in the software renderer and the
// reference; and the element's material gives glTF and course objects that fallback.
import { describe, expect, it } from 'vitest';
import { renderScene } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import { defaultScene } from '../../src/scene/default-scene';
import type { Scene, TextureSource } from '../../src/scene/scene';
import { resolveMaterial } from '../../src/element/children/object-material';
import { defaultObjectAttributes } from '../../src/element/children/object-attributes';
import { defaultFrameState } from './helpers/frame-state';

const base = defaultScene(0.75, 0);
const withTexture = (texture: TextureSource): Scene => ({ ...base, objects: base.objects.map((o) => ({ ...o, material: { ...o.material, texture } })) });
const STATE = defaultFrameState({ width: 48, height: 27, spin: 0, time: 0 });

describe('a missing image', () => {
  for (const [name, draw] of [
    ['software renderer', (s: Scene) => Buffer.from(new SoftwareRenderer().render(s, STATE, new Map()))],
    ['reference', (s: Scene) => Buffer.from(renderScene(s, STATE, new Map(), { samplesPerAxis: 1 }).rgb.buffer)],
  ] as const) {
    it(`${name}: plain with fallback none, the checker without`, () => {
      const plain = draw(withTexture({ kind: 'none' })), checker = draw(withTexture({ kind: 'procedural' }));
      expect(plain.equals(checker)).toBe(false);
      expect(draw(withTexture({ kind: 'image', url: 'gone.png', fallback: 'none' })).equals(plain)).toBe(true);
      expect(draw(withTexture({ kind: 'image', url: 'gone.png' })).equals(checker)).toBe(true);
    });
  }

  it("the element's material: a plain object's image (glTF, course file) falls back to none, others to the checker", () => {
    const v = defaultObjectAttributes();
    expect(resolveMaterial(v, { texture: 'https://x/a.png' }, true, null, { plain: true }).texture).toEqual({ kind: 'image', url: 'https://x/a.png', fallback: 'none' });
    expect(resolveMaterial(v, { texture: 'https://x/a.png' }, true, null).texture).toEqual({ kind: 'image', url: 'https://x/a.png' });
    expect(resolveMaterial(v, undefined, true, null, { plain: true }).texture).toEqual({ kind: 'none' });
  });
});
