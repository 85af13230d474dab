// The microfacet samples of rough glass (src/reference/microfacet-samples.ts): exact pairs for two pixels worked out by
// hand from lowbias32 (computed here in BigInt, apart from the code's Math.imul), and the N-rooks strata for many.
import { describe, expect, it } from 'vitest';
import { MicrofacetSamples } from '../../src/reference/microfacet-samples';

const M32 = 0xffffffffn;
/** lowbias32 (Wellons) in BigInt arithmetic. */
function lowbias32(v: number): number {
  let x = BigInt(v) & M32;
  x ^= x >> 16n;
  x = (x * 0x7feb352dn) & M32;
  x ^= x >> 15n;
  x = (x * 0x846ca68bn) & M32;
  x ^= x >> 16n;
  return Number(x);
}
const U = 2 ** 32;

describe('MicrofacetSamples', () => {
  it('lowbias32 as computed here: 0 → 0, 1 → 1753845952, 7 → 2492178918', () => {
    expect([lowbias32(0), lowbias32(1), lowbias32(7)]).toEqual([0, 1753845952, 2492178918]);
  });

  it('pixel 7, two samples: the first shuffle swaps, the second does not', () => {
    // seed = H(7) = 2492178918; u_k = H(seed + k)/2³²:
    // u0 = 1420618368/2³² < ½ → j = 0: order = [1, 0]; u1 = 2229265414/2³² ≥ ½ → j = 1: slot = [0, 1];
    // xi1[0] = (0 + u2)/2, xi2[0] = (1 + u3)/2; xi1[1] = (1 + u4)/2, xi2[1] = (0 + u5)/2.
    const seed = lowbias32(7);
    expect([0, 1, 2, 3, 4, 5].map((k) => lowbias32(seed + k)))
      .toEqual([1420618368, 2229265414, 3788636316, 916855273, 3666555108, 1656689905]);
    const s = new MicrofacetSamples(2);
    s.fill(7);
    expect([...s.xi1]).toEqual([3788636316 / U / 2, (1 + 3666555108 / U) / 2]);
    expect([...s.xi2]).toEqual([(1 + 916855273 / U) / 2, 1656689905 / U / 2]);
  });

  it('pixel 1234, two samples: both shuffles swap', () => {
    // seed = H(1234) = 1074557550; u0 = 1887047106/2³² < ½: order = [1, 0]; u1 = 1744608857/2³² < ½: slot = [1, 0];
    // xi1[1] = (0 + u2)/2, xi2[1] = (1 + u3)/2; xi1[0] = (1 + u4)/2, xi2[0] = (0 + u5)/2.
    const seed = lowbias32(1234);
    expect(seed).toBe(1074557550);
    expect([0, 1, 2, 3, 4, 5].map((k) => lowbias32(seed + k)))
      .toEqual([1887047106, 1744608857, 2499026579, 1513525380, 2536154027, 1069530266]);
    const s = new MicrofacetSamples(2);
    s.fill(1234);
    expect([...s.xi1]).toEqual([(1 + 2536154027 / U) / 2, 2499026579 / U / 2]);
    expect([...s.xi2]).toEqual([1069530266 / U / 2, (1 + 1513525380 / U) / 2]);
  });

  it('pixel 12, two samples: the first shuffle keeps its order, the second swaps', () => {
    // seed = H(12) = 2631693420; u0 = 3946455100/2³² ≥ ½ → j = 1: order = [0, 1]; u1 = 513030488/2³² < ½: slot = [1, 0];
    // xi1[1] = (0 + u2)/2, xi2[1] = (0 + u3)/2; xi1[0] = (1 + u4)/2, xi2[0] = (1 + u5)/2.
    const seed = lowbias32(12);
    expect(seed).toBe(2631693420);
    expect([0, 1, 2, 3, 4, 5].map((k) => lowbias32(seed + k)))
      .toEqual([3946455100, 513030488, 1434842290, 1734215512, 2581450202, 890355331]);
    const s = new MicrofacetSamples(2);
    s.fill(12);
    expect([...s.xi1]).toEqual([(1 + 2581450202 / U) / 2, 1434842290 / U / 2]);
    expect([...s.xi2]).toEqual([(1 + 890355331 / U) / 2, 1734215512 / U / 2]);
  });

  it('one sample: no shuffle, (H(seed), H(seed + 1))/2³²; pixel 0 has seed 0', () => {
    const s = new MicrofacetSamples(1);
    s.fill(0);
    expect([...s.xi1]).toEqual([0]);
    expect([...s.xi2]).toEqual([1753845952 / U]);
    s.fill(7);
    expect([...s.xi1]).toEqual([1420618368 / U]);
    expect([...s.xi2]).toEqual([2229265414 / U]);
  });

  it('any count: one ξ1 and one ξ2 in each of its strata, the same for the same pixel, another for another', () => {
    for (const m of [3, 16]) {
      const s = new MicrofacetSamples(m);
      expect(s.count).toBe(m);
      const seen = new Set<string>();
      for (const pixel of [0, 1, 2, 99, 4096, -1, 123456789]) {
        s.fill(pixel);
        for (const xi of [s.xi1, s.xi2]) {
          expect(xi.length).toBe(m);
          expect(xi.every((x) => x >= 0 && x < 1)).toBe(true);
          expect([...xi].map((x) => Math.floor(x * m)).sort((a, b) => a - b)).toEqual([...Array(m).keys()]);
        }
        const pairs = JSON.stringify([...s.xi1, ...s.xi2]);
        expect(seen.has(pairs)).toBe(false);
        seen.add(pairs);
      }
      // The same pixel again, after others: the same pairs.
      const a = new MicrofacetSamples(m);
      a.fill(99);
      s.fill(99);
      expect([...s.xi1]).toEqual([...a.xi1]);
      expect([...s.xi2]).toEqual([...a.xi2]);
    }
  });

  it('a negative pixel is its unsigned 32-bit value', () => {
    const a = new MicrofacetSamples(4), b = new MicrofacetSamples(4);
    a.fill(-1);
    b.fill(4294967295);
    expect([...a.xi1, ...a.xi2]).toEqual([...b.xi1, ...b.xi2]);
  });
});
