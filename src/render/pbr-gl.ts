// glTF materials in WebGL (docs/pbr.md#the-scenes-lights) in a chunk of its own: the PBR variant's shader part,
// loaded the first time a frame's scene has a glTF material (the lazy part PBR_MATERIALS,
// render/parts.ts), so a scene without one never downloads it.
import pbr from '../../shaders/pbr.glsl?raw';

/** shaders/pbr.glsl: standard.frag's PBR variant takes it after lighting.glsl. */
export const PBR_SOURCE: string = pbr;
