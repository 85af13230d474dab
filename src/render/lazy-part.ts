// A part of the renderer that only some frames need, in a chunk of its own (docs/package.md#chunks): fetched
// the first time a frame asks for it (Renderer.load), the same promise while it comes; if it
// cannot load, the promise rejects once with an Error saying what is drawn instead, and the part
// is not asked for again.

/** The one message for a part that failed to load: "`what` could not load (why); `instead`". */
export const loadFailed = (what: string, e: unknown, instead: string): string =>
  `${what} could not load (${String(e).slice(0, 200)}); ${instead}`;
export class LazyPart<T> {
  /** The part, once loaded; null before (and for ever after a failure). */
  value: T | null = null;
  private loading: Promise<void> | null = null;
  private failed = false;

  /** `instead`: what is drawn without it (ends the warning "… could not load (why); …"). */
  constructor(private readonly fetch: () => Promise<T>, private readonly name: string, private readonly instead: string) {}

  /** The part handed over by a chunk that carries it already: `value` from now on, with no fetch. */
  provide(value: T): void {
    this.value ??= value;
  }

  /** Fetches the part when `needed` and not in (nor failed); null when there is nothing to wait for. */
  load(needed: boolean): Promise<void> | null {
    if (!needed || this.value || this.failed) return null;
    return (this.loading ??= this.fetch().then(
      (value) => {
        this.value = value;
      },
      (e: unknown) => {
        this.failed = true;
        throw new Error(loadFailed(this.name, e, this.instead));
      },
    ));
  }
}

/**
 * One promise for the parts a frame is waiting for (`parts`: LazyPart.load results, null where
 * not waited for), or null for none: settled when every one is, rejected with each failure's
 * message (so each is warned about once). The caller refills one array each frame, so a frame
 * that waits for nothing allocates nothing.
 */
export function loadAll(parts: readonly (Promise<void> | null)[]): Promise<void> | null {
  let waiting = false;
  for (let i = 0; i < parts.length; i++) if (parts[i]) waiting = true;
  if (!waiting) return null;
  return Promise.allSettled(parts.slice()).then((results) => {
    const failed = results.flatMap((r) => (r.status === 'rejected' ? [r.reason instanceof Error ? r.reason.message : String(r.reason)] : []));
    if (failed.length) throw new Error(failed.join('; '));
  });
}
