// The OBJ loader (SPEC §9): text or bytes in, typed arrays out. Pure — no DOM, no GL — so the
// worker, the main thread and the tests all call this same function.
import { decodeText, type Bytes } from './decode-text';
import { LoadError } from './load-error';
import { buildMesh } from './obj/build-mesh';
import { readObj } from './obj/reader';
import type { ObjResult } from './obj/types';
import { sniffModel } from './sniff';

export type { Bounds, DrawGroup, ObjResult } from './obj/types';

export interface ObjOptions {
  /** Named in warnings and errors. */
  url?: string;
}

/**
 * Parses OBJ text. Recoverable faults become `warnings` (the statement skipped, the rest
 * kept); content that is not an OBJ or holds no drawable face throws a LoadError.
 */
export function parseObj(text: string, options: ObjOptions = {}): ObjResult {
  const url = options.url ?? '';
  rejectNonObj(text, url);
  const raw = readObj(text);
  if (raw.triangles.length === 0) {
    const dropped = raw.droppedFaces;
    if (dropped === 0) throw new LoadError(url, 'no faces to draw');
    const s = dropped === 1 ? '' : 's';
    throw new LoadError(url, `no faces to draw: ${dropped} face${s} dropped, the first here`, raw.firstDroppedLine);
  }
  return { ...buildMesh(raw), warnings: raw.warnings.result() };
}

/** Parses OBJ bytes: UTF-8 with or without a BOM, UTF-16 LE/BE with a BOM. */
export function parseObjBytes(bytes: Bytes, options: ObjOptions = {}): ObjResult {
  const url = options.url ?? '';
  const format = sniffModel(bytes);
  if (format === 'binary') throw new LoadError(url, 'binary content, not an OBJ file');
  return parseObj(decodeText(bytes), options);
}

/**
 * Centres the bounds on the origin and scales the longest side to 2 (seed 001's "standardize").
 * Returns a new result; only positions and bounds change (normals survive a uniform scale).
 */
export function normalizeObj(result: ObjResult): ObjResult {
  const { min, max } = result.bounds;
  const centre = [0, 1, 2].map((a) => (min[a] + max[a]) / 2);
  const longest = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
  const scale = longest > 0 ? 2 / longest : 1;
  const positions = new Float32Array(result.positions.length);
  for (let i = 0; i < positions.length; i++) positions[i] = (result.positions[i] - centre[i % 3]) * scale;
  const at = (a: number, v: number): number => (v - centre[a]) * scale;
  return {
    ...result,
    positions,
    bounds: {
      min: [at(0, min[0]), at(1, min[1]), at(2, min[2])],
      max: [at(0, max[0]), at(1, max[1]), at(2, max[2])],
    },
  };
}

function rejectNonObj(text: string, url: string): void {
  const format = sniffModel(text);
  if (format === 'html') throw new LoadError(url, 'an HTML page (or other markup), not an OBJ file', lineOfFirstContent(text));
  if (format === 'binary') throw new LoadError(url, 'binary content, not an OBJ file');
  if (format === 'byu-mesh' || format === 'byu-bezier') throw new LoadError(url, 'a .byu model, not an OBJ file', lineOfFirstContent(text));
}

function lineOfFirstContent(text: string): number {
  const start = Math.max(0, text.search(/\S/));
  let line = 1;
  for (let i = 0; i < start; i++) if (text.charCodeAt(i) === 10) line++;
  return line;
}
