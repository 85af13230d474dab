// Whether a frame is drawn in linear light and encoded once at its end (docs/colour.md#srgb): with
// color-space srgb, for every view but `fresnel`, which shows F, a number, unencoded. Read by
// both renderers (the reference decides for itself: reference-renderer.ts).
import type { FrameState } from './types';

export const encodesAtEnd = (state: Pick<FrameState, 'colorSpace' | 'view'>): boolean =>
  state.colorSpace === 'srgb' && state.view !== 'fresnel';
