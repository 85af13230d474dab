// The one mechanism for what only some frames need: a part is declared once (render/parts.ts for
// the renderer's, element/parts.ts for the element's) and an owner (a renderer, an element) keeps
// one LazyParts over its declarations. Each frame the owner asks one question, request(): every
// part this frame needs that is not in starts loading, and the answer says whether the frame must
// wait. How to add a part: ARCHITECTURE.md#lazy-parts.
//
// Failure policy, the same for every part: one warning ("<name> could not load (<why>); <instead>"),
// then the part is never asked for again and frames are drawn without it. No retry: a browser keeps
// a module that failed in its module map, so a second import() of the same chunk fails again
// without fetching (the HTML standard's module map); the page's reload is the retry.
import type { ChunkName } from './chunks';

/** One lazy part of an owner whose state it reads through `H` (the owner's host). */
export interface LazyPartSpec<H, T = unknown> {
  /** Names it in its warning: what the page asked for ("rough glass", or `controls="orbit"` read from the owner). */
  readonly name: string | ((host: H) => string);
  /** The chunk its module is built into (frame/chunks.ts): its group and size budget. */
  readonly chunk: ChunkName;
  /** Fetches its module. */
  readonly load: () => Promise<T>;
  /** Whether the frame the owner is about to draw needs it. Reads; never allocates, never loads. */
  readonly needed: (host: H) => boolean;
  /** True: a frame that needs it waits for it. False: frames are drawn without it meanwhile. */
  readonly holds: boolean;
  /** What is drawn without it: the end of its warning. */
  readonly instead: string;
  /** Hands the module to the owner (once, before the frame that waited for it is asked for again). */
  arrived?(host: H, value: T): void;
}

/** The warning of a part that failed: "`name` could not load (why); `instead`". */
export const loadFailed = (name: string, e: unknown, instead: string): string =>
  `${name} could not load (${String(e).slice(0, 200)}); ${instead}`;

/** Where an owner's parts report: a part settled (in or failed), a part failed (once each). */
export interface PartListener {
  settled(): void;
  warn(message: string): void;
}

const ABSENT = 0, LOADING = 1, IN = 2, FAILED = 3;

/** A part of any module type: each declaration's own `T` is checked where it is written. */
type AnySpec<H> = LazyPartSpec<H, unknown>;

export class LazyParts<H> {
  private readonly status: Uint8Array;
  private readonly values: unknown[];
  private readonly loads: (Promise<void> | null)[];
  /** The promise request() last answered with, while the parts it waits for load. */
  private waiting: Promise<void> | null = null;

  constructor(private readonly specs: readonly AnySpec<H>[], private readonly host: H, private readonly listener: PartListener) {
    this.status = new Uint8Array(specs.length);
    // Stryker disable next-line ArrowFunction: undefined or null, get() answers null until a part is in
    this.values = specs.map(() => null);
    // Stryker disable next-line ArrowFunction: undefined or null, both read as no load on its way
    this.loads = specs.map(() => null);
  }

  /**
   * The frame's one question: starts every part the frame needs that is neither in nor failed;
   * answers a promise settled when every part the frame waits for has settled (it never
   * rejects), or null when the frame waits for nothing. Allocates only when a part starts.
   */
  request(): Promise<void> | null {
    const specs = this.specs, status = this.status;
    let started = false, holds = false;
    for (let i = 0; i < specs.length; i++) {
      const s = status[i];
      if (s === IN || s === FAILED || !specs[i].needed(this.host)) continue;
      if (s === ABSENT) {
        this.start(i);
        started = true;
      }
      if (specs[i].holds) holds = true;
    }
    if (!holds) return null;
    if (started || !this.waiting) this.waiting = this.allHeld();
    return this.waiting;
  }

  /** The part's module once in; null before, and for ever after a failure. */
  get<T>(spec: LazyPartSpec<H, T>): T | null {
    const i = this.index(spec);
    // Stryker disable next-line ConditionalExpression: a part not in holds null as its value
    return this.status[i] === IN ? (this.values[i] as T) : null;
  }

  /** Fetches `spec` now, whatever the frame needs (a failure's message, a renderer switch); null if it failed. */
  fetch<T>(spec: LazyPartSpec<H, T>): Promise<T | null> {
    const i = this.index(spec);
    if (this.status[i] === ABSENT) this.start(i);
    return (this.loads[i] ?? Promise.resolve()).then(() => this.get(spec));
  }

  /** The module handed over by a chunk that carries it already: in from now on, with no fetch. */
  provide<T>(spec: LazyPartSpec<H, T>, value: T): void {
    const i = this.index(spec);
    if (this.status[i] === IN) return;
    this.status[i] = IN;
    this.values[i] = value;
    spec.arrived?.(this.host, value);
  }

  /** A part is on its way (`ready` waits for every one). */
  get loading(): boolean {
    return this.status.includes(LOADING);
  }

  private index(spec: AnySpec<H>): number {
    const i = this.specs.indexOf(spec);
    if (i < 0) throw new Error('not a part of this owner');
    return i;
  }

  private start(i: number): void {
    const spec = this.specs[i];
    this.status[i] = LOADING;
    this.loads[i] = spec.load().then((value) => {
      if (this.status[i] !== LOADING) return; // provided meanwhile
      this.status[i] = IN;
      this.values[i] = value;
      spec.arrived?.(this.host, value);
    }).catch((e: unknown) => {
      // The fetch failed, or the owner could not take the module: the same policy.
      this.status[i] = FAILED;
      this.values[i] = null;
      this.listener.warn(loadFailed(typeof spec.name === 'string' ? spec.name : spec.name(this.host), e, spec.instead));
    }).finally(() => {
      this.loads[i] = null;
      this.listener.settled();
    });
  }

  /** One promise for every held part on its way. */
  private allHeld(): Promise<void> {
    // Stryker disable next-line ArrayDeclaration: Promise.all waits for the same promises with a string among them
    const held: Promise<void>[] = [];
    // Stryker disable next-line EqualityOperator: loads[length] is undefined: nothing to wait for
    for (let i = 0; i < this.specs.length; i++) {
      const p = this.loads[i];
      if (p && this.specs[i].holds) held.push(p);
    }
    return Promise.all(held).then(() => undefined);
  }
}
