// Public entry: defines <glass-plane-scene> and exports its class and types.
import { GlassPlaneScene } from './element/glass-plane-scene';
import { GlassObject, OBJECT_TAG } from './element/children/glass-object';
import { GlassLight, LIGHT_TAG } from './element/children/glass-light';

export { GlassPlaneScene, GlassObject, GlassLight };
export { OBJECT_ATTRIBUTES, type ObjectAttributes, type Shape } from './element/children/object-attributes';
export { LIGHT_ATTRIBUTES, type LightAttributes } from './element/children/light-attributes';
export type { Progress as ModelProgress } from './element/children/model-fetch';
export type { LoadErrorDetail } from './loaders/load-error';
export type { Scene, SceneObject, Light, Glass, Material, Geometry, Transform, Bounds, Mapping, TextureSource, Vec3 } from './scene/scene';
export { ATTRIBUTES, DEBUG_VIEWS, type DebugView, type SceneAttributes } from './element/attributes';
export type { FresnelModel } from './math/fresnel';
export type {
  CameraChangeDetail, CapturePass, ErrorType, FrameReport, GlassPlaneSceneErrorDetail, GlassPlaneSceneEventMap,
  PassName, RenderStats,
} from './element/types';

export const TAG_NAME = 'glass-plane-scene';

// Children first: already in the page, they upgrade (and start loading) before their parent
// looks at them.
if (typeof customElements !== 'undefined') {
  if (!customElements.get(OBJECT_TAG)) customElements.define(OBJECT_TAG, GlassObject);
  if (!customElements.get(LIGHT_TAG)) customElements.define(LIGHT_TAG, GlassLight);
  if (!customElements.get(TAG_NAME)) customElements.define(TAG_NAME, GlassPlaneScene);
}

declare global {
  interface HTMLElementTagNameMap {
    'glass-plane-scene': GlassPlaneScene;
    'glass-object': GlassObject;
    'glass-light': GlassLight;
  }
}
