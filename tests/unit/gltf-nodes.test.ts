// glTF node graphs and matrices (src/loaders/gltf/nodes.ts, docs/gltf.md#nodes): the default scene
// chosen, the roots of a file with no scene, each refusal with the path of the way to the node, and
// translation × rotation × scale checked against a quaternion rotation computed another way.
import { describe, expect, it } from 'vitest';
import { refusal } from './helpers/refusal';
import { GltfFile } from '../../src/loaders/gltf/fields';
import { localMatrix, meshInstances } from '../../src/loaders/gltf/nodes';

const file = (json: Record<string, unknown>) => new GltfFile('n.gltf', json);
const instances = (json: Record<string, unknown>) => meshInstances(file(json)).map((m) => ({ node: m.node, mesh: m.mesh }));


describe('scenes and roots', () => {
  const nodes = [{ mesh: 0 }, { mesh: 1 }, { mesh: 2 }];

  it('draws the scene `scene` names, else scenes[0]; a scene without nodes draws nothing', () => {
    const scenes = [{ nodes: [0] }, { nodes: [2, 1] }];
    expect(instances({ scenes, nodes })).toEqual([{ node: 'nodes[0]', mesh: 0 }]);
    expect(instances({ scene: 1, scenes, nodes })).toEqual([{ node: 'nodes[2]', mesh: 2 }, { node: 'nodes[1]', mesh: 1 }]);
    expect(instances({ scenes: [{}], nodes })).toEqual([]);
  });

  it('refuses a scene index that is not one, or past the scenes, and scene nodes that are not indices', () => {
    // A top-level field's path is its bare name, as a nested one's is `scenes[0].nodes`: never `.scene`.
    expect(refusal(() => instances({ scene: 1.5, scenes: [{ nodes: [0] }], nodes }))).toEqual({ path: 'scene', message: 'scene is 1.5, not an index or count' });
    expect(refusal(() => instances({ scene: 3, scenes: [{ nodes: [0] }], nodes }))).toEqual({ path: 'scene', message: 'scenes[3] does not exist (scenes has 1)' });
    expect(refusal(() => instances({ scenes: [{ nodes: 'all' }], nodes }))).toEqual({
      path: 'scenes[0].nodes', message: 'scenes[0].nodes is not a list of indices',
    });
  });

  it('refuses a root past the nodes by the scene\'s list, and a child past them by the node\'s', () => {
    expect(refusal(() => instances({ scenes: [{ nodes: [0, 3] }], nodes }))).toEqual({ path: 'scenes[0].nodes[1]', message: 'nodes[3] does not exist (nodes has 3)' });
    expect(refusal(() => instances({ scenes: [{ nodes: [0] }], nodes: [{ children: [3] }] }))).toEqual({
      path: 'nodes[0].children[0]', message: 'nodes[3] does not exist (nodes has 1)',
    });
  });

  it('refuses children that are not a list of non-negative integers', () => {
    for (const children of ['x', [1.5], [-1], [1, 1.5]]) {
      expect(refusal(() => instances({ scenes: [{ nodes: [0] }], nodes: [{ children }, {}] })), JSON.stringify(children)).toEqual({
        path: 'nodes[0].children', message: 'nodes[0].children is not a list of indices',
      });
    }
  });

  it('without a scene, draws every node that is no one\'s child, and says so once', () => {
    const f = file({ nodes: [{ mesh: 0, children: [1] }, { mesh: 1 }, { mesh: 2 }] });
    expect(meshInstances(f).map((m) => m.node)).toEqual(['nodes[0]', 'nodes[1]', 'nodes[2]']);
    expect(f.warnings).toEqual([{ path: 'scenes', message: 'the file has no scene: every node that is no one\'s child is drawn' }]);
    const none = file({});
    expect(meshInstances(none)).toEqual([]);
    expect(none.warnings).toEqual([]);
  });

  it('without a scene, refuses a child past the nodes by the node that lists it', () => {
    expect(refusal(() => instances({ nodes: [{ mesh: 0 }, { children: [0, 5] }] }))).toEqual({
      path: 'nodes[1].children[1]', message: 'nodes[5] does not exist (nodes has 2)',
    });
    expect(refusal(() => instances({ nodes: [{ children: 'x' }] }))).toEqual({ path: 'nodes[0].children', message: 'nodes[0].children is not a list of indices' });
    expect(refusal(() => instances({ nodes: [{}, 5] }))).toEqual({ path: 'nodes[1]', message: 'nodes[1] is not an object' });
  });
});

describe('local matrices', () => {
  /** q v q*, by Hamilton products: the rotation of v by the unit quaternion (x, y, z, w). */
  function rotate([x, y, z, w]: number[], v: number[]): number[] {
    const mul = (a: number[], b: number[]) => [
      a[3] * b[0] + a[0] * b[3] + a[1] * b[2] - a[2] * b[1],
      a[3] * b[1] - a[0] * b[2] + a[1] * b[3] + a[2] * b[0],
      a[3] * b[2] + a[0] * b[1] - a[1] * b[0] + a[2] * b[3],
      a[3] * b[3] - a[0] * b[0] - a[1] * b[1] - a[2] * b[2],
    ];
    return mul(mul([x, y, z, w], [...v, 0]), [-x, -y, -z, w]).slice(0, 3);
  }

  it('takes a matrix as it is', () => {
    const matrix = Array.from({ length: 16 }, (_, i) => i + 1);
    expect(Array.from(localMatrix(file({}), { matrix, translation: [5, 5, 5] }, 'nodes[0]'))).toEqual(matrix);
  });

  it('builds T × R × S, the quaternion normalized first (here written at twice its length)', () => {
    const q = [1, 2, 3, 4].map((v) => v / Math.sqrt(30));
    const scale = [2, 3, 5];
    const m = localMatrix(file({}), { translation: [7, 8, 9], rotation: q.map((v) => 2 * v), scale }, 'nodes[0]');
    for (let c = 0; c < 3; c++) {
      const column = rotate(q, [0, 1, 2].map((r) => (r === c ? scale[c] : 0)));
      for (let r = 0; r < 3; r++) expect(m[4 * c + r], `m[${4 * c + r}]`).toBeCloseTo(column[r], 12);
      expect(m[4 * c + 3]).toBe(0);
    }
    expect(Array.from(m.subarray(12))).toEqual([7, 8, 9, 1]);
  });

  it('builds a quarter turn about z exactly as written out by hand', () => {
    const h = Math.SQRT1_2;
    const m = Array.from(localMatrix(file({}), { rotation: [0, 0, h, h], scale: [1, 2, 1] }, 'nodes[0]'), (v) => Math.round(v * 1e12) / 1e12 + 0);
    expect(m).toEqual([0, 1, 0, 0, -2, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
  });

  it('refuses the zero quaternion', () => {
    expect(refusal(() => localMatrix(file({}), { rotation: [0, 0, 0, 0] }, 'nodes[4]'))).toEqual({
      path: 'nodes[4].rotation', message: 'nodes[4].rotation is the zero quaternion',
    });
  });
});
