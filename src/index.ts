// Public entry: defines <glass-plane-scene> and exports its class and types.
import { GlassPlaneScene } from './element/glass-plane-scene';
import type { GlassObject } from './element/children/glass-object';
import type { GlassLight } from './element/children/glass-light';

export { GlassPlaneScene };
/**
 * <glass-object> and <glass-light> are defined when a scene first finds one among its children
 * (their code is a chunk of its own); defineChildren() loads and defines them now.
 */
export type { GlassObject, GlassLight };
export { defineChildren } from './element/children-loader';
export type { ObjectAttributes, Shape } from './element/children/object-attributes';
export type { LightAttributes } from './element/children/light-attributes';
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

// The children are defined by the first scene that finds one (element/children-loader.ts).
if (typeof customElements !== 'undefined' && !customElements.get(TAG_NAME)) customElements.define(TAG_NAME, GlassPlaneScene);

declare global {
  interface HTMLElementTagNameMap {
    'glass-plane-scene': GlassPlaneScene;
    'glass-object': GlassObject;
    'glass-light': GlassLight;
  }
}
