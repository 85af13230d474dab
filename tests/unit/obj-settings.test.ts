// The OBJ statements that set what the next faces are drawn with (src/loaders/obj/settings.ts):
// smoothing groups by name, coming back to one, turning smoothing off; materials by name; and the
// reader's runs of faces where either changes.
import { describe, expect, it } from 'vitest';
import { parseObj } from '../../src/loaders/obj';
import { readObj } from '../../src/loaders/obj/reader';

/** Two triangles sharing the edge 1–3 of a bent square: a vertex a position when smoothed together. */
const BENT = 'v 0 0 0\nv 1 0 0\nv 1 1 1\nv 0 1 0\n';

describe('smoothing statements', () => {
  it('shares the edge of two faces in the same group, named alike, and splits it between groups', () => {
    expect(parseObj(`${BENT}s 1\nf 1 2 3\nf 1 3 4\n`).positions.length / 3).toBe(4);
    expect(parseObj(`${BENT}s 1\nf 1 2 3\ns 2\nf 1 3 4\n`).positions.length / 3).toBe(6);
    expect(parseObj(`${BENT}s a\nf 1 2 3\ns A\nf 1 3 4\n`).positions.length / 3).toBe(4);
  });

  it('comes back to a group by its name after another', () => {
    // Faces 1 and 3 in group 1, face 2 in group 2: 1 and 3 share the edge 1–3.
    const r = parseObj(`${BENT}v 2 2 2\ns 1\nf 1 2 3\ns 2\nf 3 2 5\ns 1\nf 1 3 4\n`);
    expect(r.positions.length / 3).toBe(4 + 3);
  });

  it('turns smoothing off for s off, s 0 and a bare s, in any case', () => {
    for (const off of ['s off', 's OFF', 's 0', 's']) {
      const r = parseObj(`${BENT}${off}\nf 1 2 3\nf 1 3 4\n`);
      expect(r.positions.length / 3, off).toBe(6);
      expect(r.warnings, off).toEqual([]);
    }
  });

  it('smooths a file with no s statement, and after s off then a named group', () => {
    expect(parseObj(`${BENT}f 1 2 3\nf 1 3 4\n`).positions.length / 3).toBe(4);
    expect(parseObj(`${BENT}s off\nf 1 2 3\ns 3\nf 1 3 4\nf 1 2 3\n`).positions.length / 3).toBe(3 + 4);
  });
});

describe('usemtl', () => {
  it('draws each material\'s faces together, in order of first use, a material coming back joining its group', () => {
    const r = parseObj(`${BENT}f 1 2 3\nusemtl a\nf 1 3 4\nusemtl b\nf 1 2 3\nusemtl a\nf 2 3 4\nusemtl\nf 1 2 4\n`);
    expect(r.groups).toEqual([
      { material: null, start: 0, count: 3 },
      { material: 'a', start: 3, count: 6 },
      { material: 'b', start: 9, count: 3 },
      { material: '', start: 12, count: 3 },
    ]);
    const corners = Array.from(r.indices, (i) => [r.positions[3 * i], r.positions[3 * i + 1]].join(','));
    expect(corners.slice(3, 9)).toEqual(['0,0', '1,1', '0,1', '1,0', '1,1', '0,1']);
  });

  it('keeps a material name with spaces, and one run for repeated usemtl of the same name', () => {
    const r = parseObj(`${BENT}usemtl red glass\nf 1 2 3\nusemtl red glass\nf 1 3 4\n`);
    expect(r.groups).toEqual([{ material: 'red glass', start: 0, count: 6 }]);
  });
});

describe('runs of faces (reader.ts)', () => {
  it('starts a run only where the smoothing slot or the material changes: first face, slot, material', () => {
    // Faces 0–1 smoothed (slot 0), no material (0); face 2 material a (1); faces 3–4 in s 1 (slot 1); face 5 flat (−1).
    const raw = readObj(`${BENT}f 1 2 3\nf 1 3 4\nusemtl a\nf 1 2 3\ns 1\nf 1 3 4\nf 1 2 3\ns off\nf 1 3 4\n`);
    expect([...raw.runs.data.slice(0, raw.runs.length)]).toEqual([0, 0, 0, 2, 0, 1, 3, 1, 1, 5, -1, 1]);
  });
});
