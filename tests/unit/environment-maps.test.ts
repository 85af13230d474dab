// The environment's prefiltered maps (src/math/prefilter.ts makes them, src/math/environment-maps.ts reads them; docs/pbr.md#prefiltered-maps): texel directions, level widths
// and the bilinear read worked by hand; each level's texels against prefiltered() (math/split-sum.ts) at its roughness; a white
// furnace; the maps' own error by roughness against prefiltered() integrated afresh (bounds one point above what was measured).
import { describe, expect, it } from 'vitest';
import { addEnvironment, prefilteredAt, sampleEquirect, type EquirectMap } from '../../src/math/environment-maps';
import { levelRoughness, levelWidth, makeEnvironmentMaps, texelDirection } from '../../src/math/prefilter';
import { dfgLookup, dfgTable } from '../../src/math/dfg';
import { prefiltered, splitSum, type RadianceFn } from '../../src/math/split-sum';
import { studioRadiance } from '../../src/math/studio';
import { seeded } from './helpers/seeded';

const studio: RadianceFn = (out, x, y, z) => { out[0] = out[1] = out[2] = studioRadiance(x, y, z); };
const out = new Float64Array(3);
const round = (a: ArrayLike<number>) => Array.from(a, (x) => +x.toFixed(9));

describe('the equirectangular map', () => {
  it('texel (i, j) looks at φ = 2π(i + ½)/w − π from +z toward +x, θ = π(j + ½)/h from +y', () => {
    // φ = −3π/4, θ = π/4: (sin θ sin φ, cos θ, sin θ cos φ) = (−½, √½, −½).
    expect(round(texelDirection(out, 0, 0, 4, 2))).toEqual(round([-0.5, Math.SQRT1_2, -0.5]));
    // φ = π/4, θ = 3π/4: (½, −√½, ½).
    expect(round(texelDirection(out, 2, 1, 4, 2))).toEqual(round([0.5, -Math.SQRT1_2, 0.5]));
  });

  it('reads a texel\'s own value at its centre, between neighbours their mix, across the seam, held at the poles\' rows', () => {
    const w = 8, h = 4, map: EquirectMap = { width: w, height: h, rgb: new Float32Array(w * h * 3) };
    for (let j = 0; j < h; j++) for (let i = 0; i < w; i++) map.rgb.set([i, j, 10 * j + i], 3 * (j * w + i));
    const d = new Float64Array(3);
    texelDirection(d, 3, 2, w, h);
    expect(round(sampleEquirect(out, map, d[0], d[1], d[2]))).toEqual([3, 2, 23]);
    // On the seam φ = ±π, halfway down row 1: columns 7 and 0 mixed half and half.
    const theta = (1.5 / h) * Math.PI;
    sampleEquirect(out, map, 0, Math.cos(theta), -Math.sin(theta));
    expect(round(out)).toEqual([3.5, 1, 13.5]);
    // A quarter of a texel right of column 3's centre, a quarter below row 1's: (3.25, 1.25).
    const phi = ((3.75 / w) * 2 - 1) * Math.PI, t2 = (1.75 / h) * Math.PI;
    sampleEquirect(out, map, Math.sin(t2) * Math.sin(phi), Math.cos(t2), Math.sin(t2) * Math.cos(phi));
    expect(out[0]).toBeCloseTo(3.25, 9); expect(out[1]).toBeCloseTo(1.25, 9);
    // The zenith (φ = 0, between columns 3 and 4): row 0 held; the nadir: row 3.
    expect(round(sampleEquirect(out, map, 0, 1, 0))).toEqual([3.5, 0, 3.5]);
    expect(sampleEquirect(out, map, 0, -1, 1e-12)[1]).toBe(3);
    // A direction a rounding made a hair longer than 1 reads the pole, not NaN.
    expect(round(sampleEquirect(out, map, 0, 1.0000000000000002, 0))).toEqual([3.5, 0, 3.5]);
    expect(sampleEquirect(out, map, 0, -1.0000000000000002, 1e-12)[1]).toBe(3);
  });
});

describe('the levels', () => {
  it('level k of 8 is at roughness (k/7)², as wide as a quarter of its lobe per texel (4π/α, a power of two in [32, 256])', () => {
    expect([0, 1, 2, 7].map((k) => levelRoughness(k, 8, 2))).toEqual([0, 1 / 49, 4 / 49, 1]);
    // α = 0: the mirror, the full width. α = 0.05: 4π/α = 251 → 256. α = 0.1: 126 → 128. α = 0.2: 63 → 64; α = 0.4: 31 → 32.
    expect([0, Math.sqrt(0.05), Math.sqrt(0.1), Math.sqrt(0.2), Math.sqrt(0.4), 1].map((r) => levelWidth(r, 256, 32))).toEqual([256, 256, 128, 64, 32, 32]);
    expect(levelWidth(0.01, 256, 32)).toBe(256);
  });

  it('each texel of a rough level is prefiltered() about its centre with the level\'s share of the points; the mirror level the light itself', () => {
    const maps = makeEnvironmentMaps(studio, { levels: 3, width: 64, minWidth: 16, budget: 4096, gamma: 1 });
    // Roughness 0, ½, 1: α 0, ¼ (4π/α ≈ 50 → 64), 1 (→ 16); points 4096/(64·32) = 2 and 4096/(16·8) = 32, at least 16.
    expect(maps.levels.map((l) => [l.width, l.height])).toEqual([[64, 32], [64, 32], [16, 8]]);
    const d = new Float64Array(3);
    texelDirection(d, 20, 9, 64, 32);
    expect(maps.levels[0].rgb[3 * (9 * 64 + 20)]).toBe(Math.fround(studioRadiance(d[0], d[1], d[2])));
    expect(maps.levels[1].rgb[3 * (9 * 64 + 20) + 1]).toBe(Math.fround(prefiltered(out, studio, d, 0.5, 16)[1]));
    texelDirection(d, 5, 3, 16, 8);
    expect(maps.levels[2].rgb[3 * (3 * 16 + 5) + 2]).toBe(Math.fround(prefiltered(out, studio, d, 1, 32)[2]));
  });

  it('a roughness between two levels mixes their reads by where it falls between them (in r^(1/gamma))', () => {
    // Two 4×2 levels, each one value: 2 and 6 (roughness 0 and 1, gamma 2): roughness ¼ is halfway (√¼ = ½), 1/16 a quarter.
    const flat = (v: number): EquirectMap => ({ width: 4, height: 2, rgb: new Float32Array(24).fill(v) });
    const maps = { levels: [flat(2), flat(6)], gamma: 2 };
    expect(prefilteredAt(out, maps, 0.3, 0.4, 0.866, 0.25)[0]).toBeCloseTo(4, 12);
    expect(prefilteredAt(out, maps, 0.3, 0.4, 0.866, 1 / 16)[0]).toBeCloseTo(3, 12);
    expect(prefilteredAt(out, maps, 0, 1, 0, 2)[0]).toBeCloseTo(6, 12);
    expect(prefilteredAt(out, maps, 0, 1, 0, -1)[0]).toBeCloseTo(2, 12);
  });
});

describe('the split sum from the maps', () => {
  const table = dfgTable();

  it('in a white furnace (every level 1) is the table\'s F0·A + B plus c_diff·(1 − F0), times the intensity', () => {
    const furnace = makeEnvironmentMaps((o) => { o[0] = o[1] = o[2] = 1; }, { levels: 3, width: 32, minWidth: 16, budget: 1024 });
    const ab = new Float64Array(2), n = [0, 1, 0], v = [0.6, 0.8, 0];
    dfgLookup(ab, table, 0.8, 0.4);
    const sum = new Float64Array([0.1, 0.2, 0.3]);
    addEnvironment(sum, furnace, table, 2, [0.5, 0.8, 0.2], 0.25, 0.4, n, v);
    [0.5, 0.8, 0.2].forEach((b, c) => {
      const f0 = 0.04 * 0.75 + b * 0.25;
      expect(sum[c]).toBeCloseTo([0.1, 0.2, 0.3][c] + 2 * (f0 * ab[0] + ab[1] + b * 0.75 * (1 - f0)), 6);
    });
    // Seen from behind, or edge-on (n·v = 0): nothing added.
    addEnvironment(sum.fill(0), furnace, table, 2, [1, 1, 1], 1, 0.4, n, [0, -1, 0]);
    addEnvironment(sum, furnace, table, 2, [1, 1, 1], 1, 0.4, n, [1, 0, 0]);
    expect(Array.from(sum)).toEqual([0, 0, 0]);
  });

  // Measured (worst of six views, of the brightest): 6.52, 2.02, 0.50, 2.05 % — the bounds one point above. A roughness of 0.1 = (2.21/7)² lies
  // between levels 2 and 3 (roughness 4/49 and 9/49), where a panel's edge is mixed from two blurs of other widths than its own.
  const BOUNDS: [number, number, number][] = [[1, 0.1, 7.5], [1, 0.4, 3], [0, 0.3, 1.5], [0.5, 0.8, 3]];

  it('in the studio, against splitSum() integrated afresh at six views of each of four materials: within a point of what was measured', () => {
    const maps = makeEnvironmentMaps(studio);
    const rnd = seeded(5), exact = new Float64Array(3);
    const lines: string[] = [];
    for (const [metallic, roughness, bound] of BOUNDS) {
      let worst = 0, top = 0;
      for (let k = 0; k < 6; k++) {
        const y = rnd(), s = Math.sqrt(1 - y * y), p = 2 * Math.PI * rnd(), n = [s * Math.sin(p), y, s * Math.cos(p)];
        const v = [n[0] + 0.3 * (rnd() - 0.5), n[1] + 0.3 * (rnd() - 0.5), n[2] + 0.3 * (rnd() - 0.5)];
        const vl = Math.hypot(v[0], v[1], v[2]);
        v[0] /= vl; v[1] /= vl; v[2] /= vl;
        splitSum(exact, [0.9, 0.7, 0.5], metallic, roughness, n, v, studio, 4096);
        addEnvironment(out.fill(0), maps, table, 1, [0.9, 0.7, 0.5], metallic, roughness, n, v);
        worst = Math.max(worst, Math.abs(out[0] - exact[0]));
        top = Math.max(top, exact[0]);
      }
      lines.push(`metallic ${metallic} roughness ${roughness}: worst ${(100 * worst / top).toFixed(2)} % of the brightest`);
      expect(100 * worst / top, lines.at(-1)).toBeLessThan(bound);
    }
    console.log(`the split sum from the maps against splitSum():\n${lines.join('\n')}`);
  });
});
