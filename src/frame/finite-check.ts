// Debug check (checks mode only): every value about to become a uniform is finite.
import type { DrawMatrices, FrameSetup } from './frame-setup';
import type { FrameState } from './types';

function allFinite(xs: ArrayLike<number>): boolean {
  for (let i = 0; i < xs.length; i++) if (!Number.isFinite(xs[i])) return false;
  return true;
}

function badMatrix(m: DrawMatrices, what: string): string | null {
  if (!allFinite(m.modelViewProjection)) return `uModelViewProjection (${what})`;
  if (!allFinite(m.modelRelative)) return `uModelRelative (${what})`;
  if (!allFinite(m.normal)) return `uNormalMatrix (${what})`;
  return null;
}

/** The name of the first non-finite uniform, or null when all are finite. */
export function findNonFinite(setup: FrameSetup, state: FrameState, objectCount: number): string | null {
  for (let i = 0; i < objectCount; i++) {
    const o = setup.objects[i];
    const bad = badMatrix(o.main, `main object ${i}`) ?? badMatrix(o.mirrored, `mirrored object ${i}`);
    if (bad) return bad;
  }
  const glass = badMatrix(setup.glassMain, 'main glass') ?? badMatrix(setup.glassMirrored, 'mirrored glass');
  if (glass) return glass;
  if (!allFinite(setup.lightsMain.vectors) || !allFinite(setup.lightsMirrored.vectors)) return 'uLightVector';
  if (!allFinite(setup.reflectionViewProjection)) return 'uReflectionViewProjection';
  if (!allFinite(setup.clipPlane)) return 'uClipPlane';
  if (!allFinite(setup.viewVectorMain) || !allFinite(setup.viewVectorMirrored)) return 'uViewVector';
  if (!Number.isFinite(state.transparency)) return 'uTransparency';
  if (!Number.isFinite(state.ior)) return 'uIor';
  return null;
}
