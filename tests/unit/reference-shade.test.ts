// Per-sample shading of the reference (src/reference/shade.ts): Blinn-Phong sums worked out by hand for directional
// and point lights, the Ka = Kd form, emission, the orthographic view vector, glass Fresnel and the glass equation.
import { describe, expect, it } from 'vitest';
import { clamp01, composeGlass, glassFresnel, prepareLight, shadeObject, type PreparedLight } from '../../src/reference/shade';
import { SurfaceHit } from '../../src/reference/surface-hit';
import { GLASS_BODY } from '../../src/scene/default-scene';
import type { Light, Material, Vec3 } from '../../src/scene/scene';
import { expectClose } from './helpers/math';

const f64 = (...v: number[]) => new Float64Array(v);

function material(over: Partial<Material> = {}): Material {
  return {
    ambient: [0.2, 0.4, 0.6], diffuse: [0.5, 0.5, 0.5], specular: [1, 0.5, 0], shininess: 2, opacity: 1,
    texture: { kind: 'none' }, mapping: 'uv', ...over,
  };
}

function light(kind: Light['kind'], vector: Vec3, ambient: Vec3, diffuse: Vec3, specular: Vec3): PreparedLight {
  return prepareLight({ kind, vector, ambient, diffuse, specular });
}

/** A hit at p with normal +z. */
function hitAt(p: [number, number, number] = [0, 0, 0]): SurfaceHit {
  const h = new SurfaceHit();
  h.p.set(p);
  h.n.set([0, 0, 1]);
  return h;
}

describe('clamp01, prepareLight', () => {
  it('clamp01 clamps to [0, 1]', () => {
    expect([-0.5, 0, 0.3, 1, 1.5].map(clamp01)).toEqual([0, 0, 0.3, 1, 1]);
  });

  it('a directional vector is made unit, a point light keeps its position', () => {
    const d = prepareLight({ kind: 'directional', vector: [2, 3, 6], ambient: [1, 2, 3], diffuse: [4, 5, 6], specular: [7, 8, 9] });
    expect(d.point).toBe(false);
    expectClose([d.x, d.y, d.z], [2 / 7, 3 / 7, 6 / 7], 1e-15);
    expect([d.ambient, d.diffuse, d.specular]).toEqual([[1, 2, 3], [4, 5, 6], [7, 8, 9]]);
    const p = prepareLight({ kind: 'point', vector: [3, 0, 4], ambient: [0, 0, 0], diffuse: [0, 0, 0], specular: [0, 0, 0] });
    expect([p.point, p.x, p.y, p.z]).toEqual([true, 3, 0, 4]);
    const zero = prepareLight({ kind: 'directional', vector: [0, 0, 0], ambient: [0, 0, 0], diffuse: [0, 0, 0], specular: [0, 0, 0] });
    expect([zero.x, zero.y, zero.z]).toEqual([0, 0, 0]);
  });
});

describe('shadeObject', () => {
  // L = (0, 0.6, 0.8): N·L = 0.8; eye (0, 0, 5): V = +z; H = (0, 0.6, 1.8), N·H/|H| = 1.8/√3.6, squared 0.9.
  const key = light('directional', [0, 3, 4], [0.1, 0.2, 0.3], [1, 0.5, 0.25], [0.5, 0.5, 0.5]);
  const tex = f64(1, 0.5, 0.25);

  it('one directional light: Ka⊙tex⊙Ia + Kd⊙tex⊙Id·N·L + Ks⊙Is·(N·H)^n', () => {
    // r: 0.2·1·0.1 + 0.5·1·1·0.8 + 1·0.5·0.9 = 0.87; g: 0.4·0.5·0.2 + 0.5·0.5·0.5·0.8 + 0.5·0.5·0.9 = 0.365;
    // b: 0.6·0.25·0.3 + 0.5·0.25·0.25·0.8 + 0 = 0.07.
    const out = f64(9, 9, 9);
    expect(shadeObject(hitAt(), material(), tex, [key], f64(0, 0, 5), out)).toBe(out);
    expectClose(out, [0.87, 0.365, 0.07], 1e-15);
  });

  it('a light behind the surface adds its ambient only; a point light is aimed at from the hit', () => {
    // From p = (1, 2, 3) the point light at (3.4, 5, 6.2) is along (2.4, 3, 3.2) = 5·(0.48, 0.6, 0.64): N·L = 0.64;
    // V = +z (eye (1, 2, 8)): H = (0.48, 0.6, 1.64), (N·H)²/|H|² = 2.6896/3.28 = 0.82.
    // The point light at (1, 2, −1): L = −z, N·L < 0: its ambient only.
    const front = light('point', [3.4, 5, 6.2], [0, 0, 0], [1, 1, 1], [1, 1, 1]);
    const behind = light('point', [1, 2, -1], [0.5, 0.5, 0.5], [9, 9, 9], [9, 9, 9]);
    const out = shadeObject(hitAt([1, 2, 3]), material(), tex, [front, behind], f64(1, 2, 8), new Float64Array(3));
    // r: 0.2·1·0.5 + 0.5·1·0.64 + 1·0.82 = 1.24; g: 0.4·0.5·0.5 + 0.5·0.5·0.64 + 0.5·0.82 = 0.67;
    // b: 0.6·0.25·0.5 + 0.5·0.25·0.64 = 0.155.
    expectClose(out, [1.24, 0.67, 0.155], 1e-15);
  });

  it('a point light at the hit point lights nothing but its ambient', () => {
    const at = light('point', [1, 2, 3], [0.5, 0.5, 0.5], [9, 9, 9], [9, 9, 9]);
    const out = shadeObject(hitAt([1, 2, 3]), material(), tex, [at], f64(1, 2, 8), new Float64Array(3));
    expectClose(out, [0.1, 0.1, 0.075], 1e-15);
  });

  it('a light in the tangent plane (N·L = 0) gives no highlight', () => {
    // L = +x: with V = +z the half vector would be at 45°, (N·H)² = ½.
    const grazing = light('directional', [1, 0, 0], [0, 0, 0], [1, 1, 1], [1, 1, 1]);
    expect([...shadeObject(hitAt(), material(), tex, [grazing], f64(0, 0, 5), new Float64Array(3))]).toEqual([0, 0, 0]);
  });

  it('a tilted normal and an eye off to the side: every component counts', () => {
    // N = (0.48, 0.6, 0.64) at p = (1, 2, 3); L = N (directional): N·L = 1. Eye (1, 6, 6) = p + 5·(0, 0.8, 0.6):
    // H = (0.48, 1.4, 1.24), N·H = 0.2304 + 0.84 + 0.7936 = 1.864, |H|² = 0.2304 + 1.96 + 1.5376 = 3.728: (N·H)²/|H|² = 0.932.
    const h = hitAt([1, 2, 3]);
    h.n.set([0.48, 0.6, 0.64]);
    const l = light('directional', [0.48, 0.6, 0.64], [0, 0, 0], [1, 1, 1], [1, 1, 1]);
    const out = shadeObject(h, material(), tex, [l], f64(1, 6, 6), new Float64Array(3));
    // r: 0.5·1·1 + 1·0.932; g: 0.5·0.5·1 + 0.5·0.932; b: 0.5·0.25·1.
    expectClose(out, [1.432, 0.716, 0.125], 1e-14);
    // Eye (4, 2, 7) = p + 5·(0.6, 0, 0.8): H = (1.08, 0.6, 1.44), N·H = 1.8, |H|² = 3.6: (N·H)²/|H|² = 0.9.
    expectClose(shadeObject(h, material(), tex, [l], f64(4, 2, 7), new Float64Array(3)), [1.4, 0.7, 0.125], 1e-14);
  });

  it('writes the three channels of out and nothing past them', () => {
    const out = shadeObject(hitAt(), material(), tex, [key], f64(0, 0, 5), f64(0, 0, 0, 7));
    expectClose(out, [0.87, 0.365, 0.07, 7], 1e-15);
  });

  it('lights sum; the eye is read once and for every light', () => {
    // Two copies of the key light: twice its sum.
    const out = shadeObject(hitAt(), material(), tex, [key, key], f64(0, 0, 5), new Float64Array(3));
    expectClose(out, [1.74, 0.73, 0.14], 1e-15);
    // A second light lit from another side: L2 = +x tilted, (0.6, 0, 0.8): H2 = (0.6, 0, 1.8), (N·H2)² = 0.9.
    const side = light('directional', [3, 0, 4], [0, 0, 0], [0, 0, 0], [1, 1, 1]);
    const two = shadeObject(hitAt(), material(), tex, [key, side], f64(0, 0, 5), new Float64Array(3));
    expectClose(two, [0.87 + 0.9, 0.365 + 0.45, 0.07], 1e-15);
  });

  it('the eye moves the highlight: V = L mirrored about N puts H on the normal', () => {
    // Eye (2, −5, 8) from p = (2, 1, 0): V = (0, −0.6, 0.8); H = L + V = (0, 0, 1.6), N·H/|H| = 1: Ks⊙Is in full.
    const out = shadeObject(hitAt([2, 1, 0]), material(), tex, [key], f64(2, -5, 8), new Float64Array(3));
    expectClose(out, [0.02 + 0.4 + 0.5, 0.04 + 0.1 + 0.25, 0.07], 1e-15);
  });

  it('N·H below zero gives no highlight, even at an even shininess', () => {
    // Eye (0, −1.4, −4.8), behind the surface: V = (0, −0.28, −0.96), H = (0, 0.32, −0.16), N·H < 0: max(…, 0)² = 0
    // where (N·H/|H|)² = 0.2 would not be.
    const out = shadeObject(hitAt(), material(), tex, [key], f64(0, -1.4, -4.8), new Float64Array(3));
    expectClose(out, [0.02 + 0.4, 0.04 + 0.1, 0.07], 1e-15);
  });

  it('towardsViewer replaces the eye (an orthographic view vector)', () => {
    const out = shadeObject(hitAt(), material(), tex, [key], f64(0, -100, 1), new Float64Array(3), f64(0, 0, 1));
    expectClose(out, [0.87, 0.365, 0.07], 1e-15);
    const twice = shadeObject(hitAt(), material(), tex, [key, key], f64(0, -100, 1), new Float64Array(3), f64(0, 0, 1));
    expectClose(twice, [1.74, 0.73, 0.14], 1e-15);
  });

  it('Ka = Kd: formed as Kd⊙tex⊙(Ia + Id·N·L), to the last bit', () => {
    // L = (0.8, 0, 0.6): N·L = 0.6; Kd = Ka = 0.3, tex 0.3, Ia 0.1, Id 0.9, no specular:
    // 0.3·0.3·(0.1 + 0.54) = 0.0576 as float64, where 0.3·0.3·0.1 + 0.3·0.3·0.54 would be 0.057600000000000005.
    const l = light('directional', [4, 0, 3], [0.1, 0.1, 0.1], [0.9, 0.9, 0.9], [0, 0, 0]);
    const m = material({ ambient: [0.3, 0.3, 0.3], diffuse: [0.3, 0.3, 0.3], specular: [0, 0, 0] });
    const out = shadeObject(hitAt(), m, f64(0.3, 0.3, 0.3), [l], f64(0, 0, 5), new Float64Array(3));
    expect([...out]).toEqual([0.3 * 0.3 * (0.1 + 0.9 * 0.6), 0.0576, 0.0576]);
    expect(0.3 * 0.3 * 0.1 + 0.3 * 0.3 * (0.9 * 0.6)).not.toBe(0.0576);
  });

  it('emission adds to the lit colour', () => {
    const out = shadeObject(hitAt(), material({ emissive: [0.25, 0.5, 1] }), tex, [key], f64(0, 0, 5), new Float64Array(3));
    expectClose(out, [1.12, 0.865, 1.07], 1e-15);
  });

  it('no lights: black, or the emission', () => {
    expect([...shadeObject(hitAt(), material(), tex, [], f64(0, 0, 5), f64(9, 9, 9))]).toEqual([0, 0, 0]);
    expect([...shadeObject(hitAt(), material({ emissive: [0.1, 0.2, 0.3] }), tex, [], f64(0, 0, 5), f64(9, 9, 9))]).toEqual([0.1, 0.2, 0.3]);
  });
});

describe('glassFresnel', () => {
  it('cos θ = |N·D|/|D|, from either side: Schlick at ior 1.5 and cos 0.8 is 0.04 + 0.96·0.2⁵', () => {
    const h = hitAt();
    expect(glassFresnel('schlick', 1.5, h, f64(0, 3, -4))).toBeCloseTo(0.04 + 0.96 * 0.2 ** 5, 15);
    expect(glassFresnel('schlick', 1.5, h, f64(0, -6, 8))).toBeCloseTo(0.04 + 0.96 * 0.2 ** 5, 15);
    // classic: (1 − cos)³ = 0.6³ at cos 0.4.
    expect(glassFresnel('classic', 1.5, h, f64(0.6, 0.6928203230275509, -0.4))).toBeCloseTo(0.216, 12);
    // exact at normal incidence: ((n − 1)/(n + 1))² = 0.04.
    expect(glassFresnel('exact', 1.5, h, f64(0, 0, -2))).toBeCloseTo(0.04, 15);
    // cos θ = 1 exactly along the normal: Schlick gives R0.
    expect(glassFresnel('schlick', 2, h, f64(0, 0, 7))).toBeCloseTo(1 / 9, 15);

    // A tilted normal (0.48, 0.6, 0.64): D = −2·(0.8·N + 0.6·T), T = (0.8, 0, −0.6) ⊥ N: cos θ = 0.8 again.
    const t = hitAt();
    t.n.set([0.48, 0.6, 0.64]);
    expect(glassFresnel('schlick', 1.5, t, f64(-1.728, -0.96, -0.304))).toBeCloseTo(0.04 + 0.96 * 0.2 ** 5, 14);
  });
});

describe('composeGlass', () => {
  const r = f64(0.9, 0.5, 0.1), b = f64(0.2, 0.4, 0.6);
  // D = tex ⊙ (0.7, 0.9, 1)·0.35 = tex ⊙ (0.245, 0.315, 0.35).
  it('D is the tint times the darkness: (0.245, 0.315, 0.35)', () => {
    expectClose(GLASS_BODY, [0.245, 0.315, 0.35], 1e-15);
  });

  it('exact and schlick: F·R + (1 − F)(T·B + (1 − T)·D)', () => {
    // F 0.25, T 0.6, tex 0.5: D = (0.1225, 0.1575, 0.175);
    // r: 0.225 + 0.75·(0.12 + 0.4·0.1225) = 0.35175; g: 0.125 + 0.75·(0.24 + 0.063) = 0.35225; b: 0.025 + 0.75·(0.36 + 0.07) = 0.3475.
    for (const model of ['exact', 'schlick'] as const) {
      const out = f64(9, 9, 9);
      expect(composeGlass(model, 0.25, 0.6, 0.5, r, b, out)).toBe(out);
      expectClose(out, [0.35175, 0.35225, 0.3475], 1e-15);
    }
  });

  it('classic: a = (1 − T)(0.2 + 0.8F), mix(D, R, F)·a + B·(1 − a)', () => {
    // a = 0.4·(0.2 + 0.2) = 0.16; mix(D, R, 0.25) = (0.316875, 0.243125, 0.15625);
    // out = mix·0.16 + B·0.84 = (0.2187, 0.3749, 0.529).
    const out = composeGlass('classic', 0.25, 0.6, 0.5, r, b, new Float64Array(3));
    expectClose(out, [0.2187, 0.3749, 0.529], 1e-15);
  });

  it('writes the three channels of out and nothing past them', () => {
    expectClose(composeGlass('exact', 0.25, 0.6, 0.5, r, b, f64(0, 0, 0, 7)), [0.35175, 0.35225, 0.3475, 7], 1e-15);
    expectClose(composeGlass('classic', 0.25, 0.6, 0.5, r, b, f64(0, 0, 0, 7)), [0.2187, 0.3749, 0.529, 7], 1e-15);
  });

  it('clamped to [0, 1]', () => {
    expect([...composeGlass('schlick', 1, 0, 1, f64(2, -1, 0.5), b, new Float64Array(3))]).toEqual([1, 0, 0.5]);
    expect([...composeGlass('classic', 1, 0, 1, f64(2, -1, 0.5), b, new Float64Array(3))]).toEqual([1, 0, 0.5]);
  });
});
