// The scene value from the scene element's attributes and its children's parts (docs/scene-model.md#children):
// children's objects replace the default cube and sphere, children's lights the default light,
// and with neither it is the default scene exactly (docs/default-scene.md). Pure: no DOM.
import { defaultScene } from '../scene/default-scene';
import { hasPbrMaterial, type Glass, type Light, type Scene, type SceneObject } from '../scene/scene';
import type { SceneAttributes } from './attributes';
import type { EnvironmentImage } from '../math/environment-image';

/** The attributes the scene value is built from: a change of any other builds nothing. */
export const SCENE_ATTRIBUTES = [
  'cubeDistance', 'glassCenter', 'glassNormal', 'glassSize', 'background', 'spin', 'environment', 'environmentIntensity',
] as const;

/** `spin` is the cube's spin as drawn (0 under reduced motion unless `spin` is set). */
export type SceneInputs = Pick<SceneAttributes, (typeof SCENE_ATTRIBUTES)[number]>;

/**
 * The environment an `environment="url"` attribute gives (element/environment-files.ts, docs/pbr.md#an-image): its image once in,
 * or `neutral` (the studio) after it failed.
 */
export type EnvironmentPart = { url: string; image: EnvironmentImage } | 'neutral';

/** Children's contributions; null where the element has no such child (the default is used). */
export interface ChildParts {
  objects: readonly SceneObject[] | null;
  lights: readonly Light[] | null;
  /** The environment a URL gives: absent or null while there is none (a keyword, or the image on its way: the lights alone). */
  environment?: EnvironmentPart | null;
}

export function composeScene(v: SceneInputs, parts: ChildParts): Scene {
  const base = defaultScene(v.cubeDistance, v.spin);
  const [w, h] = v.glassSize;
  const glass: Glass | null = w > 0 && h > 0 ? { center: [...v.glassCenter], normal: [...v.glassNormal], size: [w, h] } : null;
  const scene: Scene = {
    glass,
    objects: parts.objects ?? base.objects,
    lights: parts.lights ?? base.lights,
    background: [...v.background],
  };
  // The environment lights glTF materials alone (docs/pbr.md#the-environment): a scene without one is left as it was.
  const env = parts.environment, intensity = v.environmentIntensity;
  if (!hasPbrMaterial(scene)) return scene;
  if (env && env !== 'neutral') scene.environment = { kind: 'image', intensity, url: env.url, image: env.image };
  else if (v.environment === 'neutral' || env === 'neutral') scene.environment = { kind: 'studio', intensity };
  return scene;
}

/**
 * True when something in the scene turns by the clock (an object with a spin): only then do
 * frames come without a change (docs/knobs.md#idle-elements). `spin` turns the default cube alone, so a scene of
 * children, which has no such cube, is still once its models are drawn.
 */
export function sceneSpins(scene: Scene): boolean {
  for (const o of scene.objects) if (o.transform.spin !== 0) return true;
  return false;
}
