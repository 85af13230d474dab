// A parsed OBJ as scene geometry: one part per material (usemtl draw range), each a MeshData
// sharing the model's vertex arrays with an index array of its own, so every material keeps
// its own Ka/Kd/Ks/texture. Pure: no DOM, no GL.
import type { ObjResult } from '../../loaders/obj';
import { indexArray, type MeshData } from '../../scene/geometry/mesh-data';
import type { Bounds, Geometry } from '../../scene/scene';

export interface MeshPart {
  geometry: Extract<Geometry, { kind: 'mesh' }>;
  /** The `usemtl` name of the part, or null before any usemtl. */
  material: string | null;
  /** Object-space bounding sphere of the whole model (every part shares it: conservative). */
  bounds: Bounds;
  /** False when the file has no `vt`: UVs are zeros and the default mapping is spherical. */
  hasUvs: boolean;
}

/** A sphere around the vertices: centred on their bounding box, through the farthest one. */
export function boundingSphere(positions: Float32Array): Bounds {
  if (positions.length < 3) return { center: [0, 0, 0], radius: 0 };
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i++) {
    const a = i % 3;
    if (positions[i] < min[a]) min[a] = positions[i];
    if (positions[i] > max[a]) max[a] = positions[i];
  }
  const c = [0, 1, 2].map((a) => (min[a] + max[a]) / 2);
  let r2 = 0;
  for (let i = 0; i < positions.length; i += 3) {
    const dx = positions[i] - c[0], dy = positions[i + 1] - c[1], dz = positions[i + 2] - c[2];
    r2 = Math.max(r2, dx * dx + dy * dy + dz * dz);
  }
  // float32 positions, float64 radius: one part in 1e6 more keeps every vertex inside.
  return { center: [c[0], c[1], c[2]], radius: Math.sqrt(r2) * (1 + 1e-6) };
}

/** `key` names the content (URL and options): parts are keyed `${key}#${i}`. */
export function meshParts(obj: ObjResult, key: string): MeshPart[] {
  const vertexCount = obj.positions.length / 3;
  const hasUvs = obj.uvs !== null;
  const uvs = obj.uvs ?? new Float32Array(vertexCount * 2);
  const bounds = boundingSphere(obj.positions);
  const groups = obj.groups.length > 0 ? obj.groups : [{ material: null, start: 0, count: obj.indices.length }];
  return groups.map((g, i) => {
    const whole = groups.length === 1 && g.start === 0 && g.count === obj.indices.length;
    const indices = whole ? obj.indices : copyRange(obj.indices, g.start, g.count, vertexCount);
    const data: MeshData = {
      positions: obj.positions, normals: obj.normals, uvs, indices, ...(obj.tangents ? { tangents: obj.tangents } : {}), ...(obj.colors ? { colors: obj.colors } : {}),
    };
    return { geometry: { kind: 'mesh', key: `${key}#${i}`, data }, material: g.material, bounds, hasUvs };
  });
}

function copyRange(indices: Uint16Array | Uint32Array, start: number, count: number, vertexCount: number): Uint16Array | Uint32Array {
  const out = indexArray(count, vertexCount);
  out.set(indices.subarray(start, start + count));
  return out;
}
