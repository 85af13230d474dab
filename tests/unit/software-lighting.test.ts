// The software renderer's Blinn-Phong (src/software/lighting.ts) for one point, by hand: which
// lights it adds, which side of a two-sided surface it lights, and where a highlight may be, each
// as shaders/lighting.glsl has it. Material Ka 0.2, Kd 0.5, Ks 1, n = 2; lights Ia 0.5, Id 1, Is 1.
import { describe, expect, it } from 'vitest';
import { blinnPhong, Lights } from '../../src/software/lighting';
import type { Light, Material } from '../../src/scene/scene';
import { litBy } from './helpers/lights';

const M: Material = {
  ambient: [0.2, 0.2, 0.2], diffuse: [0.5, 0.5, 0.5], specular: [1, 1, 1], shininess: 2, opacity: 1,
  texture: { kind: 'procedural' }, mapping: 'uv',
};

/** A directional light towards `vector` (a unit vector here). */
const light = (vector: [number, number, number]): Light => ({
  kind: 'directional', vector, ambient: [0.5, 0.5, 0.5], diffuse: [1, 1, 1], specular: [1, 1, 1],
});

/** `lights` set as the renderer sets them, their world vectors as they are, the eye at the origin. */
function lightsOf(ls: Light[], into = new Lights()): Lights {
  into.set(litBy(ls), ls.flatMap((l) => l.vector), [0, 0, 0]);
  return into;
}

/** The sums a and s at the origin for unit normal `n` and view vector `v`, each to 12 digits. */
function expectSums(lights: Lights, twoSided: boolean, n: number[], v: number[], a: number, s: number): void {
  const out = new Float64Array(6);
  blinnPhong(lights, M, twoSided, new Float64Array([0, 0, 0, ...n, ...v]), out);
  const want = [a, a, a, s, s, s];
  for (let k = 0; k < 6; k++) expect(out[k], `out[${k}] of ${[...out].join(' ')}`).toBeCloseTo(want[k], 12);
}

describe('blinnPhong', () => {
  it('adds each light set, and none left from an earlier set', () => {
    // Light, normal and eye all along +Z: N·L = N·H = 1, so a = 0.2 × 0.5 + 0.5 × 1 = 0.6, s = 1.
    const front = light([0, 0, 1]);
    expectSums(lightsOf([front]), false, [0, 0, 1], [0, 0, 1], 0.6, 1);
    // All MAX_LIGHTS (4) of a full set: four times that.
    expectSums(lightsOf([front, front, front, front]), false, [0, 0, 1], [0, 0, 1], 2.4, 4);
    // One light set where two were: one light's sums.
    expectSums(lightsOf([front], lightsOf([front, front])), false, [0, 0, 1], [0, 0, 1], 0.6, 1);
  });

  it('turns a two-sided normal towards the viewer only when it faces away (N·V < 0)', () => {
    // N = (0, 0.6, −0.8) seen from V = (0, 0.6, 0.8), a light along V: N·V = 0.36 − 0.64 = −0.28.
    const head = lightsOf([light([0, 0.6, 0.8])]);
    // One-sided: N·L = −0.28, ambient alone (0.1) and no highlight.
    expectSums(head, false, [0, 0.6, -0.8], [0, 0.6, 0.8], 0.1, 0);
    // Two-sided, N turned to (0, −0.6, 0.8): N·L = 0.28, a = 0.1 + 0.5 × 0.28 = 0.24; H = L + V =
    // (0, 1.2, 1.6) of length 2, N·H / 2 = 0.28, s = 0.28² = 0.0784.
    expectSums(head, true, [0, 0.6, -0.8], [0, 0.6, 0.8], 0.24, 0.0784);
    // N across the view (N·V = 0), the light along N: not turned (dot(n, v) < 0.0 on the GPU),
    // N·L = 1: a = 0.6; H = (1, 0, 1), N·H / √2 = 1/√2, s = ½.
    expectSums(lightsOf([light([1, 0, 0])]), true, [1, 0, 0], [0, 0, 1], 0.6, 0.5);
  });

  it('gives a highlight only from a light in front of the surface (N·L > 0)', () => {
    // N and V along +Z. A light in the surface's plane: N·L = 0, no highlight, though N·H = 1/√2.
    expectSums(lightsOf([light([1, 0, 0])]), false, [0, 0, 1], [0, 0, 1], 0.1, 0);
    // A light behind it, L = (0.6, 0, −0.8): N·L = −0.8, none, though N·H = 0.2 / √0.4 > 0.
    expectSums(lightsOf([light([0.6, 0, -0.8])]), false, [0, 0, 1], [0, 0, 1], 0.1, 0);
  });

  it('clamps N·H at 0: no highlight where the half vector is behind the surface', () => {
    // A one-sided surface seen from behind, V = −Z, N = +Z (a normal across a silhouette), lit from
    // its front, L = (0.6, 0, 0.8): N·L = 0.8, a = 0.1 + 0.5 × 0.8 = 0.5; H = (0.6, 0, −0.2): N·H < 0.
    expectSums(lightsOf([light([0.6, 0, 0.8])]), false, [0, 0, 1], [0, 0, -1], 0.5, 0);
  });
});
