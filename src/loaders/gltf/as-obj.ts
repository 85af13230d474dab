// A glTF model in the shape the element draws a loaded model in (an ObjResult: one vertex buffer,
// a draw group per material), so that it takes the path OBJ models take (docs/gltf.md#in-the-scene).
// Texture coordinates turn to the OBJ convention (v = 0 the image's bottom row); a group names
// its material `#i` (materials[i]), the default material null.
import type { LoadWarning } from '../load-error';
import type { ObjResult } from '../obj/types';
import type { GltfResult } from './index';

export function materialKey(index: number): string {
  return `#${index}`;
}

/**
 * A KHR_texture_transform, row-major [a, b, c, d, e, f] in glTF's UV (v down), in the UV gltfAsObj turns to (v' = 1 − v): the
 * same map of the surface, [a, −b, b + c, −d, e, 1 − e − f].
 */
export function transformAsObj(m: readonly number[]): number[] {
  const [a, b, c, d, e, f] = m;
  return [a, -b, b + c, -d, e, 1 - e - f];
}

export function gltfAsObj(r: GltfResult): ObjResult {
  const vertexCount = r.positions.length / 3;
  let uvs: Float32Array | null = null;
  if (r.uv0) {
    uvs = new Float32Array(r.uv0.length);
    // Stryker disable next-line EqualityOperator: one step more writes uvs[length], which a typed array ignores
    for (let i = 0; i < uvs.length; i += 2) {
      uvs[i] = r.uv0[i];
      uvs[i + 1] = 1 - r.uv0[i + 1];
    }
  }
  let colors: Float32Array | null = null;
  if (r.colors) {
    colors = new Float32Array(vertexCount * 3);
    // Stryker disable next-line EqualityOperator: one step more sets an empty subarray at the end, which changes nothing
    for (let v = 0; v < vertexCount; v++) colors.set(r.colors.subarray(4 * v, 4 * v + 3), 3 * v);
  }
  const indices = vertexCount > 65535 ? r.indices : Uint16Array.from(r.indices);
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  // Stryker disable next-line EqualityOperator: one step more reads undefined, less and greater than nothing
  for (let i = 0; i < r.positions.length; i++) {
    const a = i % 3;
    // Stryker disable next-line EqualityOperator: a value equal to the bound sets the bound to itself
    if (r.positions[i] < min[a]) min[a] = r.positions[i];
    // Stryker disable next-line EqualityOperator: a value equal to the bound sets the bound to itself
    if (r.positions[i] > max[a]) max[a] = r.positions[i];
  }
  const warnings: LoadWarning[] = r.warnings.map((w) => ({ line: 0, path: w.path, message: w.message }));
  return {
    positions: r.positions, normals: r.normals, uvs, colors, indices, tangents: r.tangents,
    groups: r.groups.map((g) => ({ material: g.material === null ? null : materialKey(g.material), start: g.start, count: g.count })),
    mtllibs: [], objects: [], groupNames: [], bounds: { min, max }, warnings,
  };
}
