// What a frame, or a gesture's start, computes allocates nothing: a collection mid-frame is a
// dropped frame (docs/rendering.md). The check itself is shown to see allocation in lazy-parts.test.ts.
import { describe, expect, it } from 'vitest';
import { reflectionMatrix } from '../../src/math/mirror';
import { boundsCenter } from '../../src/scene/group-rotation';
import { defaultScene } from '../../src/scene/default-scene';
import { collections, instrumented } from './helpers/collections';

// Each loop runs once before it is counted: until the optimizing compiler takes a function, the
// interpreter boxes its doubles, garbage no optimized frame makes.
describe.skipIf(instrumented)('per-frame maths allocates nothing', () => {
  it('the reflection matrix, 2 M planes', async () => {
    const out = new Float32Array(16), plane = new Float64Array([0, 0, 1, 0]);
    const loop = () => { for (let i = 0; i < 2_000_000; i++) { plane[3] = i * 1e-9; reflectionMatrix(out, plane); } };
    loop();
    expect(await collections(loop)).toBe(0);
    expect(out[14]).toBeCloseTo(-2 * 1999999e-9, 9); // the loop ran, its last plane in the matrix
  });

  it('the objects\' centre an orbit turns about, 200 k asks of the default scene', async () => {
    const objects = defaultScene(3, 0).objects, out = new Float64Array(3);
    const loop = () => { for (let i = 0; i < 200_000; i++) boundsCenter(objects, out); };
    loop();
    expect(await collections(loop)).toBe(0);
    expect(Array.from(out)).toEqual(boundsCenter(objects, [0, 0, 0]));
  });
});
