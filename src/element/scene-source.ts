// Watches the scene element's light-DOM children and gathers their parts of the scene:
// a MutationObserver for children added, removed or reordered, the children's own change
// notices for their attributes and loads, and whenDefined for children upgraded later. The
// children's own chunk (children/child-elements.ts) is fetched when the first of them is found.
import { MAX_LIGHTS, type Light, type SceneObject } from '../scene/scene';
import type { ChildParts } from './compose-scene';
import { CHILD_CHANGE, LIGHT_TAG, OBJECT_TAG } from './children/tags';
import type { GlassLight } from './children/glass-light';
import type { GlassObject } from './children/glass-object';
import { defineChildren } from './children-loader';
import { warn } from './warnings';
import type { MtlValues } from './children/object-material';
import type { Controller } from './controller';

/** What SceneSource needs of the scene element. */
export interface SceneSourceHost {
  /** The scene element: its direct children are the parts. */
  readonly element: HTMLElement;
  /** A child was added, removed, reordered, changed, upgraded, or its model arrived. */
  partsChanged(): void;
}

export class SceneSource implements Controller {
  private observer: MutationObserver | null = null;
  private parts: ChildParts | null = null;
  private warnedLights = false;
  private readonly awaiting = new Set<string>();
  /** The children's chunk is on its way: frames wait for it (the scene is not drawn without them). */
  defining = false;
  private readonly element: HTMLElement;

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

  private gather(): ChildParts {
    let objects: SceneObject[] | null = null;
    let lights: Light[] | null = null;
    let extra = 0;
    // The material of the first lighting file in document order that has loaded (SPEC §11).
    let fileMaterial: MtlValues | null = null;
    for (const child of this.element.children) {
      if (child.localName !== LIGHT_TAG || typeof (child as Partial<GlassLight>).toMaterial !== 'function') continue;
      fileMaterial = safely(() => (child as GlassLight).toMaterial(), null);
      if (fileMaterial) break;
    }
    for (const child of this.element.children) {
      const name = child.localName;
      if (name !== OBJECT_TAG && name !== LIGHT_TAG) continue;
      // Duck-typed, not instanceof: another copy of this package may have defined the tags.
      const object = child as Partial<GlassObject>, light = child as Partial<GlassLight>;
      if (typeof object.toSceneObjects !== 'function' && typeof light.toLight !== 'function') {
        this.awaitDefinition(name); // not upgraded yet: counts once it is
        continue;
      }
      if (name === OBJECT_TAG) {
        (objects ??= []).push(...safely(() => object.toSceneObjects!(fileMaterial), []));
      } else if ((lights ??= []).length < MAX_LIGHTS) {
        const l = safely(() => light.toLight!(), null);
        if (l) lights.push(l);
      } else extra++;
    }
    // Lights whose file failed or still loads add none: with none left, the default light.
    if (lights && lights.length === 0) lights = null;
    if (extra > 0 && !this.warnedLights) {
      this.warnedLights = true;
      warn(`at most ${MAX_LIGHTS} <glass-light> children are used; ${extra} more ignored`);
    }
    return { objects, lights };
  }

  private awaitDefinition(name: string): void {
    if (this.awaiting.has(name) || typeof customElements === 'undefined' || customElements.get(name)) return;
    this.awaiting.add(name);
    if (!this.defining) {
      this.defining = true;
      defineChildren().catch((e: unknown) => {
        warn(`<${name}> could not load (${String(e).slice(0, 200)}); the scene is drawn without its children`);
      }).finally(() => {
        this.defining = false;
        this.invalidate();
      });
    }
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

/** A child's bug must not take the scene down: its part is left out. */
function safely<T>(f: () => T, fallback: T): T {
  try {
    return f();
  } catch (e) {
    warn(`a child could not describe its part of the scene: ${e instanceof Error ? e.message : String(e)}`);
    return fallback;
  }
}
