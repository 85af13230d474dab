// The children's parts of the scene, gathered in document order: each <glass-object>'s objects
// (with the material of the first lighting file that has loaded, docs/course-files.md#lighting-file) and up to four
// <glass-light>s. A chunk of its own, which SceneSource fetches when it first finds a child of
// ours: a scene without children never loads it, and children another copy of the package
// defined are gathered too.
import { MAX_LIGHTS, type Light, type SceneObject } from '../../scene/scene';
import type { ChildParts } from '../compose-scene';
import { warn } from '../warnings';
import type { GlassLight } from './glass-light';
import type { GlassObject } from './glass-object';
import type { MtlValues } from './object-material';
import { LIGHT_TAG, OBJECT_TAG } from './tags';

/** What gatherParts needs of the scene's SceneSource. */
export interface GatherHost {
  /** The scene element: its direct children are the parts. */
  readonly element: HTMLElement;
  /** More than four lights were warned about (once per scene). */
  warnedLights: boolean;
  /** A child of ours not upgraded yet: the scene is gathered again once it is. */
  awaitDefinition(name: string): void;
}

export function gatherParts(host: GatherHost): ChildParts {
  let objects: SceneObject[] | null = null;
  let lights: Light[] | null = null;
  let extra = 0;
  const children = host.element.children;
  // The material of the first lighting file in document order that has loaded (docs/course-files.md#lighting-file).
  let fileMaterial: MtlValues | null = null;
  for (const child of children) {
    if (child.localName !== LIGHT_TAG || typeof (child as Partial<GlassLight>).toMaterial !== 'function') continue;
    fileMaterial = safely(() => (child as GlassLight).toMaterial(), null);
    if (fileMaterial) break;
  }
  for (const child of children) {
    const name = child.localName;
    if (name !== OBJECT_TAG && name !== LIGHT_TAG) continue;
    // Duck-typed, not instanceof: another copy of this package may have defined the tags.
    const object = child as Partial<GlassObject>, light = child as Partial<GlassLight>;
    if (typeof object.toSceneObjects !== 'function' && typeof light.toLight !== 'function') {
      host.awaitDefinition(name); // not upgraded yet: counts once it is
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
  if (extra > 0 && !host.warnedLights) {
    host.warnedLights = true;
    warn(`at most ${MAX_LIGHTS} <glass-light> children are used; ${extra} more ignored`);
  }
  return { objects, lights };
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
