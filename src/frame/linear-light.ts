// Whether a frame is drawn in linear light and encoded once at its end (docs/colour.md#srgb): with
// color-space srgb, for every view but `fresnel`, which shows F, a number, unencoded. Read by
// both renderers (the reference decides for itself: reference-renderer.ts).
import type { FrameState } from './types';

export const encodesAtEnd = (state: Pick<FrameState, 'colorSpace' | 'view'>): boolean =>
  state.colorSpace === 'srgb' && state.view !== 'fresnel';

/**
 * Whether a frame keeps light above 1 until its end and tone maps it there (docs/pbr.md#tone-mapping): encoded at the
 * end, with a tone mapping other than `none` or an exposure other than 1. Otherwise every target
 * clamps to [0, 1] as an 8-bit target does: today's frames exactly.
 */
export const toneMapped = (state: Pick<FrameState, 'colorSpace' | 'view' | 'toneMapping' | 'exposure'>): boolean =>
  encodesAtEnd(state) && ((state.toneMapping ?? 'none') !== 'none' || (state.exposure ?? 1) !== 1);
