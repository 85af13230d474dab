// Watches the scene element's light-DOM children and gathers their parts of the scene:
// a MutationObserver for children added, removed or reordered, the children's own change
// notices for their attributes and loads, and whenDefined for children upgraded later. The
// children's own chunk (children/child-elements.ts) is fetched when the first of them is found
// undefined, and what gathers their parts (children/gather-parts.ts, a chunk of its own: children
// defined by another copy of the package need it too) when the first is found: frames wait for both.
import type { ChildParts } from './compose-scene';
import { CHILD_CHANGE, LIGHT_TAG, OBJECT_TAG } from './children/tags';
import type { GlassLight } from './children/glass-light';
import type { GlassObject } from './children/glass-object';
import { defineChildren } from './children-loader';
import type { GatherHost } from './children/gather-parts';
import { warn } from './warnings';
import { loadFailed } from '../render/lazy-part';
import type { Controller } from './controller';

const NO_PARTS: ChildParts = { objects: null, lights: null };

/** children/gather-parts.ts once it is in (page-wide). */
let gatherer: typeof import('./children/gather-parts') | null = null;

/** What SceneSource needs of the scene element. */
export interface SceneSourceHost {
  /** The scene element: its direct children are the parts. */
  readonly element: HTMLElement;
  /** A child was added, removed, reordered, changed, upgraded, or its model arrived. */
  partsChanged(): void;
}

export class SceneSource implements Controller, GatherHost {
  private observer: MutationObserver | null = null;
  private parts: ChildParts | null = null;
  /** @internal GatherHost */
  warnedLights = false;
  private readonly awaiting = new Set<string>();
  /** Chunks on their way (the children's, the gatherer): frames wait for them (the scene is not drawn without them). */
  private fetching = 0;
  /** The gatherer was asked for (once per scene; after a failure, the scene is drawn without its children). */
  private gathererAsked = false;
  readonly element: HTMLElement;

  constructor(private readonly host: SceneSourceHost) {
    this.element = host.element;
  }

  hostConnected(): void {
    if (this.observer) return;
    this.observer = new MutationObserver(this.invalidate);
    this.observer.observe(this.element, { childList: true });
    this.element.addEventListener(CHILD_CHANGE, this.onChildChange);
    this.invalidate();
  }

  hostDisconnected(): void {
    this.observer?.disconnect();
    this.observer = null;
    this.element.removeEventListener(CHILD_CHANGE, this.onChildChange);
  }

  /** True while a direct <glass-object> or <glass-light> child is fetching or parsing its file. */
  get loading(): boolean {
    for (const child of this.element.children) {
      const name = child.localName;
      if ((name === OBJECT_TAG || name === LIGHT_TAG) && (child as GlassObject | GlassLight).loading === true) return true;
    }
    return false;
  }

  /** The children's objects and lights (null: none of that kind, use the default). Cached. */
  current(): ChildParts {
    return (this.parts ??= this.gather());
  }

  /** A chunk is on its way: the frame waits. */
  get defining(): boolean {
    return this.fetching > 0;
  }

  /** The children's parts, by the gatherer; before it is in, a child of ours starts loading it (and defining them). */
  private gather(): ChildParts {
    if (gatherer) return gatherer.gatherParts(this);
    for (const child of this.element.children) {
      const name = child.localName;
      if (name !== OBJECT_TAG && name !== LIGHT_TAG) continue;
      if (!this.gathererAsked) {
        this.gathererAsked = true;
        this.fetch(import('./children/gather-parts').then((m) => { gatherer = m; }), 'the children\'s parts');
      }
      this.awaitDefinition(name);
    }
    return NO_PARTS;
  }

  /** @internal GatherHost: `name` is not defined yet; its chunk is fetched, and the scene gathered again once it is. */
  awaitDefinition(name: string): void {
    if (this.awaiting.has(name) || typeof customElements === 'undefined' || customElements.get(name)) return;
    this.awaiting.add(name);
    if (this.awaiting.size === 1) this.fetch(defineChildren(), `<${name}>`);
    customElements.whenDefined(name).then(() => {
      this.awaiting.delete(name);
      this.invalidate();
    }, () => {});
  }

  /** Frames wait for `loading`; if it fails, one warning naming `what`, and the scene without the children. */
  private fetch(loading: Promise<void>, what: string): void {
    this.fetching++;
    loading.catch((e: unknown) => {
      warn(loadFailed(what, e, 'the scene is drawn without its children'));
    }).finally(() => {
      this.fetching--;
      this.invalidate();
    });
  }

  private readonly invalidate = (): void => {
    this.parts = null;
    this.host.partsChanged();
  };

  private readonly onChildChange = (e: Event): void => {
    if ((e.target as Element).parentElement !== this.element) return;
    this.invalidate();
  };
}
