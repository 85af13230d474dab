// A course `.byu` (docs/course-files.md#mesh-byu) as the model the element draws: the same ObjResult shape as an OBJ
// (one group, no UVs, no materials), plus the Bézier patch so that `resolution` can re-evaluate
// it without a new fetch. Pure: the worker, the main thread and the tests call it.
import { decodeText, type Bytes } from '../decode-text';
import type { Bounds, ObjResult } from '../obj/types';
import type { MeshData } from '../../scene/geometry/mesh-data';
import { bezierPatchMesh, type BezierPatch } from '../../scene/geometry/bezier';
import type { LoadWarning } from '../load-error';
import { parseByu } from './byu';
import type { ModelFormat } from '../sniff';
import type { BezierOrder } from './byu-bezier';

/** What a Bézier `.byu` keeps besides its mesh at the file's E. */
export interface ByuBezierInfo {
  patch: BezierPatch;
  order: BezierOrder;
  /** E as the file gives it. */
  fileResolution: number;
}

export interface ByuModel {
  obj: ObjResult;
  bezier: ByuBezierInfo | null;
}

/** `sniffed`: the bytes' sniffModel, if the caller has it. */
export function parseByuModel(bytes: Bytes, url: string, sniffed?: ModelFormat): ByuModel {
  const result = parseByu(decodeText(bytes), { url, sniffed });
  if (result.kind === 'mesh') return { obj: meshToObj(result.mesh, result.warnings, result.bounds), bezier: null };
  return {
    obj: meshToObj(result.mesh, result.warnings),
    bezier: { patch: { ...result.patch, points: Float64Array.from(result.patch.points) }, order: result.order, fileResolution: result.fileResolution },
  };
}

/** The patch evaluated on an E×E grid (E = `resolution`, already within 2..1024). */
export function bezierObj(info: ByuBezierInfo, resolution: number): ObjResult {
  return meshToObj(bezierPatchMesh(info.patch, resolution), []);
}

function meshToObj(mesh: MeshData, warnings: LoadWarning[], bounds: Bounds = boundsOf(mesh.positions)): ObjResult {
  return {
    positions: mesh.positions, normals: mesh.normals, uvs: null, colors: null, indices: mesh.indices,
    groups: [], mtllibs: [], objects: [], groupNames: [], bounds, warnings,
  };
}

function boundsOf(p: Float32Array): Bounds {
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < p.length; i++) {
    const a = i % 3;
    if (p[i] < min[a]) min[a] = p[i];
    if (p[i] > max[a]) max[a] = p[i];
  }
  return { min, max };
}
