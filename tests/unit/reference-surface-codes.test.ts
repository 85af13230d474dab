// Surface codes (src/reference/surface-codes.ts): the numbering of objects' faces, the glass's code, the shared codes past
// MAX_OBJECT_CODE, and a key's three digits, counted out by hand.
import { describe, expect, it } from 'vitest';
import { SurfaceCodes } from '../../src/reference/surface-codes';
import type { Geometry, Scene } from '../../src/scene/scene';

/** A scene of these geometries: the codes read nothing else. */
const sceneOf = (kinds: Geometry['kind'][]): Scene => ({
  glass: null, lights: [], background: [0, 0, 0],
  objects: kinds.map((kind) => ({ geometry: { kind } as Geometry })),
} as unknown as Scene);

describe('SurfaceCodes', () => {
  it('the default scene: cube faces 1..6, sphere 7, glass 8, base 9', () => {
    const c = new SurfaceCodes(sceneOf(['box', 'sphere']));
    expect([...c.first]).toEqual([1, 7]);
    expect(c.glass).toBe(8);
    expect(c.base).toBe(9);
    expect([0, 1, 2, 3, 4, 5, 6, 7, 8, 9].map((k) => c.objectOfCode(k))).toEqual([-1, 0, 0, 0, 0, 0, 0, 1, -1, -1]);
  });

  it('one code for anything but a box; codes out of range name nothing', () => {
    const c = new SurfaceCodes(sceneOf(['mesh', 'gaussian', 'box', 'sphere']));
    // mesh 1, gaussian 2, box 3..8, sphere 9, glass 10.
    expect([...c.first]).toEqual([1, 2, 3, 9]);
    expect(c.glass).toBe(10);
    expect(c.base).toBe(11);
    expect([1, 2, 3, 8, 9, 10, 11, 12, -1, -7].map((k) => c.objectOfCode(k))).toEqual([0, 1, 2, 2, 3, -1, -1, -1, -1, -1]);
  });

  it('no objects: the glass is 1', () => {
    const c = new SurfaceCodes(sceneOf([]));
    expect(c.first.length).toBe(0);
    expect(c.glass).toBe(1);
    expect(c.base).toBe(2);
    expect([0, 1, 2].map((k) => c.objectOfCode(k))).toEqual([-1, -1, -1]);
  });

  it('past code 1000 the last codes are shared, the last object owning them; the glass stays 1001', () => {
    // 1001 spheres: the 1000th takes 1000, the 1001st takes 1000 again.
    const spheres = new SurfaceCodes(sceneOf(Array<Geometry['kind']>(1001).fill('sphere')));
    expect(spheres.first[999]).toBe(1000);
    expect(spheres.first[1000]).toBe(1000);
    expect(spheres.glass).toBe(1001);
    expect(spheres.base).toBe(1002);
    expect(spheres.objectOfCode(999)).toBe(998);
    expect(spheres.objectOfCode(1000)).toBe(1000);
    expect(spheres.objectOfCode(1001)).toBe(-1);
    // 167 boxes: 166 take 1..996; the 167th would need 997..1002 and takes 995..1000, over the 166th's last two.
    const boxes = new SurfaceCodes(sceneOf(Array<Geometry['kind']>(167).fill('box')));
    expect(boxes.first[165]).toBe(991);
    expect(boxes.first[166]).toBe(995);
    expect(boxes.glass).toBe(1001);
    expect([990, 991, 994, 995, 1000, 1001].map((k) => boxes.objectOfCode(k))).toEqual([164, 165, 165, 166, 166, -1]);
  });

  it('digits: primary, behind, reflected of key = p + b·q + b²·r, any multiple of b³ dropped', () => {
    const c = new SurfaceCodes(sceneOf(['box', 'sphere'])); // b = 9
    expect(c.digits(0)).toEqual([0, 0, 0]);
    expect(c.digits(7 + 9 * 8 + 81 * 3)).toEqual([7, 8, 3]);
    expect(c.digits(8 + 81 * 6)).toEqual([8, 0, 6]);
    expect(c.digits(2 * 729 + 5 + 9 * 1 + 81 * 2)).toEqual([5, 1, 2]);
    const d = new SurfaceCodes(sceneOf(['mesh', 'mesh', 'mesh'])); // b = 5
    expect(d.digits(4 + 5 * 3 + 25 * 2)).toEqual([4, 3, 2]);
    expect(d.digits(125 + 1)).toEqual([1, 0, 0]);
  });
});
