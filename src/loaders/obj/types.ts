// What the OBJ loader hands to the renderer: typed arrays and plain data only, so it can
// cross a worker boundary by transfer.
import type { LoadWarning } from '../load-error';

/** A run of the index buffer drawn with one material, in index units (3 per triangle). */
export interface DrawGroup {
  /** The `usemtl` name, or null for faces before any `usemtl`. */
  material: string | null;
  start: number;
  count: number;
}

export interface Bounds {
  min: [number, number, number];
  max: [number, number, number];
}

export interface ObjResult {
  /** xyz per vertex; only the vertices faces use. */
  positions: Float32Array;
  /** Unit xyz per vertex: the file's `vn`, else generated (smoothing groups decide). */
  normals: Float32Array;
  /** uv per vertex (OBJ convention: v = 0 is the bottom row), or null when no face has `vt`. */
  uvs: Float32Array | null;
  /** rgb per vertex from `v x y z r g b`, or null when no vertex has colours. */
  colors: Float32Array | null;
  /** xyzw per vertex for a glTF model's normal maps (MeshData.tangents), or null: an OBJ has none. */
  tangents?: Float32Array | null;
  /** Triangles; 32-bit above 65 535 vertices (WebGL2 reserves 0xFFFF for primitive restart). */
  indices: Uint16Array | Uint32Array;
  /** One range per material, in order of first use; together they cover `indices`. */
  groups: DrawGroup[];
  mtllibs: string[];
  /** `o` names, and `g` names, each once in order of appearance. */
  objects: string[];
  groupNames: string[];
  /** Of the vertices the faces use. */
  bounds: Bounds;
  warnings: LoadWarning[];
}
