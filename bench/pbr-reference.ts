// The PBR bench's float64 reference (bench/pbr.spec.ts), cached in bench/.cache (reference-cache.ts cachedImage) by the scene,
// the state, the sampling and a digest of the reference's own sources, with the time it took when it was made.
import { createHash } from 'node:crypto';
import { renderScene, type ReferenceImage } from '../src/reference';
import type { FrameState } from '../src/frame/types';
import { pbrScene, type PbrSceneName } from './pbr-scene';
import { cachedImage, sourcesVersion } from './reference-cache';

export interface CachedReference {
  ref: ReferenceImage;
  /** ms it took to make: measured now, or when the cached file was written (NaN if that file did not keep it). */
  ms: number;
  cached: boolean;
}

const SOURCES = ['../src/reference/', '../src/scene/', '../src/math/'].map((d) => new URL(d, import.meta.url));

export function pbrReference(name: PbrSceneName, s: FrameState, samplesPerAxis: number, environmentSamples: number): CachedReference {
  const key = createHash('sha256')
    .update(JSON.stringify({ name, s, samplesPerAxis, environmentSamples, v: sourcesVersion(SOURCES), scene: pbrScene(name) }))
    .digest('hex').slice(0, 16);
  const { ref, ms, cached } = cachedImage(`pbr-${key}`, () => renderScene(pbrScene(name), s, null, { samplesPerAxis, environmentSamples }));
  return { ref, ms: ms ?? NaN, cached };
}
