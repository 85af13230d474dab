// Making an environment ready (src/frame/environment-light.ts, docs/pbr.md#prefiltered-maps): at once, or a row at a time in
// tasks of their own (a page's main thread) — the same maps and table either way, made once and shared by whoever asks.
import { describe, expect, it, vi } from 'vitest';
import { dfgLookup, dfgTable } from '../../src/math/dfg';
import { prefilteredAt } from '../../src/math/environment-maps';
import { makeEnvironmentMaps } from '../../src/math/prefilter';
import { studioRadiance } from '../../src/math/studio';
import type { Environment } from '../../src/scene/scene';

const STUDIO: Environment = { kind: 'studio', intensity: 1 };

describe('prepareEnvironmentSliced', () => {
  it('makes the same maps and table as at once, in many tasks, once for two askers; then answers with what it kept', async () => {
    vi.resetModules();
    const { prepareEnvironmentSliced, prepareEnvironment } = await import('../../src/frame/environment-light');
    const { preparedFor } = await import('../../src/frame/environment-cache');
    expect(preparedFor(STUDIO)).toBeNull();
    let ticks = 0;
    const timer = setInterval(() => { ticks++; }, 0);
    const [a, b] = await Promise.all([prepareEnvironmentSliced(STUDIO, 2), prepareEnvironmentSliced({ kind: 'studio', intensity: 5 }, 2)]);
    clearInterval(timer);
    expect(a).toBe(b);
    // The timer ran between slices: the making gave the thread back (at once it would not have run at all).
    expect(ticks).toBeGreaterThan(10);
    expect(preparedFor(STUDIO)).toBe(a);
    expect(await prepareEnvironmentSliced(STUDIO)).toBe(a);
    expect(prepareEnvironment(STUDIO)).toBe(a);
    const once = makeEnvironmentMaps((o, x, y, z) => { o[0] = o[1] = o[2] = studioRadiance(x, y, z); });
    expect(a.maps.gamma).toBe(once.gamma);
    a.maps.levels.forEach((level, k) => expect(Buffer.from(level.rgb.buffer).equals(Buffer.from(once.levels[k].rgb.buffer)), `level ${k}`).toBe(true));
    expect(Buffer.from(a.dfg.buffer).equals(Buffer.from(dfgTable().buffer))).toBe(true);
    // Its split sum is addEnvironment's on these maps: a white metal of roughness 1 straight up, the table's A + B times the map.
    // (F0 = 1, no diffuse; at roughness 1 the dominant direction is n itself.)
    const out = new Float64Array(3), ab = new Float64Array(2), p = new Float64Array(3);
    a.add(out, 2, [1, 1, 1], 1, 1, [0, 1, 0], [0, 1, 0]);
    dfgLookup(ab, a.dfg, 1, 1);
    prefilteredAt(p, a.maps, 0, 1, 0, 1);
    expect(out[0]).toBeCloseTo(2 * (ab[0] + ab[1]) * p[0], 12);
  }, 60_000);
});
