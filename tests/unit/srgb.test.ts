// The sRGB transfer curve (docs/colour.md#the-transfer-curve) against published values (IEC 61966-2-1's piecewise curve; the 8-bit
// levels below in linear light are the values every colour-management table lists), and the
// byte encoder the software renderer uses against the formula.
import { describe, expect, it } from 'vitest';
import { COLOR_SPACES, linearToSrgb, linearToSrgbByte, srgbToLinear, SRGB_BYTE_TO_LINEAR } from '../../src/math/srgb';

// 8-bit level → linear light, to 7 digits.
const PUBLISHED: [number, number][] = [
  [0, 0],
  [10, 0.0030353], // still on the linear segment: 10/255/12.92
  [64, 0.0512695],
  [128, 0.2158605],
  [200, 0.5775804],
  [255, 1],
];

describe('srgbToLinear', () => {
  it('gives the published linear value of 8-bit levels', () => {
    for (const [b, l] of PUBLISHED) expect(Math.abs(srgbToLinear(b / 255) - l), `level ${b}`).toBeLessThan(5e-8);
    expect(Math.abs(srgbToLinear(0.5) - 0.2140411)).toBeLessThan(5e-8);
  });

  it('is not a 2.2 power: linear near black (level 5 is 8× a 2.2 power’s value)', () => {
    expect(srgbToLinear(5 / 255)).toBeCloseTo(5 / 255 / 12.92, 15);
    expect(srgbToLinear(5 / 255) / (5 / 255) ** 2.2).toBeGreaterThan(8);
  });

  it('joins its segments at 0.04045 ↔ 0.0031308', () => {
    expect(Math.abs(srgbToLinear(0.04045) - 0.0031308)).toBeLessThan(1e-7);
    expect(Math.abs(((0.04045 + 0.055) / 1.055) ** 2.4 - 0.04045 / 12.92)).toBeLessThan(1e-7);
  });
});

describe('linearToSrgb', () => {
  it('encodes 0.2159 to 128/255 (0.50196): a white texture under ambient 0.2159', () => {
    // 1.055·0.2159^(1/2.4) − 0.055 = 0.502003, within 0.1 of a level of 128.
    expect(Math.abs(linearToSrgb(0.2159) - 0.5020032)).toBeLessThan(5e-7);
    expect(Math.round(linearToSrgb(0.2159) * 255)).toBe(128);
  });

  it('inverts srgbToLinear over the whole range', () => {
    for (let i = 0; i <= 1000; i++) expect(Math.abs(linearToSrgb(srgbToLinear(i / 1000)) - i / 1000)).toBeLessThan(1e-12);
  });

  it('clips above 1 and below 0 before encoding (no tone mapping); NaN is 0', () => {
    expect(linearToSrgb(1.7)).toBe(1);
    expect(linearToSrgb(-0.2)).toBe(0);
    expect(linearToSrgb(NaN)).toBe(0);
    expect(linearToSrgb(0.001)).toBeCloseTo(0.01292, 12);
  });

  it('encodes 1 as exactly 1 (white is byte 255, not 0.9999999999999999 of it)', () => {
    expect(linearToSrgb(1)).toBe(1);
  });

  it('takes the linear segment at the joints themselves (≤ 0.0031308 and ≤ 0.04045, as the standard writes)', () => {
    expect(linearToSrgb(0.0031308)).toBe(12.92 * 0.0031308);
    expect(srgbToLinear(0.04045)).toBe(0.04045 / 12.92);
  });
});

describe('byte tables', () => {
  it('SRGB_BYTE_TO_LINEAR holds decode(b/255) for every byte', () => {
    for (const [b, l] of PUBLISHED) expect(Math.abs(SRGB_BYTE_TO_LINEAR[b] - l)).toBeLessThan(5e-8);
  });

  it('linearToSrgbByte is round(encode(l)·255) for 200,000 values, thresholds included', () => {
    let differences = 0;
    const check = (l: number) => { if (linearToSrgbByte(l) !== Math.round(linearToSrgb(l) * 255)) differences++; };
    for (let i = 0; i <= 100000; i++) check(i / 100000);
    // Values a hair either side of every step.
    for (let b = 1; b < 256; b++) {
      const t = srgbToLinear((b - 0.5) / 255);
      check(t * (1 - 1e-12));
      check(t * (1 + 1e-12));
    }
    for (let i = 0; i < 99000; i++) check(((i * 7919) % 99991) / 99991 * 1.2 - 0.1);
    expect(differences).toBe(0);
    expect(linearToSrgbByte(0.2159)).toBe(128);
    expect(linearToSrgbByte(2)).toBe(255);
    expect(linearToSrgbByte(-1)).toBe(0);
  });

  it('a value exactly at a step, decode((b − ½)/255), is byte b: ties go up', () => {
    for (let b = 1; b < 256; b++) expect(linearToSrgbByte(srgbToLinear((b - 0.5) / 255)), `byte ${b}`).toBe(b);
  });

  it('SRGB_BYTE_TO_LINEAR is decode(b/255) at every one of its 256 bytes', () => {
    expect(SRGB_BYTE_TO_LINEAR.length).toBe(256);
    for (let b = 0; b < 256; b++) expect(SRGB_BYTE_TO_LINEAR[b], `byte ${b}`).toBe(srgbToLinear(b / 255));
  });
});

describe('COLOR_SPACES', () => {
  it('are the color-space attribute\'s keywords: srgb and none', () => {
    expect(COLOR_SPACES).toEqual(['srgb', 'none']);
  });
});
