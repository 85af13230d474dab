// The split-sum table (src/math/dfg.ts, docs/pbr.md#the-split-sum-table): A + B at μ = 1 is the white metal's albedo that pbr.test.ts
// integrates by a midpoint rule (0.9973 at α 0.05 … 1 − ln 2 at roughness 1); elsewhere A and B against a quadrature over
// l written out here (θ, φ on a grid, f = Fc·D·V from math/pbr.ts's terms, tied down there); the table's addressing:
// roughness 1 reads roughness 1, μ = 1 reads μ = 1, between entries bilinear.
import { describe, expect, it } from 'vitest';
import { DFG_SIZE, dfg, dfgCoordinate, dfgLookup, dfgTable, dfgVisibility } from '../../src/math/dfg';
import { smithVisibility } from '../../src/math/pbr';
import { ggxD } from '../../src/math/ggx';

/** [A, B] by the midpoint rule over l's θ (0..π/2) and φ (0..2π), n = +z, v at n·v = μ in the xz-plane. */
function quadrature(mu: number, roughness: number, steps = 400): [number, number] {
  const alpha = roughness * roughness, vx = Math.sqrt(1 - mu * mu), vz = mu;
  let a = 0, b = 0;
  const dt = Math.PI / 2 / steps, dp = (2 * Math.PI) / (2 * steps);
  for (let i = 0; i < steps; i++) {
    const t = (i + 0.5) * dt, st = Math.sin(t), ct = Math.cos(t);
    for (let j = 0; j < 2 * steps; j++) {
      const p = (j + 0.5) * dp;
      const lx = st * Math.cos(p), ly = st * Math.sin(p), lz = ct;
      let hx = lx + vx, hy = ly, hz = lz + vz;
      const hl = Math.hypot(hx, hy, hz);
      hx /= hl; hy /= hl; hz /= hl;
      const vh = vx * hx + vz * hz;
      const f = ggxD(alpha, hz) * smithVisibility(alpha, ct, mu) * ct * st * dt * dp;
      const fc = (1 - vh) ** 5;
      a += (1 - fc) * f;
      b += fc * f;
    }
  }
  return [a, b];
}

const ab = new Float64Array(2);

describe('A and B', () => {
  it('at μ = 1, A + B is the white metal\'s albedo (pbr.test.ts): 0.9973, 0.9158, 0.6878 and 1 − ln 2', () => {
    const rows: [number, number][] = [[Math.sqrt(0.05), 0.99730], [0.5, 0.91581], [Math.sqrt(0.5), 0.68785], [1, 1 - Math.LN2]];
    for (const [r, albedo] of rows) {
      dfg(ab, 1, r);
      expect(ab[0] + ab[1], `roughness ${r}`).toBeCloseTo(albedo, 3);
    }
    // Seen along the normal a smooth lobe has v·h = 1: Fc = 0, all of it in A.
    dfg(ab, 1, 0.05);
    expect(ab[1]).toBeLessThan(1e-6);
  });

  it('elsewhere, A and B as a quadrature over l (to 10⁻³ and 10⁻⁴)', () => {
    for (const [mu, r] of [[0.5, 0.5], [0.2, 0.7], [0.8, 0.3], [0.1, 1], [0.35, 0.9]]) {
      const [a, b] = quadrature(mu, r);
      dfg(ab, mu, r);
      // Measured: |ΔA| at most 3.4e-4 (μ 0.8, r 0.3), |ΔB| at most 1.4e-5; 1,024 samples gave 4.5e-3 at μ 0.2, r 0.7.
      expect(Math.abs(ab[0] - a), `A at μ ${mu}, r ${r}`).toBeLessThan(1e-3);
      expect(Math.abs(ab[1] - b), `B at μ ${mu}, r ${r}: ${b}`).toBeLessThan(1e-4);
    }
  });

  it('clamps μ and the roughness into range', () => {
    const at = (mu: number, r: number) => [...dfg([0, 0], mu, r)];
    expect(at(-1, 0.5)).toEqual(at(1e-4, 0.5));
    expect(at(2, 0.5)).toEqual(at(1, 0.5));
    expect(at(0.5, -1)).toEqual(at(0.5, 0));
    expect(at(0.5, 3)).toEqual(at(0.5, 1));
  });
});

describe('the table', () => {
  const table = dfgTable(8, 256);

  it('holds r = j/(size − 1) by rows and μ = i/(size − 1) by columns: its last row is roughness 1, its last column μ = 1', () => {
    for (const [i, j] of [[0, 0], [7, 7], [3, 5], [7, 0], [0, 7]]) {
      dfg(ab, i / 7, j / 7, 256);
      expect(table[2 * (j * 8 + i)]).toBe(Math.fround(ab[0]));
      expect(table[2 * (j * 8 + i) + 1]).toBe(Math.fround(ab[1]));
    }
  });

  it('is read at texel centres: roughness 1 reads roughness 1, and between entries bilinearly', () => {
    expect(dfgCoordinate(0, 8)).toBe(0.5 / 8);
    expect(dfgCoordinate(1, 8)).toBe(7.5 / 8);
    expect(dfgCoordinate(0.5, 8)).toBe(4 / 8);
    expect(dfgCoordinate(2, 8)).toBe(7.5 / 8);
    expect(dfgCoordinate(-1, 8)).toBe(0.5 / 8);
    const out = [0, 0];
    dfgLookup(out, table, 1, 1, 8);
    expect(out).toEqual([table[2 * 63], table[2 * 63 + 1]]);
    dfgLookup(out, table, 0, 0, 8);
    expect(out).toEqual([table[0], table[1]]);
    // Halfway between columns 2 and 3 of row 5, and a quarter of the way to row 6.
    dfgLookup(out, table, 2.5 / 7, 5.25 / 7, 8);
    for (let c = 0; c < 2; c++) {
      const e = (i: number, j: number) => table[2 * (j * 8 + i) + c];
      expect(out[c]).toBeCloseTo(((e(2, 5) + e(3, 5)) / 2) * 0.75 + ((e(2, 6) + e(3, 6)) / 2) * 0.25, 6);
    }
    expect(DFG_SIZE).toBe(32);
  });
});

describe('the table\'s visibility', () => {
  it('is smithVisibility of math/pbr.ts, written again: equal on a grid of α, n·l and n·v, and 0 below the surface', () => {
    for (const alpha of [1e-4, 0.01, 0.25, 0.7, 1]) {
      for (const nl of [-0.3, 0, 1e-4, 0.2, 0.5, 0.9, 1]) {
        for (const nv of [1e-4, 0.1, 0.6, 1]) expect(dfgVisibility(alpha, nl, nv), `α ${alpha}, n·l ${nl}, n·v ${nv}`).toBe(smithVisibility(alpha, nl, nv));
      }
    }
  });
});
