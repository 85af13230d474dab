// What the reference renderer reads from a frame: the scene-defining part of the GPU's FrameState.
import type { FrameState } from '../render/types';

/**
 * The fields of `FrameState` that define the image. Quality knobs (reflection scale, MSAA,
 * shading, tessellation) are the GPU's approximations; the reference has none, so any
 * FrameState is accepted as it is.
 */
export type ReferenceState = Pick<
  FrameState,
  'width' | 'height' | 'time' | 'spin' | 'cubeDistance' | 'transparency' | 'ior' | 'fresnel'
  | 'fov' | 'cameraPosition' | 'yaw' | 'pitch' | 'view'
>;
