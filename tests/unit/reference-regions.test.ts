// The region map (src/reference/regions.ts): what a key names (default scene and any scene), the boundary pixels and
// the edge band grown around them on small grids drawn by hand, and the glass-reflects-object tests on keys.
import { describe, expect, it } from 'vitest';
import {
  REGION_BACKGROUND as BG, REGION_CUBE as CUBE, REGION_EDGE as E, REGION_GLASS as GLASS, REGION_SPHERE as SPHERE,
  glassReflectsCube, glassReflectsObject, regionMap, regionOfCodes, regionOfKey, type Region,
} from '../../src/reference/regions';
import { SurfaceCodes } from '../../src/reference/surface-codes';
import type { Geometry, Scene } from '../../src/scene/scene';

const sceneOf = (kinds: Geometry['kind'][]): Scene => ({
  glass: null, lights: [], background: [0, 0, 0],
  objects: kinds.map((kind) => ({ geometry: { kind } as Geometry })),
} as unknown as Scene);

/** A key of the default scene (base 9): primary p, behind q, reflected r. */
const key9 = (p: number, q = 0, r = 0) => p + 9 * q + 81 * r;

describe('regionOfKey (the default scene: cube 1..6, sphere 7, glass 8)', () => {
  it('reads the primary digit only', () => {
    expect([0, 1, 2, 3, 4, 5, 6, 7, 8].map((p) => regionOfKey(p))).toEqual([BG, CUBE, CUBE, CUBE, CUBE, CUBE, CUBE, SPHERE, GLASS]);
    expect(regionOfKey(key9(0, 7, 3))).toBe(BG);
    expect(regionOfKey(key9(6, 8, 7))).toBe(CUBE);
    expect(regionOfKey(key9(7, 1, 1))).toBe(SPHERE);
    expect(regionOfKey(key9(8, 7, 1))).toBe(GLASS);
  });
});

describe('regionOfCodes', () => {
  it('boxes are the cube region, anything else the sphere region, the glass glass, the rest background', () => {
    // mesh 1, box 2..7, sphere 8, glass 9, base 10.
    const scene = sceneOf(['mesh', 'box', 'sphere']);
    const of = regionOfCodes(scene, new SurfaceCodes(scene));
    expect([0, 1, 2, 7, 8, 9].map(of)).toEqual([BG, SPHERE, CUBE, CUBE, SPHERE, GLASS]);
    expect(of(5 + 10 * 9 + 100 * 1)).toBe(CUBE);
    expect(of(9 + 10 * 8 + 100 * 2)).toBe(GLASS);
    expect(of(0 + 10 * 3 + 100 * 9)).toBe(BG);
  });

  it('for the default scene it is regionOfKey', () => {
    const scene = sceneOf(['box', 'sphere']);
    const of = regionOfCodes(scene, new SurfaceCodes(scene));
    for (let key = 0; key < 729; key += 7) expect(of(key), `key ${key}`).toBe(regionOfKey(key));
  });
});

/** A w×h grid of keys, `a` everywhere but at the given pixels, and the map drawn as rows of regions. */
function mapOf(
  w: number, h: number, a: number, at: [number, number, number][] = [], mixedAt: [number, number][] = [], regionOf?: (k: number) => Region,
) {
  const keys = new Int32Array(w * h).fill(a), mixed = new Uint8Array(w * h);
  for (const [x, y, k] of at) keys[y * w + x] = k;
  for (const [x, y] of mixedAt) mixed[y * w + x] = 1;
  const map = regionMap(keys, mixed, w, h, regionOf);
  return Array.from({ length: h }, (_, y) => [...map.subarray(y * w, (y + 1) * w)]);
}

describe('regionMap', () => {
  it('one key everywhere, none mixed: no edges, every pixel the key\'s region', () => {
    expect(mapOf(4, 3, key9(7))).toEqual([[SPHERE, SPHERE, SPHERE, SPHERE], [SPHERE, SPHERE, SPHERE, SPHERE], [SPHERE, SPHERE, SPHERE, SPHERE]]);
    expect(mapOf(1, 1, key9(8))).toEqual([[GLASS]]);
  });

  it('a mixed pixel is a boundary: the band is it and its 8 neighbours', () => {
    const C = CUBE;
    expect(mapOf(5, 4, key9(2), [], [[2, 1]])).toEqual([
      [C, E, E, E, C],
      [C, E, E, E, C],
      [C, E, E, E, C],
      [C, C, C, C, C],
    ]);
  });

  it('a key differing at the left edge: it and its neighbours are boundaries, grown by one more pixel', () => {
    // Boundaries: (0, 2) and (0..1, 1..3); the band: x ≤ 2 on every row.
    const S = SPHERE;
    expect(mapOf(5, 4, key9(7), [[0, 2, key9(8)]])).toEqual([
      [E, E, E, S, S],
      [E, E, E, S, S],
      [E, E, E, S, S],
      [E, E, E, S, S],
    ]);
  });

  it('a key differing at the right edge: nothing wraps to the next or previous row', () => {
    // Boundaries: (4, 1) and (3..4, 0..2); the band: x ≥ 2 on rows 0..3.
    const G = GLASS;
    expect(mapOf(5, 5, key9(8), [[4, 1, key9(1)]])).toEqual([
      [G, G, E, E, E],
      [G, G, E, E, E],
      [G, G, E, E, E],
      [G, G, E, E, E],
      [G, G, G, G, G],
    ]);
  });

  it('a key differing in the corner of a wide grid: rows are width long', () => {
    const S = SPHERE;
    expect(mapOf(7, 4, key9(7), [[6, 3, key9(3)]])).toEqual([
      [S, S, S, S, S, S, S],
      [S, S, S, S, E, E, E],
      [S, S, S, S, E, E, E],
      [S, S, S, S, E, E, E],
    ]);
    expect(mapOf(3, 5, key9(7), [[0, 0, key9(3)]])).toEqual([
      [E, E, E],
      [E, E, E],
      [E, E, E],
      [S, S, S],
      [S, S, S],
    ]);
  });

  it('mixed pixels on the borders: the band reaches them from inside, and never wraps', () => {
    const G = GLASS;
    // Left edge (0, 2): band x ≤ 1, rows 1..3.
    expect(mapOf(5, 5, key9(8), [], [[0, 2]])).toEqual([
      [G, G, G, G, G],
      [E, E, G, G, G],
      [E, E, G, G, G],
      [E, E, G, G, G],
      [G, G, G, G, G],
    ]);
    // Top edge (2, 0): band rows 0..1, x 1..3.
    expect(mapOf(5, 3, key9(8), [], [[2, 0]])).toEqual([
      [G, E, E, E, G],
      [G, E, E, E, G],
      [G, G, G, G, G],
    ]);
    // Right end of row 1 (4, 1): the first pixels of rows 0..2 are not next to it.
    expect(mapOf(5, 4, key9(8), [], [[4, 1]])).toEqual([
      [G, G, G, E, E],
      [G, G, G, E, E],
      [G, G, G, E, E],
      [G, G, G, G, G],
    ]);
    // Bottom right corner.
    expect(mapOf(4, 3, key9(8), [], [[3, 2]])).toEqual([
      [G, G, G, G],
      [G, G, E, E],
      [G, G, E, E],
    ]);
  });

  it('each pixel away from the band takes regionOf of its own key, asked once, and only for those', () => {
    // Keys 1 (left half) and 3 (right half), regionOf = the key itself (as a region).
    const keys: [number, number, number][] = [];
    for (let y = 0; y < 2; y++) for (let x = 4; x < 8; x++) keys.push([x, y, 3]);
    const asked: unknown[] = [];
    const R = (k: number) => { asked.push(k); return k as Region; };
    expect(mapOf(8, 2, 1, keys, [], R)).toEqual([
      [1, 1, E, E, E, E, 3, 3],
      [1, 1, E, E, E, E, 3, 3],
    ]);
    expect(asked).toEqual([1, 1, 3, 3, 1, 1, 3, 3]);
    // No band at all: every pixel, in order.
    asked.length = 0;
    mapOf(3, 2, 4, [], [], R);
    expect(asked).toEqual([4, 4, 4, 4, 4, 4]);
  });
});

describe('glassReflectsCube, glassReflectsObject', () => {
  it('glassReflectsCube: primary the glass (8), reflected digit a cube face (1..6), whatever lies behind', () => {
    for (let r = 0; r < 9; r++) expect(glassReflectsCube(key9(8, 0, r)), `reflected ${r}`).toBe(r >= 1 && r <= 6);
    expect(glassReflectsCube(key9(8, 7, 2))).toBe(true);
    expect(glassReflectsCube(key9(8, 8, 6))).toBe(true);
    expect(glassReflectsCube(key9(7, 0, 3))).toBe(false);
    expect(glassReflectsCube(key9(3, 8, 3))).toBe(false);
    // Keys are taken modulo 9³ in every digit: 2·729 on top changes nothing.
    expect(glassReflectsCube(2 * 729 + key9(8, 0, 3))).toBe(true);
    expect(glassReflectsCube(2 * 729 + key9(8, 0, 7))).toBe(false);
  });

  it('glassReflectsObject: primary the glass code and the reflected code that object\'s', () => {
    // mesh 1, box 2..7, sphere 8, glass 9, base 10.
    const codes = new SurfaceCodes(sceneOf(['mesh', 'box', 'sphere']));
    const key = (p: number, q: number, r: number) => p + 10 * q + 100 * r;
    expect(glassReflectsObject(key(9, 0, 1), codes, 0)).toBe(true);
    expect(glassReflectsObject(key(9, 4, 5), codes, 1)).toBe(true);
    expect(glassReflectsObject(key(9, 0, 5), codes, 0)).toBe(false);
    expect(glassReflectsObject(key(9, 0, 8), codes, 2)).toBe(true);
    expect(glassReflectsObject(key(8, 0, 8), codes, 2)).toBe(false);
    expect(glassReflectsObject(key(9, 0, 9), codes, -1)).toBe(true); // the glass in the glass names no object
    expect(glassReflectsObject(key(9, 0, 0), codes, 0)).toBe(false);
  });
});
