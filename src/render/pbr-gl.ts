// glTF materials and tone mapping in WebGL (docs/pbr.md#the-scenes-lights, #tone-mapping) in a chunk of its own: the PBR
// variant's shader part and the encode's tone-mapping part, loaded the first time a frame has a
// glTF material or is tone mapped (the lazy part PBR_MATERIALS, render/parts.ts), so a scene with
// neither never downloads it.
import pbr from '../../shaders/pbr.glsl?raw';
import toneMap from '../../shaders/tone-map.glsl?raw';

/** shaders/pbr.glsl: standard.frag's PBR variant takes it after lighting.glsl. */
export const PBR_SOURCE: string = pbr;

/** shaders/tone-map.glsl: encode.frag's TONE_* variants take it after their #define. */
export const TONE_MAP_SOURCE: string = toneMap;

export { PbrMapsGl } from './pbr-maps-gl';
