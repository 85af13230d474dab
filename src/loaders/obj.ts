// The OBJ loader (docs/scene-model.md#obj-and-mtl): text or bytes in, typed arrays out. Pure — no DOM, no GL — so the
// worker, the main thread and the tests all call this same function.
import { asUint8, bomOf, decodeText, type Bytes } from './decode-text';
import { LoadError } from './load-error';
import { buildMesh } from './obj/build-mesh';
import { estimateCapacities } from './obj/estimate';
import { readObj, readObjBytes, type ObjRaw } from './obj/reader';
import type { ObjResult } from './obj/types';
import { SAMPLE, sniffModel, type ModelFormat } from './sniff';

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
  rejectNonObj(url, options.sniffed ?? sniffModel(text), () => text);
  return objResult(readObj(text), url);
}

/**
 * Parses OBJ bytes: UTF-8 with or without a BOM, read as bytes (no decoding but of names and
 * messages), the same result as parseObj on their text; UTF-16 LE/BE with a BOM, transcoded.
 */
export function parseObjBytes(bytes: Bytes, options: ObjOptions = {}): ObjResult {
  const url = options.url ?? '';
  const b = asUint8(bytes);
  const sniffed = options.sniffed ?? sniffModel(b);
  if (sniffed === 'binary') throw new LoadError(url, 'binary content, not an OBJ file');
  // Where the content is rejected, its first SAMPLE bytes (what the sniffer read) name the line.
  rejectNonObj(url, sniffed, () => {
    const start = decodeText(b, SAMPLE);
    return /\S/.test(start) ? start : decodeText(b);
  });
  const { encoding, skip } = bomOf(b);
  // UTF-16 (rare) is transcoded, so that one reader, over bytes, reads every file.
  const utf8 = encoding === 'utf-8' ? b : new TextEncoder().encode(decodeText(b));
  return objResult(readObjBytes(utf8, encoding === 'utf-8' ? skip : 0, estimateCapacities(utf8)), url);
}

export { normalizeObj } from './obj-normalize';

function objResult(raw: ObjRaw, url: string): ObjResult {
  if (raw.faces.length === 0) { // every kept face has a triangle
    const dropped = raw.droppedFaces;
    if (dropped === 0) throw new LoadError(url, 'no faces to draw');
    const s = dropped === 1 ? '' : 's';
    throw new LoadError(url, `no faces to draw: ${dropped} face${s} dropped, the first here`, raw.firstDroppedLine);
  }
  return { ...buildMesh(raw), warnings: raw.warnings.result() };
}

/** `text()`: the content, or its start holding the first non-blank character (for the error's line). */
function rejectNonObj(url: string, format: ModelFormat, text: () => string): void {
  if (format === 'html') throw new LoadError(url, 'an HTML page (or other markup), not an OBJ file', lineOfFirstContent(text()));
  if (format === 'binary') throw new LoadError(url, 'binary content, not an OBJ file');
  if (format === 'byu-mesh' || format === 'byu-bezier') throw new LoadError(url, 'a .byu model, not an OBJ file', lineOfFirstContent(text()));
}

/** The 1-based line of the first non-blank character: CRLF, CR or LF ends a line, as the reader counts them. */
function lineOfFirstContent(text: string): number {
  const start = Math.max(0, text.search(/\S/));
  let line = 1;
  for (let i = 0; i < start; i++) {
    const c = text.charCodeAt(i);
    if (c === 10 || (c === 13 && text.charCodeAt(i + 1) !== 10)) line++;
  }
  return line;
}
