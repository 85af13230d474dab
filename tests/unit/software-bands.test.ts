// A frame split into bands of rows across renderers (docs/software-renderer.md#worker: one per worker, element/
// software-host.ts) is the whole frame bit for bit: each band drawn by its own renderer
// (renderBand, as a worker draws it) and put back (putBand) gives the bytes one renderer gives the
// whole frame. software-reference.test.ts's scenes (a mesh, a Bézier surface, transparency,
// orthographic), both colour spaces, 1 sample and samples 4, the default scene supersampled, in
// each debug view, rough (drawn whole in one band's renderer, sliced), with a course camera, on
// odd sizes and uneven or empty bands, and a run of frames whose caches each band keeps.
import { describe, expect, it } from 'vitest';
import type { FrameState } from '../../src/frame/types';
import { defaultScene } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import { SoftwareRenderer, putBand, renderBand, splitRows, type Band } from '../../src/software';
import { CASES, IMAGES, STATE, courseCamera } from './helpers/software-cases';
import { differingBytes } from './helpers/pixel-diff';
import { Rasterizer, VARYINGS } from '../../src/software/raster';
import { instrumented } from './helpers/collections';

/** The whole frame from `bands`, each drawn by its renderer of `renderers` (one per band). */
function banded(renderers: SoftwareRenderer[], bands: Band[], state: FrameState, scene: Scene): Uint8ClampedArray {
  const width = Math.floor(state.width);
  const frame = new Uint8ClampedArray(4 * width * Math.floor(state.height));
  bands.forEach((band, i) => putBand(frame, renderBand(renderers[i], scene, state, IMAGES, band), band, width));
  return frame;
}

function differing(a: Uint8ClampedArray, b: Uint8ClampedArray): number {
  expect(a.length).toBe(b.length);
  return differingBytes(a, b);
}

const whole = (state: FrameState, scene: Scene, samplesPerAxis = 1) => new SoftwareRenderer({ samplesPerAxis }).render(scene, state, IMAGES).slice();
const renderersOf = (count: number, samplesPerAxis = 1) => Array.from({ length: count }, () => new SoftwareRenderer({ samplesPerAxis }));

describe('Rasterizer.top and bottom', () => {
  /** Fragments (and repeated samples) per row of a 40×30 target covered by two triangles, with rows top..bottom drawn. */
  function rowsDrawn(shadeEvery: number, top: number, bottom: number): number[] {
    const r = new Rasterizer(40, 30);
    r.shadeEvery = shadeEvery;
    r.top = top;
    r.bottom = bottom;
    r.clearDepth();
    r.depthTest = false; // rows outside the band keep their depth (0 here): the box alone must keep them out
    r.derivatives = false;
    const v = new Float64Array(4 * VARYINGS);
    [[-1, -1], [1, -1], [1, 1], [-1, 1]].forEach(([x, y], i) => { v[i * VARYINGS] = x; v[i * VARYINGS + 1] = y; v[i * VARYINGS + 3] = 1; });
    const rows = new Array<number>(30).fill(0);
    const count = (sample: number) => { rows[Math.floor(sample / 40)]++; };
    r.drawTriangles(v, [0, 1, 2, 0, 2, 3], 6, { fragment: count, repeat: count });
    return rows;
  }
  for (const n of [1, 2]) {
    it(`draws only the band's rows and each of them whole (shadeEvery ${n}), its depth cleared only there`, () => {
      expect(rowsDrawn(n, 10, 20)).toEqual(Array.from({ length: 30 }, (_, y) => (y >= 10 && y < 20 ? 40 : 0)));
      expect(rowsDrawn(n, 0, Infinity)).toEqual(new Array(30).fill(40));
      const r = new Rasterizer(40, 30);
      r.top = 10;
      r.bottom = 20;
      r.clearDepth();
      expect([r.depth[9 * 40 + 39], r.depth[10 * 40], r.depth[19 * 40 + 39], r.depth[20 * 40]]).toEqual([0, Infinity, Infinity, 0]);
    });
  }
});

describe('splitRows', () => {
  it('covers every row once, top first, evenly or by weight', () => {
    expect(splitRows(90, 2)).toEqual([{ top: 0, bottom: 45 }, { top: 45, bottom: 90 }]);
    expect(splitRows(91, 3)).toEqual([{ top: 0, bottom: 30 }, { top: 30, bottom: 61 }, { top: 61, bottom: 91 }]);
    expect(splitRows(100, 2, [3, 1])).toEqual([{ top: 0, bottom: 75 }, { top: 75, bottom: 100 }]);
    expect(splitRows(1, 3)).toEqual([{ top: 0, bottom: 0 }, { top: 0, bottom: 1 }, { top: 1, bottom: 1 }]);
  });
});

// Under StrykerJS these frames (160×90, dozens per test) take minutes; small-frames.test.ts draws bands there.
describe.skipIf(instrumented)('a frame in bands is the whole frame, bit for bit', () => {
  const scene = defaultScene(0.75, 0.8);
  for (const c of CASES) {
    for (const colorSpace of ['none', 'srgb'] as const) {
      for (const samples of [0, 4]) {
        it(`${c.name}, ${colorSpace}, samples ${samples}: 2 and 3 bands`, () => {
          const state: FrameState = { ...STATE, ...c.state, colorSpace, samples };
          const want = whole(state, c.scene);
          expect(differing(banded(renderersOf(2), splitRows(state.height, 2), state, c.scene), want)).toBe(0);
          expect(differing(banded(renderersOf(3), splitRows(state.height, 3, [1, 3, 2]), state, c.scene), want)).toBe(0);
        });
      }
    }
  }
  const variants: [string, Partial<FrameState>, number?][] = [
    ['161×91, samples 4', { width: 161, height: 91, samples: 4 }], ['supersampled 2×2', { samples: 4 }, 2], ['supersampled 3×3, 161×91', { width: 161, height: 91 }, 3],
    ['view scene', { view: 'scene' }], ['view reflection', { view: 'reflection' }], ['view fresnel', { view: 'fresnel' }],
    ['view passes', { view: 'passes', width: 161, height: 91 }], ['rough 0.3, samples 4', { roughness: 0.3, samples: 4 }],
    ['rough 0.3, srgb', { roughness: 0.3, colorSpace: 'srgb' }], ['course camera', { courseCamera: courseCamera() }],
    ['gouraud', { shading: 'gouraud' }], ['flat, samples 4', { shading: 'flat', samples: 4 }],
  ];
  for (const [name, over, n] of variants) {
    it(`default scene, ${name}: 2 bands, 4 uneven ones (one empty), one row each`, () => {
      const state: FrameState = { ...STATE, ...over };
      const want = whole(state, scene, n);
      expect(differing(banded(renderersOf(2, n), splitRows(state.height, 2), state, scene), want)).toBe(0);
      expect(differing(banded(renderersOf(4, n), [{ top: 0, bottom: 7 }, { top: 7, bottom: 7 }, { top: 7, bottom: 50 }, { top: 50, bottom: state.height }], state, scene), want)).toBe(0);
      if (state.roughness) return; // drawn whole for every band: one frame per row is slow and shows nothing more
      const rows = Array.from({ length: state.height }, (_, y) => ({ top: y, bottom: y + 1 }));
      const one = new SoftwareRenderer({ samplesPerAxis: n });
      expect(differing(banded(rows.map(() => one), rows, state, scene), want)).toBe(0);
    });
  }

  it('a run of frames (the cube turning, then the camera, then rough and back), each band kept by its renderer', () => {
    const renderers = renderersOf(2);
    let state: FrameState = { ...STATE, colorSpace: 'srgb' };
    const steps: Partial<FrameState>[] = [{}, {}, {}, { yaw: STATE.yaw + 0.5 }, {}, { roughness: 0.3 }, { roughness: 0 }, {}, { samples: 4 }, {}, { height: 91 }, {}];
    for (const [k, over] of steps.entries()) {
      state = { ...state, ...over, time: state.time + 0.05 };
      const bands = splitRows(state.height, 2, [1 + (k % 3), 2]);
      expect(differing(banded(renderers, bands, state, scene), whole(state, scene)), `frame ${k}`).toBe(0);
    }
  });
});
