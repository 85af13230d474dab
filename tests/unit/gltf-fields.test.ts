// The glTF reader's checked JSON fields (src/loaders/gltf/fields.ts, docs/gltf.md#errors): each
// wrong type, missing item or out-of-range number refused with the path and message it names;
// fallbacks used only for absent fields; warnings said once each and capped; values shown short.
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { GltfFile, int, num, numbers, object, optionalObject, shownValue, str } from '../../src/loaders/gltf/fields';

const file = (json: Record<string, unknown> = {}) => new GltfFile('f.gltf', json);

/** The path and message of the LoadError `read` throws. */
function refusal(read: () => unknown): { path: string | undefined; message: string } {
  try {
    read();
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    expect((e as LoadError).url).toBe('f.gltf');
    return { path: (e as LoadError).path, message: (e as LoadError).detail.message };
  }
  throw new Error('read without an error');
}

describe('warnings', () => {
  it('keeps one warning per message, and at most 100', () => {
    const f = file();
    f.warn('a', 'same');
    f.warn('b', 'same');
    expect(f.warnings).toEqual([{ path: 'a', message: 'same' }]);
    for (let i = 0; i < 150; i++) f.warn(`p${i}`, `message ${i}`);
    expect(f.warnings.length).toBe(100);
    expect(f.warnings[99]).toEqual({ path: 'p98', message: 'message 98' });
  });
});

describe('top-level lists and their items', () => {
  it('refuses a top-level field that is not an array, and an item past the end or not an object', () => {
    expect(refusal(() => file({ nodes: {} }).list('nodes'))).toEqual({ path: 'nodes', message: 'nodes is not an array' });
    expect(file().list('nodes')).toEqual([]);
    const f = file({ accessors: [{ count: 1 }, 7] });
    expect(f.item('accessors', 0, 'x')).toEqual({ count: 1 });
    expect(refusal(() => f.item('accessors', 2, 'meshes[0].indices'))).toEqual({
      path: 'meshes[0].indices', message: 'accessors[2] does not exist (accessors has 2)',
    });
    expect(refusal(() => f.item('accessors', 1, 'meshes[0].indices'))).toEqual({ path: 'accessors[1]', message: 'accessors[1] is not an object' });
  });

  it('refuses null, a number, a string and an array where an object is needed; reads an absent optional one as undefined', () => {
    for (const v of [null, 3, 'x', [1]]) expect(refusal(() => object(file(), v, 'materials[2]'))).toEqual({ path: 'materials[2]', message: 'materials[2] is not an object' });
    expect(object(file(), { a: 1 }, 'm')).toEqual({ a: 1 });
    expect(optionalObject(file(), {}, 'extensions', 'materials[0]')).toBeUndefined();
    expect(refusal(() => optionalObject(file(), { extensions: 5 }, 'extensions', 'materials[0]'))).toEqual({
      path: 'materials[0].extensions', message: 'materials[0].extensions is not an object',
    });
  });
});

describe('numbers', () => {
  it('uses the fallback only when the field is absent', () => {
    expect(num(file(), { scale: 2 }, 'scale', 'n', 5)).toBe(2);
    expect(num(file(), {}, 'scale', 'n', 5)).toBe(5);
    expect(int(file(), { byteOffset: 8 }, 'byteOffset', 'v', 0)).toBe(8);
  });

  it('refuses a string, a missing value and an infinite one (1e400 in the JSON)', () => {
    expect(refusal(() => num(file(), { scale: '3' }, 'scale', 'n'))).toEqual({ path: 'n.scale', message: 'n.scale is "3", not a number' });
    expect(refusal(() => num(file(), {}, 'scale', 'n'))).toEqual({ path: 'n.scale', message: 'n.scale is missing, not a number' });
    const { scale } = JSON.parse('{"scale": 1e400}');
    expect(refusal(() => num(file(), { scale }, 'scale', 'n'))).toEqual({ path: 'n.scale', message: 'n.scale is null, not a number' });
  });

  it('accepts a number at either end of its range and refuses one past either', () => {
    expect(num(file(), { m: 0 }, 'm', 'p', undefined, 0, 1)).toBe(0);
    expect(num(file(), { m: 1 }, 'm', 'p', undefined, 0, 1)).toBe(1);
    expect(refusal(() => num(file(), { m: -0.5 }, 'm', 'p', undefined, 0, 1))).toEqual({ path: 'p.m', message: 'p.m is -0.5, outside [0, 1]' });
    expect(refusal(() => num(file(), { m: 1.5 }, 'm', 'p', undefined, 0, 1))).toEqual({ path: 'p.m', message: 'p.m is 1.5, outside [0, 1]' });
  });

  it('refuses a fraction or a negative where an index is needed, and one above its maximum', () => {
    expect(refusal(() => int(file(), { i: 1.5 }, 'i', 'p'))).toEqual({ path: 'p.i', message: 'p.i is 1.5, not an index or count' });
    expect(refusal(() => int(file(), { i: -1 }, 'i', 'p'))).toEqual({ path: 'p.i', message: 'p.i is -1, not an index or count' });
    expect(int(file(), { i: 4 }, 'i', 'p', undefined, 4)).toBe(4);
    expect(refusal(() => int(file(), { i: 5 }, 'i', 'p', undefined, 4))).toEqual({ path: 'p.i', message: 'p.i is 5, above 4' });
  });

  it('reads a fixed-length array of finite numbers, or the fallback when absent', () => {
    expect(numbers(file(), { t: [1, 2, 3] }, 't', 'n', 3, [0, 0, 0])).toEqual([1, 2, 3]);
    expect(numbers(file(), {}, 't', 'n', 3, [0, 0, 0])).toEqual([0, 0, 0]);
    const { big } = JSON.parse('{"big": [1, 1e400, 3]}');
    for (const t of [5, [1, 2], [1, 2, 3, 4], [1, '2', 3], ['1', '2', '3'], big]) {
      expect(refusal(() => numbers(file(), { t }, 't', 'nodes[0]', 3, [0, 0, 0])), JSON.stringify(t)).toEqual({
        path: 'nodes[0].t', message: 'nodes[0].t is not an array of 3 numbers',
      });
    }
  });
});

describe('strings and shown values', () => {
  it('reads a string, uses the fallback only when absent, and refuses a number', () => {
    expect(str(file(), { uri: 'a.bin' }, 'uri', 'b', 'x')).toBe('a.bin');
    expect(str(file(), {}, 'uri', 'b', 'x')).toBe('x');
    expect(str(file(), { uri: '' }, 'uri', 'b')).toBe('');
    expect(refusal(() => str(file(), { uri: 4 }, 'uri', 'buffers[0]'))).toEqual({ path: 'buffers[0].uri', message: 'buffers[0].uri is 4, not a string' });
    expect(refusal(() => str(file(), {}, 'uri', 'buffers[0]'))).toEqual({ path: 'buffers[0].uri', message: 'buffers[0].uri is missing, not a string' });
  });

  it('shows a value as its JSON, cut after 40 characters', () => {
    expect(shownValue(undefined)).toBe('missing');
    expect(shownValue(null)).toBe('null');
    expect(shownValue({ a: [1, 'b'] })).toBe('{"a":[1,"b"]}');
    expect(shownValue(Symbol('s'))).toBe('Symbol(s)');
    const forty = 'x'.repeat(38);
    expect(shownValue(forty)).toBe(`"${forty}"`);
    expect(shownValue(`${forty}y`)).toBe(`"${forty}y…`);
  });
});
