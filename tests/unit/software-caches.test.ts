// The frame-to-frame caches' contracts (src/software/glass-cache.ts, object-cache.ts): an entry
// is read back only in a frame whose key is exactly the one it was written under (and the frame
// before had it too), by the sample or triangle that wrote it. The renderer's own frames are held
// to the bit in software-baseline.test.ts; a multisampled pixel on the glass's diagonal, or on an
// edge between two triangles, differs there in last bits only, below what 8 bits show, so those
// are tied down here.
import { describe, expect, it } from 'vitest';
import { GlassCache, GLASS_KEY_LENGTH } from '../../src/software/glass-cache';
import { MAX_CACHED_OBJECTS, MAX_CACHED_PIXELS, ObjectCache, OBJECT_KEY_LENGTH } from '../../src/software/object-cache';
import { SoftwareRenderer } from '../../src/software';
import { defaultScene } from '../../src/scene/default-scene';
import { DEFAULT_CUBE_DISTANCE } from '../../src/element/attributes';
import { defaultFrameState } from './helpers/frame-state';
import { differingBytes } from './helpers/pixel-diff';
import { instrumented } from './helpers/collections';
import { prepareEnvironment } from '../../src/frame/environment-light';
import { STUDIO, studioGrid } from './helpers/pbr-scenes';
import { courseBasis, type CourseCamera } from '../../src/math/course-camera';

const key = (...values: number[]) => {
  const k = new Float64Array(GLASS_KEY_LENGTH);
  k.set(values);
  return k;
};
const MODEL = ['exact'], TEXTURE = {};

describe('GlassCache', () => {
  it('keeps an entry while the key stays, at the sample that wrote it only', () => {
    const c = new GlassCache();
    c.begin(key(1, 2, 3), [MODEL, TEXTURE], 16);
    expect(c.active, 'a new key: nothing read or kept').toBe(false);
    expect(c.has(5, 0)).toBe(false);
    c.set(5, 2, 0.25, 0.75);
    expect(c.has(5, 2)).toBe(true);
    expect(c.has(5, 0)).toBe(false);
    expect(c.has(4, 2)).toBe(false);
    c.begin(key(1, 2, 3), [MODEL, TEXTURE], 16);
    expect(c.active, 'the key of the frame before').toBe(true);
    expect(c.has(5, 2)).toBe(true);
    expect([c.f[5], c.texel[5]]).toEqual([0.25, 0.75]);
  });

  const changes: [string, Float64Array, unknown[], number][] = [
    ['a value', key(1, 2, 4), [MODEL, TEXTURE], 16],
    ['the last value', (() => { const k = key(1, 2, 3); k[GLASS_KEY_LENGTH - 1] = 1; return k; })(), [MODEL, TEXTURE], 16],
    ['0 to −0', key(1, 2, 3, -0), [MODEL, TEXTURE], 16],
    ['an object', key(1, 2, 3), [['exact'], TEXTURE], 16],
    ['one object fewer', key(1, 2, 3), [MODEL], 16],
    ['more pixels', key(1, 2, 3), [MODEL, TEXTURE], 17],
  ];
  for (const [name, values, objects, pixels] of changes) {
    it(`forgets every entry when ${name} changes`, () => {
      const c = new GlassCache();
      c.begin(key(1, 2, 3), [MODEL, TEXTURE], 16);
      c.set(5, 0, 0.25, 0.75);
      c.begin(values, objects, pixels);
      expect(c.active).toBe(false);
      expect(c.has(5, 0)).toBe(false);
    });
  }

  it('keeps nothing across a NaN key or a clear()', () => {
    const c = new GlassCache();
    c.begin(key(NaN), [], 4);
    c.set(1, 0, 0.5, 0.5);
    c.begin(key(NaN), [], 4);
    expect(c.has(1, 0)).toBe(false);
    c.begin(key(1), [], 4);
    c.set(1, 0, 0.5, 0.5);
    c.clear();
    c.begin(key(1), [], 4);
    expect(c.has(1, 0)).toBe(false);
  });
});

const objectKey = (...values: number[]) => {
  const k = new Float64Array(OBJECT_KEY_LENGTH);
  k.set(values);
  return k;
};
const MESH = {};

describe('ObjectCache', () => {
  it('an object\'s second unchanged draw keeps its colours, the third reads them, for the triangle that wrote them', () => {
    const c = new ObjectCache();
    c.begin(0, objectKey(1, 2), [MESH], 16);
    expect(c.current, 'a new key: not cached').toBe(0);
    expect(c.has(3, 7)).toBe(false);
    c.begin(0, objectKey(1, 2), [MESH], 16);
    expect(c.current).not.toBe(0);
    expect(c.has(3, 7)).toBe(false);
    c.set(3, 7, 0.5, 0.25, 0.125);
    c.begin(0, objectKey(1, 2), [MESH], 16);
    expect(c.has(3, 7)).toBe(true);
    expect(c.has(3, 8), 'another triangle').toBe(false);
    expect(c.has(2, 7), 'another pixel').toBe(false);
    expect([...c.rgb.subarray(9, 12)]).toEqual([0.5, 0.25, 0.125]);
  });

  it('one object\'s entries are not another\'s, and a changed key, object or grid forgets them', () => {
    const c = new ObjectCache();
    const kept = () => {
      c.begin(0, objectKey(1, 2), [MESH], 16);
      c.begin(0, objectKey(1, 2), [MESH], 16);
      c.set(3, 7, 0.5, 0.25, 0.125);
    };
    kept();
    c.begin(1, objectKey(1, 2), [MESH], 16);
    c.begin(1, objectKey(1, 2), [MESH], 16);
    expect(c.has(3, 7), 'object 1 reads object 0').toBe(false);
    for (const [name, values, objects, pixels] of [
      ['a value', objectKey(1, 3), [MESH], 16], ['the last value', (() => { const k = objectKey(1, 2); k[OBJECT_KEY_LENGTH - 1] = 1; return k; })(), [MESH], 16],
      ['0 to −0', objectKey(1, 2, -0), [MESH], 16], ['the mesh', objectKey(1, 2), [{}], 16], ['the grid', objectKey(1, 2), [MESH], 32],
    ] as [string, Float64Array, unknown[], number][]) {
      kept();
      c.begin(0, values, objects, pixels);
      c.begin(0, values, objects, pixels);
      expect(c.has(3, 7), name).toBe(false);
    }
  });

  it(`follows ${MAX_CACHED_OBJECTS} objects and grids up to ${MAX_CACHED_PIXELS} pixels`, () => {
    const c = new ObjectCache();
    for (let k = 0; k < 2; k++) c.begin(MAX_CACHED_OBJECTS - 1, objectKey(1), [], 4);
    expect(c.current).not.toBe(0);
    for (let k = 0; k < 2; k++) c.begin(MAX_CACHED_OBJECTS, objectKey(1), [], 4);
    expect(c.current).toBe(0);
    for (let k = 0; k < 2; k++) c.begin(0, objectKey(1), [], MAX_CACHED_PIXELS + 1);
    expect(c.current).toBe(0);
  });
});

// Under StrykerJS these runs (96×70, two renderers) take minutes; small-frames.test.ts's run resizes there.
describe.skipIf(instrumented)('the software renderer across resizes', () => {
  // Frames 2 and 3 at a size read its caches; a size met after another (the height alone
  // shrinking, caches as large as before) must not read what another size wrote. Each frame against a fresh renderer's, bit for bit.
  const sizes: [number, number][] = [[96, 70], [96, 70], [96, 70], [96, 54], [96, 54], [70, 96], [70, 96], [96, 54], [96, 54], [120, 54], [120, 54]];
  // The course's camera fixes the view's extent (hx, hy), not the canvas: a height alone changes
  // the grid and nothing else the draws are keyed on but the grid's size.
  const basis = courseBasis([1 - 3.6, 1 - 2.4, 0 - 4], [0, 1, 0]) as Exclude<ReturnType<typeof courseBasis>, string>;
  const course: CourseCamera = { c: [3.6, 2.4, 4], ...basis, d: 1, hx: 0.6, hy: 0.5 };
  for (const [label, over] of [
    ['default', {}], ['multisampled', { samples: 4 }], ['rough', { roughness: 0.3 }], ['the course\'s camera', { courseCamera: course }],
  ] as const) {
    it(`${label}: every frame of a run of sizes (a height alone changing among them) is a fresh renderer's`, () => {
      const live = new SoftwareRenderer(), scene = defaultScene(DEFAULT_CUBE_DISTANCE, 0);
      for (const [width, height] of sizes) {
        const state = defaultFrameState({ width, height, spin: 0, ...over });
        const got = live.render(scene, state).slice(), want = new SoftwareRenderer().render(scene, state);
        expect(got.length, `${width}×${height}`).toBe(4 * width * height);
        expect(differingBytes(got, want), `${width}×${height}`).toBe(0);
      }
    });
  }
});

// The environment is a light: a cached colour from before its intensity or its presence changed is stale (a change of
// `environment-intensity` or `environment` keeps the scene's materials as they were, so nothing else in the key moves).
describe.skipIf(instrumented)('the software renderer across environment changes', () => {
  it('every frame of a run of intensities, and of the environment on and off, is a fresh renderer\'s', () => {
    prepareEnvironment(STUDIO);
    const state = defaultFrameState({ width: 64, height: 36, cameraPosition: [0, 1.5, 3.3], yaw: -90, pitch: -8, time: 0, spin: 0, toneMapping: 'neutral' });
    const grid = studioGrid(), live = new SoftwareRenderer();
    for (const environment of [STUDIO, STUDIO, { ...STUDIO, intensity: 3 }, { ...STUDIO, intensity: 3 }, null, null, STUDIO]) {
      const scene = { ...grid, environment };
      const got = live.render(scene, state).slice(), want = new SoftwareRenderer().render(scene, state);
      expect(differingBytes(got, want), `environment ${JSON.stringify(environment)}`).toBe(0);
    }
  });
});
