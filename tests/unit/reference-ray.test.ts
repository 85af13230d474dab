// The reference's small value types (src/reference/ray.ts, surface-hit.ts, layer.ts): their start values and the
// mirrored ray, worked out by hand across oblique planes.
import { describe, expect, it } from 'vitest';
import { Layer } from '../../src/reference/layer';
import { Ray } from '../../src/reference/ray';
import { SURFACE_NONE, SurfaceHit } from '../../src/reference/surface-hit';
import { expectClose } from './helpers/math';

const set = (a: Float64Array, v: number[]) => { a.set(v); return a; };

describe('Ray', () => {
  it('starts at the origin looking down −z, with no differentials', () => {
    const r = new Ray();
    expect([...r.origin]).toEqual([0, 0, 0]);
    expect([...r.direction]).toEqual([0, 0, -1]);
    for (const a of [r.ddx, r.ddy, r.odx, r.ody]) expect([...a]).toEqual([0, 0, 0]);
  });

  it('mirrorOf the plane y = 1: y of points goes to 2 − y, y of every vector changes sign', () => {
    const r = new Ray();
    set(r.origin, [1, 3, 2]);
    set(r.direction, [0.5, -1, 0.25]);
    set(r.ddx, [0.1, 0.2, 0.3]);
    set(r.ddy, [-0.4, 0.5, 0.6]);
    set(r.odx, [0.7, -0.8, 0.9]);
    set(r.ody, [1.1, 1.2, -1.3]);
    const m = new Ray();
    expect(m.mirrorOf(r, [0, 1, 0, -1])).toBe(m);
    expect([...m.origin]).toEqual([1, -1, 2]);
    expect([...m.direction]).toEqual([0.5, 1, 0.25]);
    expect([...m.ddx]).toEqual([0.1, -0.2, 0.3]);
    expect([...m.ddy]).toEqual([-0.4, -0.5, 0.6]);
    expect([...m.odx]).toEqual([0.7, 0.8, 0.9]);
    expect([...m.ody]).toEqual([1.1, -1.2, -1.3]);
    // The source is left as it was.
    expect([...r.origin]).toEqual([1, 3, 2]);
    expect([...r.ddy]).toEqual([-0.4, 0.5, 0.6]);
  });

  it('mirrorOf the oblique plane x + y = 0 (n = (1, 1, 0)/√2): (a, b, c) → (−b, −a, c) for points and vectors', () => {
    const s = Math.SQRT1_2;
    const r = new Ray();
    set(r.origin, [2, 0, 1]);
    set(r.direction, [1, 0, -1]);
    set(r.ddx, [0, 3, 0]);
    set(r.ddy, [1, 2, 3]);
    set(r.odx, [4, 0, 0]);
    set(r.ody, [0, 0, 5]);
    const m = new Ray().mirrorOf(r, [s, s, 0, 0]);
    expectClose(m.origin, [0, -2, 1]);
    expectClose(m.direction, [0, -1, -1]);
    expectClose(m.ddx, [-3, 0, 0]);
    expectClose(m.ddy, [-2, -1, 3]);
    expectClose(m.odx, [0, -4, 0]);
    expectClose(m.ody, [0, 0, 5]);
  });
});

describe('SurfaceHit', () => {
  it('starts as "nothing": the background code, no object, no frame, at infinity', () => {
    const h = new SurfaceHit();
    expect(SURFACE_NONE).toBe(0);
    expect(h.surface).toBe(0);
    expect(h.object).toBe(-1);
    expect(h.frame).toBeNull();
    expect(h.t).toBe(Infinity);
    expect([h.u, h.v]).toEqual([0, 0]);
    for (const a of [h.p, h.n, h.ng, h.q, h.nq, h.gu, h.gv]) expect([...a]).toEqual([0, 0, 0]);
  });
});

describe('Layer', () => {
  it('holds three hits and four colours of its own', () => {
    const l = new Layer();
    const hits = [l.a, l.b, l.glass];
    for (const h of hits) expect(h).toBeInstanceOf(SurfaceHit);
    expect(new Set(hits).size).toBe(3);
    const colours = [l.colour, l.behind, l.reflection, l.tex];
    for (const c of colours) expect([...c]).toEqual([0, 0, 0]);
    expect(new Set(colours.map((c) => c.buffer)).size).toBe(4);
  });
});
