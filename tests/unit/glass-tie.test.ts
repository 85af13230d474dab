// A face lying in the glass plane (a picture behind a glass wall): the glass covers it
// when its object is on the plane or beyond it, and an object on the viewer's side stays in front
// — in the float64 reference and the software renderer alike, against values worked by hand.
import { describe, expect, it } from 'vitest';
import { renderScene } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import { fresnel } from '../../src/math/fresnel';
import type { FrameState } from '../../src/frame/types';
import type { Scene, SceneObject } from '../../src/scene/scene';
import { AMBIENT, material, N, quad, STATE as BASE } from './helpers/quad-scenes';

// quad-scenes.ts's 17 × 17 frame, looking head-on at a glass wall z = 0: the centre pixel looks
// along the normal (F = 0.04 at ior 1.5). As stored, T = 1.
const STATE: FrameState = { ...BASE, transparency: 1, colorSpace: 'none' };
const WHITE = material([1, 1, 1], { kind: 'none' });

/** A white picture at z (the glass plane by default), x, y ∈ [−0.5, 0.5], facing the viewer; its bounds' centre at z = `centreZ`. */
const picture = (centreZ: number, z = 0): SceneObject => quad(-0.5, -0.5, 0.5, 0.5, z, WHITE, 1, centreZ);

const scene = (o: SceneObject): Scene => ({ glass: { center: [0, 0, 0], normal: [0, 0, 1], size: [6, 6] }, objects: [o], lights: [AMBIENT], background: [0, 0, 0] });
const centre = (rgba: ArrayLike<number>) => rgba[4 * (8 * N + 8)];
/** `name`'s renderer with the state changed by `over`. */
function drawWith(name: string, over: Partial<FrameState>, s: Scene): ArrayLike<number> {
  const state = { ...STATE, ...over };
  if (name === 'reference') return renderScene(s, state).rgba;
  return new SoftwareRenderer().render(s, name.includes('multisampled') ? { ...state, samples: 4 } : state);
}

describe('a face in the glass plane', () => {
  // T = 1: out = F·R + (1 − F)·B, R = the black background, B = 1: (1 − 0.04)·255 = 244.8.
  const covered = Math.round((1 - fresnel('exact', 1, 1.5)) * 255);

  it('the hand value: 245', () => expect(covered).toBe(245));

  for (const [name, draw] of [
    ['reference', (s: Scene) => renderScene(s, STATE).rgba],
    ['software renderer', (s: Scene) => new SoftwareRenderer().render(s, STATE)],
    ['software renderer, multisampled', (s: Scene) => new SoftwareRenderer().render(s, { ...STATE, samples: 4 })],
  ] as const) {
    it(`${name}: a picture on the glass, seen through it, is 245, not 255`, () => {
      expect(centre(draw(scene(picture(0))))).toBe(covered);
      // Its object beyond the plane: the same.
      expect(centre(draw(scene(picture(-0.1))))).toBe(covered);
    });

    it(`${name}: an object on the viewer's side keeps its face in the plane in front of the glass (255)`, () => {
      expect(centre(draw(scene(picture(0.1))))).toBe(255);
    });

    // Single samples: a multisampled frame mixes the face's edges with the glass around it.
    if (!name.includes('multisampled')) it(`${name}: seen obliquely, every pixel of that face is in front (a tie by a rounding either way is a tie)`, () => {
      // Off to the side and above: the glass and the face meet each ray a rounding apart, the
      // glass nearer for some (the reference let it win those: 6 of the 17 × 17 were 245).
      const oblique = { ...STATE, cameraPosition: [0.9, 0.7, 1.6] as [number, number, number], yaw: -119, pitch: -20 };
      const rgba = name === 'reference' ? renderScene(scene(picture(0.1)), oblique).rgba : new SoftwareRenderer().render(scene(picture(0.1)), oblique);
      const values = new Set<number>();
      for (let i = 0; i < N * N; i++) values.add(rgba[4 * i]);
      expect([...values].sort((a, b) => a - b)).toEqual([0, 255]);
    });

    it(`${name}: a face beyond the glass is seen through it whatever side its object's centre is on (245)`, () => {
      expect(centre(draw(scene(picture(0.1, -0.3))))).toBe(covered);
    });

    it(`${name}: a face in front of the glass stays in front whatever side its object's centre is on (255)`, () => {
      // Drawn over with transparency 0 the glass would show its dark body there, not white.
      expect(centre(drawWith(name, { transparency: 0 }, scene(picture(-0.1, 0.3))))).toBe(255);
      expect(centre(drawWith(name, { transparency: 0 }, scene(picture(0, 0.01))))).toBe(255);
    });
  }

  for (const [name, draw] of [
    ['reference', (s: Scene) => renderScene(s, { ...STATE, view: 'reflection' }).rgba],
    ['software renderer', (s: Scene) => new SoftwareRenderer().render(s, { ...STATE, view: 'reflection' })],
  ] as const) {
    it(`${name}: the reflection leaves out a face touching the glass (5e-6 in front of it), keeps one 1e-3 in front`, () => {
      // MIRROR_CONTACT (1e-5): nearer than that to the glass is against it, not in front of it.
      expect(centre(draw(scene(picture(0.1, 5e-6))))).toBe(0);
      expect(centre(draw(scene(picture(0.1, 1e-3))))).toBe(255);
    });
  }
});
