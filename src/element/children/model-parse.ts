// Bytes → ObjResult: sniff the content once (an HTML page or binary bytes are load errors), then
// parse the OBJ or the course's `.byu` (docs/course-files.md#mesh-byu) on the main thread, or in a worker above
// WORKER_THRESHOLD so a big file does not block the page. Where a worker cannot start, the
// main thread parses it.
import { LoadError } from '../../loaders/load-error';
import { parseObjBytes, type ObjResult } from '../../loaders/obj';
import type { ObjJobRequest, ObjJobResponse } from '../../loaders/obj-job';
import { parseByuModel, type ByuBezierInfo } from '../../loaders/course/byu-model';
import { sniffModel, type ModelFormat } from '../../loaders/sniff';

/** Files at least this big are parsed off the main thread. */
export const WORKER_THRESHOLD = 256 * 1024;

/** The load error a sniffed format means, or null for something to hand to the OBJ parser. */
export function formatProblem(format: ModelFormat): string | null {
  switch (format) {
    case 'html': return 'an HTML page (or other markup), not a model: is the URL right?';
    case 'binary': return 'binary content, not a model file';
    default: return null;
  }
}

export interface ParsedModel {
  obj: ObjResult;
  /** A Bézier `.byu`: its patch, index order and E (null for an OBJ or a mesh `.byu`). */
  bezier: ByuBezierInfo | null;
  /** A course `.byu` (mesh or Bézier): drawn without a texture unless one is set (docs/course-files.md#mesh-byu). */
  byu: boolean;
}

/** `sniffed`: the content's format, when the caller has sniffed it (a load sniffs once). */
export async function parseModelBytes(bytes: Uint8Array, url: string, sniffed: ModelFormat = sniffModel(bytes)): Promise<ParsedModel> {
  const problem = formatProblem(sniffed);
  if (problem) throw new LoadError(url, problem);
  // Content too broken to say (a .byu without its face count) is named by the URL, so that
  // the .byu parser reports the faulty line (docs/course-files.md#text-conventions).
  const byu = sniffed === 'byu-mesh' || sniffed === 'byu-bezier' || (sniffed === 'unknown' && isByuUrl(url));
  const format = byu ? 'byu' : 'obj';
  if (bytes.length >= WORKER_THRESHOLD) {
    const result = await parseInWorker(bytes, url, format, sniffed);
    if (result) return result;
  }
  return format === 'byu'
    ? { ...parseByuModel(bytes, url, sniffed), byu: true }
    : { obj: parseObjBytes(bytes, { url, sniffed }), bezier: null, byu: false };
}

function isByuUrl(url: string): boolean {
  return /\.byu$/i.test(url.split(/[?#]/, 1)[0]);
}

let nextId = 1;

/** Resolves null when no worker could run the job (the caller parses on the main thread). */
function parseInWorker(bytes: Uint8Array, url: string, format: 'obj' | 'byu', sniffed: ModelFormat): Promise<ParsedModel | null> {
  return new Promise((resolve, reject) => {
    let worker: Worker;
    try {
      worker = new Worker(new URL('../../loaders/obj-worker.ts', import.meta.url), { type: 'module' });
    } catch {
      resolve(null);
      return;
    }
    const id = nextId++;
    worker.onmessage = (e: MessageEvent<ObjJobResponse>) => {
      worker.terminate();
      const r = e.data;
      if (r.ok) resolve({ obj: r.result, bezier: r.bezier ?? null, byu: format === 'byu' });
      else reject(new LoadError(r.error.url, r.error.message, r.error.line ?? r.error.path));
    };
    // A worker that fails to load (CSP, no module workers) reports here: parse on this thread.
    worker.onerror = (e) => {
      e.preventDefault();
      worker.terminate();
      resolve(null);
    };
    // Copied, not transferred: the bytes stay usable for the main-thread fallback.
    const buffer = bytes.slice().buffer as ArrayBuffer;
    const request: ObjJobRequest = { id, url, bytes: buffer, format, sniffed };
    worker.postMessage(request, [buffer]);
  });
}
