// deepFreeze (src/scene/scene.ts): the scene value the element hands over is frozen all the way
// down, but typed arrays, which cannot be (docs/scene-model.md#one-scene-value).
import { describe, expect, it } from 'vitest';
import { deepFreeze } from '../../src/scene/scene';

describe('deepFreeze', () => {
  it('freezes every nested object and array, and returns the value itself', () => {
    const value = { a: { b: [1, { c: 2 }] }, d: [[3]] };
    expect(deepFreeze(value)).toBe(value);
    for (const part of [value, value.a, value.a.b, value.a.b[1], value.d, value.d[0]]) expect(Object.isFrozen(part)).toBe(true);
    expect(() => { (value.a.b[1] as { c: number }).c = 5; }).toThrow(TypeError);
  });

  it('leaves typed arrays (a mesh\'s data) writable, and what they hold untouched', () => {
    const positions = new Float32Array([1, 2, 3]);
    const value = { mesh: { positions, indices: new Uint32Array(3) } };
    deepFreeze(value);
    expect(Object.isFrozen(value.mesh)).toBe(true);
    positions[0] = 9;
    expect(positions[0]).toBe(9);
  });

  it('takes primitives and null as they are', () => {
    expect(deepFreeze(null)).toBeNull();
    expect(deepFreeze(3)).toBe(3);
    expect(deepFreeze('x')).toBe('x');
    expect(deepFreeze(undefined)).toBeUndefined();
  });

  it('ends on a cycle: a value already frozen is not walked again', () => {
    const a: { self?: unknown; child: { n: number } } = { child: { n: 1 } };
    a.self = a;
    deepFreeze(a);
    expect(Object.isFrozen(a)).toBe(true);
    expect(Object.isFrozen(a.child)).toBe(true);
  });
});
