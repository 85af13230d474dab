// The box and the sphere of the reference (src/reference/analytic-tracers.ts): entry points, faces and codes, UVs and
// their world gradients, normals under rotation and (negative, non-uniform) scale, worked out by hand.
import { describe, expect, it } from 'vitest';
import { BoxTracer, SphereTracer } from '../../src/reference/analytic-tracers';
import { ObjectFrame } from '../../src/reference/object-frame';
import { Ray } from '../../src/reference/ray';
import { SurfaceHit } from '../../src/reference/surface-hit';
import type { Transform } from '../../src/scene/scene';
import { expectClose } from './helpers/math';

const frame = (over: Partial<Transform> = {}, time = 0) =>
  new ObjectFrame({ position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0, ...over }, time);

function ray(o: [number, number, number], d: [number, number, number]): Ray {
  const r = new Ray();
  r.origin.set(o);
  r.direction.set(d);
  return r;
}

describe('BoxTracer', () => {
  it('the +z face from above: code, object, frame, t, points, UV and gradients', () => {
    // Edge 2 at the origin; from (0.5, 0.25, 5) down −z: enters z = 1 at t = 4. +z face: u along +x, v along +y:
    // u = ½ + 0.5/2, v = ½ + 0.25/2; gradients a/size, b/size.
    const f = frame();
    const box = new BoxTracer(f, 2, 3, 10);
    const hit = new SurfaceHit();
    expect(box.hit(ray([0.5, 0.25, 5], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.object, hit.t]).toEqual([10, 3, 4]);
    expect(hit.frame).toBe(f);
    expect([...hit.p]).toEqual([0.5, 0.25, 1]);
    expect([...hit.q]).toEqual([0.5, 0.25, 1]);
    expect([...hit.nq]).toEqual([0, 0, 1]);
    expect([...hit.n]).toEqual([0, 0, 1]);
    expect([...hit.ng]).toEqual([0, 0, 1]);
    expect([hit.u, hit.v]).toEqual([0.75, 0.625]);
    expect([...hit.gu]).toEqual([0.5, 0, 0]);
    expect([...hit.gv]).toEqual([0, 0.5, 0]);
  });

  it('every face in BOX_FACES order (+z, −z, +x, −x, +y, −y), entered from outside', () => {
    // Edge 1 centred at (0, 0, −10); each ray aims at a point off the face's centre, (0.1, 0.2) along its (u, v) axes.
    const box = new BoxTracer(frame({ position: [0, 0, -10] }), 1, 0, 1);
    const cases: [[number, number, number], [number, number, number], number[], number][] = [
      [[0.1, 0.2, -5], [0, 0, -1], [0, 0, 1], 1],
      [[-0.1, 0.2, -15], [0, 0, 1], [0, 0, -1], 2],
      [[5, 0.2, -10.1], [-1, 0, 0], [1, 0, 0], 3],
      [[-5, 0.2, -9.9], [1, 0, 0], [-1, 0, 0], 4],
      [[0.1, 5, -10.2], [0, -1, 0], [0, 1, 0], 5],
      [[0.1, -5, -9.8], [0, 1, 0], [0, -1, 0], 6],
    ];
    for (const [o, d, n, code] of cases) {
      const hit = new SurfaceHit();
      expect(box.hit(ray(o, d), 0, 0, null, hit), `code ${code}`).toBe(true);
      expect(hit.surface, `code ${code}`).toBe(code);
      expect(hit.t, `code ${code}`).toBeCloseTo(4.5, 12);
      expectClose(hit.n, n);
      expectClose(hit.nq, n);
      expect(hit.u, `code ${code}`).toBeCloseTo(0.6, 12);
      expect(hit.v, `code ${code}`).toBeCloseTo(0.7, 12);
    }
  });

  it('misses: beside a slab it is parallel to, or through no common interval', () => {
    const box = new BoxTracer(frame(), 2, 0, 1);
    const miss = (o: [number, number, number], d: [number, number, number]) => box.hit(ray(o, d), -1e9, 0, null, new SurfaceHit());
    expect(miss([0, 5, 5], [0, 0, -1])).toBe(false);
    expect(miss([0, -5, 5], [0, 0, -1])).toBe(false);
    expect(miss([5, 0, 5], [0, 0, -1])).toBe(false);
    expect(miss([-5, 0, 5], [0, 0, -1])).toBe(false);
    expect(miss([0, 0, 5], [0, 0, 0])).toBe(false); // no direction at all
    expect(miss([0, 0, 0.5], [0, 0, 0])).toBe(false); // no direction, from inside: no slab is entered
    // Along (−1, 0, −1) from (8, 0, 5): x in the slab for t ∈ [7, 9], z for t ∈ [4, 6].
    expect(miss([8, 0, 5], [-1, 0, -1])).toBe(false);
  });

  it('the box is closed: a ray along a face, or through an edge only, hits it', () => {
    const box = new BoxTracer(frame(), 2, 0, 1);
    const hit = new SurfaceHit();
    // Along the face x = 1, down −z.
    expect(box.hit(ray([1, 0, 5], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.t]).toEqual([1, 4]);
    expect(box.hit(ray([-1, -1, 5], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    // Along (−1, 0, −1) from (7, 0, 5): x in [6, 8], z in [4, 6]: only the edge (1, 0, −1) at t = 6.
    expect(box.hit(ray([7, 0, 5], [-1, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect(hit.t).toBe(6);
    // Through the edge (1, 0, 1) from (6, 0, 6): x and z are entered at t = 5 together: the first axis's face (+x).
    expect(box.hit(ray([6, 0, 6], [-1, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.t]).toEqual([3, 5]);
  });

  it('the entry point, the later of the slabs\' entries, and its face', () => {
    // From (3.5, 0.5, 5) along (−1, 0, −1): x entered at t = 2.5, z at t = 4 (the later): the +z face at (−0.5, 0.5, 1).
    const box = new BoxTracer(frame(), 2, 0, 1);
    const hit = new SurfaceHit();
    expect(box.hit(ray([3.5, 0.5, 5], [-1, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.t]).toEqual([1, 4]);
    expect([...hit.p]).toEqual([-0.5, 0.5, 1]);
    expect([hit.u, hit.v]).toEqual([0.25, 0.75]);
  });

  it('kept: t beyond tMin, within near and far, and on the clip side', () => {
    const box = new BoxTracer(frame(), 2, 0, 1);
    const r = ray([0, 0, 5], [0, 0, -1]);
    expect(box.hit(r, 3.9, 0, null, new SurfaceHit())).toBe(true);
    expect(box.hit(r, 4, 0, null, new SurfaceHit())).toBe(false);
    // The hit (0, 0, 1) is on the + side of z = 0.5 and not on the − side.
    expect(box.hit(r, 0, 1, [0, 0, 1, -0.5], new SurfaceHit())).toBe(true);
    expect(box.hit(r, 0, -1, [0, 0, 1, -0.5], new SurfaceHit())).toBe(false);
    // From (0, 0, −5) looking away: the box is entered at t = −6, before near.
    expect(box.hit(ray([0, 0, -5], [0, 0, -1]), -1e9, 0, null, new SurfaceHit())).toBe(false);
  });

  it('turned, moved and scaled: points and normals in the world, UV gradients R·S⁻¹·axis/size', () => {
    // Rz(90°): object (x, y, z) → world (−y, x, z); T = (10, 0, 0); S = (1, 2, 1); edge 2: the world box spans y ∈ [−1, 1]
    // (object x), x ∈ 10 + [−2, 2] (object y), z ∈ [−1, 1]. From (9.6, 5, 0.6) down −y: object o = (5, 0.2, 0.6),
    // d = (−1, 0, 0): the +x object face (BOX_FACES 2, u along −z, v along +y) at t = 4, q = (1, 0.2, 0.6):
    // u = ½ − 0.6/2 = 0.2, v = ½ + 0.2/2 = 0.6; n = R(1, 0, 0) = (0, 1, 0); gu = R(0, 0, −1)/2, gv = R(0, ½, 0)/2 = (−¼, 0, 0).
    const box = new BoxTracer(frame({ position: [10, 0, 0], rotation: [0, 0, 90], scale: [1, 2, 1] }), 2, 0, 1);
    const hit = new SurfaceHit();
    expect(box.hit(ray([9.6, 5, 0.6], [0, -1, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.surface).toBe(3);
    expect(hit.t).toBeCloseTo(4, 12);
    expectClose(hit.p, [9.6, 1, 0.6]);
    expectClose(hit.q, [1, 0.2, 0.6]);
    expectClose(hit.nq, [1, 0, 0]);
    expectClose(hit.n, [0, 1, 0]);
    expectClose(hit.ng, [0, 1, 0]);
    expect(hit.u).toBeCloseTo(0.2, 12);
    expect(hit.v).toBeCloseTo(0.6, 12);
    expectClose(hit.gu, [0, 0, -0.5]);
    expectClose(hit.gv, [-0.25, 0, 0]);
  });

  it('a negative scale turns the faces: the world normal still points out of the box', () => {
    // S = (−1, 1, 1): world +x is object −x. From (5, 0.2, 0.3) along −x: object d = (+1, 0, 0), the −x object face
    // (BOX_FACES 3, normal (−1, 0, 0)), whose world normal is (+1, 0, 0) after the flip.
    const box = new BoxTracer(frame({ scale: [-1, 1, 1] }), 2, 0, 1);
    const hit = new SurfaceHit();
    expect(box.hit(ray([5, 0.2, 0.3], [-1, 0, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.surface).toBe(4);
    expect(hit.t).toBe(4);
    expectClose(hit.nq, [-1, 0, 0]);
    expectClose(hit.n, [1, 0, 0]);
    // −x face: u along +z, v along +y; q = (−1, 0.2, 0.3): u = ½ + 0.3/2, v = ½ + 0.2/2; gu = (0, 0, 1)/2, and with
    // S⁻¹ on x the −x face's a has no x part.
    expect([hit.u, hit.v]).toEqual([0.65, 0.6]);
    expectClose(hit.gu, [0, 0, 0.5]);
    // The same on y and z: S = (1, −1, −1), from above along −z is object +z: the −z face, world normal +z.
    const yz = new BoxTracer(frame({ scale: [1, -1, -1] }), 2, 0, 1);
    expect(yz.hit(ray([0.2, 0.1, 5], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect(hit.surface).toBe(2);
    expectClose(hit.n, [0, 0, 1]);
    expect(yz.hit(ray([0.2, 5, 0.1], [0, -1, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.surface).toBe(6);
    expectClose(hit.n, [0, 1, 0]);
    // −y face: u along +x, v along +z; the world gradient of v is R·S⁻¹·(0, 0, 1)/2 = (0, 0, −½).
    expectClose(hit.gv, [0, 0, -0.5]);
  });
  it('a miss returns false even into a hit that held a hit before', () => {
    const box = new BoxTracer(frame(), 2, 0, 1);
    const hit = new SurfaceHit();
    expect(box.hit(ray([0, 0, 5], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect(box.hit(ray([0, 5, 5], [0, 0, -1]), 0, 0, null, hit)).toBe(false); // beside a slab it is parallel to
    expect(box.hit(ray([0, 0, 5], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect(box.hit(ray([8, 0, 5], [-1, 0, -1]), 0, 0, null, hit)).toBe(false); // no common interval
  });

  it('directions of any length: t on the ray\'s own scale', () => {
    // From (3.5, 0.5, 5) along (−0.5, 0, −0.5): x entered at t = 5, z at t = 8: the +z face at (−0.5, 0.5, 1).
    const box = new BoxTracer(frame(), 2, 0, 1);
    const hit = new SurfaceHit();
    expect(box.hit(ray([3.5, 0.5, 5], [-0.5, 0, -0.5]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.t]).toEqual([1, 8]);
    // Along (−4, 0, −4): t = 1.
    expect(box.hit(ray([3.5, 0.5, 5], [-4, 0, -4]), 0, 0, null, hit)).toBe(true);
    expect(hit.t).toBe(1);
    // Along (−0.25, 0, 0) from (5, 0.2, 0.3): the +x face at t = 16.
    expect(box.hit(ray([5, 0.2, 0.3], [-0.25, 0, 0]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.t]).toEqual([3, 16]);
  });

  it('a non-uniform scale: each face\'s UV gradients divided by the scale of the axes they run along', () => {
    // S = (2, 3, 4), edge 2: the world box spans [−2, 2] × [−3, 3] × [−4, 4]. gu = S⁻¹·a/2, gv = S⁻¹·b/2.
    const box = new BoxTracer(frame({ scale: [2, 3, 4] }), 2, 0, 1);
    const hit = new SurfaceHit();
    // +z face (a = +x, b = +y) from above at (1, 1.5): q = (0.5, 0.5, 1): u = v = ¾.
    expect(box.hit(ray([1, 1.5, 9], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.t, hit.u, hit.v]).toEqual([1, 5, 0.75, 0.75]);
    expectClose(hit.gu, [0.25, 0, 0]);
    expectClose(hit.gv, [0, 1 / 6, 0]);
    // +x face (a = −z, b = +y).
    expect(box.hit(ray([9, 1.5, 2], [-1, 0, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.surface).toBe(3);
    expectClose(hit.gu, [0, 0, -0.125]);
    expectClose(hit.gv, [0, 1 / 6, 0]);
    // +y face (a = +x, b = −z).
    expect(box.hit(ray([1, 9, 2], [0, -1, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.surface).toBe(5);
    expectClose(hit.gu, [0.25, 0, 0]);
    expectClose(hit.gv, [0, 0, -0.125]);
    // −x face (a = +z, b = +y).
    expect(box.hit(ray([-9, 1.5, 2], [1, 0, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.surface).toBe(4);
    expectClose(hit.gu, [0, 0, 0.125]);
  });
});

describe('SphereTracer', () => {
  it('the near pole along −z: t, point, normal, UV (½, ½) and its gradients', () => {
    // Radius 2 at (0, 0, −10), from the origin: t = 8, q = (0, 0, 2), nq = +z; u = ½ + atan2(0, 1)/2π, v = acos(0)/π.
    // ρ² = 1: ∂u = (nq.z, 0, −nq.x)/(2π·r) = (1/4π, 0, 0); ∂v = (0, 1/(π·r), 0) = (0, 1/2π, 0).
    const f = frame({ position: [0, 0, -10] });
    const s = new SphereTracer(f, 2, 4, 7);
    const hit = new SurfaceHit();
    expect(s.hit(ray([0, 0, 0], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect([hit.surface, hit.object, hit.t]).toEqual([7, 4, 8]);
    expect(hit.frame).toBe(f);
    expect([...hit.p]).toEqual([0, 0, -8]);
    expect([...hit.q]).toEqual([0, 0, 2]);
    expect([...hit.nq]).toEqual([0, 0, 1]);
    expect([...hit.n]).toEqual([0, 0, 1]);
    expect([...hit.ng]).toEqual([0, 0, 1]);
    expect([hit.u, hit.v]).toEqual([0.5, 0.5]);
    expectClose(hit.gu, [1 / (4 * Math.PI), 0, 0], 1e-15);
    expectClose(hit.gv, [0, 1 / (2 * Math.PI), 0], 1e-15);
  });

  it('off-centre and with a long direction: t on the ray\'s own scale, u from atan2(n.x, n.z)', () => {
    // From (1, 0, 0) along (0, 0, −2): closest approach at t = 5 (1 from the centre), half-chord √3 (t: √3/2):
    // t = 5 − √3/2, q = (1, 0, √3), nq = (½, 0, √3/2); u = ½ + (π/6)/2π = 7/12; v = ½.
    // ρ² = 1: ∂u = (√3/2, 0, −½)/(2π·2), ∂v = (0, 1/2π, 0).
    const s = new SphereTracer(frame({ position: [0, 0, -10] }), 2, 0, 1);
    const hit = new SurfaceHit();
    expect(s.hit(ray([1, 0, 0], [0, 0, -2]), 0, 0, null, hit)).toBe(true);
    expect(hit.t).toBeCloseTo(5 - Math.sqrt(3) / 2, 12);
    expectClose(hit.p, [1, 0, -10 + Math.sqrt(3)]);
    expectClose(hit.q, [1, 0, Math.sqrt(3)]);
    expectClose(hit.nq, [0.5, 0, Math.sqrt(3) / 2]);
    expectClose(hit.n, [0.5, 0, Math.sqrt(3) / 2]);
    expect(hit.u).toBeCloseTo(7 / 12, 12);
    expect(hit.v).toBeCloseTo(0.5, 12);
    expectClose(hit.gu, [Math.sqrt(3) / 2 / (4 * Math.PI), 0, -0.5 / (4 * Math.PI)]);
    expectClose(hit.gv, [0, 1 / (2 * Math.PI), 0]);
  });

  it('above and below: v = acos(−n.y)/π, the gradient of v 1/(π·r·ρ)', () => {
    // Radius 1 at the origin, from (0, 5, 0.6) down: q = (0, 0.8, 0.6): v = acos(−0.8)/π, ρ = 0.6; u = ½ + atan2(0, 0.6)/2π.
    const s = new SphereTracer(frame(), 1, 0, 1);
    const hit = new SurfaceHit();
    expect(s.hit(ray([0, 5, 0.6], [0, -1, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.t).toBeCloseTo(4.2, 12);
    expect(hit.v).toBeCloseTo(Math.acos(-0.8) / Math.PI, 12);
    expect(hit.u).toBeCloseTo(0.5, 12);
    expectClose(hit.gv, [0, 1 / (Math.PI * 0.6), 0]);
    // ∂u = (nq.z, 0, −nq.x)/(2π·ρ²) = (0.6/(2π·0.36), 0, 0).
    expectClose(hit.gu, [0.6 / (2 * Math.PI * 0.36), 0, 0]);
    expect(s.hit(ray([0, -5, -0.6], [0, 1, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.v).toBeCloseTo(Math.acos(0.8) / Math.PI, 12);
    // u of n = (0, −0.8, −0.6): ½ + atan2(0, −0.6)/2π = 1.
    expect(hit.u).toBeCloseTo(1, 12);
  });

  it('at a pole ρ² is capped at 1e-300: v = 0 or 1 and finite gradients', () => {
    const s = new SphereTracer(frame(), 1, 0, 1);
    const hit = new SurfaceHit();
    expect(s.hit(ray([0, -5, 0], [0, 1, 0]), 0, 0, null, hit)).toBe(true);
    expect([hit.u, hit.v]).toEqual([0.5, 0]);
    expect(hit.gv[1]).toBe(1 / (Math.PI * 1e-150));
    expect(s.hit(ray([0, 5, 0], [0, -1, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.v).toBe(1);
  });

  it('a miss, a tangent ray (hit), and what kept rejects', () => {
    const s = new SphereTracer(frame({ position: [0, 0, -10] }), 2, 0, 1);
    expect(s.hit(ray([2.01, 0, 0], [0, 0, -1]), 0, 0, null, new SurfaceHit())).toBe(false);
    const hit = new SurfaceHit();
    expect(s.hit(ray([2, 0, 0], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect(hit.t).toBe(10);
    expect(s.hit(ray([0, 0, 0], [0, 0, -1]), 8, 0, null, new SurfaceHit())).toBe(false);
    expect(s.hit(ray([0, 0, 0], [0, 0, -1]), 0, -1, [0, 0, 1, 9], new SurfaceHit())).toBe(false);
    expect(s.hit(ray([0, 0, 0], [0, 0, -1]), 0, 1, [0, 0, 1, 9], new SurfaceHit())).toBe(true);
  });

  it('turned and scaled: q from the world point, a unit world normal R·S⁻¹·n, gradients R·S⁻¹·∂', () => {
    // S = (1, 2, 1) (an ellipsoid 2 tall), Rz(90°): object (x, y, z) → world (−y, x, z). From (−6.2, 0.8, 0) along +x:
    // Rᵀ(x, y, z) = (y, −x, z) gives (0.8, 6.2, 0), S⁻¹ o = (0.8, 3.1, 0); d = S⁻¹·Rᵀ(1, 0, 0) = (0, −0.5, 0):
    // it meets the unit sphere at q = (0.8, 0.6, 0) at t = (3.1 − 0.6)/0.5 = 5.
    const f = frame({ rotation: [0, 0, 90], scale: [1, 2, 1] });
    const s = new SphereTracer(f, 1, 0, 1);
    const hit = new SurfaceHit();
    expect(s.hit(ray([-6.2, 0.8, 0], [1, 0, 0]), 0, 0, null, hit)).toBe(true);
    expect(hit.t).toBeCloseTo(5, 12);
    expectClose(hit.p, [-1.2, 0.8, 0]);
    expectClose(hit.q, [0.8, 0.6, 0]);
    expectClose(hit.nq, [0.8, 0.6, 0]);
    // R·S⁻¹·(0.8, 0.6, 0) = R·(0.8, 0.3, 0) = (−0.3, 0.8, 0), normalised by √0.73.
    expectClose(hit.n, [-0.3 / Math.sqrt(0.73), 0.8 / Math.sqrt(0.73), 0]);
    expectClose(hit.ng, hit.n);
    // ρ² = 0.64: ∂u = (0, 0, −0.8/(2π·0.64)), unchanged by R·S⁻¹; ∂v = (0, 1/(π·0.8), 0) → S⁻¹ (0, ½/(0.8π), 0)
    // → R (−½/(0.8π), 0, 0).
    expectClose(hit.gu, [0, 0, -0.8 / (2 * Math.PI * 0.64)]);
    expectClose(hit.gv, [-0.5 / (0.8 * Math.PI), 0, 0]);
  });

  it('a turned unit-scale frame uses R·n as it is', () => {
    // Ry(90°) by the spin: object x → world −z. From (0, 0, −5) along +z hits the object +x pole: n = (0, 0, −1).
    const s = new SphereTracer(frame({ spin: Math.PI / 2 }, 1), 1, 0, 1);
    const hit = new SurfaceHit();
    expect(s.hit(ray([0, 0, -5], [0, 0, 1]), 0, 0, null, hit)).toBe(true);
    expectClose(hit.nq, [1, 0, 0]);
    expectClose(hit.n, [0, 0, -1]);
    expect(hit.u).toBeCloseTo(0.75, 12);
  });

  it('a miss returns false even into a hit that held a hit before', () => {
    const s = new SphereTracer(frame({ position: [0, 0, -10] }), 2, 0, 1);
    const hit = new SurfaceHit();
    expect(s.hit(ray([0, 0, 0], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    expect(s.hit(ray([2.01, 0, 0], [0, 0, -1]), 0, 0, null, hit)).toBe(false);
  });

  it('off the axis in x and y: the closest approach point, the half chord, the normal', () => {
    // Radius 2 at the origin, from (1.2, 0.6, 5) down −z: closest approach (1.2, 0.6, 0), 1.8 from the centre… h² = 4 − 1.8 = 2.2;
    // q = (1.2, 0.6, √2.2), nq = q/2.
    const s = new SphereTracer(frame(), 2, 0, 1);
    const hit = new SurfaceHit();
    expect(s.hit(ray([1.2, 0.6, 5], [0, 0, -1]), 0, 0, null, hit)).toBe(true);
    const z = Math.sqrt(2.2);
    expect(hit.t).toBeCloseTo(5 - z, 12);
    expectClose(hit.q, [1.2, 0.6, z]);
    expectClose(hit.nq, [0.6, 0.3, z / 2]);
    expectClose(hit.n, [0.6, 0.3, z / 2]);
    expect(hit.v).toBeCloseTo(Math.acos(-0.3) / Math.PI, 12);
  });

  it('a unit scale: the world normal is R·nq as it is, not normalised again', () => {
    // Rotation (20°, −35°, 50°): object point (0.8, 0, 0.6) of the unit sphere, reached along −n from 3 away (there R·nq is
    // unit only up to rounding: normalising it again would move a last bit).
    const f = frame({ rotation: [20, -35, 50] });
    const n = f.gradientToWorld(new Float64Array(3), [0.8, 0, 0.6]);
    const s = new SphereTracer(f, 1, 0, 1);
    const hit = new SurfaceHit();
    expect(s.hit(ray([4 * n[0], 4 * n[1], 4 * n[2]], [-n[0], -n[1], -n[2]]), 0, 0, null, hit)).toBe(true);
    expectClose(hit.nq, [0.8, 0, 0.6]);
    expect([...hit.n]).toEqual([...f.gradientToWorld(new Float64Array(3), hit.nq)]);
  });
});
