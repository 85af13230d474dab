// The CPU renderer's environment (docs/pbr.md#the-environment), made ready where it draws: in each worker, or on the main
// thread when there is none. The maps are made once there, a row at a time (frame/environment-light.ts, loaded only by a scene with a glTF
// material under an environment); a frame before they are in would be drawn without the environment, so the host waits.

import { preparedFor } from '../frame/environment-cache';
import { hasPbrMaterial, type Scene } from '../scene/scene';

/** Settles once `scene`'s environment is made ready here, at once when it needs none or has it; never rejects (drawn without). */
export function environmentReady(scene: Scene): Promise<void> | null {
  const env = scene.environment;
  if (!env || preparedFor(env) !== null || !hasPbrMaterial(scene)) return null;
  return import('../frame/environment-light').then((m) => m.prepareEnvironmentSliced(env), () => undefined).then(() => undefined, () => undefined);
}
