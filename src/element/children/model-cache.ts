// One fetch and parse per URL per page (docs/scene-model.md#loading): elements share a pending load and keep the
// result. Each user holds a reference; when the last one lets go of a load still under way,
// it is aborted. A failed load is forgotten, so setting the URL again later tries again.
// Models, the course's camera and lighting files (docs/course-files.md#lighting-file) and environment images, each kind keyed apart.
import { LoadError, type LoadErrorDetail } from '../../loaders/load-error';
import type { LoadedModel } from './model-loader';
import type { Progress } from './model-fetch';
import type { CourseFileKind, LoadedCourseFile } from './course-files';

interface Entry<T = unknown> {
  promise: Promise<T>;
  controller: AbortController;
  refs: number;
  settled: boolean;
  listeners: Set<(p: Progress) => void>;
  last: Progress | null;
}

const cache = new Map<string, Entry>();

export interface Handle<T> {
  readonly promise: Promise<T>;
  /** Stop listening; the last release of an unfinished load aborts it. Idempotent. */
  release(): void;
}

export type ModelHandle = Handle<LoadedModel>;

/** A load error as the `error` event's detail, whatever was thrown. */
export function loadErrorDetail(url: string, e: unknown): LoadErrorDetail {
  if (e instanceof LoadError) return e.detail;
  return { type: 'load', url, message: e instanceof Error ? e.message : String(e) };
}

type Loader<T> = (signal: AbortSignal, onProgress: (p: Progress) => void) => Promise<T>;

function start<T extends { warnings: string[] }>(key: string, url: string, load: Loader<T>): Entry<T> {
  const controller = new AbortController();
  const entry: Entry<T> = { promise: null!, controller, refs: 0, settled: false, listeners: new Set(), last: null };
  entry.promise = load(controller.signal, (p) => {
    entry.last = p;
    for (const l of entry.listeners) l(p);
  });
  entry.promise.then(
    (model) => {
      entry.settled = true;
      // Once per URL, not once per element showing it.
      for (const w of model.warnings) console.warn(w);
    },
    (e) => {
      entry.settled = true;
      if (cache.get(key) === entry) cache.delete(key);
      if (controller.signal.aborted) return;
      const d = loadErrorDetail(url, e);
      console.error(e instanceof LoadError ? e.message : `glass-plane-scene: ${url}: ${d.message}`);
    },
  );
  return entry;
}

export function acquireModel(url: string, onProgress: (p: Progress) => void): ModelHandle {
  // The loaders are a chunk of their own, fetched when a page first asks for a model (docs/package.md#chunks).
  return acquire(`model ${url}`, url, onProgress, (signal, progress) =>
    import('./model-loader').then(({ loadModel }) => loadModel(url, signal, progress)));
}

/** A camera `.cfg` or an `iluminacao.txt` (docs/course-files.md#lighting-file), once per URL per page like a model. */
export function acquireCourseFile<K extends CourseFileKind>(kind: K, url: string, onProgress: (p: Progress) => void = () => {}): Handle<LoadedCourseFile<K>> {
  return acquire(`${kind} ${url}`, url, onProgress, (signal, progress) =>
    import('./course-files').then(({ loadCourseFile }) => loadCourseFile(kind, url, signal, progress)));
}

/** Any file loaded once per `key` per page by `load` (the environment's image, element/environment-files.ts, brings its own). */
export function acquire<T extends { warnings: string[] }>(key: string, url: string, onProgress: (p: Progress) => void, load: Loader<T>): Handle<T> {
  let entry = cache.get(key) as Entry<T> | undefined;
  if (!entry) cache.set(key, (entry = start(key, url, load)));
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
        if (cache.get(key) === e) cache.delete(key);
      }
    },
  };
}
