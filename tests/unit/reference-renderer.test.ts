// The reference's frame loop (src/reference/reference-renderer.ts): where each pixel's samples go, their footprints, the
// box filter over them, the colour encoding, the first key and the mixed flag, the microfacet slots — with the sample
// tracer's `sample` replaced by a recorder (its own work is reference-sample-tracer.test.ts's), and tiny real frames.
import { afterEach, describe, expect, it, vi } from 'vitest';
import { renderReference, renderScene, DEFAULT_MICROFACET_SAMPLES } from '../../src/reference/reference-renderer';
import { REGION_CUBE, REGION_EDGE, REGION_GLASS, REGION_SPHERE } from '../../src/reference/regions';
import { SampleTracer } from '../../src/reference/sample-tracer';
import { linearToSrgb } from '../../src/math/srgb';
import { defaultScene } from '../../src/scene/default-scene';
import type { FrameState } from '../../src/frame/types';
import type { Scene } from '../../src/scene/scene';
import { defaultFrameState } from './helpers/frame-state';
import { expectClose } from './helpers/math';

afterEach(() => vi.restoreAllMocks());

const state = (over: Partial<FrameState> = {}): FrameState =>
  defaultFrameState({ width: 3, height: 2, view: 'final', colorSpace: 'none', roughness: 0, courseCamera: null, ...over });
const SCENE: Scene = defaultScene(0.75, 0.8);

interface Call { x: number; y: number; fx: number; fy: number; first: number | null; count: number | null; xi1: number[] }

/** Replaces SampleTracer.sample: records each call, answers with `answer(call index)`: [colour, key]. */
function record(answer: (n: number, call: Call) => [number[], number]) {
  const calls: Call[] = [];
  vi.spyOn(SampleTracer.prototype, 'sample').mockImplementation(function (this: SampleTracer, x, y, fx, fy, out) {
    const mf = this.microfacets;
    const call = { x, y, fx, fy, first: mf ? mf.first : null, count: mf ? mf.count : null, xi1: mf ? [...mf.xi1] : [] };
    const [colour, key] = answer(calls.length, call);
    calls.push(call);
    out.set(colour);
    return key;
  });
  return calls;
}

describe('renderScene: samples', () => {
  it('one sample per pixel at its centre, footprint 2/W × 2/H, rows top first', () => {
    const calls = record(() => [[0, 0, 0], 0]);
    renderScene(SCENE, state());
    // x = (px + ½)·2/3 − 1, y = 1 − (py + ½)·2/2.
    expect(calls.map((c) => [c.x, c.y])).toEqual([
      [-2 / 3, 0.5], [0, 0.5], [2 / 3, 0.5], [-2 / 3, -0.5], [0, -0.5], [2 / 3, -0.5],
    ].map(([x, y]) => [expect.closeTo(x, 15), expect.closeTo(y, 15)]));
    for (const c of calls) expect([c.fx, c.fy]).toEqual([2 / 3, 1]);
  });

  it('n × n samples at the centres of equal strata, footprint 2/(W·n) × 2/(H·n)', () => {
    const calls = record(() => [[0, 0, 0], 0]);
    renderScene(SCENE, state({ width: 1, height: 1 }), null, { samplesPerAxis: 2 });
    expect(calls.map((c) => [c.x, c.y])).toEqual([[-0.5, 0.5], [0.5, 0.5], [-0.5, -0.5], [0.5, -0.5]]);
    for (const c of calls) expect([c.fx, c.fy]).toEqual([1, 1]);
    // 3 per axis over a 2×1 frame: strata ⅓ of a pixel.
    const more = record(() => [[0, 0, 0], 0]);
    renderScene(SCENE, state({ width: 2, height: 1 }), null, { samplesPerAxis: 3 });
    expect(more.length).toBe(18);
    expect(more[0].x).toBeCloseTo(1 / 6 - 1, 15);
    expect(more[0].y).toBeCloseTo(1 - 1 / 3, 15);
    expect(more[4].x).toBeCloseTo(0.5 - 1, 15);
    expect(more[4].y).toBeCloseTo(0, 15);
    expect(more[9].x).toBeCloseTo(1 / 6, 15);
    expect([more[0].fx, more[0].fy]).toEqual([1 / 3, 2 / 3]);
  });

  it('the mean of the samples (as light: encoded once with srgb, not in the fresnel view); RGBA8 rounded, alpha 255', () => {
    const colours = [[0.1, 0.2, 0.3], [0.3, 0.2, 0.1], [0.5, 0.5, 0.5], [0.7, 0.9, 0.2]];
    record((n) => [colours[n % 4], 1]);
    const img = renderScene(SCENE, state({ width: 1, height: 1 }), null, { samplesPerAxis: 2 });
    const mean = [0.4, 0.45, 0.275];
    expectClose(img.rgb, mean, 1e-15);
    expect([...img.rgba]).toEqual([...mean.map((c) => Math.round(c * 255)), 255]);
    record((n) => [colours[n % 4], 1]);
    const srgb = renderScene(SCENE, state({ width: 1, height: 1, colorSpace: 'srgb' }), null, { samplesPerAxis: 2 });
    expectClose(srgb.rgb, mean.map(linearToSrgb), 1e-15);
    expect([...srgb.rgba]).toEqual([...mean.map((c) => Math.round(linearToSrgb(c) * 255)), 255]);
    record((n) => [colours[n % 4], 1]);
    const fresnel = renderScene(SCENE, state({ width: 1, height: 1, colorSpace: 'srgb', view: 'fresnel' }), null, { samplesPerAxis: 2 });
    expectClose(fresnel.rgb, mean, 1e-15);
  });

  it('each pixel keeps its first sample\'s key; a pixel whose samples disagree is an edge, with its neighbours', () => {
    // 3×2 pixels of 2×2 samples: keys 1 (cube) everywhere but the last sample of pixel (2, 1), 7 (sphere).
    record((n) => [[0, 0, 0], n === 23 ? 7 : 1]);
    const img = renderScene(SCENE, state(), null, { samplesPerAxis: 2 });
    expect([...img.keys]).toEqual([1, 1, 1, 1, 1, 1]);
    expect([...img.regions]).toEqual([REGION_CUBE, REGION_EDGE, REGION_EDGE, REGION_CUBE, REGION_EDGE, REGION_EDGE]);
    // The first sample different: that is the pixel's key.
    record((n) => [[0, 0, 0], n === 20 ? 8 : 7]);
    const other = renderScene(SCENE, state(), null, { samplesPerAxis: 2 });
    expect([...other.keys]).toEqual([7, 7, 7, 7, 7, 8]);
    // All agree: regions by key (the default scene's codes: 7 sphere, 8 glass).
    record(() => [[0, 0, 0], 8]);
    expect([...renderScene(SCENE, state(), null, { samplesPerAxis: 2 }).regions]).toEqual(Array(6).fill(REGION_GLASS));
    record(() => [[0, 0, 0], 7]);
    expect([...renderScene(SCENE, state()).regions]).toEqual(Array(6).fill(REGION_SPHERE));
  });
});

describe('renderScene: options and sizes', () => {
  it('defaults: 1 sample, point filter; supersampled: box; both as asked; the sample count floored, at least 1', () => {
    record(() => [[0, 0, 0], 0]);
    const one = renderScene(SCENE, state({ width: 1, height: 1 }));
    expect([one.samplesPerAxis, one.textureFilter, one.view, one.microfacetSamples]).toEqual([1, 'point', 'final', 0]);
    expect(renderScene(SCENE, state({ width: 1, height: 1 }), null, { samplesPerAxis: 2.9 }).samplesPerAxis).toBe(2);
    expect(renderScene(SCENE, state({ width: 1, height: 1 }), null, { samplesPerAxis: 2 }).textureFilter).toBe('box');
    expect(renderScene(SCENE, state({ width: 1, height: 1 }), null, { samplesPerAxis: 0.5 }).samplesPerAxis).toBe(1);
    expect(renderScene(SCENE, state({ width: 1, height: 1 }), null, { samplesPerAxis: 3, textureFilter: 'point' }).textureFilter).toBe('point');
    expect(renderScene(SCENE, state({ width: 1, height: 1 }), null, { textureFilter: 'box' }).textureFilter).toBe('box');
  });

  it('sizes are floored, never negative; the codes are the scene\'s', () => {
    record(() => [[0, 0, 0], 0]);
    const six = renderScene(SCENE, state({ width: 3, height: 2 }));
    expect([six.rgb.length, six.rgba.length, six.keys.length, six.regions.length]).toEqual([18, 24, 6, 6]);
    expect([...six.rgba].filter((_, i) => i % 4 === 3)).toEqual([255, 255, 255, 255, 255, 255]);
    const img = renderScene(SCENE, state({ width: 2.7, height: 1.2 }));
    expect([img.width, img.height, img.rgb.length, img.rgba.length, img.keys.length, img.regions.length]).toEqual([2, 1, 6, 8, 2, 2]);
    expect(img.codes!.glass).toBe(8);
    const none = renderScene(SCENE, state({ width: -3, height: 2 }));
    expect([none.width, none.height, none.rgb.length]).toEqual([0, 2, 0]);
  });

  it("'passes' is refused", () => {
    expect(() => renderScene(SCENE, state({ view: 'passes' }))).toThrow(
      'glass-plane-scene: the reference renderer draws one view at a time, not "passes"');
  });
});

describe('renderScene: rough glass', () => {
  it('each sample takes its own slice of the pixel\'s microfacet normals, filled per pixel', () => {
    // 2×2 samples, 10 asked: ⌈10/4⌉ = 3 per sample, 12 in all; sample (sx, sy) starts at (2·sy + sx)·3.
    const calls = record(() => [[0, 0, 0], 0]);
    const img = renderScene(SCENE, state({ width: 2, height: 1, roughness: 0.3 }), null, { samplesPerAxis: 2, microfacetSamples: 10 });
    expect(img.microfacetSamples).toBe(12);
    expect(calls.map((c) => c.first)).toEqual([0, 3, 6, 9, 0, 3, 6, 9]);
    expect(calls.every((c) => c.count === 3 && c.xi1.length === 12)).toBe(true);
    // Pixel 0 and pixel 1 draw different normals; the samples of a pixel share them.
    expect(calls[1].xi1).toEqual(calls[0].xi1);
    expect(calls[4].xi1).not.toEqual(calls[0].xi1);
  });

  it('the default count, at least one per sample, none when polished', () => {
    record(() => [[0, 0, 0], 0]);
    expect(DEFAULT_MICROFACET_SAMPLES).toBe(256);
    expect(renderScene(SCENE, state({ width: 1, height: 1, roughness: 0.3 })).microfacetSamples).toBe(256);
    expect(renderScene(SCENE, state({ width: 1, height: 1, roughness: 0.3 }), null, { samplesPerAxis: 3 }).microfacetSamples).toBe(261);
    expect(renderScene(SCENE, state({ width: 1, height: 1, roughness: 0.3 }), null, { samplesPerAxis: 2, microfacetSamples: 1 }).microfacetSamples)
      .toBe(4);
    const calls = record(() => [[0, 0, 0], 0]);
    expect(renderScene(SCENE, state({ width: 1, height: 1, roughness: 0 })).microfacetSamples).toBe(0);
    expect(calls[0].first).toBeNull();
  });
});

describe('renderReference, and a real frame', () => {
  it('renderReference draws the default scene at the state\'s cube distance and spin', () => {
    const s = state({ width: 4, height: 3, cubeDistance: 0.5, spin: 1.3, time: 0.7 });
    const a = renderReference(s), b = renderScene(defaultScene(0.5, 1.3), s);
    expect([...a.rgb]).toEqual([...b.rgb]);
    expect([...a.keys]).toEqual([...b.keys]);
    // Another distance, another spin: other pixels.
    expect([...renderScene(defaultScene(0.75, 1.3), s).rgb]).not.toEqual([...a.rgb]);
    expect([...renderScene(defaultScene(0.5, 0.2), s).rgb]).not.toEqual([...a.rgb]);
  });

  it('the images reach the sample tracer', () => {
    // The sphere of the default scene textured with a one-texel red image: with the image its pixel is red above all
    // (the white highlight aside), as the sample tracer given the image draws it; without, the procedural grey on green.
    const red = new Map([['red.png', { width: 1, height: 1, data: new Uint8Array([255, 0, 0, 255]) }]]);
    const [cube, ball] = SCENE.objects;
    const redBall = { ...ball, material: { ...ball.material, texture: { kind: 'image' as const, url: 'red.png' } } };
    const s: Scene = { ...SCENE, glass: null, objects: [cube, redBall] };
    // A view straight at the sphere (1, 1, −1.5) from 4 in front of it.
    const st = state({ width: 1, height: 1, cameraPosition: [1, 1, 2.5], yaw: -90, pitch: 0, projection: 'perspective' });
    const out = new Float64Array(3);
    new SampleTracer(s, st, 'point', red).sample(0, 0, 2, 2, out);
    const img = renderScene(s, st, red);
    expect([...img.rgb]).toEqual([...out]);
    expect(out[0]).toBeGreaterThan(3 * out[1]);
    const plain = renderScene(s, st).rgb;
    expect(plain[0]).toBeLessThan(3 * plain[1]);
  });

  it('a 1×1 frame is its centre sample', () => {
    const s = state({ width: 1, height: 1 });
    const out = new Float64Array(3);
    const key = new SampleTracer(SCENE, s, 'point').sample(0, 0, 2, 2, out);
    const img = renderScene(SCENE, s);
    expect([...img.rgb]).toEqual([...out]);
    expect(img.keys[0]).toBe(key);
  });
});
