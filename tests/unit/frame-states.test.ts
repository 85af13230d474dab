// The element's FrameStates (src/element/frame-state.ts): tone-mapping="auto" decided by the scene (docs/pbr.md#in-the-frame),
// the other keywords and the exposure as parsed.
import { describe, expect, it } from 'vitest';
import { FrameStates } from '../../src/element/frame-state';
import { defaultAttributes, type SceneAttributes } from '../../src/element/attributes';
import { defaultScene } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import { pbrMaterial, withPbr } from './helpers/pbr-scenes';

const fill = (over: Partial<SceneAttributes>, scene: Scene | null) =>
  new FrameStates().fill({ ...defaultAttributes(), ...over }, 0, 64, 32, 0, scene);

describe('tone mapping in the frame state', () => {
  const plain = defaultScene(0.75, 0);
  const gltf: Scene = { ...plain, objects: [...plain.objects, { ...plain.objects[0], material: withPbr(pbrMaterial()) }] };

  it('auto: neutral with a glTF material, none without (or before any scene)', () => {
    expect(fill({}, gltf).toneMapping).toBe('neutral');
    expect(fill({}, plain).toneMapping).toBe('none');
    expect(fill({}, null).toneMapping).toBe('none');
  });

  it('a curve asked for is the curve, whatever the scene; the exposure as parsed', () => {
    for (const t of ['neutral', 'aces', 'none'] as const) {
      expect(fill({ toneMapping: t }, gltf).toneMapping).toBe(t);
      expect(fill({ toneMapping: t }, plain).toneMapping).toBe(t);
    }
    expect(fill({}, plain).exposure).toBe(1);
    expect(fill({ exposure: 2.5 }, plain).exposure).toBe(2.5);
  });
});
