// The course's mesh `.byu` (docs/course-files.md#mesh-byu): `NV NT`, NV lines `x y z`, NT lines `i j k` (1-based),
// with vertex normals as the course teaches them.
import { LoadError, type LoadWarning } from '../load-error';
import { Warnings } from '../warnings';
import { indexArray, type MeshData } from '../../scene/geometry/mesh-data';
import { CourseLines, rejectNonText, type ContentLine } from './course-text';
import type { ModelFormat } from '../sniff';

export interface ByuMeshResult {
  /**
   * All NV vertices in file order (faces index them), normals as `courseVertexNormals`, uvs
   * all 0 (the course's objects have none), the kept faces as triangles in file order.
   */
  mesh: MeshData;
  /** NV and NT as the header states them. */
  vertexCount: number;
  declaredFaceCount: number;
  /** Faces kept: NT less those dropped for an index outside 1..NV. */
  faceCount: number;
  /** Bounds of the vertices the kept faces use. */
  bounds: { min: [number, number, number]; max: [number, number, number] };
  warnings: LoadWarning[];
}

/** A line holding x y z or i j k is at least 5 characters and a line break long. */
const MIN_LINE = 6;

/**
 * Reads exactly the counts of the header; content after them is ignored with one warning.
 * A missing count, a token that is not a number or fewer lines than counted throw a
 * LoadError with the line; a face with an index outside 1..NV (or not a whole number) is
 * dropped with a warning naming its line, but a negative last index is the classic BYU end
 * of a face, read as its absolute value. No face left is a LoadError.
 */
export function parseByuMesh(text: string, options: { url?: string; sniffed?: ModelFormat } = {}): ByuMeshResult {
  const url = options.url ?? '';
  rejectNonText(text, url, 'a .byu file', options.sniffed);
  const lines = new CourseLines(text, url);
  const warnings = new Warnings();

  const header = lines.require(2, 'no header "NV NT"');
  if (header.tokens.length < 2) throw new LoadError(url, 'the header needs two counts, "NV NT"; the face count is missing', header.line);
  const nv = lines.count(header.tokens[0], header.line, 'vertex count NV', 0);
  const nt = lines.count(header.tokens[1], header.line, 'face count NT', 1);
  if (header.tokens.length > 2) warnings.add(header.line, 'values after "NV NT" ignored');

  // Sized by the text too: a header claiming 10¹² vertices in a small file fails on reading,
  // not on allocating.
  const room = Math.floor(text.length / MIN_LINE) + 1;
  const positions = new Float32Array(3 * Math.min(nv, room));
  for (let k = 0; k < nv; k++) {
    const l = lines.require(3, `after ${k} of the ${nv} vertices the header (line ${header.line}) counts`);
    positions.set(lines.numbers(l, 3, `vertex ${k + 1}`), 3 * k);
    extra(l, 3, warnings, 'vertex');
  }

  const kept: number[] = [];
  let firstDropped = 0;
  for (let f = 0; f < nt; f++) {
    const l = lines.require(3, `after ${f} of the ${nt} faces the header (line ${header.line}) counts`);
    const [a, b, end] = lines.numbers(l, 3, `face ${f + 1}`);
    extra(l, 3, warnings, 'face');
    // Classic BYU polygon lists mark a face's last corner with a minus sign: |end| is that corner.
    const c = Math.abs(end);
    const bad = [a, b, c].findIndex((i) => !Number.isInteger(i) || i < 1 || i > nv);
    if (bad >= 0) {
      warnings.add(l.line, `face ${f + 1}: index ${[a, b, end][bad]} is outside 1..${nv}; face dropped`);
      if (firstDropped === 0) firstDropped = l.line;
      continue;
    }
    kept.push(a - 1, b - 1, c - 1);
  }

  const rest = lines.rest();
  if (rest) {
    const s = rest.count === 1 ? '' : 's';
    warnings.add(rest.first, `${rest.count} line${s} after the ${nv} vertices and ${nt} faces the header counts; ignored`);
  }
  if (kept.length === 0) throw new LoadError(url, `no faces to draw: all ${nt} dropped, the first here`, firstDropped);

  const indices = indexArray(kept.length, nv);
  indices.set(kept);
  const mesh: MeshData = {
    positions,
    normals: courseVertexNormals(positions, indices),
    uvs: new Float32Array(2 * nv),
    indices,
  };
  return {
    mesh, vertexCount: nv, declaredFaceCount: nt, faceCount: kept.length / 3,
    bounds: usedBounds(positions, indices), warnings: warnings.result(),
  };
}

/**
 * Vertex normals as the course teaches: the normalised sum of the unit normals
 * (b − a) × (c − a) of the faces around each vertex — every face counts the same, whatever
 * its area. A face of zero area adds nothing; a vertex whose sum is zero (no face, or faces
 * that cancel) gets +z.
 */
export function courseVertexNormals(positions: ArrayLike<number>, indices: ArrayLike<number>): Float32Array {
  const sum = new Float64Array(positions.length);
  for (let t = 0; t < indices.length; t += 3) {
    const a = 3 * indices[t], b = 3 * indices[t + 1], c = 3 * indices[t + 2];
    const ux = positions[b] - positions[a], uy = positions[b + 1] - positions[a + 1], uz = positions[b + 2] - positions[a + 2];
    const vx = positions[c] - positions[a], vy = positions[c + 1] - positions[a + 1], vz = positions[c + 2] - positions[a + 2];
    const nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const length = Math.hypot(nx, ny, nz);
    if (!(length > 0)) continue;
    for (const o of [a, b, c]) {
      sum[o] += nx / length; sum[o + 1] += ny / length; sum[o + 2] += nz / length;
    }
  }
  const normals = new Float32Array(positions.length);
  for (let o = 0; o < sum.length; o += 3) {
    const length = Math.hypot(sum[o], sum[o + 1], sum[o + 2]);
    if (length > 1e-12) {
      normals[o] = sum[o] / length; normals[o + 1] = sum[o + 1] / length; normals[o + 2] = sum[o + 2] / length;
    } else {
      normals[o + 2] = 1;
    }
  }
  return normals;
}

/** One warning per kind of line (not per line) for values past the three read. */
function extra(l: ContentLine, used: number, warnings: Warnings, kind: string): void {
  if (l.tokens.length > used) warnings.addOncePerKeyword(kind, l.line, `${kind} lines with more than ${used} values: the rest ignored (the first such line)`);
}

function usedBounds(p: Float32Array, indices: ArrayLike<number>): ByuMeshResult['bounds'] {
  const min: [number, number, number] = [Infinity, Infinity, Infinity];
  const max: [number, number, number] = [-Infinity, -Infinity, -Infinity];
  for (let t = 0; t < indices.length; t++) {
    for (let c = 0; c < 3; c++) {
      const x = p[3 * indices[t] + c];
      if (x < min[c]) min[c] = x;
      if (x > max[c]) max[c] = x;
    }
  }
  return { min, max };
}
