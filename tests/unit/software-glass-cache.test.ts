// GlassCache's contract (src/software/glass-cache.ts): an entry is read back only in a frame
// whose key is exactly the one it was written under, at the sample of its pixel that wrote it.
// The renderer's own frames are held to the bit in software-baseline.test.ts; a multisampled
// pixel on the glass's diagonal, shaded by both triangles, differs there in the last bits of F
// only, below what 8 bits show, so the sample is tied down here.
import { describe, expect, it } from 'vitest';
import { GlassCache, GLASS_KEY_LENGTH } from '../../src/software/glass-cache';

const key = (...values: number[]) => {
  const k = new Float64Array(GLASS_KEY_LENGTH);
  k.set(values);
  return k;
};
const MODEL = ['exact'], TEXTURE = {};

describe('GlassCache', () => {
  it('keeps an entry while the key stays, at the sample that wrote it only', () => {
    const c = new GlassCache();
    c.begin(key(1, 2, 3), [MODEL, TEXTURE], 16);
    expect(c.has(5, 0)).toBe(false);
    c.set(5, 2, 0.25, 0.75);
    expect(c.has(5, 2)).toBe(true);
    expect(c.has(5, 0)).toBe(false);
    expect(c.has(4, 2)).toBe(false);
    c.begin(key(1, 2, 3), [MODEL, TEXTURE], 16);
    expect(c.has(5, 2)).toBe(true);
    expect([c.f[5], c.texel[5]]).toEqual([0.25, 0.75]);
  });

  const changes: [string, Float64Array, unknown[], number][] = [
    ['a value', key(1, 2, 4), [MODEL, TEXTURE], 16],
    ['the last value', (() => { const k = key(1, 2, 3); k[GLASS_KEY_LENGTH - 1] = 1; return k; })(), [MODEL, TEXTURE], 16],
    ['0 to −0', key(1, 2, 3, -0), [MODEL, TEXTURE], 16],
    ['an object', key(1, 2, 3), [['exact'], TEXTURE], 16],
    ['one object fewer', key(1, 2, 3), [MODEL], 16],
    ['more pixels', key(1, 2, 3), [MODEL, TEXTURE], 17],
  ];
  for (const [name, values, objects, pixels] of changes) {
    it(`forgets every entry when ${name} changes`, () => {
      const c = new GlassCache();
      c.begin(key(1, 2, 3), [MODEL, TEXTURE], 16);
      c.set(5, 0, 0.25, 0.75);
      c.begin(values, objects, pixels);
      expect(c.has(5, 0)).toBe(false);
    });
  }

  it('keeps nothing across a NaN key or a clear()', () => {
    const c = new GlassCache();
    c.begin(key(NaN), [], 4);
    c.set(1, 0, 0.5, 0.5);
    c.begin(key(NaN), [], 4);
    expect(c.has(1, 0)).toBe(false);
    c.begin(key(1), [], 4);
    c.set(1, 0, 0.5, 0.5);
    c.clear();
    c.begin(key(1), [], 4);
    expect(c.has(1, 0)).toBe(false);
  });
});
