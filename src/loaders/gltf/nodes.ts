// The default scene's node hierarchy flattened (docs/gltf.md#nodes): each node that has a mesh,
// with its world matrix (the parents' matrices times its own: a matrix, or translation ×
// rotation × scale). Walked without recursion, each node at most once: a cycle, or a node with
// two parents, is an error naming the second way to it, and a million nodes cost one pass.
import { fieldPath, GltfFile, int, numbers, object, type Obj } from './fields';

export interface MeshInstance {
  mesh: number;
  /** Column-major 4×4, float64. */
  matrix: Float64Array;
  /** `nodes[i]`, for messages. */
  node: string;
}

const IDENTITY = [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1];

/** The roots drawn: the default scene's (`scene`, else scenes[0]), else every node that is no one's child. */
function roots(file: GltfFile): { roots: number[]; from: string } {
  const scenes = file.list('scenes');
  if (scenes.length > 0) {
    const index = int(file, file.json, 'scene', '', 0);
    const scene = file.item('scenes', index, 'scene');
    const nodes = scene.nodes === undefined ? [] : indexList(file, scene, 'nodes', `scenes[${index}]`);
    return { roots: nodes, from: `scenes[${index}].nodes` };
  }
  const child = new Uint8Array(file.list('nodes').length);
  file.list('nodes').forEach((n, i) => {
    const node = object(file, n, `nodes[${i}]`);
    // Stryker disable next-line ConditionalExpression,EqualityOperator: child[c] for c >= child.length is past the typed array's end: a no-op
    if (node.children !== undefined) for (const c of indexList(file, node, 'children', `nodes[${i}]`)) if (c < child.length) child[c] = 1;
  });
  const all: number[] = [];
  child.forEach((isChild, i) => { if (!isChild) all.push(i); });
  if (all.length > 0) file.warn('scenes', 'the file has no scene: every node that is no one\'s child is drawn');
  // Stryker disable next-line StringLiteral: `from` names only a root that is missing or reached twice, and these roots are neither
  return { roots: all, from: 'nodes' };
}

export function meshInstances(file: GltfFile): MeshInstance[] {
  const count = file.list('nodes').length;
  const seen = new Uint8Array(count);
  const out: MeshInstance[] = [];
  const { roots: top, from } = roots(file);
  // Each entry: a node to visit, its parent's world matrix, and where its index was read.
  const stack: { node: number; parent: Float64Array; from: string }[] = [];
  for (let i = top.length - 1; i >= 0; i--) stack.push({ node: top[i], parent: new Float64Array(IDENTITY), from: `${from}[${i}]` });
  while (stack.length > 0) {
    const { node: index, parent, from: where } = stack.pop()!;
    const path = `nodes[${index}]`;
    // Stryker disable next-line ConditionalExpression,EqualityOperator: file.item below refuses the same index with the same path and message
    if (index >= count) file.fail(where, `${path} does not exist (nodes has ${count})`);
    if (seen[index]) file.fail(where, `${path} is reached a second time: the node graph has a cycle, or a node with two parents`);
    seen[index] = 1;
    const node = file.item('nodes', index, where);
    const world = multiply(parent, localMatrix(file, node, path));
    if (node.mesh !== undefined) out.push({ mesh: int(file, node, 'mesh', path), matrix: world, node: path });
    if (node.children !== undefined) {
      const children = indexList(file, node, 'children', path);
      for (let c = children.length - 1; c >= 0; c--) stack.push({ node: children[c], parent: world, from: `${path}.children[${c}]` });
    }
  }
  return out;
}

function indexList(file: GltfFile, o: Obj, key: string, path: string): number[] {
  const v = o[key];
  if (!Array.isArray(v) || !v.every((x) => Number.isInteger(x) && x >= 0)) file.fail(fieldPath(path, key), `${fieldPath(path, key)} is not a list of indices`);
  return v as number[];
}

/** A node's own matrix: `matrix`, else T × R × S (glTF's order; the quaternion as x, y, z, w). */
export function localMatrix(file: GltfFile, node: Obj, path: string): Float64Array {
  if (node.matrix !== undefined) return Float64Array.from(numbers(file, node, 'matrix', path, 16, IDENTITY));
  const [tx, ty, tz] = numbers(file, node, 'translation', path, 3, [0, 0, 0]);
  const [x, y, z, w0] = numbers(file, node, 'rotation', path, 4, [0, 0, 0, 1]);
  const [sx, sy, sz] = numbers(file, node, 'scale', path, 3, [1, 1, 1]);
  const len = Math.hypot(x, y, z, w0);
  if (len === 0) file.fail(`${path}.rotation`, `${path}.rotation is the zero quaternion`);
  // Exporters write quaternions rounded: normalized here rather than refused.
  const [qx, qy, qz, qw] = [x / len, y / len, z / len, w0 / len];
  const m = new Float64Array(16);
  m[0] = (1 - 2 * (qy * qy + qz * qz)) * sx;
  m[1] = 2 * (qx * qy + qz * qw) * sx;
  m[2] = 2 * (qx * qz - qy * qw) * sx;
  m[4] = 2 * (qx * qy - qz * qw) * sy;
  m[5] = (1 - 2 * (qx * qx + qz * qz)) * sy;
  m[6] = 2 * (qy * qz + qx * qw) * sy;
  m[8] = 2 * (qx * qz + qy * qw) * sz;
  m[9] = 2 * (qy * qz - qx * qw) * sz;
  m[10] = (1 - 2 * (qx * qx + qy * qy)) * sz;
  m[12] = tx;
  m[13] = ty;
  m[14] = tz;
  m[15] = 1;
  return m;
}

/** a × b, column-major. */
export function multiply(a: Float64Array, b: Float64Array): Float64Array {
  const out = new Float64Array(16);
  // Stryker disable next-line EqualityOperator: c = 4 writes only past out's 16 elements, a no-op
  for (let c = 0; c < 4; c++) {
    // Stryker disable next-line EqualityOperator: r = 4 writes the next column's first element before it is written, or past the end
    for (let r = 0; r < 4; r++) {
      out[4 * c + r] = a[r] * b[4 * c] + a[4 + r] * b[4 * c + 1] + a[8 + r] * b[4 * c + 2] + a[12 + r] * b[4 * c + 3];
    }
  }
  return out;
}
