// What the reader hands to build-mesh.ts: the file's elements and kept faces as flat lists.
import type { F64List, I32List } from './growable';
import type { Warnings } from '../warnings';

/** Smoothing slot of faces under `s off` / `s 0`: flat normals. */
export const FLAT = -1;
/**
 * Ints per face record: first corner, corner count, first triangle, triangle count, smoothing
 * slot, material. A triangle as written has no entry in `triangles` (its first triangle is −1):
 * it is its three corners, in order.
 */
export const FACE_INTS = 6;

export interface ObjRaw {
  positions: F64List;
  /** rgb per vertex once any vertex had a colour (earlier ones filled with white), else null. */
  colors: F64List | null;
  uvs: F64List;
  normals: F64List;
  /** Per kept corner: its position index (0-based). */
  corners: I32List;
  /** Per kept corner: its uv index, −1 for none; null while no corner has one (then filled with −1 back to the first). */
  cornerUvs: I32List | null;
  /** Per kept corner: its normal index, −1 for none; null while no corner has one. */
  cornerNormals: I32List | null;
  /** Per triangle of a kept polygon: three global corner numbers (a face of 3 has none: FACE_INTS). */
  triangles: I32List;
  faces: I32List;
  materials: (string | null)[];
  objects: string[];
  groupNames: string[];
  mtllibs: string[];
  warnings: Warnings;
  droppedFaces: number;
  firstDroppedLine: number;
}
