// The float64 reference's rough glass (docs/rough-glass.md#reference-monte-carlo) against values worked out independently here:
// a white half-plane seen in (and through) a rough glass wall, head-on and orthographic, whose
// share of the GGX lobe is integrated by quadrature over θm, φm with D written out again and
// Snell's law applied by angles, not through src/math/ggx.ts; roughness 0 as the polished path
// bit for bit; a white enclosure that makes rough glass equal polished glass exactly.
import { describe, expect, it } from 'vitest';
import { renderScene } from '../../src/reference';
import { fresnel } from '../../src/math/fresnel';
import { defaultScene } from '../../src/scene/default-scene';
import { DEFAULT_CUBE_DISTANCE } from '../../src/element/attributes';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from './helpers/frame-state';
import type { Light, Material, Scene, SceneObject } from '../../src/scene/scene';

const AMBIENT: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [1, 1, 1], diffuse: [0, 0, 0], specular: [0, 0, 0] };
const WHITE: Material = { ambient: [1, 1, 1], diffuse: [0, 0, 0], specular: [0, 0, 0], shininess: 1, opacity: 1, texture: { kind: 'none' }, mapping: 'uv' };

function mesh(key: string, positions: number[], indices: number[]): SceneObject {
  const count = positions.length / 3;
  return {
    geometry: {
      kind: 'mesh', key,
      data: {
        positions: new Float32Array(positions), normals: new Float32Array(positions.length).fill(0).map((_, i) => (i % 3 === 2 ? 1 : 0)),
        uvs: new Float32Array(2 * count), indices: new Uint16Array(indices),
      },
    },
    transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: WHITE,
    bounds: { center: [0, 0, 0], radius: 200 },
  };
}

/** The half-plane x > 0 at depth z (a quad 50 × 100: every ray that matters meets it or misses it at x ≤ 0). */
const halfPlane = (z: number) => mesh(`half ${z}`, [0, -50, z, 50, -50, z, 50, 50, z, 0, 50, z], [0, 1, 2, 0, 2, 3]);

/** 32 × 32 px, orthographic, looking down −z from z = 2 at a glass wall z = 0 (x, y ∈ [−1, 1] on screen). */
const W = 32;
const HEAD_ON: FrameState = defaultFrameState({
  width: W, height: W, spin: 0, cubeDistance: 0, transparency: 1,
  fov: 2 * Math.atan(0.5) * (180 / Math.PI), cameraPosition: [0, 0, 2], yaw: -90, pitch: 0, target: [0, 0, 0],
  projection: 'orthographic', colorSpace: 'none', samples: 0,
});
const wall = (objects: SceneObject[]): Scene => ({ glass: { center: [0, 0, 0], normal: [0, 0, 1], size: [20, 20] }, objects, lights: [AMBIENT], background: [0, 0, 0] });

/** Share of D(m)·cosθm over the normals `keep` accepts that `white` also accepts (midpoint rule). */
function lobeShare(alpha: number, keep: (th: number, ph: number) => boolean, white: (th: number, ph: number) => boolean): number {
  const nt = 3000, np = 360, a2 = alpha * alpha;
  let all = 0, lit = 0;
  for (let i = 0; i < nt; i++) {
    const th = ((i + 0.5) / nt) * (Math.PI / 2), c = Math.cos(th), t = Math.tan(th);
    const w = (a2 / (Math.PI * c ** 4 * (a2 + t * t) ** 2)) * c * Math.sin(th);
    for (let j = 0; j < np; j++) {
      const ph = ((j + 0.5) / np) * 2 * Math.PI;
      if (!keep(th, ph)) continue;
      all += w;
      if (white(th, ph)) lit += w;
    }
  }
  return lit / all;
}

/** Pixel column i's x on the glass (row 16, y ≈ 0). */
const xOf = (i: number) => -1 + (2 * (i + 0.5)) / W;
const row = (rgb: Float64Array, y: number) => Array.from({ length: W }, (_, i) => rgb[3 * (y * W + i)]);

describe('reference rough glass (docs/rough-glass.md#reference-monte-carlo)', () => {
  const F = fresnel('exact', 1, 1.5);

  for (const roughness of [0.3, 0.6]) {
    const alpha = roughness * roughness;

    it(`roughness ${roughness}: R̃ of a white half-plane behind the viewer, 3 from the glass, is the lobe's share that reaches it`, () => {
      const ref = renderScene(wall([halfPlane(3)]), { ...HEAD_ON, roughness }, null, { microfacetSamples: 1024 });
      expect(ref.microfacetSamples).toBe(1024);
      const got = row(ref.rgb, 16).map((v) => v / F);
      for (const i of [10, 13, 15, 16, 18, 21]) {
        // d = −z: r leaves at 2θm from the normal, kept while 2θm < 90°, and meets z = 3 at
        // x + 3·tan 2θm·cos φm.
        const want = lobeShare(alpha, (th) => 2 * th < Math.PI / 2, (th, ph) => xOf(i) + 3 * Math.tan(2 * th) * Math.cos(ph) > 0);
        expect(Math.abs(got[i] - want), `column ${i} (x ${xOf(i).toFixed(3)}): ${got[i].toFixed(4)} vs ${want.toFixed(4)}`).toBeLessThan(0.02);
      }
    });

    for (const depth of [0.25, 2]) {
      it(`roughness ${roughness}: B̃ of a white half-plane ${depth} behind the glass is the share of transmitted directions that reach it`, () => {
        const ref = renderScene(wall([halfPlane(-depth)]), { ...HEAD_ON, roughness }, null, { microfacetSamples: 1024 });
        const got = row(ref.rgb, 16).map((v) => v / (1 - F));
        // Into the facet at θm: sin θ1 = sin θm / 1.5; inside at θm − θ1 from −z, towards the
        // azimuth φm + π; out of the flat face at δ with sin δ = 1.5·sin(θm − θ1) (lost past 1).
        const delta = (th: number) => Math.asin(1.5 * Math.sin(th - Math.asin(Math.sin(th) / 1.5)));
        const keep = (th: number) => 1.5 * Math.sin(th - Math.asin(Math.sin(th) / 1.5)) <= 1;
        for (const i of [4, 10, 14, 15, 16, 17, 21, 27]) {
          const want = lobeShare(alpha, keep, (th, ph) => xOf(i) - depth * Math.tan(delta(th)) * Math.cos(ph) > 0);
          expect(Math.abs(got[i] - want), `column ${i} (x ${xOf(i).toFixed(3)}): ${got[i].toFixed(4)} vs ${want.toFixed(4)}`).toBeLessThan(0.02);
        }
      });
    }
  }

  it('an edge far behind the glass is blurred wider than one close to it (contact hardening)', () => {
    const width = (depth: number) => {
      const got = row(renderScene(wall([halfPlane(-depth)]), { ...HEAD_ON, roughness: 0.5 }, null, { microfacetSamples: 256 }).rgb, 16).map((v) => v / (1 - F));
      return got.filter((v) => v > 0.1 && v < 0.9).length;
    };
    const near = width(0.05), far = width(1.5);
    expect(near).toBeLessThanOrEqual(2);
    expect(far).toBeGreaterThanOrEqual(4 * Math.max(1, near));
  });

  it('roughness 0 is the polished path bit for bit', () => {
    // roughness absent (undefined) here, 0 below.
    const state = defaultFrameState({ width: 48, height: 27, time: 1.25, roughness: undefined });
    const scene = defaultScene(DEFAULT_CUBE_DISTANCE, 0.8);
    const a = renderScene(scene, state, null, { samplesPerAxis: 2 }), b = renderScene(scene, { ...state, roughness: 0 }, null, { samplesPerAxis: 2 });
    expect(Buffer.from(b.rgb.buffer).equals(Buffer.from(a.rgb.buffer))).toBe(true);
    expect(b.microfacetSamples).toBe(0);
    const rough = renderScene(scene, { ...state, roughness: 0.4 }, null, { samplesPerAxis: 2 });
    expect(Buffer.from(rough.rgb.buffer).equals(Buffer.from(a.rgb.buffer))).toBe(false);
  });

  it('inside a white enclosure rough glass is polished glass exactly: every kept direction sees white, the dropped ones are not averaged in', () => {
    // An inward box of side 60 about the origin (the reference draws both faces of a mesh).
    const s = 30, p = [-s, -s, -s, s, -s, -s, s, s, -s, -s, s, -s, -s, -s, s, s, -s, s, s, s, s, -s, s, s];
    const faces = [0, 1, 2, 0, 2, 3, 4, 6, 5, 4, 7, 6, 0, 4, 5, 0, 5, 1, 3, 2, 6, 3, 6, 7, 0, 3, 7, 0, 7, 4, 1, 5, 6, 1, 6, 2];
    const scene: Scene = { ...wall([mesh('box', p, faces)]), glass: { center: [0, 0, 0], normal: [0, 1, 0], size: [20, 20] } };
    // A grazing view of a glass floor, where a wide lobe sends many directions under the floor.
    const state: FrameState = {
      ...HEAD_ON, projection: undefined, target: null, fov: 60, cameraPosition: [0, 0.6, 4], yaw: -90, pitch: -10, transparency: 0.5, colorSpace: 'srgb',
    };
    const polished = renderScene(scene, state).rgb;
    for (const roughness of [0.5, 1]) {
      const rough = renderScene(scene, { ...state, roughness }, null, { microfacetSamples: 64 }).rgb;
      let worst = 0;
      for (let i = 0; i < rough.length; i++) worst = Math.max(worst, Math.abs(rough[i] - polished[i]));
      expect(worst, `roughness ${roughness}`).toBeLessThan(1e-12);
    }
  });
});
