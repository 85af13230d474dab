// Every OBJ the loader tests parse, parsed both ways (text and bytes): the tests below run again with
// parseObj and parseObjBytes wrapped so that each call also runs the other path and expects
// the same result bit for bit, or the same LoadError — text as UTF-8 bytes, bytes as the
// text the whole file decodes to (what parseObjBytes did before it read bytes).
import { afterAll, expect, vi } from 'vitest';
import type * as Obj from '../../src/loaders/obj';
import { expectSameOutcome, outcomeOf, type Outcome } from './helpers/obj-same';
import { instrumented } from './helpers/collections';

const compared = { text: 0, bytes: 0 };

vi.mock('../../src/loaders/obj', async (importOriginal) => {
  const real = await importOriginal<typeof Obj>();
  const { decodeText } = await import('../../src/loaders/decode-text');
  const { sniffModel } = await import('../../src/loaders/sniff');
  const { LoadError } = await import('../../src/loaders/load-error');
  const settle = (o: Outcome): Obj.ObjResult => {
    if (!o.ok) throw o.error;
    return o.result;
  };
  const viaText = (bytes: Uint8Array, options: Obj.ObjOptions = {}): Obj.ObjResult => {
    const sniffed = options.sniffed ?? sniffModel(bytes);
    if (sniffed === 'binary') throw new LoadError(options.url ?? '', 'binary content, not an OBJ file');
    return real.parseObj(decodeText(bytes), { ...options, sniffed });
  };
  return {
    ...real,
    parseObj(text: string, options?: Obj.ObjOptions): Obj.ObjResult {
      const want = outcomeOf(() => real.parseObj(text, options));
      const bytes = new TextEncoder().encode(text);
      // Lone surrogates have no UTF-8: such text has no byte twin to compare.
      if (new TextDecoder().decode(bytes) === text) {
        expectSameOutcome(outcomeOf(() => real.parseObjBytes(bytes, options)), want, JSON.stringify(text.slice(0, 80)));
        compared.text++;
      }
      return settle(want);
    },
    parseObjBytes(input: ArrayBuffer | Uint8Array, options?: Obj.ObjOptions): Obj.ObjResult {
      const got = outcomeOf(() => real.parseObjBytes(input, options));
      const bytes = input instanceof Uint8Array ? input : new Uint8Array(input);
      expectSameOutcome(got, outcomeOf(() => viaText(bytes, options)), `${bytes.length} bytes`);
      compared.bytes++;
      return settle(got);
    },
  };
});

await import('./obj.test');
await import('./obj-faults.test');
await import('./obj-polygons.test');
// The scans (seconds each under StrykerJS, for every mutant they cover) only outside it.
if (!instrumented) await import('./obj-data.test');
await import('./obj-job.test');
await import('./mesh-parts.test');

afterAll(() => {
  // The wrapper ran: a mock that stopped applying would pass every test above unchecked.
  expect(compared.text).toBeGreaterThan(50);
  expect(compared.bytes).toBeGreaterThan(5);
});
