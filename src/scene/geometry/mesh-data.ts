// CPU-side mesh description shared by every geometry builder; the GL Mesh uploads it.
export interface MeshData {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint16Array | Uint32Array;
  /**
   * Per vertex, the centroid of its triangle: only in flat meshes (flat.ts), where every
   * triangle has vertices of its own and lighting is computed once per face, at its centroid.
   */
  centroids?: Float32Array;
  /**
   * xyzw per vertex where a glTF material has a normal map (docs/gltf.md#tangents): the direction of increasing u, and w the
   * side of the bitangent w·(N × T) (the normal map's +Y). Absent: no normal map is drawn on the mesh.
   */
  tangents?: Float32Array;
  /** Linear RGB per vertex (a glTF file's COLOR_0): a glTF material's base colour is multiplied by it. Absent: white. */
  colors?: Float32Array;
}

export function indexArray(count: number, vertexCount: number): Uint16Array | Uint32Array {
  return vertexCount > 65535 ? new Uint32Array(count) : new Uint16Array(count);
}
