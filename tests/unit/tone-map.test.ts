// Tone mapping (src/math/tone-map.ts, docs/pbr.md#tone-mapping) at points worked by hand: PBR
// Neutral's offset below 0.08, its identity below the compression start and its compression and
// desaturation above it; ACES's fitted curve at 0 and 1 and a grey and a colour through its matrices.
import { describe, expect, it } from 'vitest';
import { acesCurve, toneMap, toneMapAces, toneMapNeutral, TONE_MAPPINGS } from '../../src/math/tone-map';

const rounded = (v: ArrayLike<number>, digits = 6) => Array.from(v, (x) => Number(x.toFixed(digits)) + 0);

describe('Khronos PBR Neutral', () => {
  it('takes 0.04 off a colour whose darkest channel is 0.08 or more, and leaves it there below 0.76', () => {
    expect(rounded(toneMapNeutral([0, 0, 0], 0.5, 0.5, 0.5))).toEqual([0.46, 0.46, 0.46]);
    expect(rounded(toneMapNeutral([0, 0, 0], 0.08, 0.5, 0.79))).toEqual([0.04, 0.46, 0.75]);
  });

  it('takes x − 6.25x² off below 0.08 (x the darkest channel): 0 stays 0', () => {
    // x = 0.05: 0.05 − 6.25 · 0.0025 = 0.034375.
    expect(rounded(toneMapNeutral([0, 0, 0], 0.05, 0.5, 0.3))).toEqual([0.015625, 0.465625, 0.265625]);
    expect(toneMapNeutral([1, 1, 1], 0, 0, 0)).toEqual([0, 0, 0]);
  });

  it('compresses a peak past 0.76 toward 1 and the colour toward white', () => {
    // (2, 1, 0.5) − 0.04 = (1.96, 0.96, 0.46); d = 0.24; new peak 1 − 0.0576/(1.96 + 0.24 − 0.76) = 0.96;
    // scaled by 0.96/1.96; mixed toward 0.96 by 1 − 1/(0.15 · (1.96 − 0.96) + 1) = 0.130435.
    const t = 1 - 1 / 1.15, k = 0.96 / 1.96;
    const expected = [1.96, 0.96, 0.46].map((c) => c * k * (1 - t) + 0.96 * t);
    expect(rounded(toneMapNeutral([0, 0, 0], 2, 1, 0.5))).toEqual(rounded(expected));
    expect(rounded(expected)).toEqual([0.96, 0.534091, 0.321136]);
    expect(rounded(toneMapNeutral([0, 0, 0], 2, 2, 2))).toEqual([0.96, 0.96, 0.96]);
    // (3, 1, 0.5) − 0.04: peak 2.96 → 1 − 0.0576/2.44 = 0.976393; mixed by 1 − 1/(0.15 · 1.983607 + 1) = 0.229311.
    expect(rounded(toneMapNeutral([0, 0, 0], 3, 1, 0.5))).toEqual([0.976393, 0.467951, 0.34084]);
    // At the start exactly: the new peak is 1 − d²/d = 0.76, the colour itself.
    expect(rounded(toneMapNeutral([0, 0, 0], 0.8, 0.8, 0.8))).toEqual([0.76, 0.76, 0.76]);
    // Never past 1, however bright.
    expect(Math.max(...toneMapNeutral([0, 0, 0], 1e6, 10, 0.1))).toBeLessThan(1);
  });
});

describe('ACES (Hill\'s fit)', () => {
  it('the curve: −0.000090537/0.238081 at 0, 1.0244881/1.654761 at 1', () => {
    expect(acesCurve(0)).toBeCloseTo(-0.000090537 / 0.238081, 15);
    expect(acesCurve(1)).toBeCloseTo((1.0245786 - 0.000090537) / (0.983729 + 0.432951 + 0.238081), 15);
    expect(acesCurve(1)).toBeCloseTo(0.619115, 6);
  });

  it('a grey stays grey (the matrices\' rows sum to 1, the last output row to 0.99999), a colour goes through both', () => {
    expect(rounded(toneMapAces([0, 0, 0], 1, 1, 1))).toEqual([0.619115, 0.619115, 0.619109]);
    expect(rounded(toneMapAces([0, 0, 0], 0.18, 0.18, 0.18))).toEqual([0.105591, 0.105591, 0.10559]);
    expect(rounded(toneMapAces([0, 0, 0], 1, 0.5, 0.25))).toEqual([0.63499, 0.3846, 0.20316]);
  });

  it('clamps to [0, 1]: black below the curve\'s 0, white far above', () => {
    expect(toneMapAces([1, 1, 1], 0, 0, 0)).toEqual([0, 0, 0]);
    expect(toneMapAces([0, 0, 0], 100, 100, 100)).toEqual([1, 1, 1]);
    expect(rounded(toneMapAces([0, 0, 0], 10, 0, 0))).toEqual([1, 0.484271, 0.17261]);
  });
});

describe('toneMap', () => {
  it('dispatches by name, and none passes the colour through', () => {
    expect(TONE_MAPPINGS).toEqual(['neutral', 'aces', 'none']);
    expect(toneMap('neutral', [0, 0, 0], 2, 1, 0.5)).toEqual(toneMapNeutral([0, 0, 0], 2, 1, 0.5));
    expect(toneMap('aces', [0, 0, 0], 2, 1, 0.5)).toEqual(toneMapAces([0, 0, 0], 2, 1, 0.5));
    expect(toneMap('none', [0, 0, 0], 2, 1, 0.5)).toEqual([2, 1, 0.5]);
  });
});
