// The course's Bézier `.byu` (docs/course-files.md#bezier-byu): `m n` (degrees), E (evaluations per direction), then
// the (m + 1)(n + 1) control points in one of the two index orders the course's files use.
import { LoadError, type LoadWarning } from '../load-error';
import { Warnings } from '../warnings';
import type { MeshData } from '../../scene/geometry/mesh-data';
import {
  bezierPatchMesh, MAX_BEZIER_RESOLUTION, MIN_BEZIER_RESOLUTION, type BezierPatch,
} from '../../scene/geometry/bezier';
import { CourseLines, rejectNonText } from './course-text';
import type { ModelFormat } from '../sniff';

/**
 * `'first-fastest'`: the file lists P(0,0), P(1,0), … P(m,0), P(0,1), … (the index running
 * 0..m varies fastest); `'second-fastest'`: P(0,0), P(0,1), … P(0,n), P(1,0), ….
 */
export type BezierOrder = 'first-fastest' | 'second-fastest';

export interface ByuBezierResult {
  /** The control net in bezier.ts's layout, whichever order the file used. */
  patch: BezierPatch;
  order: BezierOrder;
  /** Total edge length of the net as read in `order`, and as read the other way. */
  netLength: number;
  otherNetLength: number;
  /** E as the file gives it, and the E the mesh was built with. */
  fileResolution: number;
  resolution: number;
  mesh: MeshData;
  warnings: LoadWarning[];
}

/**
 * Above this degree a patch is refused: de Casteljau costs O(degree²) per grid point, and
 * a 1024² grid of degree-32 points already takes seconds. The course's patches are cubic.
 */
export const MAX_BEZIER_DEGREE = 32;

/**
 * Parses the text and evaluates the patch on an E×E grid (E from the file, or `resolution`
 * when given; either clamped to 2..1024 with a warning). The index order is the one whose
 * control net has the shorter total edge length (the other reading zig-zags across the
 * surface); when both are equal within 1e-9 — always so for m = n, where the two readings
 * are the same net transposed, the same surface with u and v swapped — the order is
 * `'second-fastest'`, the row-by-row reading of `for i: for j: read P(i, j)`.
 */
export function parseByuBezier(text: string, options: { url?: string; resolution?: number; sniffed?: ModelFormat } = {}): ByuBezierResult {
  const url = options.url ?? '';
  rejectNonText(text, url, 'a .byu file', options.sniffed);
  const lines = new CourseLines(text, url);
  const warnings = new Warnings();

  const header = lines.require(2, 'no header "m n"');
  if (header.tokens.length < 2) throw new LoadError(url, 'the header needs two degrees, "m n"; the second is missing', header.line);
  const m = lines.count(header.tokens[0], header.line, 'degree m', 1);
  const n = lines.count(header.tokens[1], header.line, 'degree n', 1);
  if (m > MAX_BEZIER_DEGREE || n > MAX_BEZIER_DEGREE) {
    throw new LoadError(url, `degrees (${m}, ${n}): above ${MAX_BEZIER_DEGREE} is not supported`, header.line);
  }
  if (header.tokens.length > 2) warnings.add(header.line, 'values after "m n" ignored');

  const second = lines.require(1, 'no line with the number of evaluations E');
  const fileResolution = lines.count(second.tokens[0], second.line, 'evaluations E', MIN_BEZIER_RESOLUTION);
  if (second.tokens.length > 1) warnings.add(second.line, 'values after E ignored');

  const count = (m + 1) * (n + 1);
  const file = new Float64Array(3 * count);
  for (let k = 0; k < count; k++) {
    const l = lines.require(3, `after ${k} of the ${count} control points of a (${m}, ${n}) patch`);
    file.set(lines.numbers(l, 3, `control point ${k + 1}`), 3 * k);
    if (l.tokens.length > 3) warnings.addOncePerKeyword('point', l.line, 'control point lines with more than 3 values: the rest ignored (the first such line)');
  }
  const rest = lines.rest();
  if (rest) {
    const s = rest.count === 1 ? '' : 's';
    warnings.add(rest.first, `${rest.count} line${s} after the ${count} control points; ignored`);
  }

  // The file's k-th point in 'second-fastest' order is already P(i, j) at k = i·(n + 1) + j.
  const transposed = firstFastestNet(file, m, n);
  const rowWise = netLength(file, m, n);
  const columnWise = netLength(transposed, m, n);
  const firstFastest = columnWise < rowWise * (1 - 1e-9);
  const order: BezierOrder = firstFastest ? 'first-fastest' : 'second-fastest';
  const patch: BezierPatch = { degreeU: m, degreeV: n, points: firstFastest ? transposed : file };

  let resolution = options.resolution ?? fileResolution;
  const clamped = Math.max(MIN_BEZIER_RESOLUTION, Math.min(MAX_BEZIER_RESOLUTION, Math.round(resolution) || MIN_BEZIER_RESOLUTION));
  if (clamped !== resolution) {
    const from = options.resolution === undefined ? `E = ${fileResolution} (line ${second.line})` : `resolution ${resolution}`;
    warnings.add(second.line, `${from} is outside ${MIN_BEZIER_RESOLUTION}..${MAX_BEZIER_RESOLUTION}; using ${clamped}`);
    resolution = clamped;
  }
  return {
    patch, order,
    netLength: firstFastest ? columnWise : rowWise,
    otherNetLength: firstFastest ? rowWise : columnWise,
    fileResolution, resolution,
    mesh: bezierPatchMesh(patch, resolution),
    warnings: warnings.result(),
  };
}

/** The file's points read with i (0..m) fastest, rearranged to P(i, j) at i·(n + 1) + j. */
function firstFastestNet(file: Float64Array, m: number, n: number): Float64Array {
  const out = new Float64Array(file.length);
  for (let k = 0; k < (m + 1) * (n + 1); k++) {
    const i = k % (m + 1), j = Math.floor(k / (m + 1));
    out.set(file.subarray(3 * k, 3 * k + 3), 3 * (i * (n + 1) + j));
  }
  return out;
}

/** Sum of |P(i+1, j) − P(i, j)| and |P(i, j+1) − P(i, j)| over the net. */
export function netLength(p: ArrayLike<number>, m: number, n: number): number {
  const at = (i: number, j: number): number => 3 * (i * (n + 1) + j);
  const edge = (a: number, b: number): number => Math.hypot(p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2]);
  let total = 0;
  for (let i = 0; i <= m; i++) {
    for (let j = 0; j <= n; j++) {
      if (i < m) total += edge(at(i, j), at(i + 1, j));
      if (j < n) total += edge(at(i, j), at(i, j + 1));
    }
  }
  return total;
}
