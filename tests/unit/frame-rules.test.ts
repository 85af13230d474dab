// The small rules of src/frame that both renderers read (which passes run and why not, the
// checks mode's first non-finite uniform, the rough gather's rings and distance codes, rough or
// polished, linear light encoded at the end), each value worked out by hand from the docs.
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { findNonFinite } from '../../src/frame/finite-check';
import type { FrameSetup } from '../../src/frame/frame-setup';
import type { ScreenRect } from '../../src/frame/glass-bounds';
import { encodesAtEnd } from '../../src/frame/linear-light';
import { glassSkipReason, passesFor, PASSES } from '../../src/frame/pass-reports';
import {
  distanceCode, ROUGH_FIRST_RING, ROUGH_GATHER, ROUGH_MAX_RINGS, ROUGH_REACH, ROUGHNESS_QUALITIES, roughRings,
} from '../../src/frame/rough-glass';
import { isRough } from '../../src/frame/roughness';
import { buildMesh, meshKey } from '../../src/frame/mesh-choice';
import { boxMesh } from '../../src/scene/geometry/box';
import { gaussianMesh } from '../../src/scene/geometry/gaussian';
import { reflectionGrid } from '../../src/frame/reflection-lod';
import { sphereScreenRadius } from '../../src/frame/sphere-screen';
import type { FrameState } from '../../src/frame/types';

describe('passesFor: the frozen pass reports a frame gives', () => {
  it('the final and passes views run all three passes', () => {
    expect(PASSES).toEqual(['reflection', 'scene', 'glass']);
    for (const view of ['final', 'passes'] as const) {
      expect(passesFor(view)).toEqual({ reflection: { ran: true }, scene: { ran: true }, glass: { ran: true } });
    }
  });

  it('each debug view names the passes it skips', () => {
    expect(passesFor('reflection')).toEqual({
      reflection: { ran: true },
      scene: { ran: false, reason: 'debug-view reflection' },
      glass: { ran: false, reason: 'debug-view reflection' },
    });
    expect(passesFor('scene')).toEqual({
      reflection: { ran: false, reason: 'debug-view scene' },
      scene: { ran: true },
      glass: { ran: false, reason: 'debug-view scene' },
    });
    expect(passesFor('fresnel')).toEqual({
      reflection: { ran: false, reason: 'debug-view fresnel (F needs no reflection)' },
      scene: { ran: true },
      glass: { ran: true },
    });
  });

  it('a skipped glass skips the reflection too, in the final view only, for the reason given', () => {
    // A reason of its own: the records are cached per reason, module-wide (a test elsewhere may
    // have asked for a real one first).
    expect(passesFor('final', 'a reason only this test gives')).toEqual({
      reflection: { ran: false, reason: 'a reason only this test gives' },
      scene: { ran: true },
      glass: { ran: false, reason: 'a reason only this test gives' },
    });
    // Another view keeps its own reports: its skips are the view's.
    expect(passesFor('scene', 'glass off screen')).toBe(passesFor('scene'));
    expect(passesFor('passes', 'no glass')).toBe(passesFor('passes'));
  });

  it('the reports are shared and frozen: a kept report never changes, and none is built per frame', () => {
    const a = passesFor('final', 'no glass');
    expect(passesFor('final', 'no glass')).toBe(a);
    expect(passesFor('final', 'glass too small')).not.toBe(a);
    expect(passesFor('final')).toBe(passesFor('final'));
    for (const r of [a, passesFor('final'), passesFor('reflection')]) {
      expect(Object.isFrozen(r)).toBe(true);
      for (const p of PASSES) expect(Object.isFrozen(r[p])).toBe(true);
    }
  });
});

describe('glassSkipReason', () => {
  const setup = (o: Partial<Pick<FrameSetup, 'hasGlass' | 'orthographic' | 'viewDot' | 'eyeDistance'>>) =>
    ({ hasGlass: true, orthographic: false, viewDot: -1, eyeDistance: 5, ...o }) as FrameSetup;
  const rect = (x0: number, y0: number, x1: number, y1: number, area = (x1 - x0) * (y1 - y0)): ScreenRect =>
    ({ x0, y0, x1, y1, area }) as ScreenRect;
  const onScreen = rect(10, 10, 100, 60);

  it('no glass skips both passes, optimized or not', () => {
    expect(glassSkipReason(setup({ hasGlass: false }), onScreen, true)).toBe('no glass');
    expect(glassSkipReason(setup({ hasGlass: false }), onScreen, false)).toBe('no glass');
  });

  it('glass on screen runs; with optimize off even glass off screen runs', () => {
    expect(glassSkipReason(setup({}), onScreen, true)).toBeUndefined();
    expect(glassSkipReason(setup({}), rect(5, 5, 5, 5), false)).toBeUndefined();
  });

  it('off screen: an empty rectangle in x or in y', () => {
    expect(glassSkipReason(setup({}), rect(50, 10, 50, 60, 0), true)).toBe('glass off screen');
    expect(glassSkipReason(setup({}), rect(60, 10, 50, 60, 0), true)).toBe('glass off screen');
    expect(glassSkipReason(setup({}), rect(10, 40, 100, 40, 0), true)).toBe('glass off screen');
    expect(glassSkipReason(setup({}), rect(10, 41, 100, 40, 0), true)).toBe('glass off screen');
  });

  it('too small: under half a pixel of area (0.5 px² itself is drawn)', () => {
    expect(glassSkipReason(setup({}), rect(10, 10, 10.7, 10.7, 0.49), true)).toBe('glass too small');
    expect(glassSkipReason(setup({}), rect(10, 10, 10.7, 10.7, 0.5), true)).toBeUndefined();
  });

  it('edge-on: a perspective eye within 1e-3 of the plane (either side), an orthographic view with |forward·n| < 1e-3', () => {
    const line = rect(10, 10, 100, 10.004, 0.36);
    const empty = rect(10, 10, 100, 10, 0);
    for (const eyeDistance of [0, 5e-4, -5e-4, 0.00099]) {
      expect(glassSkipReason(setup({ eyeDistance }), line, true)).toBe('glass edge-on');
      expect(glassSkipReason(setup({ eyeDistance }), empty, true)).toBe('glass edge-on');
    }
    // 1e-3 itself is not edge-on: a thin glass is too small, an empty one off screen.
    expect(glassSkipReason(setup({ eyeDistance: 1e-3 }), line, true)).toBe('glass too small');
    expect(glassSkipReason(setup({ eyeDistance: -1e-3 }), empty, true)).toBe('glass off screen');
    // Orthographic: the eye's distance is not the test, the view direction is.
    const ortho = (viewDot: number, eyeDistance = 0) => setup({ orthographic: true, viewDot, eyeDistance });
    expect(glassSkipReason(ortho(5e-4, 10), line, true)).toBe('glass edge-on');
    expect(glassSkipReason(ortho(-5e-4, 10), line, true)).toBe('glass edge-on');
    expect(glassSkipReason(ortho(-1e-3, 0), line, true)).toBe('glass too small');
    expect(glassSkipReason(ortho(0.5, 0), empty, true)).toBe('glass off screen');
    // Edge-on needs the glass to be (nearly) a line: a visible glass runs.
    expect(glassSkipReason(setup({ eyeDistance: 0 }), onScreen, true)).toBeUndefined();
  });
});

describe('findNonFinite (checks mode): the first uniform that is not finite', () => {
  const matrices = () => ({ modelViewProjection: new Float32Array(16), modelRelative: new Float32Array(16), normal: new Float32Array(9) });
  const make = () => ({
    objects: [{ main: matrices(), mirrored: matrices() }, { main: matrices(), mirrored: matrices() }],
    glassMain: matrices(), glassMirrored: matrices(),
    lightsMain: { vectors: new Float32Array(16) }, lightsMirrored: { vectors: new Float32Array(16) },
    reflectionViewProjection: new Float32Array(16), clipPlane: new Float32Array(4),
    viewVectorMain: new Float32Array(3), viewVectorMirrored: new Float32Array(3),
  });
  const state = { transparency: 0.5, ior: 1.5 } as FrameState;
  type Setup = ReturnType<typeof make>;
  const check = (s: Setup, st = state, count = 2) => findNonFinite(s as unknown as FrameSetup, st, count);

  it('all finite: null', () => {
    expect(check(make())).toBeNull();
  });

  it('names each uniform, and which object and pass it belongs to', () => {
    const cases: [(s: Setup) => void, string][] = [
      [(s) => (s.objects[0].main.modelViewProjection[15] = NaN), 'uModelViewProjection (main object 0)'],
      [(s) => (s.objects[1].main.modelRelative[3] = Infinity), 'uModelRelative (main object 1)'],
      [(s) => (s.objects[0].main.normal[8] = -Infinity), 'uNormalMatrix (main object 0)'],
      [(s) => (s.objects[1].mirrored.normal[0] = NaN), 'uNormalMatrix (mirrored object 1)'],
      [(s) => (s.glassMain.modelRelative[0] = NaN), 'uModelRelative (main glass)'],
      [(s) => (s.glassMirrored.modelViewProjection[5] = NaN), 'uModelViewProjection (mirrored glass)'],
      [(s) => (s.lightsMain.vectors[15] = NaN), 'uLightVector'],
      [(s) => (s.lightsMirrored.vectors[0] = NaN), 'uLightVector'],
      [(s) => (s.reflectionViewProjection[7] = NaN), 'uReflectionViewProjection'],
      [(s) => (s.clipPlane[3] = NaN), 'uClipPlane'],
      [(s) => (s.viewVectorMain[2] = NaN), 'uViewVector'],
      [(s) => (s.viewVectorMirrored[1] = NaN), 'uViewVector'],
    ];
    for (const [spoil, name] of cases) {
      const s = make();
      spoil(s);
      expect(check(s), name).toBe(name);
    }
    expect(check(make(), { transparency: NaN, ior: 1.5 } as FrameState)).toBe('uTransparency');
    expect(check(make(), { transparency: 0.5, ior: Infinity } as FrameState)).toBe('uIor');
  });

  it('the first one wins: objects, then the glass, lights, reflection, clip plane, view vector, transparency, ior', () => {
    const s = make();
    s.objects[1].mirrored.modelRelative[0] = NaN;
    s.glassMain.normal[0] = NaN;
    s.clipPlane[0] = NaN;
    expect(check(s, { transparency: NaN, ior: NaN } as FrameState)).toBe('uModelRelative (mirrored object 1)');
  });

  it('objects past the frame\'s count are not this frame\'s uniforms', () => {
    const s = make();
    s.objects[1].main.normal[0] = NaN;
    expect(check(s, state, 1)).toBeNull();
  });
});

describe('the rough gather\'s numbers (docs/rough-glass.md#quality)', () => {
  it('the qualities\' neighbours per ring and mip bias are the docs\' table', () => {
    const doc = readFileSync(new URL('../../docs/rough-glass.md', import.meta.url), 'utf8');
    expect(ROUGHNESS_QUALITIES).toEqual(['low', 'medium', 'high']);
    for (const q of ROUGHNESS_QUALITIES) {
      const row = doc.match(new RegExp(`^\\| \`${q}\`(?: \\(default\\))? \\| (\\d+) \\| (.+?) \\|$`, 'm'));
      expect(row, q).not.toBeNull();
      expect(ROUGH_GATHER[q].angles).toBe(Number(row![1]));
      expect(ROUGH_GATHER[q].lodBias).toBe(Number(row![2].replace('−', '-')));
    }
  });

  it('the rings: reach 8α per texel of slope from a first ring of 1 texel, doubling, at most 12', () => {
    expect([ROUGH_REACH, ROUGH_FIRST_RING, ROUGH_MAX_RINGS]).toEqual([8, 1, 12]);
    // reach = 8 α t; rings = ⌈log2 reach⌉ + 1 above a reach of 1, else 1.
    expect(roughRings(0, 100)).toBe(1);
    expect(roughRings(0.125, 1)).toBe(1); // reach 1 exactly: the centre and first ring suffice
    expect(roughRings(0.25, 1)).toBe(2); // reach 2: log2 2 = 1
    expect(roughRings(0.3, 1)).toBe(3); // reach 2.4: ⌈1.26⌉ + 1
    expect(roughRings(0.5, 4)).toBe(5); // reach 16
    expect(roughRings(1, 128)).toBe(11); // reach 1024: log2 = 10
    expect(roughRings(1, 129)).toBe(12); // reach 1032: ⌈10.01⌉ + 1
    expect(roughRings(1, 1e6)).toBe(12);
  });

  it('distance codes: u = h / (1 + h); nothing there (∞) is 1; on or in front of the glass is 0', () => {
    expect(distanceCode(1)).toBe(0.5);
    expect(distanceCode(3)).toBe(0.75);
    expect(distanceCode(0.25)).toBe(0.2);
    expect(distanceCode(Infinity)).toBe(1);
    expect(distanceCode(0)).toBe(0);
    expect(distanceCode(-2)).toBe(0);
    expect(distanceCode(NaN)).toBe(0);
  });
});

describe('rough or polished, encoded at the end or not', () => {
  it('isRough: only a roughness above 0 (absent, 0, negative and NaN are polished)', () => {
    expect(isRough({})).toBe(false);
    expect(isRough({ roughness: 0 })).toBe(false);
    expect(isRough({ roughness: -0.5 })).toBe(false);
    expect(isRough({ roughness: NaN })).toBe(false);
    expect(isRough({ roughness: 1e-6 })).toBe(true);
    expect(isRough({ roughness: 1 })).toBe(true);
  });

  it('encodesAtEnd: sRGB output in every view but fresnel; color-space none never', () => {
    for (const view of ['final', 'passes', 'reflection', 'scene'] as const) {
      expect(encodesAtEnd({ colorSpace: 'srgb', view })).toBe(true);
      expect(encodesAtEnd({ colorSpace: 'none', view })).toBe(false);
    }
    expect(encodesAtEnd({ colorSpace: 'srgb', view: 'fresnel' })).toBe(false);
  });
});

describe('boundaries of the level-of-detail rules', () => {
  it('reflectionGrid: the coarsest grid whose cells span at most 4 px — exactly 16 cells is grid 16', () => {
    // cells = extent · px per unit / 4.
    expect(reflectionGrid(64, 1)).toBe(16);
    expect(reflectionGrid(64.01, 1)).toBe(32);
    expect(reflectionGrid(256 * 4, 1)).toBe(256);
    expect(reflectionGrid(256 * 4 + 1, 1)).toBe(0);
  });

  it('sphereScreenRadius: an eye within 1.0001 radii is inside (Infinity), just outside it is finite', () => {
    const state = { cameraPosition: [0, 0, 0] as const, height: 100, fov: 90 };
    expect(sphereScreenRadius(state, [1.0001, 0, 0], 1)).toBe(Infinity);
    expect(sphereScreenRadius(state, [1.00005, 0, 0], 1)).toBe(Infinity);
    const just = sphereScreenRadius(state, [1.0002, 0, 0], 1);
    expect(Number.isFinite(just)).toBe(true);
    // focal 50 px (fov 90°, 100 px): 50 · tan(asin(1/1.0002)).
    expect(just).toBeCloseTo(50 * Math.tan(Math.asin(1 / 1.0002)), 6);
  });

  it('glassSkipReason: an edge-on eye with 0.5 px² of glass still draws it', () => {
    const setup = { hasGlass: true, orthographic: false, viewDot: -1, eyeDistance: 0 } as FrameSetup;
    expect(glassSkipReason(setup, { x0: 10, y0: 10, x1: 11, y1: 11, area: 0.5 } as ScreenRect, true)).toBeUndefined();
  });
});

describe('meshKey and buildMesh', () => {
  it('names each geometry\'s content; builds a Gaussian only with its generator', () => {
    expect(meshKey({ kind: 'box', size: 2 })).toBe('box:2');
    expect(meshKey({ kind: 'gaussian', resolution: 64 })).toBe('gaussian:64');
    const data = boxMesh(1);
    expect(meshKey({ kind: 'mesh', key: 'a.obj', data })).toBe('mesh:a.obj');
    expect(meshKey({ kind: 'sphere', radius: 0.5 }, 24)).toBe('sphere:0.5:24');
    expect(buildMesh({ kind: 'mesh', key: 'a.obj', data })).toBe(data);
    expect(() => buildMesh({ kind: 'gaussian', resolution: 8 })).toThrow('buildMesh: a Gaussian needs its generator');
    expect(buildMesh({ kind: 'gaussian', resolution: 8 }, 0, gaussianMesh).positions.length).toBe(8 * 8 * 3);
  });
});
