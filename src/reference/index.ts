// The float64 CPU reference renderer: the image the GPU path approximates, and how far off it is.
export { renderReference, renderScene, type ReferenceImage, type ReferenceOptions } from './reference-renderer';
export { compareImages, REGION_NAMES, type CompareOptions, type ImageComparison, type PerRegion, type RegionName } from './metrics';
export {
  REGION_BACKGROUND, REGION_CUBE, REGION_EDGE, REGION_GLASS, REGION_SPHERE, glassReflectsCube, glassReflectsObject,
  regionOfKey, type Region,
} from './regions';
export type { ReferenceState, ViewState } from './reference-state';
export type { DecodedImage, SceneImages } from '../scene/decoded-image';
export { SurfaceCodes } from './surface-codes';
export type { TextureFilter } from './sample-tracer';
