// The software renderer's glass (docs/rendering.md#the-glass-equation) pixel by pixel against colours worked out here: the
// glass equation F·R + (1 − F)·(T·B + (1 − T)·D), and the classic blend, at
// transparencies where T and 1 − T differ, with each Fresnel model written out in this file
// (never src/math/fresnel.ts), from both sides of the glass.
import { describe, expect, it } from 'vitest';
import { GlassShader, GLASS_INDICES } from '../../src/software/glass-shader';
import { MipTexture } from '../../src/software/mip-texture';
import { Rasterizer } from '../../src/software/raster';
import type { GlassFrame } from '../../src/scene/glass-frame';
import type { FresnelModel } from '../../src/math/fresnel';

// 32×16 pixels, vertical fov 90° (1/tan 45° = 1), aspect 2, the eye 2 units from the glass
// z = 0 on its axis. The glass, 16×8 and centred on the origin, fills the view: its corners
// project to NDC (±2, ±2), exactly on the pixel grid, so snapping moves nothing.
const W = 32, H = 16, ASPECT = W / H, NEAR = 0.1, FAR = 100, DISTANCE = 2;
const FRAME: GlassFrame = {
  plane: [0, 0, 1, 0], a: [1, 0, 0], b: [0, 1, 0],
  corners: [[-8, -4, 0], [8, -4, 0], [8, 4, 0], [-8, 4, 0]],
};

/**
 * Projection × view for eye-relative points, column-major, written out: perspective with
 * f = 1/tan(45°) = 1 (P[0] = f/aspect, P[5] = f, P[10] = (far + near)/(near − far), P[11] = −1,
 * P[14] = 2·far·near/(near − far)); the view looks down −Z from +Z (identity) or down +Z from
 * −Z (a half turn about Y: view x = −x, view z = −z, which negates columns 0 and 2).
 */
function viewProjection(fromFront: boolean): Float64Array {
  const m = new Float64Array(16);
  const s = fromFront ? 1 : -1;
  m[0] = s / ASPECT;
  m[5] = 1;
  m[10] = (s * (FAR + NEAR)) / (NEAR - FAR);
  m[11] = -s;
  m[14] = (2 * FAR * NEAR) / (NEAR - FAR);
  return m;
}

/** cos θ at pixel (i, j): the ray through its centre is (x_ndc·aspect, y_ndc, −1) in view space, the glass normal its z. */
function cosAt(i: number, j: number): number {
  const x = ((2 * (i + 0.5)) / W - 1) * ASPECT, y = 1 - (2 * (j + 0.5)) / H;
  return 1 / Math.hypot(x, y, 1);
}

/** Unpolarised Fresnel from the textbook (Snell's law, then rs and rp). */
function exactByHand(c: number, n: number): number {
  const cosT = Math.sqrt(1 - (1 - c * c) / (n * n));
  const rs = (c - n * cosT) / (c + n * cosT);
  const rp = (n * c - cosT) / (n * c + cosT);
  return (rs * rs + rp * rp) / 2;
}

function fresnelByHand(model: FresnelModel, c: number, n: number): number {
  if (model === 'classic') return (1 - c) ** 3;
  if (model === 'schlick') {
    const r0 = ((n - 1) / (n + 1)) ** 2;
    return r0 + (1 - r0) * (1 - c) ** 5;
  }
  return exactByHand(c, n);
}

// What lies behind (B), the reflection (R) and the glass texture's grey (a 1×1 texture, so every
// level and filter gives it): three different colours so a swapped operand shows in some channel.
const B = [0.6, 0.3, 0.1];
const R = [0.2, 0.5, 0.9];
const GREY = 0.8;
/** D = tex ⊙ (0.7, 0.9, 1.0) ⊙ 0.35 (docs/rendering.md#the-glass-equation). */
const D = [0.7, 0.9, 1.0].map((k) => GREY * k * 0.35);

function glassEquation(model: FresnelModel, c: number, ior: number, t: number): number[] {
  const f = fresnelByHand(model, c, ior);
  if (model === 'classic') {
    // Classic: colour = mix(D, R, F), alpha = (1 − T)(0.2 + 0.8F), straight alpha blending.
    const a = (1 - t) * (0.2 + 0.8 * f);
    return D.map((d, k) => (d + (R[k] - d) * f) * a + B[k] * (1 - a));
  }
  return D.map((d, k) => f * R[k] + (1 - f) * (t * B[k] + (1 - t) * d));
}

/** Draws the glass over a frame filled with B (reflection R) and returns the colour buffer. */
function drawGlass(mode: 'compose' | 'fresnel', model: FresnelModel, ior: number, t: number, fromFront = true): Float32Array {
  const r = new Rasterizer(W, H);
  r.clearDepth();
  const g = new GlassShader();
  g.mode = mode;
  g.model = model;
  g.ior = ior;
  g.transparency = t;
  g.texture = new MipTexture(1, 1, 1, new Float32Array([GREY]));
  g.colour = new Float32Array(3 * W * H);
  g.reflection = new Float32Array(3 * W * H);
  for (let p = 0; p < W * H; p++) {
    g.colour.set(B, 3 * p);
    g.reflection.set(R, 3 * p);
  }
  g.setup(FRAME, [0, 0, fromFront ? DISTANCE : -DISTANCE], viewProjection(fromFront), [0, 0, 0, 1]);
  g.draw(r, GLASS_INDICES);
  return g.colour;
}

/** The largest difference from `expected(i, j)` over every pixel and channel. */
function worstError(colour: Float32Array, expected: (i: number, j: number) => number[]): number {
  let worst = 0;
  for (let j = 0; j < H; j++) {
    for (let i = 0; i < W; i++) {
      const e = expected(i, j), o = 3 * (j * W + i);
      for (let k = 0; k < 3; k++) worst = Math.max(worst, Math.abs(colour[o + k] - e[k]));
    }
  }
  return worst;
}

// The colour buffer is Float32: 1e-6 is a few float32 steps at these values; every defect
// below (a swapped T, another model's F, a lost |N·V|) moves some pixel by more than 1e-3.
const EPS = 1e-6;

describe('software glass, every pixel against the hand-computed glass colour', () => {
  it('the view spans cos θ from 0.43 to 1 (65° to normal incidence)', () => {
    expect(cosAt(0, 0)).toBeCloseTo(1 / Math.hypot(31 / 16, 15 / 16, 1), 12);
    expect(cosAt(0, 0)).toBeLessThan(0.44);
    expect(cosAt(15, 7)).toBeGreaterThan(0.99);
  });

  for (const model of ['exact', 'schlick', 'classic'] as const) {
    for (const t of [0.2, 0.9]) {
      it(`${model}, T = ${t}, ior 1.5`, () => {
        const worst = worstError(drawGlass('compose', model, 1.5, t), (i, j) => glassEquation(model, cosAt(i, j), 1.5, t));
        expect(worst).toBeLessThan(EPS);
      });
    }
  }

  it('ior 1.33 and T = 0.35 (exact and Schlick depend on ior, classic does not)', () => {
    for (const model of ['exact', 'schlick', 'classic'] as const) {
      const worst = worstError(drawGlass('compose', model, 1.33, 0.35), (i, j) => glassEquation(model, cosAt(i, j), 1.33, 0.35));
      expect(worst, model).toBeLessThan(EPS);
    }
  });

  it('seen from behind the glass (eye at z = −2): the same colours, cos θ = abs(N·V)', () => {
    for (const model of ['exact', 'schlick', 'classic'] as const) {
      // The half turn mirrors x, and cosAt is symmetric in x: pixel (i, j) sees cos θ of (i, j).
      const worst = worstError(drawGlass('compose', model, 1.5, 0.2, false), (i, j) => glassEquation(model, cosAt(i, j), 1.5, 0.2));
      expect(worst, model).toBeLessThan(EPS);
    }
  });

  it('debug-view fresnel writes F of the chosen model, and the three models differ here', () => {
    for (const model of ['exact', 'schlick', 'classic'] as const) {
      const worst = worstError(drawGlass('fresnel', model, 1.5, 0.5), (i, j) => [0, 1, 2].map(() => fresnelByHand(model, cosAt(i, j), 1.5)));
      expect(worst, model).toBeLessThan(EPS);
    }
    // At the corner pixel (cos θ ≈ 0.43) the models are far apart, so a wrong one shows.
    const c = cosAt(0, 0);
    expect(Math.abs(fresnelByHand('exact', c, 1.5) - fresnelByHand('schlick', c, 1.5))).toBeGreaterThan(5e-3);
    expect(Math.abs(fresnelByHand('exact', c, 1.5) - fresnelByHand('classic', c, 1.5))).toBeGreaterThan(0.05);
  });
});
