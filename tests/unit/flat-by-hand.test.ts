// Flat shading's per-face copies (src/scene/geometry/flat.ts) on triangles done by hand: the
// face normal turned to agree with the corners' mean normal, a degenerate face's mean normal, a
// tie (mean ⊥ face) kept as wound, and each corner's position, UV and the face's centroid.
import { describe, expect, it } from 'vitest';
import { flatMesh } from '../../src/scene/geometry/flat';
import type { MeshData } from '../../src/scene/geometry/mesh-data';
import { expectClose } from './helpers/math';

const POSITIONS = [[0, 0, 0], [2, 0, 0], [0, 2, 0], [9, 9, 9], [4, 0, 0], [0, 0, 0], [2, 0, 0], [0, 2, 0]];
const NORMALS = [[0, 0, 1], [1, 0.5, 0.5], [0, 0, 1], [0, 0, 0], [0.5, 1, 0.25], [1, 0, 0], [0, 0, 0], [0, 0, 0]];
const UVS = [[0.1, 0.2], [0.3, 0.4], [0.5, 0.6], [0, 0], [0.7, 0.8], [0.15, 0.25], [0.35, 0.45], [0.55, 0.65]];
const FACES = [
  [0, 1, 2], // cross (0, 0, 4); corners' mean (1, 0.5, 2.5) agrees: (0, 0, 1)
  [0, 2, 1], // cross (0, 0, −4) against the same mean: turned, (0, 0, 1)
  [0, 1, 4], // on a line: the mean (1.5, 1.5, 1.75) of length 2.75, (6, 6, 7)/11
  [5, 6, 7], // cross (0, 0, 4), mean (1, 0, 0) at right angles: kept as wound, (0, 0, 1)
  [6, 7, 6], // no area and no normals: (0, 0, 0), not NaN
];

function mesh(): MeshData {
  return {
    positions: new Float32Array(POSITIONS.flat()), normals: new Float32Array(NORMALS.flat()),
    uvs: new Float32Array(UVS.flat()), indices: new Uint16Array([...FACES.flat(), 0, 1]),
  };
}

describe('flatMesh by hand', () => {
  it('gives each face three corners of its own, in order, with their positions and UVs; loose indices dropped', () => {
    const out = flatMesh(mesh());
    const corners = FACES.flat();
    expect(Array.from(out.indices)).toEqual(corners.map((_, i) => i));
    expect(Array.from(out.positions)).toEqual(corners.flatMap((v) => POSITIONS[v]));
    expectClose(Array.from(out.uvs), corners.flatMap((v) => UVS[v]), 1e-7);
  });

  it('face normals: turned towards the corners\' mean, the mean where the face has no area', () => {
    const out = flatMesh(mesh());
    const per = [[0, 0, 1], [0, 0, 1], [6 / 11, 6 / 11, 7 / 11], [0, 0, 1], [0, 0, 0]];
    expectClose(Array.from(out.normals), per.flatMap((n) => [...n, ...n, ...n]), 1e-7);
  });

  it('every corner carries its face\'s centroid', () => {
    const out = flatMesh(mesh());
    const c = [[2 / 3, 2 / 3, 0], [2 / 3, 2 / 3, 0], [2, 0, 0], [2 / 3, 2 / 3, 0], [4 / 3, 2 / 3, 0]];
    expectClose(Array.from(out.centroids!), c.flatMap((n) => [...n, ...n, ...n]), 1e-7);
  });
});
