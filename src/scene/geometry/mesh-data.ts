// CPU-side mesh description shared by every geometry builder; the GL Mesh uploads it.
export interface MeshData {
  positions: Float32Array;
  normals: Float32Array;
  uvs: Float32Array;
  indices: Uint16Array | Uint32Array;
}

export function indexArray(count: number, vertexCount: number): Uint16Array | Uint32Array {
  return vertexCount > 65535 ? new Uint32Array(count) : new Uint16Array(count);
}
