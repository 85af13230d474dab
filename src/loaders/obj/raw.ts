// What the reader hands to build-mesh.ts: the file's elements and kept faces as flat lists.
import type { F64List, I32List } from './growable';
import type { Warnings } from '../warnings';

/** Smoothing slot of faces under `s off` / `s 0`: flat normals. */
export const FLAT = -1;
/** Ints per run of `runs`: its first face (a kept face's number), smoothing slot, material. */
export const RUN_INTS = 3;

export interface ObjRaw {
  positions: F64List;
  /** rgb per vertex once any vertex had a colour (earlier ones filled with white), else null. */
  colors: F64List | null;
  uvs: F64List;
  normals: F64List;
  /** Per kept corner: its position index (0-based). A face's corners follow the face before's. */
  corners: I32List;
  /** Per kept corner: its uv index, −1 for none; null while no corner has one (then filled with −1 back to the first). */
  cornerUvs: I32List | null;
  /** Per kept corner: its normal index, −1 for none; null while no corner has one. */
  cornerNormals: I32List | null;
  /** Per triangle of a kept polygon: three global corner numbers (a triangle as written has none). */
  triangles: I32List;
  /**
   * Per kept face, in order: its corner count; a polygon's (more than 3) is followed by how
   * many of `triangles` it kept (they follow the polygon before's). A triangle is 1 int.
   */
  faces: I32List;
  faceCount: number;
  /** Triangles of every kept face, as drawn. */
  triangleCount: number;
  /** Where the smoothing slot or material changes: RUN_INTS ints a run of kept faces, in order. */
  runs: I32List;
  materials: (string | null)[];
  objects: string[];
  groupNames: string[];
  mtllibs: string[];
  warnings: Warnings;
  droppedFaces: number;
  firstDroppedLine: number;
}
