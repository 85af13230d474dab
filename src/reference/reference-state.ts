// What the reference renderer reads from a frame: the image-defining part of the GPU's FrameState.
import type { FrameState } from '../frame/types';

/**
 * The view of a scene: canvas size, clock, glass optics, camera and which view to draw. Quality
 * knobs (reflection scale, MSAA, shading, tessellation) are the GPU's approximations; the
 * reference has none, so any FrameState is accepted as it is.
 */
export type ViewState = Pick<
  FrameState,
  'width' | 'height' | 'time' | 'transparency' | 'ior' | 'fresnel' | 'fov' | 'cameraPosition' | 'yaw' | 'pitch' | 'view'
  | 'projection' | 'target' | 'courseCamera' | 'colorSpace' | 'roughness' | 'toneMapping' | 'exposure'
>;

/**
 * The largest value a sample's colour is held to (docs/pbr.md#tone-mapping): 1 as the GPU's 8-bit targets clamp, or none
 * when the frame is tone mapped (srgb, a view that is encoded, a curve other than `none` or an
 * exposure other than 1) and keeps its light until the end. The reference's own reading of the rule
 * the renderers share (frame/linear-light.ts toneMapped).
 */
export function colourCeiling(view: Pick<ViewState, 'colorSpace' | 'view' | 'toneMapping' | 'exposure'>): number {
  const encoded = view.colorSpace === 'srgb' && view.view !== 'fresnel';
  return encoded && ((view.toneMapping ?? 'none') !== 'none' || (view.exposure ?? 1) !== 1) ? Infinity : 1;
}

/** A view of the default scene (docs/default-scene.md): the view plus the cube's distance and spin. */
export type ReferenceState = ViewState & Pick<FrameState, 'spin' | 'cubeDistance'>;
