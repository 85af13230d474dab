// The scene value (SPEC §9) the renderers draw: built from the attributes that shape it and the
// children's parts when one of them changes, and kept until then. The trackball's turn is not in
// it: the turn travels in each frame's state (FrameState.turn), so a turn or a camera move builds
// nothing and the frame loop allocates no scene while things move. The page's `scene` is the
// value with the turn applied, built when read.
import type { ReadonlyQuat } from 'gl-matrix';
import { boundsCenter, rotateScene, type SceneTurn } from '../scene/group-rotation';
import type { Scene } from '../scene/scene';
import { composeScene, SCENE_ATTRIBUTES, type ChildParts, type SceneInputs } from './compose-scene';
import type { SceneAttributes } from './attributes';

/** What SceneValue needs of the scene element. */
export interface SceneValueHost {
  /** The attributes that shape the scene, with the spin as drawn. */
  inputs(): SceneInputs;
  /** The children's objects and lights. */
  parts(): ChildParts;
  /** The trackball's rotations of the objects and of the first light (live: changed in place). */
  readonly objectRotation: ReadonlyQuat;
  readonly lightRotation: ReadonlyQuat;
}

const SHAPING: ReadonlySet<keyof SceneAttributes> = new Set(SCENE_ATTRIBUTES);

export class SceneValue {
  /** Values built so far (stats.sceneBuilds): one per change of content. */
  builds = 0;
  /** The turn for the frame state: the live rotations, about the centre of this value's objects. */
  readonly turn: SceneTurn;
  private readonly center = new Float64Array(3);
  private value: Scene | null = null;
  private turnedValue: Scene | null = null;

  constructor(private readonly host: SceneValueHost) {
    this.turn = { objects: host.objectRotation, light: host.lightRotation, center: this.center };
  }

  /** What the renderers draw, without the turn: the same object until the content changes. */
  get current(): Scene {
    if (!this.value) {
      this.value = composeScene(this.host.inputs(), this.host.parts());
      this.center.set(boundsCenter(this.value.objects));
      this.builds++;
    }
    return this.value;
  }

  /** The page's value: `current` with the trackball's turn applied (the same object while neither changes). */
  get turned(): Scene {
    return (this.turnedValue ??= rotateScene(this.current, this.host.objectRotation, this.host.lightRotation));
  }

  /** An attribute changed: the value is built again only if it shapes the scene. */
  attributeChanged(property: keyof SceneAttributes): void {
    if (SHAPING.has(property)) this.contentChanged();
  }

  /** A child, a model or the reduced-motion preference changed. */
  contentChanged(): void {
    this.value = this.turnedValue = null;
  }

  /** The trackball turned: only the page's value is stale. */
  turnChanged(): void {
    this.turnedValue = null;
  }
}
