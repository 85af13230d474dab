// The primitives of a model as one vertex buffer and one index buffer, grouped by material in
// order of first use (the shape of an OBJ's draw groups, docs/gltf.md#primitives).
import type { Piece } from './primitives';

export interface Merged {
  /** xyz per vertex, in the model's space (node matrices applied). */
  positions: Float32Array;
  /** Unit xyz per vertex: the file's, or flat where it has none. */
  normals: Float32Array;
  /** TEXCOORD_0 as glTF has it (v = 0 the image's top row), or null when no primitive has one. */
  uv0: Float32Array | null;
  uv1: Float32Array | null;
  /** COLOR_0 as linear RGBA, or null when no primitive has one (1 where one primitive lacks it). */
  colors: Float32Array | null;
  /** xyzw per vertex where some primitive's material has a normal map (zeros for the others), else null. */
  tangents: Float32Array | null;
  indices: Uint32Array;
  /** One index range per material (materials[i], or null: the default material), in order of first use. */
  groups: { material: number | null; start: number; count: number }[];
}

export function mergePieces(pieces: readonly Piece[]): Merged {
  if (pieces.length === 1) {
    // One primitive (most product models): its arrays as they are.
    const [p] = pieces;
    return { positions: p.positions, normals: p.normals, uv0: p.uv0, uv1: p.uv1, colors: p.colors, tangents: p.tangents, indices: p.indices, groups: [{ material: p.material, start: 0, count: p.indices.length }] };
  }
  const vertexCount = pieces.reduce((n, p) => n + p.positions.length / 3, 0);
  const positions = new Float32Array(vertexCount * 3);
  const normals = new Float32Array(vertexCount * 3);
  const uv0 = pieces.some((p) => p.uv0) ? new Float32Array(vertexCount * 2) : null;
  const uv1 = pieces.some((p) => p.uv1) ? new Float32Array(vertexCount * 2) : null;
  const colors = pieces.some((p) => p.colors) ? new Float32Array(vertexCount * 4).fill(1) : null;
  const tangents = pieces.some((p) => p.tangents) ? new Float32Array(vertexCount * 4) : null;
  const first: number[] = [];
  let at = 0;
  for (const p of pieces) {
    first.push(at);
    positions.set(p.positions, 3 * at);
    normals.set(p.normals, 3 * at);
    if (uv0 && p.uv0) uv0.set(p.uv0, 2 * at);
    if (uv1 && p.uv1) uv1.set(p.uv1, 2 * at);
    if (colors && p.colors) colors.set(p.colors, 4 * at);
    if (tangents && p.tangents) tangents.set(p.tangents, 4 * at);
    at += p.positions.length / 3;
  }
  // Materials in order of first use; each group the pieces of one material, in file order.
  const order = [...new Set(pieces.map((p) => p.material))];
  const indices = new Uint32Array(pieces.reduce((n, p) => n + p.indices.length, 0));
  const groups: Merged['groups'] = [];
  let start = 0;
  for (const material of order) {
    const from = start;
    pieces.forEach((p, k) => {
      if (p.material !== material) return;
      // Stryker disable next-line EqualityOperator: one step more writes slot start + length, which the next piece writes again (or lies past the end)
      for (let i = 0; i < p.indices.length; i++) indices[start + i] = p.indices[i] + first[k];
      start += p.indices.length;
    });
    groups.push({ material, start: from, count: start - from });
  }
  return { positions, normals, uv0, uv1, colors, tangents, indices, groups };
}
