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
  | 'projection' | 'target' | 'courseCamera' | 'colorSpace' | 'roughness'
>;

/** A view of the default scene (docs/default-scene.md): the view plus the cube's distance and spin. */
export type ReferenceState = ViewState & Pick<FrameState, 'spin' | 'cubeDistance'>;
