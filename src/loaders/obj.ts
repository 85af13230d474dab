// The OBJ loader (SPEC §9): text or bytes in, typed arrays out. Pure — no DOM, no GL — so the
// worker, the main thread and the tests all call this same function.
import { decodeText, type Bytes } from './decode-text';
import { LoadError } from './load-error';
import { buildMesh } from './obj/build-mesh';
import { readObj } from './obj/reader';
import type { ObjResult } from './obj/types';
import { sniffModel, type ModelFormat } from './sniff';

export type { Bounds, DrawGroup, ObjResult } from './obj/types';

export interface ObjOptions {
  /** Named in warnings and errors. */
  url?: string;
  /** The content's sniffModel, if the caller has it (a load sniffs once). */
  sniffed?: ModelFormat;
}

/**
 * Parses OBJ text. Recoverable faults become `warnings` (the statement skipped, the rest
 * kept); content that is not an OBJ or holds no drawable face throws a LoadError.
 */
export function parseObj(text: string, options: ObjOptions = {}): ObjResult {
  const url = options.url ?? '';
  rejectNonObj(text, url, options.sniffed ?? sniffModel(text));
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
  const sniffed = options.sniffed ?? sniffModel(bytes);
  if (sniffed === 'binary') throw new LoadError(url, 'binary content, not an OBJ file');
  return parseObj(decodeText(bytes), { ...options, sniffed });
}

export { normalizeObj } from './obj-normalize';

function rejectNonObj(text: string, url: string, format: ModelFormat): void {
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
