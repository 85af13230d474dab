// Debug check (checks mode only): every value about to become a uniform is finite.
import type { FrameSetup, ObjectName } from './frame-setup';
import type { FrameState } from './types';

const OBJECTS: readonly ObjectName[] = ['cube', 'sphere', 'glass'];

function allFinite(xs: ArrayLike<number>): boolean {
  for (let i = 0; i < xs.length; i++) if (!Number.isFinite(xs[i])) return false;
  return true;
}

/** The name of the first non-finite uniform, or null when all are finite. */
export function findNonFinite(setup: FrameSetup, state: FrameState): string | null {
  for (const view of ['main', 'mirrored'] as const) {
    for (const o of OBJECTS) {
      const m = setup[view][o];
      if (!allFinite(m.modelViewProjection)) return `uModelViewProjection (${view} ${o})`;
      if (!allFinite(m.modelRelative)) return `uModelRelative (${view} ${o})`;
      if (!allFinite(m.normal)) return `uNormalMatrix (${view} ${o})`;
    }
  }
  if (!allFinite(setup.reflectionViewProjection)) return 'uReflectionViewProjection';
  if (!allFinite(setup.clipPlane)) return 'uClipPlane';
  if (!Number.isFinite(state.transparency)) return 'uTransparency';
  if (!Number.isFinite(state.ior)) return 'uIor';
  return null;
}
