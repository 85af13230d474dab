// Watches the scene element's light-DOM children and gathers their parts of the scene:
// a MutationObserver for children added, removed or reordered, the children's own change
// notices for their attributes and loads, and whenDefined for children upgraded later. The
// children's own elements (children/child-elements.ts) and what gathers their parts
// (children/gather-parts.ts: children defined by another copy of the package need it too) are
// lazy parts (element/parts.ts), which read hasUndefinedChild() and hasChild(). The image an `environment` URL names is a part of
// the scene too (element/environment-files.ts, its own lazy part, ENVIRONMENT_FILE), handed over here when it is in.
import type { ChildParts } from './compose-scene';
import { CHILD_CHANGE, LIGHT_TAG, OBJECT_TAG } from './children/tags';
import type { GlassLight } from './children/glass-light';
import type { GlassObject } from './children/glass-object';
import type { GatherHost } from './children/gather-parts';
import type { Controller } from './controller';
import type { EnvironmentFiles } from './environment-files';

const NO_PARTS: ChildParts = { objects: null, lights: null };

const isOurs = (name: string): boolean => name === OBJECT_TAG || name === LIGHT_TAG;

/** What SceneSource needs of the scene element. */
export interface SceneSourceHost {
  /** The scene element: its direct children are the parts. */
  readonly element: HTMLElement;
  /** A child was added, removed, reordered, changed, upgraded, or its model arrived; or the environment's image. */
  partsChanged(): void;
  /** The `environment` attribute: a keyword or a URL. */
  environment(): string;
}

/** A URL, not one of the environment's keywords. */
export const isEnvironmentUrl = (environment: string): boolean => environment !== 'neutral' && environment !== 'none';

export class SceneSource implements Controller, GatherHost {
  private observer: MutationObserver | null = null;
  private parts: ChildParts | null = null;
  /** @internal GatherHost */
  warnedLights = false;
  private readonly awaiting = new Set<string>();
  /** children/gather-parts.ts once it is in. */
  private gatherer: typeof import('./children/gather-parts') | null = null;
  /** element/environment-files.ts once it is in. */
  private files: EnvironmentFiles | null = null;
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
    this.files?.release();
  }

  /** True while a direct <glass-object> or <glass-light> child is fetching or parsing its file. */
  get loading(): boolean {
    for (const child of this.element.children) {
      const name = child.localName;
      if (isOurs(name) && (child as GlassObject | GlassLight).loading === true) return true;
    }
    return this.files?.loading ?? false;
  }

  /**
   * The children's objects and lights (null: none of that kind, use the default), cached; and the environment's image when the
   * attribute names one, asked for here (a scene is built once per change).
   */
  current(): ChildParts {
    const parts = (this.parts ??= this.gather()), src = this.host.environment();
    if (!isEnvironmentUrl(src)) {
      this.files?.release();
      return parts;
    }
    const environment = this.files?.partFor(src) ?? null;
    return environment ? { ...parts, environment } : parts;
  }

  /** The environment's image code is in: the scene is built again, asking for the image. */
  filesArrived(chunk: typeof import('./environment-files')): void {
    this.files = new chunk.EnvironmentFiles({ element: this.element, changed: this.invalidate });
    this.invalidate();
  }

  /** A direct child is a <glass-object> or <glass-light> (defined or not). */
  hasChild(): boolean {
    const children = this.element.children;
    for (let i = 0; i < children.length; i++) if (isOurs(children[i].localName)) return true;
    return false;
  }

  /** A direct child is a <glass-object> or <glass-light> whose element is not defined yet. */
  hasUndefinedChild(): boolean {
    if (typeof customElements === 'undefined') return false;
    const children = this.element.children;
    for (let i = 0; i < children.length; i++) {
      const name = children[i].localName;
      if (isOurs(name) && !customElements.get(name)) return true;
    }
    return false;
  }

  /** What gathers the children's parts is in: they are gathered again. */
  gathererArrived(gatherer: typeof import('./children/gather-parts')): void {
    this.gatherer = gatherer;
    this.invalidate();
  }

  /** The children's parts, by the gatherer; none before it is in. */
  private gather(): ChildParts {
    return this.gatherer ? this.gatherer.gatherParts(this) : NO_PARTS;
  }

  /** @internal GatherHost: `name` is not defined yet; the scene is gathered again once it is (by whichever copy defines it). */
  awaitDefinition(name: string): void {
    if (this.awaiting.has(name) || typeof customElements === 'undefined' || customElements.get(name)) return;
    this.awaiting.add(name);
    customElements.whenDefined(name).then(() => {
      this.awaiting.delete(name);
      this.invalidate();
    }, () => {});
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
