// The float64 reference of the default scene in one bench view (docs/knobs.md#measuring-accuracy), cached on disk in
// bench/.cache by everything that defines it — size, time, view, colour space, samples and a
// digest of the reference's own sources — since at 64 spp it takes longer than the frames it
// judges. Shared by bench.spec.ts (WebGL rows) and software.spec.ts (software rows).
import { existsSync, mkdirSync, readdirSync, readFileSync, writeFileSync } from 'node:fs';
import { createHash } from 'node:crypto';
import { renderReference, type ReferenceImage } from '../src/reference';
import { DEFAULT_CUBE_DISTANCE } from '../src/element/attributes';
import type { ColorSpace } from '../src/frame/types';
import type { BenchView } from './views';

const CACHE = new URL('./.cache/', import.meta.url);

export interface ReferenceRequest {
  width: number;
  height: number;
  time: number;
  view: BenchView;
  /** Each row is scored against the reference in its own colour space (docs/colour.md#srgb). */
  colorSpace: ColorSpace;
  samplesPerAxis: number;
}

export function cachedReference(r: ReferenceRequest): ReferenceImage {
  // Written out, not defaultFrameState(): its JSON is the file's key, and the fields the factory
  // adds (projection, target, roughness, ...) would change every key and drop the cached files.
  const state = {
    width: r.width, height: r.height, time: r.time, spin: 0.8, cubeDistance: DEFAULT_CUBE_DISTANCE, transparency: 0.5,
    ior: 1.5, fresnel: 'exact' as const, fov: 60, cameraPosition: r.view.cameraPosition, yaw: r.view.yaw, pitch: r.view.pitch,
    colorSpace: r.colorSpace, view: 'final' as const,
  };
  const sources = ['../src/reference/', '../src/scene/', '../src/math/'].map((d) => new URL(d, import.meta.url));
  // The state (colour space included) is the key: a none and an srgb reference never share a file.
  const key = createHash('sha256').update(JSON.stringify({ state, spp: r.samplesPerAxis, v: sourcesVersion(sources) })).digest('hex').slice(0, 16);
  return cachedImage(`reference-${key}`, () => renderReference(state, { samplesPerAxis: r.samplesPerAxis })).ref;
}

/**
 * The reference image `compute` makes, kept in bench/.cache/`name`.json (`name` carries the key of everything that defines it):
 * read back when it is there, else computed, timed and written. `ms` is the time it took to make, now or when the file was
 * written (null for a file written before the time was kept); `cached` says which.
 */
export function cachedImage(name: string, compute: () => ReferenceImage): { ref: ReferenceImage; ms: number | null; cached: boolean } {
  const file = new URL(`${name}.json`, CACHE);
  if (existsSync(file)) {
    const j = JSON.parse(readFileSync(file, 'utf8'));
    const ref = { ...j, rgba: new Uint8ClampedArray(Buffer.from(j.rgba, 'base64')), rgb: new Float64Array(new Uint8Array(Buffer.from(j.rgb, 'base64')).buffer), regions: new Uint8Array(Buffer.from(j.regions, 'base64')) };
    return { ref, ms: typeof j.ms === 'number' ? j.ms : null, cached: true };
  }
  const t0 = performance.now();
  const ref = compute();
  const ms = performance.now() - t0;
  mkdirSync(CACHE, { recursive: true });
  writeFileSync(file, JSON.stringify({
    ...ref, rgba: Buffer.from(ref.rgba).toString('base64'), rgb: Buffer.from(new Uint8Array(ref.rgb.buffer)).toString('base64'),
    regions: Buffer.from(ref.regions).toString('base64'), keys: undefined, codes: undefined, ms,
  }));
  return { ref, ms, cached: false };
}

/** A digest of the reference's own sources, so a change to them invalidates the cache. */
export function sourcesVersion(dirs: URL[]): string {
  const h = createHash('sha256');
  for (const d of dirs) {
    for (const f of readdirSync(d).sort()) {
      if (f.endsWith('.ts')) h.update(readFileSync(new URL(f, d)));
    }
  }
  return h.digest('hex').slice(0, 12);
}
