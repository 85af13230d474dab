// The byte parser against the text parser: the same ObjResult bit for bit, or the same LoadError.
import { expect } from 'vitest';
// Imports no parser (only its types): obj-bytes-suite.test.ts uses it inside a mock of obj.ts.
import { LoadError } from '../../../src/loaders/load-error';
import type { ObjResult } from '../../../src/loaders/obj';

export type Outcome = { ok: true; result: ObjResult } | { ok: false; error: unknown };

export function outcomeOf(parse: () => ObjResult): Outcome {
  try {
    return { ok: true, result: parse() };
  } catch (error) {
    return { ok: false, error };
  }
}

function bitsOf(a: ArrayBufferView): Uint8Array {
  return new Uint8Array(a.buffer, a.byteOffset, a.byteLength);
}

/** Typed arrays compared byte for byte (−0, NaN payloads and all), the rest deeply. */
export function expectSameOutcome(got: Outcome, want: Outcome, label = ''): void {
  if (!want.ok) {
    expect(got.ok, `${label}: expected an error, got a result`).toBe(false);
    if (got.ok) return;
    expect(got.error, label).toBeInstanceOf(LoadError);
    const g = got.error as LoadError, w = want.error as LoadError;
    expect({ message: g.message, detail: g.detail }, label).toEqual({ message: w.message, detail: w.detail });
    return;
  }
  expect(got.ok, `${label}: ${got.ok ? '' : String(got.error)}`).toBe(true);
  if (!got.ok) return;
  const g = got.result, w = want.result;
  expect(Object.keys(g).sort(), label).toEqual(Object.keys(w).sort());
  for (const key of Object.keys(w) as (keyof ObjResult)[]) {
    const a = g[key], b = w[key];
    if (ArrayBuffer.isView(b)) {
      expect(a?.constructor, `${label}: ${key}`).toBe(b.constructor);
      expect(Buffer.compare(bitsOf(a as ArrayBufferView), bitsOf(b)), `${label}: ${key} differs`).toBe(0);
    } else {
      expect(a, `${label}: ${key}`).toEqual(b);
    }
  }
}

