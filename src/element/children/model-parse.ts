// Bytes → ObjResult: sniff the content (an HTML page, binary bytes or a .byu are load errors),
// then parse the OBJ on the main thread, or in a worker above WORKER_THRESHOLD so a big file
// does not block the page. Where a worker cannot start, the main thread parses it.
import { LoadError } from '../../loaders/load-error';
import { parseObjBytes, type ObjResult } from '../../loaders/obj';
import type { ObjJobRequest, ObjJobResponse } from '../../loaders/obj-job';
import { sniffModel, type ModelFormat } from '../../loaders/sniff';

/** Files at least this big are parsed off the main thread. */
export const WORKER_THRESHOLD = 256 * 1024;

/** The load error a sniffed format means, or null for something to hand to the OBJ parser. */
export function formatProblem(format: ModelFormat): string | null {
  switch (format) {
    case 'html': return 'an HTML page (or other markup), not a model: is the URL right?';
    case 'binary': return 'binary content, not a model file';
    case 'byu-mesh': case 'byu-bezier': return '.byu models: format not supported yet';
    default: return null;
  }
}

export async function parseModelBytes(bytes: Uint8Array, url: string): Promise<ObjResult> {
  const problem = formatProblem(sniffModel(bytes));
  if (problem) throw new LoadError(url, problem);
  if (bytes.length >= WORKER_THRESHOLD) {
    const result = await parseInWorker(bytes, url);
    if (result) return result;
  }
  return parseObjBytes(bytes, { url });
}

let nextId = 1;

/** Resolves null when no worker could run the job (the caller parses on the main thread). */
function parseInWorker(bytes: Uint8Array, url: string): Promise<ObjResult | null> {
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
      if (r.ok) resolve(r.result);
      else reject(new LoadError(r.error.url, r.error.message, r.error.line));
    };
    // A worker that fails to load (CSP, no module workers) reports here: parse on this thread.
    worker.onerror = (e) => {
      e.preventDefault();
      worker.terminate();
      resolve(null);
    };
    // Copied, not transferred: the bytes stay usable for the main-thread fallback.
    const buffer = bytes.slice().buffer as ArrayBuffer;
    const request: ObjJobRequest = { id, url, bytes: buffer };
    worker.postMessage(request, [buffer]);
  });
}
