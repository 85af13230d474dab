// Consumer test (scripts/check-package.mjs): the Vue GlobalComponents entries as Volar reads them.
import 'glass-plane-scene/vue';
import type { GlobalComponents } from 'vue';

type Props<T extends keyof GlobalComponents> = InstanceType<GlobalComponents[T]>['$props'];

export const scene: Props<'glass-plane-scene'> = {
  fresnel: 'classic', controls: true, 'camera-position': '0 1 4', samples: '4', onCameraChange: (e) => console.log(e.detail.rotation),
};
export const object: Props<'glass-object'> = { shape: 'gaussian', normalizeModel: true, onLoad: (e) => console.log(e.detail.warnings) };
export const light: Props<'glass-light'> = { ambient: '0.1 0.1 0.1', specular: '2 2 2' };
// @ts-expect-error renderer is auto, webgl or software
export const wrong: Props<'glass-plane-scene'> = { renderer: 'gpu' };
