// An object's frame (src/reference/object-frame.ts): model = T · Rz·Ry·Rx · R_y(spin·t) · S, with the rotations' order
// and each map (points, directions, gradients, normals) worked out by hand for quarter turns.
import { describe, expect, it } from 'vitest';
import { ObjectFrame } from '../../src/reference/object-frame';
import type { Transform, Vec3 } from '../../src/scene/scene';
import { expectClose } from './helpers/math';

const transform = (over: Partial<Transform> = {}): Transform => ({ position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0, ...over });
const out = () => new Float64Array(3);
/** The object's axis k in the world: column k of the matrix. */
const axis = (f: ObjectFrame, k: number) => [f.matrix[4 * k], f.matrix[4 * k + 1], f.matrix[4 * k + 2]];

describe('ObjectFrame', () => {
  it('the identity: matrix I, unit scale, every map the identity', () => {
    const f = new ObjectFrame(transform(), 0);
    expectClose(f.matrix, [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
    expect(f.unitScale).toBe(true);
    expect([...f.pointToObject(out(), [1, 2, 3])]).toEqual([1, 2, 3]);
  });

  it('rotation X then Y: object x → −z, y → +x, z → −y (Ry(90°)·Rx(90°))', () => {
    const f = new ObjectFrame(transform({ rotation: [90, 90, 0] }), 0);
    expectClose(axis(f, 0), [0, 0, -1]);
    expectClose(axis(f, 1), [1, 0, 0]);
    expectClose(axis(f, 2), [0, -1, 0]);
  });

  it('rotation X then Z: object x → +y, y → +z, z → +x (Rz(90°)·Rx(90°))', () => {
    const f = new ObjectFrame(transform({ rotation: [90, 0, 90] }), 0);
    expectClose(axis(f, 0), [0, 1, 0]);
    expectClose(axis(f, 1), [0, 0, 1]);
    expectClose(axis(f, 2), [1, 0, 0]);
  });

  it('the spin about the object Y comes first: rotation X 90° with spin·t = 90° maps x → +y, y → +z, z → +x', () => {
    // Rx(90°)·Ry(90°): x → Ry → −z → Rx → +y; y → y → +z; z → +x → +x.
    const f = new ObjectFrame(transform({ rotation: [90, 0, 0], spin: Math.PI / 4 }), 2);
    expectClose(axis(f, 0), [0, 1, 0]);
    expectClose(axis(f, 1), [0, 0, 1]);
    expectClose(axis(f, 2), [1, 0, 0]);
    // At time 0 the spin is nothing.
    expectClose(axis(new ObjectFrame(transform({ rotation: [90, 0, 0], spin: Math.PI / 4 }), 0), 0), [1, 0, 0]);
  });

  it('the position is the translation; the scale is kept apart, unitScale only for (1, 1, 1)', () => {
    const f = new ObjectFrame(transform({ position: [4, -5, 6], scale: [2, 3, 4] }), 0);
    expect([f.matrix[12], f.matrix[13], f.matrix[14], f.matrix[15]]).toEqual([4, -5, 6, 1]);
    expect([...f.scale]).toEqual([2, 3, 4]);
    expect(f.unitScale).toBe(false);
    for (const scale of [[2, 1, 1], [1, 2, 1], [1, 1, 2]] as Vec3[]) expect(new ObjectFrame(transform({ scale }), 0).unitScale).toBe(false);
  });

  // Rz(90°): object x → +y, y → −x, z → z; T = (1, 2, 3), S = (2, 4, 0.5).
  const f = new ObjectFrame(transform({ position: [1, 2, 3], rotation: [0, 0, 90], scale: [2, 4, 0.5] }), 0);

  it('pointToObject = S⁻¹·Rᵀ·(p − T)', () => {
    // p − T = (−2, 3, 1); Rᵀ: (x, y, z) → (y, −x, z) = (3, 2, 1); S⁻¹: (1.5, 0.5, 2).
    expectClose(f.pointToObject(out(), [-1, 5, 4]), [1.5, 0.5, 2]);
  });

  it('directionToObject = S⁻¹·Rᵀ·d, without the translation', () => {
    // d = (−2, 3, 1) → (3, 2, 1) → (1.5, 0.5, 2).
    expectClose(f.directionToObject(out(), [-2, 3, 1]), [1.5, 0.5, 2]);
  });

  it('gradientToWorld = R·S⁻¹·g, not normalised', () => {
    // g = (4, 8, 1) → S⁻¹ (2, 2, 2) → R: (x, y, z) → (−y, x, z) = (−2, 2, 2).
    expectClose(f.gradientToWorld(out(), [4, 8, 1]), [-2, 2, 2]);
  });

  it('normalToWorld = normalize(R·S⁻¹·n); a zero normal stays zero', () => {
    // n = (0, 4, 0) → (0, 1, 0) → (−1, 0, 0); n = (2, 0, 1) → (1, 0, 2) → (0, 1, 2)/√5.
    expectClose(f.normalToWorld(out(), [0, 4, 0]), [-1, 0, 0]);
    expectClose(f.normalToWorld(out(), [2, 0, 1]), [0, 1 / Math.sqrt(5), 2 / Math.sqrt(5)]);
    expect([...f.normalToWorld(out(), [0, 0, 0])]).toEqual([0, 0, 0]);
  });

  // Ry(90°)·Rx(90°) (object x → −z, y → +x, z → −y), T = (1, 2, 3), S = (2, 4, 0.5): Rᵀ·v = (−v_z, v_x, −v_y).
  const g = new ObjectFrame(transform({ position: [1, 2, 3], rotation: [90, 90, 0], scale: [2, 4, 0.5] }), 0);

  it('every entry of the rotation counts: the maps in a frame with no axis left in place', () => {
    // p − T = (4, −2, 6) → Rᵀ (−6, 4, 2) → S⁻¹ (−3, 1, 4); the same vector as a direction.
    expectClose(g.pointToObject(out(), [5, 0, 9]), [-3, 1, 4]);
    expectClose(g.directionToObject(out(), [4, -2, 6]), [-3, 1, 4]);
    // g = (2, 8, 1) → S⁻¹ (1, 2, 2) → R: 1·(0, 0, −1) + 2·(1, 0, 0) + 2·(0, −1, 0) = (2, −2, −1), of length 3.
    expectClose(g.gradientToWorld(out(), [2, 8, 1]), [2, -2, -1]);
    expectClose(g.normalToWorld(out(), [2, 8, 1]), [2 / 3, -2 / 3, -1 / 3]);
  });

  it('each map writes the three components of out and nothing past them', () => {
    const four = () => new Float64Array([7, 7, 7, 7]);
    expect(g.pointToObject(four(), [5, 0, 9])[3]).toBe(7);
    expect(g.directionToObject(four(), [4, -2, 6])[3]).toBe(7);
    expect(g.gradientToWorld(four(), [2, 8, 1])[3]).toBe(7);
    expect(g.normalToWorld(four(), [2, 8, 1])[3]).toBe(7);
  });
});
