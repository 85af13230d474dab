// A glTF material at one point under general lights (docs/pbr.md#the-scenes-lights): the software renderer's pbrLights and the
// reference's shadePbr against the rule written out here — per light Ia⊙c_diff + π·Id·(N·L)·f(l, v), f from gltfBrdf
// (tied to hand values in pbr.test.ts), the vectors worked below — for an oblique normal, a point light off to one side
// and a directional one given unnormalised, a two-sided surface seen from behind, and lights of different colours.
import { describe, expect, it } from 'vitest';
import { Lights, pbrLights } from '../../src/software/lighting';
import { prepareLight, shadePbr } from '../../src/reference/shade';
import { SurfaceHit } from '../../src/reference/surface-hit';
import { gltfBrdf, punctualAlpha } from '../../src/math/pbr';
import type { Light } from '../../src/scene/scene';
import type { PbrMaterial } from '../../src/scene/pbr-material';
import { litBy } from './helpers/lights';
import { pbrMaterial } from './helpers/pbr-scenes';

type V3 = [number, number, number];
const dot = (a: V3, b: V3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const unit = (a: V3): V3 => { const l = Math.hypot(...a); return [a[0] / l, a[1] / l, a[2] / l]; };

/** The rule, at point p with unit normal n and unit view vector v (towards the eye), for base colour `base`. */
function expected(m: PbrMaterial, base: V3, lights: Light[], p: V3, n: V3, v: V3): V3 {
  const out: V3 = [0, 0, 0];
  const f = [0, 0, 0];
  const nv = dot(n, v);
  for (const light of lights) {
    const l = unit(light.kind === 'point' ? [light.vector[0] - p[0], light.vector[1] - p[1], light.vector[2] - p[2]] : [...light.vector]);
    const h = unit([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
    const nl = dot(n, l);
    gltfBrdf(f, { baseColor: base, metallic: m.metallic, alpha: punctualAlpha(m.roughness) }, nl, nv, dot(n, h), dot(v, h));
    for (let k = 0; k < 3; k++) out[k] += light.ambient[k] * base[k] * (1 - m.metallic) + Math.PI * light.diffuse[k] * Math.max(nl, 0) * f[k];
  }
  return out;
}

const M = pbrMaterial({ baseColor: [0.9, 0.6, 0.3, 1], metallic: 0.3, roughness: 0.45 });
const BASE: V3 = [0.9, 0.6, 0.3];
const P: V3 = [0.4, -0.2, 1.1];
const N = unit([0.3, 0.5, 0.8]);
const V = unit([-0.2, 0.4, 1]);
const LIGHTS: Light[] = [
  { kind: 'point', vector: [2, 1.5, 3], ambient: [0.05, 0.1, 0.15], diffuse: [0.8, 0.6, 0.4], specular: [9, 9, 9] },
  { kind: 'directional', vector: [-1, 2, 1.5], ambient: [0.2, 0.1, 0.05], diffuse: [0.3, 0.5, 0.9], specular: [9, 9, 9] },
];

/** pbrLights at p (eye-relative: the eye at the origin here) for normal `n`, view `v`. */
function software(ls: Light[], n: V3, v: V3, twoSided = false, m = M, lights = new Lights()): Float64Array {
  lights.set(litBy(ls), ls.flatMap((l) => l.vector), [0, 0, 0]);
  const out = new Float64Array(6);
  pbrLights(lights, m, twoSided, new Float64Array([...P, ...n, ...v]), BASE, [m.metallic, m.roughness, 1], out);
  return out;
}

function reference(ls: Light[], n: V3, v: V3, m = M, tex: V3 = [1, 1, 1], orthographic = false): Float64Array {
  const hit = new SurfaceHit();
  hit.p.set(P);
  hit.n.set(n);
  // The eye along v from p, 2 units away; orthographic: an eye elsewhere, v given as the view's own vector.
  const eye = orthographic ? new Float64Array([9, -7, 3]) : new Float64Array([P[0] + 2 * v[0], P[1] + 2 * v[1], P[2] + 2 * v[2]]);
  return shadePbr(hit, m, undefined, new Float64Array(tex), ls.map(prepareLight), eye, new Float64Array(3), orthographic ? new Float64Array(v) : null);
}

describe('a glTF material at one point', () => {
  it('a point and a directional light of different colours, an oblique normal: both renderers as the rule', () => {
    const want = expected(M, BASE, LIGHTS, P, N, V);
    // Both lights light it (N·L > 0) and their highlights differ: neither term is zero.
    expect(want.every((x) => x > 0.05)).toBe(true);
    const soft = software(LIGHTS, N, V), ref = reference(LIGHTS, N, V);
    for (let k = 0; k < 3; k++) {
      expect(soft[k], `software ${k}`).toBeCloseTo(want[k], 12);
      expect(ref[k], `reference ${k}`).toBeCloseTo(want[k], 12);
    }
    // Each light alone: the sum is theirs.
    for (const l of LIGHTS) {
      const one = expected(M, BASE, [l], P, N, V);
      for (let k = 0; k < 3; k++) expect(software([l], N, V)[k]).toBeCloseTo(one[k], 12);
    }
  });

  it('a light behind the surface adds its ambient alone; a view from behind gets no direct light', () => {
    const behind: Light = { ...LIGHTS[1], vector: [-0.3, -0.5, -0.8] };
    const want = BASE.map((b, k) => behind.ambient[k] * b * 0.7);
    for (const got of [software([behind], N, V), reference([behind], N, V)]) for (let k = 0; k < 3; k++) expect(got[k]).toBeCloseTo(want[k], 12);
    const away = unit([-0.3, -0.5, -0.2]);
    const ambient = BASE.map((b, k) => (LIGHTS[0].ambient[k] + LIGHTS[1].ambient[k]) * b * 0.7);
    for (let k = 0; k < 3; k++) expect(software(LIGHTS, N, away)[k]).toBeCloseTo(ambient[k], 12);
  });

  it('two-sided: seen from behind, the normal turns to the viewer (one-sided keeps it)', () => {
    const back: V3 = [-N[0], -N[1], -N[2]];
    const want = expected(M, BASE, LIGHTS, P, N, V);
    const flipped = software(LIGHTS, back, V, true);
    for (let k = 0; k < 3; k++) expect(flipped[k]).toBeCloseTo(want[k], 12);
    const kept = software(LIGHTS, back, V, false);
    const ambient = BASE.map((b, k) => (LIGHTS[0].ambient[k] + LIGHTS[1].ambient[k]) * b * 0.7);
    for (let k = 0; k < 3; k++) expect(kept[k]).toBeCloseTo(ambient[k], 12);
  });

  it('two-sided and seen from the front: the normal as it is (where a sign slip in N·V would turn it)', () => {
    for (const [n, v] of [[unit([0.1, 0.9, 0.5]), unit([0.3, 0.8, -0.3])], [unit([0.2, 0.3, 0.9]), unit([0.3, -0.1, 0.95])]] as [V3, V3][]) {
      const want = expected(M, BASE, LIGHTS, P, n, v);
      const got = software(LIGHTS, n, v, true);
      for (let k = 0; k < 3; k++) expect(got[k], `${n} ${v}`).toBeCloseTo(want[k], 12);
    }
  });

  it('four lights, and a set of fewer after them: each set\'s own lights alone', () => {
    const four = [...LIGHTS, { ...LIGHTS[0], vector: [-2, 3, 1] as V3 }, { ...LIGHTS[1], vector: [0.5, 0.2, 1] as V3 }];
    const lights = new Lights();
    const all = software(four, N, V, false, M, lights);
    const want4 = expected(M, BASE, four, P, N, V);
    for (let k = 0; k < 3; k++) expect(all[k]).toBeCloseTo(want4[k], 12);
    const one = software([LIGHTS[1]], N, V, false, M, lights);
    const want1 = expected(M, BASE, [LIGHTS[1]], P, N, V);
    for (let k = 0; k < 3; k++) expect(one[k]).toBeCloseTo(want1[k], 12);
  });

  it('the reference: the texture is in the base colour (and F0); an orthographic view\'s own vector', () => {
    const tex: V3 = [0.5, 0.25, 0.8];
    const base: V3 = [BASE[0] * tex[0], BASE[1] * tex[1], BASE[2] * tex[2]];
    const want = expected(M, base, LIGHTS, P, N, V);
    const got = reference(LIGHTS, N, V, M, tex);
    for (let k = 0; k < 3; k++) expect(got[k]).toBeCloseTo(want[k], 12);
    const ortho = reference(LIGHTS, N, V, M, [1, 1, 1], true), plain = expected(M, BASE, LIGHTS, P, N, V);
    for (let k = 0; k < 3; k++) expect(ortho[k]).toBeCloseTo(plain[k], 12);
  });

  it('a point light at the point itself lights nothing but its ambient (no NaN)', () => {
    const at: Light = { ...LIGHTS[0], vector: P };
    const want = BASE.map((b, k) => at.ambient[k] * b * 0.7);
    for (const got of [software([at], N, V), reference([at], N, V)]) for (let k = 0; k < 3; k++) expect(got[k]).toBeCloseTo(want[k], 12);
  });

  it('unlit: the base colour, whatever the lights', () => {
    const unlit = { ...M, unlit: true };
    for (const got of [software(LIGHTS, N, V, false, unlit), reference(LIGHTS, N, V, unlit)]) expect([...got.subarray(0, 3)]).toEqual(BASE);
  });
});
