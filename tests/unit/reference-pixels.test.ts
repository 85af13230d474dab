// The reference renderer against pixels computed by hand: shading, camera rays, glass, Fresnel anchors.
// Expected values use the numbers of docs/default-scene.md and docs/rendering.md written out here, not the modules under test.
import { describe, expect, it } from 'vitest';
import { renderReference, REGION_BACKGROUND, REGION_CUBE, REGION_GLASS, REGION_SPHERE, type ReferenceState } from '../../src/reference';
import { texel } from '../../src/scene/procedural-texture';
import { defaultFrameState } from './helpers/frame-state';

const STATE: ReferenceState = defaultFrameState({
  width: 33, height: 33, spin: 0, cubeDistance: 2.5, cameraPosition: [0, 1, 6], yaw: -90, pitch: 0, colorSpace: 'none',
});
const BG = 0.1;
const L = [0.4, 1, 0.6].map((c) => c / Math.hypot(0.4, 1, 0.6));
const TINT_DARK = [0.7 * 0.35, 0.9 * 0.35, 1.0 * 0.35];

/** The default Blinn-Phong (docs/default-scene.md#material-and-lighting) for a surface with normal n seen head-on (V = N = n, default +Z). */
function facingShade(albedo: number[], tex: number, n = [0, 0, 1]): number[] {
  const nl = n[0] * L[0] + n[1] * L[1] + n[2] * L[2];
  const h = [L[0] + n[0], L[1] + n[1], L[2] + n[2]];
  const nh = (n[0] * h[0] + n[1] * h[1] + n[2] * h[2]) / Math.hypot(h[0], h[1], h[2]);
  return albedo.map((a) => a * tex * (0.15 + 0.85 * Math.max(nl, 0)) + (nl > 0 ? 0.5 * nh ** 32 : 0));
}

/** Camera 4 units out along n from p, looking back along −n (yaw, pitch in degrees). */
function lookingAlong(p: number[], n: number[]): Pick<ReferenceState, 'cameraPosition' | 'yaw' | 'pitch'> {
  const deg = 180 / Math.PI;
  return {
    cameraPosition: [p[0] + 4 * n[0], p[1] + 4 * n[1], p[2] + 4 * n[2]],
    yaw: Math.atan2(-n[2], -n[0]) * deg,
    pitch: Math.asin(-n[1]) * deg,
  };
}

/** The texture's bilinear value at UV, from texels, written independently of the sampler. */
function bilinearByHand(u: number, v: number): number {
  const s = u * 512 - 0.5, t = v * 512 - 0.5;
  const i = Math.floor(s), j = Math.floor(t), x = s - i, y = t - j;
  const at = (a: number, b: number) => texel(((a % 512) + 512) % 512, ((b % 512) + 512) % 512) / 255;
  return at(i, j) * (1 - x) * (1 - y) + at(i + 1, j) * x * (1 - y) + at(i, j + 1) * (1 - x) * y + at(i + 1, j + 1) * x * y;
}

/** Unpolarised Fresnel written from the textbook form (Snell's law, then rs and rp). */
function fresnelByHand(cosI: number, n: number): number {
  const sinT = Math.sqrt(1 - cosI * cosI) / n;
  const cosT = Math.sqrt(1 - sinT * sinT);
  const rs = (cosI - n * cosT) / (cosI + n * cosT);
  const rp = (cosT - n * cosI) / (cosT + n * cosI);
  return (rs * rs + rp * rp) / 2;
}

function rgbAt(img: { width: number; rgb: Float64Array }, x: number, y: number): number[] {
  const i = 3 * (y * img.width + x);
  return [img.rgb[i], img.rgb[i + 1], img.rgb[i + 2]];
}

function expectRgb(actual: number[], expected: number[], eps = 1e-9): void {
  for (let k = 0; k < 3; k++) expect(Math.abs(actual[k] - expected[k]), `channel ${k}: ${actual[k]} vs ${expected[k]}`).toBeLessThanOrEqual(eps);
}

// A glass point whose UV is the centre of texel (100, 300): x = 100.5/64 − 4, y = 300.5/128 − 1.
const GLASS_POINT = [100.5 / 64 - 4, 300.5 / 128 - 1] as const;
const GLASS_TEX = texel(100, 300) / 255;

describe('hand-computed pixels', () => {
  it('the cube\'s +Z face at the centre of texel (200, 350), seen head-on', () => {
    // u = x + 1.5, v = y − 0.5 on the +Z face of the unrotated cube at (−1, 1, 2.5); face at z = 3.
    const x = 200.5 / 512 - 1.5, y = 350.5 / 512 + 0.5;
    const img = renderReference({ ...STATE, cameraPosition: [x, y, 7] });
    const expected = facingShade([0.8, 0.3, 0.3], texel(200, 350) / 255);
    expectRgb(rgbAt(img, 16, 16), expected);
    expect(Array.from(img.rgba.slice(4 * (16 * 33 + 16), 4 * (16 * 33 + 16) + 4))).toEqual([...expected.map((c) => Math.round(c * 255)), 255]);
    expect(img.regions[16 * 33 + 16]).toBe(REGION_CUBE);
  });

  it('the sphere\'s nearest point: UV (½, ½) is the mean of four texels across a checker corner', () => {
    const img = renderReference({ ...STATE, view: 'scene', cameraPosition: [1, 1, 5] });
    const tex = (texel(255, 255) + texel(256, 255) + texel(255, 256) + texel(256, 256)) / 4 / 255;
    expectRgb(rgbAt(img, 16, 16), facingShade([0.3, 0.8, 0.3], tex));
    expect(img.regions[16 * 33 + 16]).toBe(REGION_SPHERE);
  });

  it('the rotated cube (spin·time = π/6): the +Z face turns towards +X, as gl-matrix rotateY does', () => {
    // R_y(θ)·(x, y, z) = (x cos θ + z sin θ, y, −x sin θ + z cos θ); the +Z face's normal → (sin θ, 0, cos θ).
    const th = Math.PI / 6, c = Math.cos(th), sn = Math.sin(th);
    const a = 100.5 / 512 - 0.5, b = 400.5 / 512 - 0.5; // face point (a, b, ½): UV = (a + ½, b + ½)
    const p = [-1 + a * c + 0.5 * sn, 1 + b, 2.5 - a * sn + 0.5 * c];
    const n = [sn, 0, c];
    const img = renderReference({ ...STATE, view: 'scene', spin: 1, time: th, ...lookingAlong(p, n) });
    expectRgb(rgbAt(img, 16, 16), facingShade([0.8, 0.3, 0.3], texel(100, 400) / 255, n));
  });

  it('an off-axis sphere point: u = ½ + atan2(n.x, n.z)/2π, v = acos(−n.y)/π', () => {
    const n = [0.48, 0.6, 0.64];
    const p = [1 + 0.75 * n[0], 1 + 0.75 * n[1], -1.5 + 0.75 * n[2]];
    const img = renderReference({ ...STATE, view: 'scene', ...lookingAlong(p, n) });
    const tex = bilinearByHand(0.5 + Math.atan2(0.48, 0.64) / (2 * Math.PI), Math.acos(-0.6) / Math.PI);
    expectRgb(rgbAt(img, 16, 16), facingShade([0.3, 0.8, 0.3], tex, n));
  });

  it('an off-centre glass pixel: NDC mapping (top row first, aspect), glass UV, bilinear texture and Fresnel angle', () => {
    const s: ReferenceState = { ...STATE, width: 40, height: 20, cameraPosition: [-2.5, 1, 3] };
    const img = renderReference(s);
    const [px, py] = [16, 6];
    const tanY = Math.tan(Math.PI / 6), tanX = tanY * 2;
    const d = [((2 * (px + 0.5)) / 40 - 1) * tanX, (1 - (2 * (py + 0.5)) / 20) * tanY, -1];
    const hit = [-2.5 + 3 * d[0], 1 + 3 * d[1]];
    const tex = bilinearByHand((hit[0] + 4) / 8, (hit[1] + 1) / 4);
    const f = fresnelByHand(1 / Math.hypot(d[0], d[1], d[2]), 1.5);
    const expected = TINT_DARK.map((t) => f * BG + (1 - f) * (0.5 * BG + 0.5 * tex * t));
    expectRgb(rgbAt(img, px, py), expected);
    expect(img.regions[py * 40 + px]).toBe(REGION_GLASS);
  });

  it('a reflected pixel: the cube\'s top face seen in the glass, shaded with V towards the mirrored eye', () => {
    // X on the top face (y = 1.5) at the centre of texel (300, 200): u = x + 1.5, v = 3 − z.
    const X = [300.5 / 512 - 1.5, 1.5, 3 - 200.5 / 512];
    const eye: [number, number, number] = [X[0], 3.5, 1];
    const mirroredEye = [eye[0], eye[1], -eye[2]];
    // The mirror ray E′→X crosses the glass at P; the camera looks straight at P.
    const s = mirroredEye[2] / (mirroredEye[2] - X[2]);
    const P = [X[0], mirroredEye[1] + s * (X[1] - mirroredEye[1]), 0];
    const pitch = (Math.atan2(P[1] - eye[1], eye[2]) * 180) / Math.PI;
    const state: ReferenceState = { ...STATE, cameraPosition: eye, pitch };

    const v = [0, mirroredEye[1] - X[1], mirroredEye[2] - X[2]];
    const vl = Math.hypot(v[0], v[1], v[2]);
    const h = [L[0] + v[0] / vl, L[1] + v[1] / vl, L[2] + v[2] / vl];
    const nh = h[1] / Math.hypot(h[0], h[1], h[2]);
    const tex = texel(300, 200) / 255;
    const r = [0.8, 0.3, 0.3].map((a) => Math.min(1, a * tex * (0.15 + 0.85 * L[1]) + 0.5 * nh ** 32));
    expectRgb(rgbAt(renderReference({ ...state, view: 'reflection' }), 16, 16), r);

    // The final pixel: the glass equation with that R, B = background, D from the glass texture at P.
    const f = fresnelByHand(1 / Math.hypot(P[1] - eye[1], eye[2]), 1.5);
    const d = bilinearByHand((P[0] + 4) / 8, (P[1] + 1) / 4);
    const expected = TINT_DARK.map((k, c) => f * r[c] + (1 - f) * (0.5 * BG + 0.5 * d * k));
    expectRgb(rgbAt(renderReference(state), 16, 16), expected);
  });

  it('a pixel that sees nothing is the background', () => {
    const img = renderReference({ ...STATE, cameraPosition: [0, 50, 6] });
    expectRgb(rgbAt(img, 16, 16), [BG, BG, BG], 0);
    expect(img.regions[16 * 33 + 16]).toBe(REGION_BACKGROUND);
  });
});

describe('Fresnel anchors through a glass pixel with nothing behind or reflected', () => {
  const headOn: ReferenceState = { ...STATE, cameraPosition: [GLASS_POINT[0], GLASS_POINT[1], 4] };
  const glassEquation = (f: number, t: number) => TINT_DARK.map((k) => f * BG + (1 - f) * (t * BG + (1 - t) * GLASS_TEX * k));

  it('normal incidence: F = 0.04 (exact and Schlick), and the glass equation with it', () => {
    for (const fresnel of ['exact', 'schlick'] as const) {
      expect(rgbAt(renderReference({ ...headOn, fresnel, view: 'fresnel' }), 16, 16)[0]).toBeCloseTo(0.04, 12);
      expectRgb(rgbAt(renderReference({ ...headOn, fresnel }), 16, 16), glassEquation(0.04, 0.5));
    }
  });

  it('classic at normal incidence: F = 0, out = D·a + B·(1 − a) with a = 0.2(1 − T)', () => {
    const t = 0.3, a = 0.2 * (1 - t);
    expect(rgbAt(renderReference({ ...headOn, fresnel: 'classic', view: 'fresnel' }), 16, 16)[0]).toBe(0);
    const expected = TINT_DARK.map((k) => GLASS_TEX * k * a + BG * (1 - a));
    expectRgb(rgbAt(renderReference({ ...headOn, fresnel: 'classic', transparency: t }), 16, 16), expected);
  });

  it('Brewster\'s angle for ior 1.5 (56.31°): F = 0.07396 = ½((n² − 1)/(n² + 1))²', () => {
    const theta = Math.atan(1.5);
    // forward = (−sin θ, 0, −cos θ): yaw −90° − θ; the eye 4 units back from the glass point.
    const f = [-Math.sin(theta), 0, -Math.cos(theta)];
    const eye: [number, number, number] = [GLASS_POINT[0] - 4 * f[0], GLASS_POINT[1], -4 * f[2]];
    const s: ReferenceState = { ...STATE, cameraPosition: eye, yaw: -90 - (theta * 180) / Math.PI };
    const F = rgbAt(renderReference({ ...s, view: 'fresnel' }), 16, 16)[0];
    expect(Math.abs(F - 0.07396)).toBeLessThan(5e-6);
    expect(Math.abs(F - 0.5 * (1.25 / 3.25) ** 2)).toBeLessThan(1e-12);
    expectRgb(rgbAt(renderReference(s), 16, 16), glassEquation(F, 0.5));
  });

  it('transparency 0.2 and 0.9, where T and 1 − T differ: the glass equation at normal incidence', () => {
    for (const t of [0.2, 0.9]) {
      for (const fresnel of ['exact', 'schlick'] as const) {
        expectRgb(rgbAt(renderReference({ ...headOn, fresnel, transparency: t }), 16, 16), glassEquation(0.04, t));
      }
    }
  });

  it('each model at 56.31° with T = 0.2: exact, Schlick R0 + (1 − R0)(1 − cos θ)^5, classic (1 − cos θ)^3', () => {
    const theta = Math.atan(1.5), c = Math.cos(theta), t = 0.2;
    const f = [-Math.sin(theta), 0, -Math.cos(theta)];
    const eye: [number, number, number] = [GLASS_POINT[0] - 4 * f[0], GLASS_POINT[1], -4 * f[2]];
    const s: ReferenceState = { ...STATE, cameraPosition: eye, yaw: -90 - (theta * 180) / Math.PI, transparency: t };
    expectRgb(rgbAt(renderReference({ ...s, fresnel: 'exact' }), 16, 16), glassEquation(0.5 * (1.25 / 3.25) ** 2, t));
    const schlick = 0.04 + 0.96 * (1 - c) ** 5;
    expect(rgbAt(renderReference({ ...s, fresnel: 'schlick', view: 'fresnel' }), 16, 16)[0]).toBeCloseTo(schlick, 12);
    expectRgb(rgbAt(renderReference({ ...s, fresnel: 'schlick' }), 16, 16), glassEquation(schlick, t));
    // Classic: colour = mix(D, R, F), a = (1 − T)(0.2 + 0.8F), straight alpha over B; R = B = background here.
    const classic = (1 - c) ** 3, a = (1 - t) * (0.2 + 0.8 * classic);
    const expected = TINT_DARK.map((k) => (GLASS_TEX * k + (BG - GLASS_TEX * k) * classic) * a + BG * (1 - a));
    expectRgb(rgbAt(renderReference({ ...s, fresnel: 'classic' }), 16, 16), expected);
  });

  it('near grazing incidence (cos θ = 0.01) F is close to 1, as the textbook formula says', () => {
    // Eye 0.02 above the plane, yaw 180° + asin(0.01): the centre ray meets the glass 2 units on.
    const yaw = 180 + (Math.asin(0.01) * 180) / Math.PI;
    const F = rgbAt(renderReference({ ...STATE, cameraPosition: [3.9, 1, 0.02], yaw, view: 'fresnel' }), 16, 16)[0];
    expect(Math.abs(F - fresnelByHand(0.01, 1.5))).toBeLessThan(1e-9);
    expect(F).toBeGreaterThan(0.9);
  });
});
