// One fetch and parse per URL per page (SPEC §9): elements share a pending load and keep the
// result. Each user holds a reference; when the last one lets go of a load still under way,
// it is aborted. A failed load is forgotten, so setting the URL again later tries again.
import { LoadError, type LoadErrorDetail } from '../../loaders/load-error';
import type { LoadedModel } from './model-loader';
import type { Progress } from './model-fetch';

interface Entry {
  promise: Promise<LoadedModel>;
  controller: AbortController;
  refs: number;
  settled: boolean;
  listeners: Set<(p: Progress) => void>;
  last: Progress | null;
}

const cache = new Map<string, Entry>();

export interface ModelHandle {
  readonly promise: Promise<LoadedModel>;
  /** Stop listening; the last release of an unfinished load aborts it. Idempotent. */
  release(): void;
}

/** A load error as the `error` event's detail, whatever was thrown. */
export function loadErrorDetail(url: string, e: unknown): LoadErrorDetail {
  if (e instanceof LoadError) return e.detail;
  return { type: 'load', url, message: e instanceof Error ? e.message : String(e) };
}

function start(url: string): Entry {
  const controller = new AbortController();
  const entry: Entry = { promise: null!, controller, refs: 0, settled: false, listeners: new Set(), last: null };
  // The loaders are a chunk of their own, fetched when a page first asks for a model (SPEC §12).
  entry.promise = import('./model-loader').then(({ loadModel }) => loadModel(url, controller.signal, (p) => {
    entry.last = p;
    for (const l of entry.listeners) l(p);
  }));
  entry.promise.then(
    (model) => {
      entry.settled = true;
      // Once per URL, not once per element showing it.
      for (const w of model.warnings) console.warn(w);
    },
    (e) => {
      entry.settled = true;
      if (cache.get(url) === entry) cache.delete(url);
      if (controller.signal.aborted) return;
      const d = loadErrorDetail(url, e);
      console.error(e instanceof LoadError ? e.message : `glass-plane-scene: ${url}: ${d.message}`);
    },
  );
  return entry;
}

export function acquireModel(url: string, onProgress: (p: Progress) => void): ModelHandle {
  let entry = cache.get(url);
  if (!entry) cache.set(url, (entry = start(url)));
  const e = entry;
  e.refs++;
  e.listeners.add(onProgress);
  if (e.last && !e.settled) onProgress(e.last);
  let released = false;
  return {
    promise: e.promise,
    release() {
      if (released) return;
      released = true;
      e.listeners.delete(onProgress);
      if (--e.refs === 0 && !e.settled) {
        e.controller.abort();
        if (cache.get(url) === e) cache.delete(url);
      }
    },
  };
}
