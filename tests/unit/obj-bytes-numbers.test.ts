// The byte scanner's numbers: a million varied tokens read from bytes, each exactly
// what parseFloat gives on the token (Object.is: −0 and all), and NaN where the text scanner
// refuses the token ("1e", ".", "inf"). Tokens are made deterministically: integers, decimals,
// exponents, signs and leading dots, mantissas past 17 digits, huge and tiny exponents,
// subnormals, the shortest forms of random doubles and the exact halfway points between two.
import { describe, expect, it } from 'vitest';
import { ByteScanner } from '../../src/loaders/obj/byte-scanner';
import { Scanner } from '../../src/loaders/obj/scanner';
import { instrumented } from './helpers/collections';

// Under StrykerJS (every call instrumented) a million took minutes a mutant: there 1,000, the same makers.
const COUNT = instrumented ? 1_000 : 1_000_000;
/** The numbers the scanners accept (src/loaders/obj/scanner.ts). */
const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

let seed = 2022;
function random(n: number): number { // mulberry32
  seed = (seed + 0x6d2b79f5) | 0;
  let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
  t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
  return ((t ^ (t >>> 14)) >>> 0) % n;
}
const pick = <T>(list: readonly T[]): T => list[random(list.length)];
const digits = (n: number): string => Array.from({ length: n }, () => String(random(10))).join('');

const view = new DataView(new ArrayBuffer(8));
/** A double from random bits: any exponent, subnormals and all (not NaN or ±Infinity). */
function randomDouble(): number {
  for (;;) {
    view.setUint32(0, random(2 ** 32));
    view.setUint32(4, random(2 ** 32));
    const x = view.getFloat64(0);
    if (Number.isFinite(x)) return x;
  }
}

/** The exact decimal midway between |x| and the next double up: a tie parseFloat must break to even. */
function halfway(x: number): string {
  view.setFloat64(0, Math.abs(x));
  const bits = view.getBigUint64(0);
  const exponent = Number(bits >> 52n);
  const fraction = bits & ((1n << 52n) - 1n);
  const m = exponent === 0 ? fraction : fraction | (1n << 52n);
  const e = (exponent === 0 ? 1 : exponent) - 1075; // |x| = m · 2^e
  const twice = 2n * m + 1n; // the midpoint is twice · 2^(e − 1)
  const k = e - 1;
  if (k >= 0) return (twice << BigInt(k)).toString();
  const s = (twice * 5n ** BigInt(-k)).toString().padStart(-k + 1, '0'); // twice · 5^−k / 10^−k
  return `${s.slice(0, s.length + k)}.${s.slice(s.length + k)}`;
}

function sign(): string {
  return pick(['', '', '', '-', '+']);
}

function exponentPart(): string {
  const e = pick([() => String(random(25)), () => String(random(400)), () => String(300 + random(30)), () => '0'.repeat(random(4)) + String(random(10))])();
  return `${pick(['e', 'E'])}${pick(['', '-', '+'])}${e}`;
}

const MAKERS: (() => string)[] = [
  () => sign() + digits(1 + random(9)), // integers
  () => sign() + digits(1 + random(20)), // integers past 2^53 too
  () => `${sign()}${digits(random(6))}.${digits(random(10))}`, // decimals, leading and trailing dots
  () => `${sign()}${digits(1 + random(4))}.${digits(random(8))}${exponentPart()}`, // exponents
  () => `${sign()}.${digits(1 + random(6))}${exponentPart()}`,
  () => `${sign()}${digits(1 + random(40))}.${digits(random(40))}`, // long mantissas
  () => `${sign()}0.${'0'.repeat(random(30))}${digits(1 + random(20))}`, // leading zeros
  () => `${sign()}${digits(1 + random(20))}e-${300 + random(30)}`, // subnormals and underflow
  () => `${sign()}${digits(1 + random(20))}e${290 + random(30)}`, // near and past the largest double
  () => sign() + String(randomDouble()), // shortest round-trip forms, any exponent
  () => sign() + randomDouble().toPrecision(1 + random(21)),
  () => sign() + randomDouble().toExponential(random(21)),
  () => sign() + (random(2 ** 20) / 2 ** random(20)).toFixed(random(12)), // what exporters write
  () => sign() + halfway(random(4) ? random(2 ** 30) / 2 ** random(40) : randomDouble()), // ties
  () => pick(['1e', '.', '+.5e-3', 'inf', 'nan', 'Infinity', '-', '+', '1e+', '..5', '1.2.3', '0x10', '1_0', 'e5', '-.e1',
    '1e5.5', '.e', '5e-', '+-1', '1..', '١', `${digits(3)}x`, `1e${digits(7)}`, `0.${'0'.repeat(400)}1e401`, '00.00e-00']),
];

/** Exponents past the scanners' cap (100000) that digits after the point bring back near 1. */
const CAPPED = [`0.${'0'.repeat(99_999)}1e100000`, `0.${'0'.repeat(99_999)}1e1000005`, `-0.${'0'.repeat(99_990)}5e1000000`,
  `1${'0'.repeat(99_995)}e-100000`, `1${'0'.repeat(99_995)}e-1000000`];

function makeTokens(): string[] {
  const tokens: string[] = [...CAPPED];
  for (let i = 0; i < COUNT; i++) tokens.push(pick(MAKERS)());
  return tokens;
}

describe('ByteScanner.readNumber', () => {
  it(`reads ${COUNT.toLocaleString('en')} varied tokens exactly as parseFloat does (and refuses what the text scanner refuses)`, { timeout: 60_000 }, () => {
    const tokens = makeTokens();
    const text = tokens.join(' ');
    const bytes = new TextEncoder().encode(text);
    const byBytes = new ByteScanner(bytes);
    const byText = new Scanner(text);
    const differences: string[] = [];
    let valid = 0, long = 0, at = 0, textAt = 0;
    for (const token of tokens) {
      const ok = NUMBER.test(token);
      if (ok) valid++;
      if (token.length > 17) long++;
      const want = ok ? parseFloat(token) : NaN;
      const got = byBytes.readNumber();
      const textGot = byText.readNumber();
      if (!Object.is(got, want) || !Object.is(textGot, want)) differences.push(`${token.slice(0, 80)}: bytes ${got}, text ${textGot}, parseFloat ${want}`);
      byBytes.skipBlank();
      byText.skipBlank();
      // Each left on the next token (offsets in bytes and in UTF-16 units).
      at += new TextEncoder().encode(token).length + 1;
      textAt += token.length + 1;
      if (byBytes.pos !== Math.min(at, bytes.length) || byText.pos !== Math.min(textAt, text.length)) differences.push(`${token.slice(0, 80)}: cursor off`);
    }
    expect(differences.slice(0, 10)).toEqual([]);
    expect(byBytes.atEnd()).toBe(true);
    // The mix reaches both paths and the refusals.
    expect(valid).toBeGreaterThan(0.9 * COUNT);
    expect(long).toBeGreaterThan(0.1 * COUNT);
  });
});
