// The software glass shader (src/software/glass-shader.ts) beyond software-glass.test.ts's uniform colours: what draw()
// sets on the rasterizer and restores, the footprint (mask mode), the texture read through the glass's UV and its
// screen derivatives, an orthographic view vector, the clamps, rough glass's gathered R̃ and B̃ (a stand-in gather),
// multisampling, and the frame-to-frame cache (a frame after a change shades as a fresh shader does; the texture reads it
// saves, counted, and each number of its key alone), the glass equation at F between 0 and 1 for each model, and a
// rolled camera's UV, derivatives and depth against rays cast here.
import { describe, expect, it } from 'vitest';
import { mat4 } from 'gl-matrix';
import { GlassShader, GLASS_INDICES, GLASS_TIE_BIAS, type GlassMode } from '../../src/software/glass-shader';
import { MipTexture } from '../../src/software/mip-texture';
import { Rasterizer } from '../../src/software/raster';
import type { RoughGather } from '../../src/software/rough-gather';
import type { GlassFrame } from '../../src/scene/glass-frame';
import { fresnel, type FresnelModel } from '../../src/math/fresnel';

// software-glass.test.ts's view: 32×16 pixels, fov 90°, the eye 2 units in front of the 16×8 glass z = 0, whose corners
// project onto NDC (±2, ±2): the glass fills the view, u = (x + 8)/16 and v = (y + 4)/8 affine in the screen (the
// glass faces the camera): pixel (i, j) reads u = (i + ½)/32, v = 1 − (j + ½)/16.
const W = 32, H = 16, NEAR = 0.1, FAR = 100;
const FRAME: GlassFrame = {
  plane: [0, 0, 1, 0], a: [1, 0, 0], b: [0, 1, 0],
  corners: [[-8, -4, 0], [8, -4, 0], [8, 4, 0], [-8, 4, 0]],
};
const VP = (() => {
  const m = new Float64Array(16);
  m[0] = H / W; m[5] = 1; m[10] = (FAR + NEAR) / (NEAR - FAR); m[11] = -1; m[14] = (2 * FAR * NEAR) / (NEAR - FAR);
  return m;
})();
const EYE = [0, 0, 2];
const BODY = [0.7 * 0.35, 0.9 * 0.35, 1.0 * 0.35];
/** Normal incidence: exact Fresnel ((n − 1)/(n + 1))², 0.04 at ior 1.5. */
const F0 = 0.04;

interface Settings {
  mode?: GlassMode;
  model?: FresnelModel;
  ior?: number;
  transparency?: number;
  texture?: MipTexture;
  view?: number[];
  frame?: GlassFrame;
  rough?: RoughGather | null;
  roughTransmission?: boolean;
  B?: number[];
  R?: number[];
}
const GREY = new MipTexture(1, 1, 1, new Float32Array([0.8]));

/** A shader set up for one frame over a colour buffer of B and a reflection of R (per sample). */
function apply(g: GlassShader, s: Settings, samples: number): void {
  g.mode = s.mode ?? 'compose';
  g.model = s.model ?? 'exact';
  g.ior = s.ior ?? 1.5;
  g.transparency = s.transparency ?? 0.5;
  g.texture = s.texture ?? GREY;
  g.rough = s.rough ?? null;
  g.roughTransmission = s.roughTransmission ?? false;
  g.colour = new Float32Array(3 * samples);
  g.reflection = new Float32Array(3 * samples);
  g.mask = new Uint8Array(samples);
  for (let p = 0; p < samples; p++) {
    g.colour.set(s.B ?? [0.6, 0.3, 0.1], 3 * p);
    g.reflection.set(s.R ?? [0.2, 0.5, 0.9], 3 * p);
  }
  g.setup(s.frame ?? FRAME, EYE, VP, s.view ?? [0, 0, 0, 1]);
}

function rasterizer(n = 1): Rasterizer {
  const r = new Rasterizer(W * n, H * n);
  r.shadeEvery = n;
  r.clearDepth();
  return r;
}

/** The colour buffer after drawing each settings in turn with one shader and one rasterizer (the last frame's). */
function frames(list: Settings[], n = 1): Float32Array {
  const g = new GlassShader(), r = rasterizer(n);
  for (const s of list) {
    apply(g, s, W * H * n * n);
    r.clearDepth();
    g.draw(r, GLASS_INDICES);
  }
  return g.colour;
}

const at = (c: Float32Array, i: number, j: number) => [c[3 * (j * W + i)], c[3 * (j * W + i) + 1], c[3 * (j * W + i) + 2]];

describe('GlassShader.draw and the rasterizer', () => {
  it('draws with no culling, no user plane, the depth test on, no depth write; the bias and barycentrics restored', () => {
    const g = new GlassShader(), r = rasterizer();
    apply(g, { mode: 'fresnel' }, W * H);
    r.cull = 'back';
    r.frontCCW = false; // the glass's corners run counter-clockwise: culled as back faces here, were culling kept
    r.userClip = true; // its vertices' user distance is 0: kept either way
    r.depthTest = false;
    r.depthWrite = true;
    r.depthBias = 0.5;
    r.barycentrics = false;
    // Something at NDC depth −1 (nearest) over the left half: the glass is hidden there.
    for (let j = 0; j < H; j++) for (let i = 0; i < W / 2; i++) r.depth[j * W + i] = -1;
    g.draw(r, GLASS_INDICES);
    expect(at(g.colour, 3, 5)).toEqual([0.6, 0.3, 0.1].map(Math.fround));
    expect(at(g.colour, 20, 5)[0]).toBeLessThan(0.2); // F, at most 0.09 in this view
    expect(r.depth[5 * W + 20]).toBe(Infinity);
    expect([r.depthBias, r.barycentrics, r.depthTest, r.depthWrite, r.cull, r.userClip]).toEqual([0, true, true, false, 'none', false]);
  });

  it('is pushed back by GLASS_TIE_BIAS: a surface at the glass depth plus less than the bias is in front of it', () => {
    // The glass at NDC depth z (everywhere equal: it faces the camera) = (far + near)/(far − near) − 2·far·near/((far − near)·2).
    const z = Math.fround((FAR + NEAR) / (FAR - NEAR) - (2 * FAR * NEAR) / ((FAR - NEAR) * 2));
    const g = new GlassShader(), r = rasterizer();
    apply(g, { mode: 'fresnel' }, W * H);
    r.depth.fill(Math.fround(z + GLASS_TIE_BIAS / 2));
    g.draw(r, GLASS_INDICES);
    expect(at(g.colour, 20, 5)[0]).toBeCloseTo(0.6, 6);
    r.depth.fill(Math.fround(z + 2 * GLASS_TIE_BIAS));
    g.draw(r, GLASS_INDICES);
    expect(at(g.colour, 20, 5)[0]).toBeLessThan(0.2);
  });

  it("mode 'mask' sets the footprint's bytes to 1 and leaves the colour", () => {
    const g = new GlassShader(), r = rasterizer();
    apply(g, { mode: 'mask', frame: { ...FRAME, corners: [[-8, -4, 0], [0, -4, 0], [0, 4, 0], [-8, 4, 0]] } }, W * H);
    g.draw(r, GLASS_INDICES);
    // The left half of the glass: x < 0, the left 16 columns.
    for (let j = 0; j < H; j++) for (let i = 0; i < W; i++) expect(g.mask[j * W + i], `${i},${j}`).toBe(i < 16 ? 1 : 0);
    expect(at(g.colour, 3, 3)).toEqual([0.6, 0.3, 0.1].map(Math.fround));
    // Multisampled: every sample of the footprint.
    const m = new GlassShader(), r2 = rasterizer(2);
    apply(m, { mode: 'mask' }, 4 * W * H);
    m.draw(r2, GLASS_INDICES);
    expect(m.mask.every((b) => b === 1)).toBe(true);
  });
});

describe('the glass equation at a pixel', () => {
  it('a new shader composes (exact Fresnel, ior 1.5, T = ½), polished, without rough transmission', () => {
    const g = new GlassShader(), r = rasterizer();
    g.texture = GREY;
    g.colour = new Float32Array(3 * W * H).fill(0.25);
    g.reflection = new Float32Array(3 * W * H).fill(0.75);
    g.setup(FRAME, EYE, VP, [0, 0, 1, 0]);
    g.draw(r, GLASS_INDICES);
    // F = 0.04: 0.04·0.75 + 0.96·(½·0.25 + ½·0.8·BODY).
    at(g.colour, 4, 4).forEach((x, k) => expect(x).toBeCloseTo(0.04 * 0.75 + 0.96 * (0.125 + 0.4 * BODY[k]), 6));
    expect([g.mode, g.model, g.ior, g.transparency, g.rough, g.roughTransmission]).toEqual(['compose', 'exact', 1.5, 0.5, null, false]);
  });

  it('an orthographic view vector (w = 0) gives cos θ = |N·V| = 1 everywhere: F = 0.04', () => {
    const c = frames([{ mode: 'fresnel', view: [0, 0, 1, 0] }]);
    for (const [i, j] of [[0, 0], [31, 15], [16, 8]]) expect(at(c, i, j)).toEqual([F0, F0, F0].map(Math.fround));
    // Seen from the glass's other side (V = −N): the same.
    expect(at(frames([{ mode: 'fresnel', view: [0, 0, -1, 0] }]), 0, 0)[0]).toBe(Math.fround(F0));
  });

  it('clamps R to 1 before mixing and the result to [0, 1]', () => {
    // Orthographic: F = 0.04. T = 0, B = 0, D = 0.8·BODY: out = 0.04·min(R, 1) + 0.96·D.
    const c = frames([{ view: [0, 0, 1, 0], transparency: 0, B: [0, 0, 0], R: [3, 0.5, 0] }]);
    const want = [0.04 * 1 + 0.96 * 0.8 * BODY[0], 0.04 * 0.5 + 0.96 * 0.8 * BODY[1], 0.96 * 0.8 * BODY[2]];
    at(c, 7, 7).forEach((x, k) => expect(x).toBeCloseTo(want[k], 6));
    // T = 1 over B = (−2, 5, 0.5): 0.04·R + 0.96·B clamped: 0, 1, and 0.04·0.2... + 0.48.
    const d = frames([{ view: [0, 0, 1, 0], transparency: 1, B: [-2, 5, 0.5], R: [0.2, 0.2, 0.2] }]);
    expect(at(d, 7, 7)).toEqual([0, 1, Math.fround(0.04 * 0.2 + 0.96 * 0.5)]);
    // Classic: colour = mix(D, R, F), alpha = (1 − T)(0.2 + 0.8F); F = 0 at cos θ = 1 ((1 − c)³): alpha = 0.2(1 − T).
    const e = frames([{ model: 'classic', view: [0, 0, 1, 0], transparency: 0, B: [-5, 5, 0.5], R: [3, 3, 3] }]);
    expect(at(e, 7, 7)).toEqual([0, 1, Math.fround(0.8 * BODY[2] * 0.2 + 0.5 * 0.8)]);
  });

  it("reads the texture at the glass's UV with its screen derivatives: 64×32 texels a texel a pixel, 256×128 two levels down", () => {
    // The view sees the glass's middle half: u = 0.25 + (2i + 1)/128, v = 0.75 − (2j + 1)/64 at pixel (i, j), a texel
    // of 64×32 a pixel: s = 64u − ½ = 16 + i, t = 32v − ½ = 23 − j, exactly on texel (16 + i, 23 − j).
    const tex64 = new MipTexture(1, 64, 32, Float32Array.from({ length: 2048 }, (_, p) => ((p % 64) + 64 * Math.floor(p / 64)) / 4096));
    // T = 0, B = R = 0, orthographic (F = 0.04): out = 0.96·tex·BODY.
    const base = { view: [0, 0, 1, 0], transparency: 0, B: [0, 0, 0], R: [0, 0, 0] };
    const c = frames([{ ...base, texture: tex64 }]);
    for (const [i, j] of [[0, 0], [5, 3], [31, 15], [17, 9]]) {
      expect(at(c, i, j)[2] / (0.96 * BODY[2]), `${i},${j}`).toBeCloseTo((16 + i + 64 * (23 - j)) / 4096, 5);
    }
    // 256×128 texels: four a pixel either way, λ = 2: level 2's texel (16 + i, 23 − j), the mean of level 0's 4×4
    // block under it (with the derivatives lost, level 0 read bilinearly would give the mean of its middle 2×2 only).
    const val = (x: number, y: number) => ((x * 37 + y * 91) % 17) / 16;
    const tex256 = new MipTexture(1, 256, 128, Float32Array.from({ length: 256 * 128 }, (_, p) => val(p % 256, Math.floor(p / 256))));
    const d = frames([{ ...base, texture: tex256 }]);
    for (const [i, j] of [[0, 0], [5, 3], [31, 15]]) {
      let mean = 0;
      for (let y = 0; y < 4; y++) for (let x = 0; x < 4; x++) mean += val(4 * (16 + i) + x, 4 * (23 - j) + y) / 16;
      expect(at(d, i, j)[2] / (0.96 * BODY[2]), `${i},${j}`).toBeCloseTo(mean, 5);
    }
  });
});

describe('rough glass: the gathered R̃ and B̃ replace the sample\'s R and B', () => {
  /** A stand-in gather: R̃ = (0.9, 0.1, 0.4) for pass 0, B̃ = (0.3, 0.3, 0.8) for pass 1; each whether it had any. */
  function gather(hasR: boolean, hasB: boolean, seen: number[][] = []): RoughGather {
    return {
      gather(out: Float64Array, rel: ArrayLike<number>, pass: 0 | 1): boolean {
        seen.push([rel[0], rel[1], rel[2], pass]);
        out.set(pass === 0 ? [0.9, 0.1, 0.4] : [0.3, 0.3, 0.8]);
        return pass === 0 ? hasR : hasB;
      },
    } as unknown as RoughGather;
  }
  const base = { view: [0, 0, 1, 0], transparency: 0.5, B: [0.6, 0.3, 0.1], R: [0.2, 0.5, 0.9] };
  const D = BODY.map((k) => 0.8 * k);
  const glass = (f: number, r: number[], b: number[]) => D.map((d, k) => f * r[k] + (1 - f) * (0.5 * b[k] + 0.5 * d));

  for (const [hasR, hasB] of [[true, true], [true, false], [false, true], [false, false]]) {
    it(`R̃ ${hasR ? 'gathered' : 'none (R kept)'}, B̃ ${hasB ? 'gathered' : 'none (B kept)'}, with roughTransmission`, () => {
      const seen: number[][] = [];
      const c = frames([{ ...base, rough: gather(hasR, hasB, seen), roughTransmission: true }]);
      const want = glass(F0, hasR ? [0.9, 0.1, 0.4] : base.R, hasB ? [0.3, 0.3, 0.8] : base.B);
      at(c, 9, 4).forEach((x, k) => expect(x).toBeCloseTo(want[k], 6));
      // Gathered at each fragment's eye-relative point: pixel (9, 4) sees the glass at x = 16u − 8 = −1.625 (u = 0.25 +
      // 19/128), y = 8v − 4 = 0.875 (v = 0.75 − 9/64), 2 below the eye; pass 0, then pass 1.
      const near = (p: number[], pass: number) => Math.abs(p[0] + 1.625) < 1e-9 && Math.abs(p[1] - 0.875) < 1e-9 && p[2] === -2 && p[3] === pass;
      expect(seen.filter((p) => near(p, 0))).toHaveLength(1);
      expect(seen.filter((p) => near(p, 1))).toHaveLength(1);
      expect(seen).toHaveLength(2 * W * H);
    });
  }

  it('without roughTransmission only R̃ is gathered; classic mixes R̃ over B by its alpha', () => {
    const seen: number[][] = [];
    const c = frames([{ ...base, rough: gather(true, true, seen), roughTransmission: false }]);
    expect(seen.every((s) => s[3] === 0)).toBe(true);
    const want = glass(F0, [0.9, 0.1, 0.4], base.B);
    at(c, 2, 2).forEach((x, k) => expect(x).toBeCloseTo(want[k], 6));
    // Classic at cos θ = 1: F = 0, alpha = 0.5·0.2 = 0.1: 0.1·D + 0.9·B̃ (R̃ weighted by F = 0).
    const e = frames([{ ...base, model: 'classic', rough: gather(true, true), roughTransmission: true }]);
    at(e, 2, 2).forEach((x, k) => expect(x).toBeCloseTo(0.1 * D[k] + 0.9 * [0.3, 0.3, 0.8][k], 6));
    // Clamped: B̃ of 5 gives 1, and R̃ of 3 counts as 1.
    const big = { gather: (out: Float64Array) => { out.set([5, 5, -9]); return true; } } as unknown as RoughGather;
    const f = frames([{ ...base, transparency: 1, rough: big, roughTransmission: true }]);
    expect(at(f, 2, 2)).toEqual([1, 1, 0]);
    const g = frames([{ ...base, transparency: 1, R: [0, 0, 0], B: [0, 0, 0], rough: big, roughTransmission: false }]);
    expect(at(g, 2, 2)).toEqual([Math.fround(0.04), Math.fround(0.04), 0]);
  });
});

describe('the frame-to-frame cache: a frame shades as a fresh shader would', () => {
  const tex = new MipTexture(1, 4, 4, Float32Array.from({ length: 16 }, (_, i) => (i * 7) % 16 / 16), true);
  const base: Settings = { texture: tex, transparency: 0.3 };
  const changes: [string, Settings][] = [
    ['ior', { ior: 1.33 }], ['model', { model: 'schlick' }], ['mode', { mode: 'fresnel' }], ['texture', { texture: GREY }],
    ['view vector', { view: [0.6, 0, 0.8, 0] }], ['normal', { frame: { ...FRAME, plane: [0.6, 0, 0.8, 0] } }],
    ['corners', { frame: { ...FRAME, corners: [[-8, -4, 0], [8, -4, 0], [8, 4, 0], [-6, 4, 0]] } }],
  ];
  for (const n of [1, 2]) {
    it(`the same frame a third time (read from the cache) is the first frame, shadeEvery ${n}`, () => {
      expect([...frames([base, base, base], n)]).toEqual([...frames([base], n)]);
    });
    for (const [name, change] of changes) {
      it(`after two frames, one with another ${name} is a fresh shader's, shadeEvery ${n}`, () => {
        const next = { ...base, ...change };
        const want = frames([next], n);
        expect([...frames([base, base, next], n)]).toEqual([...want]);
        expect([...frames([base, base, next, next, next], n)]).toEqual([...want]);
        expect([...want]).not.toEqual([...frames([base], n)]);
      });
    }
  }

  for (const [w, h] of [[2 * W, H], [W, 2 * H]]) {
    it(`a rasterizer of another width or height alone starts again (${w}×${h} and ${W}×${H}, either first)`, () => {
      const draw = (s: GlassShader, width: number, height: number) => {
        const r = new Rasterizer(width, height);
        r.clearDepth();
        apply(s, base, width * height);
        s.draw(r, GLASS_INDICES);
        return [...s.colour];
      };
      for (const [[w0, h0], [w1, h1]] of [[[W, H], [w, h]], [[w, h], [W, H]]]) {
        const g = new GlassShader();
        draw(g, w0, h0);
        draw(g, w0, h0);
        expect(draw(g, w1, h1)).toEqual(draw(new GlassShader(), w1, h1));
      }
    });
  }

  it('a rasterizer of another size starts again', () => {
    const g = new GlassShader();
    let r = rasterizer();
    for (let k = 0; k < 2; k++) { apply(g, base, W * H); r.clearDepth(); g.draw(r, GLASS_INDICES); }
    // Now 2× the samples in each direction at one sample a pixel: a 64×32 frame of the same view.
    r = new Rasterizer(2 * W, 2 * H);
    r.clearDepth();
    apply(g, base, 4 * W * H);
    g.draw(r, GLASS_INDICES);
    const h = new GlassShader(), r2 = new Rasterizer(2 * W, 2 * H);
    r2.clearDepth();
    apply(h, base, 4 * W * H);
    h.draw(r2, GLASS_INDICES);
    expect([...g.colour]).toEqual([...h.colour]);
  });
});

/** A texture that counts its reads (the glass cache's work saved shows as reads not made). */
class Counting extends MipTexture {
  reads = 0;
  override sample(a: Float64Array, out: Float64Array): void {
    this.reads++;
    super.sample(a, out);
  }
}

describe('the frame-to-frame cache: what it reads, and when it reads none', () => {
  const P = W * H;
  /** Draws `list` in turn with one shader and rasterizer: the texture reads each frame made, and the last frame's colour. */
  function reads(list: Settings[], n = 1, depth?: (frame: number, r: Rasterizer) => void) {
    const g = new GlassShader(), r = rasterizer(n), count: number[] = [];
    list.forEach((s, frame) => {
      const tex = (s.texture ?? g.texture) as Counting;
      const before = tex.reads;
      apply(g, s, P * n * n);
      r.clearDepth();
      depth?.(frame, r);
      g.draw(r, GLASS_INDICES);
      count.push(tex.reads - before);
    });
    return { count, colour: g.colour };
  }
  const tex = new Counting(1, 4, 4, Float32Array.from({ length: 16 }, (_, i) => ((i * 5) % 16) / 16), true);
  const base: Settings = { texture: tex, transparency: 0.3 };

  for (const n of [1, 2]) {
    it(`compose: a pixel's texel read in the first two frames of a still glass, none in the third (shadeEvery ${n})`, () => {
      // Multisampled, the 32 pixels the rectangle's diagonal splits are shaded by both triangles, each at a sample of
      // its own: one entry a pixel keeps the last, so those pixels read again every frame (twice).
      const [first, still] = n === 1 ? [P, 0] : [P + 32, 64];
      expect(reads([base, base, base, base], n).count).toEqual([first, first, still, still]);
      // The fresnel view and the footprint read no texel; the mode is part of the key.
      const f = { ...base, mode: 'fresnel' as const }, m = { ...base, mode: 'mask' as const };
      expect(reads([base, base, f, f, f, base, base, base], n).count).toEqual([first, first, 0, 0, 0, first, first, still]);
      // The renderer's order, footprint then glass each frame: the footprint leaves the cache as the glass left it.
      const run = reads([m, base, m, base, m, base], n);
      expect(run.count).toEqual([0, first, 0, first, 0, still]);
      expect([...run.colour]).toEqual([...reads([base], n).colour]);
    });

    it(`rough glass neither reads nor keeps entries: the polished frame after it starts again (shadeEvery ${n})`, () => {
      const rough = { gather: (out: Float64Array) => { out.set([0.9, 0.1, 0.4]); return true; } } as unknown as RoughGather;
      const r = { ...base, rough, roughTransmission: true };
      const [first, still] = n === 1 ? [P, 0] : [P + 32, 64];
      const run = reads([base, base, r, r, base, base, base], n);
      expect(run.count).toEqual([first, first, first, first, first, first, still]);
      expect([...run.colour]).toEqual([...reads([base], n).colour]);
    });
  }

  it('an object moving over a still glass: the pixels it uncovers read their texel afresh (the footprint pass keeps none)', () => {
    // The renderer's order, footprint then glass; the glass's left half hidden in frame 3 only.
    const m = { ...base, mode: 'mask' as const };
    const hideLeft = (frame: number, r: Rasterizer) => {
      if (frame === 3) for (let p = 0; p < P; p++) if (p % W < W / 2) r.depth[p] = -1;
    };
    const run = reads([m, base, m, base, m, base], 1, hideLeft);
    expect(run.count).toEqual([0, P, 0, P / 2, 0, P / 2]);
    expect([...run.colour]).toEqual([...reads([base]).colour]);
  });

  it('multisampled: an entry is read back only at the sample that shaded it', () => {
    // Sample 0 of every pixel hidden (frames 0–2), then samples 0 and 1 (frames 3–4): the pixel is shaded at its
    // sample 1, then 2; the first frame at a new sample reads again, the next reads the entry.
    const hide = (frame: number, r: Rasterizer) => {
      for (let p = 0; p < 4 * P; p++) {
        const x = p % (2 * W), y = Math.floor(p / (2 * W)), s = 2 * (y % 2) + (x % 2);
        if (s === 0 || (frame >= 3 && s === 1)) r.depth[p] = -1;
      }
    };
    // The diagonal's 16 pixels whose shaded samples both triangles hold read again each frame, as above.
    const run = reads([base, base, base, base, base], 2, hide);
    expect(run.count).toEqual([P + 16, P + 16, 32, P + 16, 32]);
    const fresh = reads([base], 2, (_, r) => hide(3, r));
    expect([...run.colour]).toEqual([...fresh.colour]);
  });
});

describe('the cache key: each of its numbers alone changed starts again', () => {
  // A normal and an orthographic view vector with no zero component: flipping any one changes N·V.
  const N: GlassFrame = { ...FRAME, plane: [0.48, 0.6, 0.64, 0] };
  const V = [0.6, 0.48, 0.64, 0];
  const tex = new MipTexture(1, 4, 4, Float32Array.from({ length: 16 }, (_, i) => ((i * 7) % 16) / 16), true);
  const base: Settings = { texture: tex, frame: N, view: V, transparency: 0.3 };
  const flip = (v: number[], k: number) => v.map((c, i) => (i === k ? -c : c));
  const changes: [string, Settings][] = [
    ...[0, 1, 2].map((k): [string, Settings] => [`view ${'xyz'[k]}`, { view: flip(V, k) }]),
    ['view w (perspective)', { view: [...V.slice(0, 3), 1] }],
    ...[0, 1, 2].map((k): [string, Settings] => [`normal ${'xyz'[k]}`, { frame: { ...N, plane: flip(N.plane as number[], k) as unknown as GlassFrame['plane'] } }]),
  ];
  for (const [name, change] of changes) {
    it(`${name}`, () => {
      const next = { ...base, ...change };
      const want = frames([next]);
      expect([...frames([base, base, next])]).toEqual([...want]);
      expect([...want]).not.toEqual([...frames([base])]);
    });
  }

  it('F at cos θ = |N·V| of a normal and view vector with no zero component; a zero view vector counts as cos θ = 1', () => {
    const want = Math.fround(fresnel('exact', 0.288 + 0.288 + 0.4096, 1.5));
    for (const [i, j] of [[0, 0], [20, 9]]) expect(at(frames([{ ...base, mode: 'fresnel' }]), i, j)[1]).toBeCloseTo(want, 7);
    expect(at(frames([{ mode: 'fresnel', view: [0, 0, 0, 0] }]), 9, 9)).toEqual([F0, F0, F0].map(Math.fround));
  });

  it('the grid: the same samples shaded once per 2×2 pixel after once each', () => {
    const g = new GlassShader(), one = new Rasterizer(2 * W, 2 * H), two = new Rasterizer(2 * W, 2 * H);
    two.shadeEvery = 2;
    for (const r of [one, one, two]) { apply(g, base, 4 * W * H); r.clearDepth(); g.draw(r, GLASS_INDICES); }
    expect([...g.colour]).toEqual([...frames([base], 2)]);
  });
});

describe('the glass equation off normal incidence (F between 0 and 1), each model, polished and rough', () => {
  // Orthographic, V = (0, 0, 1) on the normal (0.6, 0, 0.8): cos θ = 0.8 everywhere.
  const frame: GlassFrame = { ...FRAME, plane: [0.6, 0, 0.8, 0] };
  const B = [0.6, 0.3, 0.1], R = [0.2, 0.5, 0.9], T = 0.3, D = BODY.map((k) => 0.8 * k);
  const R2 = [0.9, 0.1, 0.4], B2 = [0.3, 0.35, 0.8];
  const rough = { gather: (out: Float64Array, _: unknown, pass: number) => { out.set(pass === 0 ? R2 : B2); return true; } } as unknown as RoughGather;
  for (const model of ['exact', 'schlick', 'classic'] as const) {
    const f = fresnel(model, 0.8, 1.5);
    const glass = (r: number[], b: number[]) => D.map((d, k) => model === 'classic'
      ? (d + (r[k] - d) * f) * ((1 - T) * (0.2 + 0.8 * f)) + b[k] * (1 - (1 - T) * (0.2 + 0.8 * f))
      : f * r[k] + (1 - f) * (T * b[k] + (1 - T) * d));
    it(`${model}: F = ${f.toFixed(4)}`, () => {
      expect(f).toBeGreaterThan(0.007);
      const s: Settings = { model, frame, view: [0, 0, 1, 0], transparency: T, B, R };
      at(frames([s]), 11, 6).forEach((x, k) => expect(x).toBeCloseTo(glass(R, B)[k], 6));
      at(frames([{ ...s, rough, roughTransmission: true }]), 11, 6).forEach((x, k) => expect(x).toBeCloseTo(glass(R2, B2)[k], 6));
    });
  }
});

describe('a tilted glass seen by a turned camera, every pixel against rays cast here', () => {
  // The glass through the origin with normal (0.6, 0, 0.8): u along (0.8, 0, −0.6) (16 wide), v along +Y (8 high).
  const TILTED: GlassFrame = {
    plane: [0.6, 0, 0.8, 0], a: [0.8, 0, -0.6], b: [0, 1, 0],
    corners: [[-6.4, -4, 4.8], [6.4, -4, -4.8], [6.4, 4, -4.8], [-6.4, 4, 4.8]],
  };
  const eye = [1, 0.5, 9];

  /** Eye-relative view-projection: `projection` × the turn of a camera at `eye` looking at the origin. */
  function relativeVP(projection: mat4, up: [number, number, number] = [0, 1, 0]): Float64Array {
    const view = mat4.lookAt(mat4.create(), eye as [number, number, number], [0, 0, 0], up);
    view[12] = view[13] = view[14] = 0;
    return Float64Array.from(mat4.multiply(mat4.create(), projection, view));
  }

  /** Where pixel (i, j)'s ray meets the glass plane (eye-relative), and whether inside the rectangle (|s| < 8, |t| < 4, 1e-6 off). */
  function hit(vp: Float64Array, i: number, j: number): { rel: number[]; inside: boolean } {
    const inv = mat4.invert(mat4.create(), vp as unknown as mat4)!;
    const x = (2 * (i + 0.5)) / W - 1, y = 1 - (2 * (j + 0.5)) / H;
    const un = (z: number) => {
      const v = [0, 1, 2, 3].map((r) => inv[r] * x + inv[4 + r] * y + inv[8 + r] * z + inv[12 + r]);
      return [v[0] / v[3], v[1] / v[3], v[2] / v[3]];
    };
    const p0 = un(-0.5), p1 = un(0.5), d = [p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2]];
    // n·(eye + p0 + k·d) = 0.
    const n = [0.6, 0, 0.8], dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    const k = -(dot(n, eye) + dot(n, p0)) / dot(n, d);
    const rel = [p0[0] + k * d[0], p0[1] + k * d[1], p0[2] + k * d[2]];
    const w = [eye[0] + rel[0], eye[1] + rel[1], eye[2] + rel[2]];
    const s = dot(w, [0.8, 0, -0.6]), t = w[1];
    return { rel, inside: Math.abs(s) < 8 - 1e-6 && Math.abs(t) < 4 - 1e-6 && Math.abs(Math.abs(s) - 8) > 1e-3 && Math.abs(Math.abs(t) - 4) > 1e-3 };
  }

  function exact(c: number, n: number): number {
    const cosT = Math.sqrt(1 - (1 - c * c) / (n * n));
    const rs = (c - n * cosT) / (c + n * cosT), rp = (n * c - cosT) / (n * c + cosT);
    return (rs * rs + rp * rp) / 2;
  }

  function draw(vp: Float64Array, view: number[], mode: GlassMode): GlassShader {
    const g = new GlassShader(), r = rasterizer();
    g.mode = mode;
    g.texture = GREY;
    g.colour = new Float32Array(3 * W * H).fill(-1);
    g.reflection = new Float32Array(3 * W * H);
    g.mask = new Uint8Array(W * H);
    g.setup(TILTED, eye, vp, view);
    g.draw(r, GLASS_INDICES);
    return g;
  }

  it('perspective: the footprint where the rays meet the rectangle, F of |N·V| from the eye at each', () => {
    const vp = relativeVP(mat4.perspective(mat4.create(), Math.PI / 3, W / H, 0.1, 100));
    const mask = draw(vp, [0, 0, 0, 1], 'mask').mask, f = draw(vp, [0, 0, 0, 1], 'fresnel').colour;
    let inside = 0;
    for (let j = 0; j < H; j++) {
      for (let i = 0; i < W; i++) {
        const h = hit(vp, i, j), p = j * W + i;
        if (!h.inside && mask[p] === 1) {
          // Drawn but outside: only on the rectangle's rim (the test leaves 1e-3 either side undecided).
          continue;
        }
        expect(mask[p], `${i},${j}`).toBe(h.inside ? 1 : 0);
        if (!h.inside) continue;
        inside++;
        const len = Math.hypot(h.rel[0], h.rel[1], h.rel[2]);
        const c = Math.abs(0.6 * h.rel[0] + 0.8 * h.rel[2]) / len;
        expect(f[3 * p], `${i},${j}`).toBeCloseTo(exact(c, 1.5), 4); // the corners snapped to 1/256 px: 6e-6 seen
      }
    }
    expect(inside).toBeGreaterThan(150);
  });

  it('orthographic, off-centre: the footprint by the same rays, F of |N·V| for the view vector', () => {
    const vp = relativeVP(mat4.ortho(mat4.create(), -9, 7, -3, 5, 0.1, 100));
    const forward = [-eye[0], -eye[1], -eye[2]], fl = Math.hypot(forward[0], forward[1], forward[2]);
    const view = [-forward[0] / fl, -forward[1] / fl, -forward[2] / fl, 0];
    const mask = draw(vp, view, 'mask').mask, f = draw(vp, view, 'fresnel').colour;
    const want = exact(Math.abs(0.6 * view[0] + 0.8 * view[2]), 1.5);
    let inside = 0;
    for (let j = 0; j < H; j++) {
      for (let i = 0; i < W; i++) {
        const h = hit(vp, i, j), p = j * W + i;
        if (!h.inside && mask[p] === 1) continue;
        expect(mask[p], `${i},${j}`).toBe(h.inside ? 1 : 0);
        if (!h.inside) continue;
        inside++;
        expect(f[3 * p]).toBeCloseTo(want, 6);
      }
    }
    expect(inside).toBeGreaterThan(150);
    expect(inside).toBeLessThan(W * H);
  });

  // A camera rolled about its axis and looking down at the glass: every entry of the view-projection is non-zero, the
  // glass's v runs across the screen as well as down it.
  const ROLLED = relativeVP(mat4.perspective(mat4.create(), Math.PI / 3, W / H, 0.1, 100), [0.5, 1, 0.2]);
  const uvAt = (x: number, y: number) => {
    const h = hit(ROLLED, x - 0.5, y - 0.5), w = [eye[0] + h.rel[0], eye[1] + h.rel[1], eye[2] + h.rel[2]];
    return [(0.8 * w[0] - 0.6 * w[2] + 8) / 16, (w[1] + 4) / 8];
  };

  // The same rectangle with its corners in the other order (u from the far side): its triangles wind the other way.
  const FLIPPED: GlassFrame = { ...TILTED, corners: [TILTED.corners[1], TILTED.corners[0], TILTED.corners[3], TILTED.corners[2]] };
  for (const [name, glassFrame, flip] of [['', TILTED, false], [', its corners in the other order', FLIPPED, true]] as const) it(`rolled${name}: the texture is read at each pixel's UV with the UV's derivatives across and down the screen`, () => {
    const g = new GlassShader(), r = rasterizer();
    let pixel = -1;
    const reads = new Map<number, number[]>();
    g.texture = { sample: (a: Float64Array, out: Float64Array) => { reads.set(pixel, [...a]); out[0] = 0.5; } } as unknown as MipTexture;
    const fragment = g.fragment.bind(g);
    g.fragment = (p: number, rr: Rasterizer) => { pixel = p; fragment(p, rr); };
    g.colour = new Float32Array(3 * W * H);
    g.reflection = new Float32Array(3 * W * H);
    g.mask = new Uint8Array(W * H);
    g.setup(glassFrame, eye, ROLLED, [0, 0, 0, 1]);
    g.draw(r, GLASS_INDICES);
    let checked = 0;
    for (let j = 0; j < H; j++) {
      for (let i = 0; i < W; i++) {
        if (!hit(ROLLED, i, j).inside) continue;
        const got = reads.get(j * W + i);
        expect(got, `${i},${j}`).toBeDefined();
        const x = i + 0.5, y = j + 0.5, d = 1e-3;
        const uv = uvAt(x, y), px = uvAt(x + d, y), mx = uvAt(x - d, y), py = uvAt(x, y + d), my = uvAt(x, y - d);
        const want = [uv[0], uv[1], (px[0] - mx[0]) / (2 * d), (px[1] - mx[1]) / (2 * d), (py[0] - my[0]) / (2 * d), (py[1] - my[1]) / (2 * d)];
        if (flip) [0, 2, 4].forEach((k) => (want[k] = k === 0 ? 1 - want[0] : -want[k]));
        // The corners snap to 1/256 px: UV within 3e-4 (a 64th of a pixel's step), the derivatives within 2 %.
        for (let k = 0; k < 2; k++) expect(Math.abs(got![k] - want[k]), `${i},${j} ${k}`).toBeLessThan(3e-4);
        for (let k = 2; k < 6; k++) expect(Math.abs(got![k] - want[k]), `${i},${j} ${k}`).toBeLessThan(0.02 * Math.abs(want[k]) + 1e-5);
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(150);
    expect(Math.min(...[2, 3, 4, 5].map((k) => Math.max(...[...reads.values()].map((a) => Math.abs(a[k])))))).toBeGreaterThan(0.005);
  });

  it('rolled: the footprint where the rays meet the rectangle, at the depth of the plane there', () => {
    const mask = draw(ROLLED, [0, 0, 0, 1], 'mask').mask;
    const depthAt = (rel: number[]) => {
      const v = ROLLED, c = [2, 3].map((k) => v[k] * rel[0] + v[4 + k] * rel[1] + v[8 + k] * rel[2] + v[12 + k]);
      return c[0] / c[1];
    };
    // A surface 1e-4 in front of the glass at every pixel hides it; one 1e-4 behind it does not.
    const drawn = (offset: number) => {
      const g = new GlassShader(), r = rasterizer();
      g.mode = 'fresnel';
      g.colour = new Float32Array(3 * W * H).fill(-1);
      g.setup(TILTED, eye, ROLLED, [0, 0, 0, 1]);
      for (let j = 0; j < H; j++) for (let i = 0; i < W; i++) r.depth[j * W + i] = depthAt(hit(ROLLED, i, j).rel) + offset;
      g.draw(r, GLASS_INDICES);
      return g.colour;
    };
    const front = drawn(-1e-4), behind = drawn(1e-4);
    let inside = 0;
    for (let j = 0; j < H; j++) {
      for (let i = 0; i < W; i++) {
        const h = hit(ROLLED, i, j), p = j * W + i;
        if (!h.inside && mask[p] === 1) continue;
        expect(mask[p], `${i},${j}`).toBe(h.inside ? 1 : 0);
        if (!h.inside) continue;
        inside++;
        expect(front[3 * p], `${i},${j}`).toBe(-1);
        expect(behind[3 * p], `${i},${j}`).toBeGreaterThan(0);
      }
    }
    expect(inside).toBeGreaterThan(150);
    expect(inside).toBeLessThan(W * H);
  });
});
