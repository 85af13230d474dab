// Which hits the reference keeps (src/reference/clip.ts): view depth within [near, far], beyond tMin, and on the
// mirrored pass the eye's side of the glass at least MIRROR_CONTACT from it; the same rule as an interval of t.
import { afterEach, describe, expect, it } from 'vitest';
import { clipRange, kept, keptInterval, setClipRange, visible } from '../../src/reference/clip';
import { Ray } from '../../src/reference/ray';
import { SurfaceHit } from '../../src/reference/surface-hit';
import { MIRROR_CONTACT, type Plane } from '../../src/math/mirror';

const Z0: Plane = [0, 0, 1, 0];
const C = MIRROR_CONTACT;

afterEach(() => setClipRange(0.1, 100));

function hitAt(t: number, p: [number, number, number] = [0, 0, 0]): SurfaceHit {
  const h = new SurfaceHit();
  h.t = t;
  h.p.set(p);
  return h;
}

function ray(o: [number, number, number], d: [number, number, number]): Ray {
  const r = new Ray();
  r.origin.set(o);
  r.direction.set(d);
  return r;
}

describe('clipRange, visible', () => {
  it("starts at the default camera's near 0.1 and far 100, both ends kept", () => {
    expect(clipRange).toEqual({ near: 0.1, far: 100 });
    expect(visible(0.1)).toBe(true);
    expect(visible(100)).toBe(true);
    expect(visible(0.0999999)).toBe(false);
    expect(visible(100.000001)).toBe(false);
  });

  it('setClipRange moves both ends', () => {
    setClipRange(2, 3);
    expect(clipRange).toEqual({ near: 2, far: 3 });
    expect([1.999, 2, 2.5, 3, 3.001].map(visible)).toEqual([false, true, true, true, false]);
  });
});

describe('kept', () => {
  it('without a clip side: t > tMin (strictly) and within [near, far]; the plane is not read', () => {
    expect(kept(hitAt(5), 4, 0, null)).toBe(true);
    expect(kept(hitAt(5), 5, 0, null)).toBe(false);
    expect(kept(hitAt(5), 6, 0, null)).toBe(false);
    expect(kept(hitAt(0.05), 0, 0, null)).toBe(false); // before near
    expect(kept(hitAt(150), 0, 0, null)).toBe(false); // beyond far
  });

  it('on the mirrored pass: clipSide × distance from the glass at least MIRROR_CONTACT', () => {
    // Z0: the distance of p is its z.
    expect(kept(hitAt(5, [3, 4, C]), 0, 1, Z0)).toBe(true);
    expect(kept(hitAt(5, [3, 4, 2]), 0, 1, Z0)).toBe(true);
    expect(kept(hitAt(5, [3, 4, C / 2]), 0, 1, Z0)).toBe(false);
    expect(kept(hitAt(5, [3, 4, -2]), 0, 1, Z0)).toBe(false);
    expect(kept(hitAt(5, [3, 4, -C]), 0, -1, Z0)).toBe(true);
    expect(kept(hitAt(5, [3, 4, 2]), 0, -1, Z0)).toBe(false);
    // The side rule does not lift the others.
    expect(kept(hitAt(5, [0, 0, 2]), 5, 1, Z0)).toBe(false);
    expect(kept(hitAt(500, [0, 0, 2]), 0, 1, Z0)).toBe(false);
  });
});

describe('keptInterval', () => {
  const out = new Float64Array(2);

  it('without a clip side: [max(tMin, near), far]', () => {
    expect(keptInterval(ray([0, 0, 5], [0, 0, -1]), 0, 0, null, out)).toBe(true);
    expect([...out]).toEqual([0.1, 100]);
    expect(keptInterval(ray([0, 0, 5], [0, 0, -1]), 7, 0, null, out)).toBe(true);
    expect([...out]).toEqual([7, 100]);
    expect(keptInterval(ray([0, 0, 5], [0, 0, -1]), 100, 0, null, out)).toBe(true); // lo = hi: kept
    expect([...out]).toEqual([100, 100]);
    expect(keptInterval(ray([0, 0, 5], [0, 0, -1]), 101, 0, null, out)).toBe(false);
    expect([...out]).toEqual([101, 100]);
  });

  it('towards the glass from the kept side: hi = where the ray comes within MIRROR_CONTACT of it', () => {
    // z = 5 − 2t ≥ C ⇔ t ≤ (5 − C)/2.
    expect(keptInterval(ray([0, 0, 5], [1, 0, -2]), 0, 1, Z0, out)).toBe(true);
    expect(out[0]).toBe(0.1);
    expect(out[1]).toBeCloseTo((5 - C) / 2, 14);
    // From the other side (clipSide −1): −z = 5 − 2t ≥ C, the same.
    expect(keptInterval(ray([0, 0, -5], [0, 0, 2]), 0, -1, Z0, out)).toBe(true);
    expect(out[1]).toBeCloseTo((5 - C) / 2, 14);
  });

  it('away from the glass from its far side: lo = where the ray reaches MIRROR_CONTACT on the kept side', () => {
    // z = −4 + 0.5t ≥ C ⇔ t ≥ 2(4 + C).
    expect(keptInterval(ray([0, 0, -4], [0, 0, 0.5]), 0, 1, Z0, out)).toBe(true);
    expect(out[0]).toBeCloseTo(2 * (4 + C), 13);
    expect(out[1]).toBe(100);
    // tMin beyond that: tMin.
    expect(keptInterval(ray([0, 0, -4], [0, 0, 0.5]), 9, 1, Z0, out)).toBe(true);
    expect([...out]).toEqual([9, 100]);
  });

  it('towards the glass from its far side, or too far away: empty', () => {
    expect(keptInterval(ray([0, 0, -4], [0, 0, -1]), 0, 1, Z0, out)).toBe(false);
    expect(out[1]).toBeCloseTo(-(4 + C), 13);
    // Away from the glass on the kept side, but the contact would be reached only beyond far.
    expect(keptInterval(ray([0, 0, -300], [0, 0, 1]), 0, 1, Z0, out)).toBe(false);
    expect(out[0]).toBeCloseTo(300 + C, 10);
  });

  it('parallel to the glass: all of [near, far] on the kept side, nothing on the other', () => {
    expect(keptInterval(ray([0, 0, 1], [1, 0, 0]), 0, 1, Z0, out)).toBe(true);
    expect([...out]).toEqual([0.1, 100]);
    expect(keptInterval(ray([0, 0, C], [0, 1, 0]), 0, 1, Z0, out)).toBe(true); // exactly at the contact distance
    expect(keptInterval(ray([0, 0, 1], [1, 0, 0]), 0, -1, Z0, out)).toBe(false);
    expect(keptInterval(ray([0, 0, C / 2], [1, 0, 0]), 0, 1, Z0, out)).toBe(false);
  });

  it('an oblique plane: every component of n counts', () => {
    // n = (0.48, 0.6, 0.64) (unit), d = 0: the origin (3, 4, 5) is 1.44 + 2.4 + 3.2 = 7.04 from it; the direction
    // −(3, 4, 5)/5 approaches it at n·d = −7.04/5 per unit t, so the contact distance comes at t = 5(7.04 − C)/7.04.
    const n: Plane = [0.48, 0.6, 0.64, 0];
    expect(keptInterval(ray([3, 4, 5], [-0.6, -0.8, -1]), 0, 1, n, out)).toBe(true);
    expect(out[1]).toBeCloseTo((5 * (7.04 - C)) / 7.04, 12);
  });

  it('the plane is read with its offset: z = 2 (n = +z, d = −2)', () => {
    // z = 10 − t ≥ 2 + C ⇔ t ≤ 8 − C.
    expect(keptInterval(ray([0, 0, 10], [0, 0, -1]), 0, 1, [0, 0, 1, -2], out)).toBe(true);
    expect(out[1]).toBeCloseTo(8 - C, 13);
  });
});
