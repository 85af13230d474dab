// The scene value (docs/scene-model.md#one-scene-value) the renderers draw: built from the attributes that shape it and the
// children's parts when one of them changes, and kept until then. The trackball's turn is not in
// it: the turn travels in each frame's state (FrameState.turn), so a turn or a camera move builds
// nothing and the frame loop allocates no scene while things move. The page's `scene` is the
// value with the turn applied, built when read. What applies a turn and finds the centre it turns
// about (scene/group-rotation.ts) is a lazy part (element/parts.ts, GROUP_ROTATION), fetched when
// a turn is first set (or brought by the controls' chunk): frames wait for it, and until it is
// in, `scene` is the value unturned.
import type { ReadonlyQuat } from 'gl-matrix';
import { isIdentity, type SceneTurn } from '../scene/turn';
import { deepFreeze, materialImages, type Scene } from '../scene/scene';
import { composeScene, SCENE_ATTRIBUTES, type ChildParts, type SceneInputs } from './compose-scene';
import type { SceneAttributes } from './attributes';

/** The group rotation's chunk: what turns the scene value and finds the objects' centre. */
export type GroupRotation = typeof import('../scene/group-rotation');

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
  /** `center` is this value's (false after a build until the group rotation is in). */
  private centered = false;
  private value: Scene | null = null;
  /** The value names an image texture (found when it is built). */
  private images = false;
  private turnedValue: Scene | null = null;
  /** What applies a turn, once in. */
  private rotation: GroupRotation | null = null;

  constructor(private readonly host: SceneValueHost) {
    this.turn = { objects: host.objectRotation, light: host.lightRotation, center: this.center };
  }

  /** What the renderers draw, without the turn: the same object until the content changes. */
  get current(): Scene {
    if (!this.value) {
      this.value = deepFreeze(composeScene(this.host.inputs(), this.host.parts()));
      this.images = this.value.objects.some((o) => materialImages(o.material).length > 0);
      this.centered = false;
      this.builds++;
    }
    const code = this.rotation;
    if (!this.centered && code) {
      code.boundsCenter(this.value.objects, this.center);
      this.centered = true;
    }
    return this.value;
  }

  /**
   * The page's value: `current` with the trackball's turn applied (the same object while neither
   * changes); `current` while no turn is set, or before the group rotation's chunk is in.
   */
  get turned(): Scene {
    const code = this.rotation;
    if (!code) return this.current;
    return (this.turnedValue ??= deepFreeze(code.rotateScene(this.current, this.host.objectRotation, this.host.lightRotation)));
  }

  /** The value last built names an image texture. */
  namesImages(): boolean {
    return this.value !== null && this.images;
  }

  /** A turn is set (the objects' or the light's rotation is not the identity). */
  turnSet(): boolean {
    return !isIdentity(this.host.objectRotation) || !isIdentity(this.host.lightRotation);
  }

  /** The group rotation is in (its own chunk, or the controls'): the next read applies the turn. */
  rotationArrived(code: GroupRotation): void {
    this.rotation = code;
    this.centered = false;
    this.turnedValue = null;
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
