// The element's lazy parts (frame/lazy-parts.ts): what only some pages need, each declared once.
// The element asks for them, with its renderer's (render/parts.ts), once per frame.
import type { LazyPartSpec } from '../frame/lazy-parts';
import type { SceneAttributes } from './attributes';
import type { CameraRig } from './camera-rig';
import type { SceneSource } from './scene-source';
import type { SceneValue } from './scene-value';
import { isEnvironmentUrl } from './scene-source';
import { hasPbrMaterial } from '../scene/scene';

/** What the element's parts read and are handed to: its attributes and controllers. */
export interface ElementPartsHost {
  readonly values: Readonly<SceneAttributes>;
  readonly rig: CameraRig;
  readonly scenes: SceneValue;
  readonly source: SceneSource;
  /** The scene drawn this frame names an image texture (checked once per scene value). */
  namesImages(): boolean;
  /** The image textures' code is in. */
  imagesArrived(chunk: typeof import('./texture-images')): void;
  /** The controls' chunk carried the group rotation: it is in without a fetch of its own. */
  provideRotation(code: typeof import('../scene/group-rotation')): void;
}

type Part<T> = LazyPartSpec<ElementPartsHost, T>;

/** The flyby's keys and mouse, orbit and trackball pointers, the write-back (with the group rotation). */
export const CONTROLS: Part<typeof import('./controls/controls')> = {
  name: (h) => `controls="${h.values.controls}"`, chunk: 'controls', load: () => import('./controls/controls'),
  needed: (h) => h.values.controls !== null, holds: true, instead: 'the scene does not respond to input',
  arrived: (h, chunk) => {
    h.provideRotation(chunk.groupRotation);
    h.rig.controlsArrived(chunk);
  },
};

/** What turns the scene value and finds the centre a turn is about. */
export const GROUP_ROTATION: Part<typeof import('../scene/group-rotation')> = {
  name: "the trackball's turn", chunk: 'group-rotation', load: () => import('../scene/group-rotation'),
  needed: (h) => h.scenes.turnSet(), holds: true, instead: 'the objects turn about the origin, and `scene` leaves the turn out',
  arrived: (h, code) => h.scenes.rotationArrived(code),
};

/** camera-src: the course camera file's reader. Frames are drawn from the camera attributes meanwhile. */
export const CAMERA_SOURCE: Part<typeof import('./camera-source')> = {
  name: 'camera-src', chunk: 'camera-extras', load: () => import('./camera-source'),
  needed: (h) => h.values.cameraSrc !== null, holds: false, instead: 'the camera attributes stay the view',
  arrived: (h, chunk) => h.rig.sourceArrived(chunk),
};

/** What gathers the children's parts (children defined by another copy of the package need it too). */
export const GATHER_PARTS: Part<typeof import('./children/gather-parts')> = {
  name: "the children's parts", chunk: 'scene-extras', load: () => import('./children/gather-parts'),
  needed: (h) => h.source.hasChild(), holds: true, instead: 'the scene is drawn without its children',
  arrived: (h, gatherer) => h.source.gathererArrived(gatherer),
};

/** <glass-object> and <glass-light>, defined when the first is found undefined. */
export const CHILD_ELEMENTS: Part<typeof import('./children/child-elements')> = {
  name: '<glass-object> and <glass-light>', chunk: 'child-elements', load: () => import('./children/child-elements'),
  needed: (h) => h.source.hasUndefinedChild(), holds: true, instead: 'the scene is drawn without its children',
  arrived: (_h, chunk) => chunk.defineChildren(),
};

/** Image textures: fetched and decoded once per URL. Objects are textured procedurally meanwhile. */
export const TEXTURE_IMAGES: Part<typeof import('./texture-images')> = {
  name: 'image textures', chunk: 'scene-extras', load: () => import('./texture-images'),
  needed: (h) => h.namesImages(), holds: false, instead: 'using the procedural texture',
  arrived: (h, chunk) => h.imagesArrived(chunk),
};

/** `environment="url"`: the image's reader and the making of its maps. Until it is in, glTF materials see the lights alone. */
export const ENVIRONMENT_FILE: Part<typeof import('./environment-files')> = {
  name: 'environment', chunk: 'environment-files', load: () => import('./environment-files'),
  needed: (h) => isEnvironmentUrl(h.values.environment) && hasPbrMaterial(h.scenes.current), holds: false,
  instead: 'glTF materials are lit by the scene\'s lights alone',
  arrived: (h, chunk) => h.source.filesArrived(chunk),
};

/** The message part's texts; fetched by Failure when something fails (never by a frame). */
export const FAILURE_MESSAGES: Part<typeof import('./failure-messages')> = {
  name: 'the failure messages', chunk: 'diagnostics', load: () => import('./failure-messages'),
  needed: () => false, holds: false, instead: "the message part shows the error's own text",
};

export const ELEMENT_PARTS: readonly Part<unknown>[] = [
  CONTROLS, GROUP_ROTATION, CAMERA_SOURCE, GATHER_PARTS, CHILD_ELEMENTS, TEXTURE_IMAGES, ENVIRONMENT_FILE, FAILURE_MESSAGES,
];
