// Is a frame's glass rough (docs/rough-glass.md#roughness-zero)? Roughness absent, 0 or not a number: polished, and every
// renderer draws today's glass exactly. Kept apart from rough-glass.ts, whose numbers only rough
// frames load.
import type { FrameState } from './types';

export function isRough(state: Pick<FrameState, 'roughness'>): boolean {
  return (state.roughness ?? 0) > 0;
}
