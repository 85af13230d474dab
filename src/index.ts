// Public entry: defines <glass-plane-scene> and exports its class and types.
import { GlassPlaneScene } from './element/glass-plane-scene';

export { GlassPlaneScene };
export { ATTRIBUTES, DEBUG_VIEWS, type DebugView, type SceneAttributes } from './element/attributes';
export type { FresnelModel } from './math/fresnel';
export type {
  CameraChangeDetail, CapturePass, ErrorType, FrameReport, GlassPlaneSceneErrorDetail, GlassPlaneSceneEventMap,
  PassName, RenderStats,
} from './element/types';

export const TAG_NAME = 'glass-plane-scene';

if (typeof customElements !== 'undefined' && !customElements.get(TAG_NAME)) {
  customElements.define(TAG_NAME, GlassPlaneScene);
}

declare global {
  interface HTMLElementTagNameMap {
    'glass-plane-scene': GlassPlaneScene;
  }
}
