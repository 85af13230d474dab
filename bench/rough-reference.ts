// The rough glass bench's frames and float64 reference (bench/rough.spec.ts, bench/refine.spec.ts): the floor of
// bench/rough-scene.ts at a roughness and ior, and its reference cached in bench/.cache (reference-cache.ts cachedImage) by its
// state, its sampling and a digest of the reference's own sources. BENCH_SMOKE=1 makes both tiny.
import { createHash } from 'node:crypto';
import { renderScene, type ReferenceImage } from '../src/reference';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import type { FrameState } from '../src/frame/types';
import { roughFloorScene, ROUGH_FLOOR_VIEW } from './rough-scene';
import { cachedImage, sourcesVersion } from './reference-cache';

const SMOKE = process.env.BENCH_SMOKE === '1';
export const ROUGH_SIZE = SMOKE ? { width: 80, height: 45 } : { width: 320, height: 180 };
/** The reference: 4×4 strata per pixel, this many microfacet normals each (at 2×2 × 256 doubling moved the rows by ~1 dB). */
export const ROUGH_REF_SPP = SMOKE ? 1 : 4;
export const ROUGH_MICROFACETS = SMOKE ? 16 : 1024;

export function roughState(roughness: number, ior: number, extra: Partial<FrameState> = {}): FrameState {
  const v = ROUGH_FLOOR_VIEW;
  return defaultFrameState({
    width: ROUGH_SIZE.width, height: ROUGH_SIZE.height, spin: 0, cubeDistance: 0, ior, cameraPosition: v.cameraPosition, yaw: v.yaw, pitch: v.pitch,
    roughness, ...extra,
  });
}

/** The reference of a case, cached; `ms` the time it took to make (now or when cached), null if not kept. */
export function roughReference(roughness: number, ior: number, microfacets = ROUGH_MICROFACETS): { ref: ReferenceImage; ms: number | null; cached: boolean } {
  const s = roughState(roughness, ior);
  const sources = ['../src/reference/', '../src/scene/', '../src/math/'].map((d) => new URL(d, import.meta.url));
  const key = createHash('sha256').update(JSON.stringify({ s, spp: ROUGH_REF_SPP, microfacets, v: sourcesVersion(sources), scene: 'rough-floor' })).digest('hex').slice(0, 16);
  return cachedImage(`rough-${key}`, () => renderScene(roughFloorScene(), s, null, { samplesPerAxis: ROUGH_REF_SPP, microfacetSamples: microfacets }));
}
