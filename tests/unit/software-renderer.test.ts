// The software renderer's own decisions (src/software/software-renderer.ts), each on frames small enough to draw in a
// few milliseconds: the output array and its size, the band of rows, the sample counts, the views without a glass, the
// order transparent objects blend in (worked out here), opaque objects depth-tested in any order, the rough glass's
// settings, the phase times, and each image's texture built once per colour space. small-frames.test.ts holds whole
// frames to the bit; these say what each switch of the renderer must do.
import { createHash } from 'node:crypto';
import { describe, expect, it } from 'vitest';
import { SoftwareRenderer } from '../../src/software';
import type { SoftwareTiming } from '../../src/software';
import type { FrameState } from '../../src/frame/types';
import { defaultScene } from '../../src/scene/default-scene';
import type { Scene, SceneObject } from '../../src/scene/scene';
import type { DecodedImage } from '../../src/scene/decoded-image';
import { CASES, IMAGES, STATE } from './helpers/software-cases';
import { AMBIENT, material, N, quad, STATE as QUAD_STATE } from './helpers/quad-scenes';

const W = 24, H = 14;
const SMALL: FrameState = { ...STATE, width: W, height: H, spin: 0.3 };
const scene = defaultScene(0.75, 0.8);
const noGlass: Scene = { ...scene, glass: null };

const frame = (s: Scene | null, state: Partial<FrameState>, n = 1, images: ReadonlyMap<string, DecodedImage> | null = IMAGES) =>
  Buffer.from(new SoftwareRenderer({ samplesPerAxis: n }).render(s, { ...SMALL, ...state }, images));
const rows = (b: Buffer, top: number, bottom: number) => b.subarray(4 * W * top, 4 * W * bottom);

describe('the output', () => {
  it('is 4 bytes a pixel of floor(width) × floor(height), a negative size none; one array while the size stays', () => {
    const r = new SoftwareRenderer();
    const a = r.render(scene, SMALL, IMAGES);
    expect(a.length).toBe(4 * W * H);
    expect(r.render(scene, { ...SMALL, time: 2 }, IMAGES)).toBe(a);
    const b = r.render(scene, { ...SMALL, width: W + 0.9, height: H - 0.2 }, IMAGES);
    expect(b.length).toBe(4 * W * (H - 1));
    expect(b).not.toBe(a);
    for (const [width, height] of [[0, H], [W, 0], [-3, H], [0.5, 0.5]]) expect(r.render(scene, { ...SMALL, width, height }).length).toBe(0);
  });

  it('a frame of no pixels builds no texture: an image changed after it is drawn as it is then', () => {
    const image: DecodedImage = { width: 2, height: 2, data: new Uint8Array(16).fill(255) };
    const images = new Map([['a.png', image]]);
    const textured = withImage(scene, 'a.png');
    const r = new SoftwareRenderer();
    r.render(textured, { ...SMALL, width: 0 }, images);
    r.render(textured, { ...SMALL, height: 0 }, images);
    image.data.set([200, 10, 10, 255, 10, 200, 10, 255, 10, 10, 200, 255, 90, 90, 90, 255]);
    expect(Buffer.from(r.render(textured, SMALL, images)).equals(frame(textured, {}, 1, images))).toBe(true);
  });
});

describe('the band of rows', () => {
  // Another background: every row of B differs from A's.
  const other: Scene = { ...scene, background: [0.3, 0.2, 0.1] };
  const A = frame(scene, {}), B = frame(other, { time: 2.9 });

  it('draws only the band\'s rows (clamped to the frame), the others left as the frame before drew them', () => {
    for (let y = 0; y < H; y++) expect(rows(A, y, y + 1).equals(rows(B, y, y + 1)), `row ${y}`).toBe(false);
    const r = new SoftwareRenderer();
    const cases: [{ top: number; bottom: number }, number, number][] = [
      [{ top: 3, bottom: 7 }, 3, 7], [{ top: -5, bottom: 4.9 }, 0, 4], [{ top: 10.5, bottom: 99 }, 10, H], [{ top: 9, bottom: 2 }, 9, 9],
    ];
    for (const [band, top, bottom] of cases) {
      r.band = null;
      const whole = r.render(scene, SMALL, IMAGES);
      r.band = band;
      const out = r.render(other, { ...SMALL, time: 2.9 }, IMAGES);
      expect(out).toBe(whole);
      const want = Buffer.concat([rows(A, 0, top), rows(B, top, bottom), rows(A, bottom, H)]);
      expect(Buffer.from(out).equals(want), `${band.top}..${band.bottom}`).toBe(true);
    }
  });

  it('is ignored by rough glass and the passes view, which draw the whole frame', () => {
    const r = new SoftwareRenderer();
    expect([r.drawsBands(SMALL), r.drawsBands({ ...SMALL, roughness: 0 }), r.drawsBands({ ...SMALL, roughness: 0.3 }), r.drawsBands({ ...SMALL, view: 'passes' })])
      .toEqual([true, true, false, false]);
    for (const over of [{ roughness: 0.3 }, { view: 'passes' as const }]) {
      r.band = null;
      r.render(scene, SMALL, IMAGES);
      r.band = { top: 3, bottom: 7 };
      expect(Buffer.from(r.render(other, { ...SMALL, ...over }, IMAGES)).equals(frame(other, over))).toBe(true);
    }
  });
});

describe('samples', () => {
  it('samples 2 or more multisample (2×2 a pixel, as 4), fewer do not; supersampled frames never do', () => {
    const s0 = frame(scene, { samples: 0 });
    expect(frame(scene, { samples: 1 }).equals(s0)).toBe(true);
    expect(frame(scene, { samples: 4 }).equals(s0)).toBe(false);
    expect(frame(scene, { samples: 2 }).equals(frame(scene, { samples: 4 }))).toBe(true);
    expect(frame(scene, { samples: 4 }, 2).equals(frame(scene, { samples: 0 }, 2))).toBe(true);
  });

  it('samplesPerAxis is floored and held to 1..8', () => {
    const one = frame(scene, {}, 1), two = frame(scene, {}, 2), eight = frame(scene, {}, 8);
    expect(two.equals(one)).toBe(false);
    expect(eight.equals(two)).toBe(false);
    expect(frame(scene, {}, 0).equals(one)).toBe(true);
    expect(frame(scene, {}, -2).equals(one)).toBe(true);
    expect(frame(scene, {}, 2.9).equals(two)).toBe(true);
    expect(frame(scene, {}, 12).equals(eight)).toBe(true);
    expect(new SoftwareRenderer().samplesPerAxis).toBe(1);
  });
});

describe('the views of a scene without a glass', () => {
  const empty = frame({ ...noGlass, objects: [] }, { view: 'scene' });
  it('the reflection is the background everywhere, F is black, the final frame is the scene', () => {
    expect(new Set(empty.subarray(0, 4 * W * H).reduce<string[]>((s, _, i) => (i % 4 ? s : [...s, `${empty.subarray(i, i + 4)}`]), [])).size).toBe(1);
    expect(frame(noGlass, { view: 'scene' }).equals(empty)).toBe(false);
    expect(frame(noGlass, { view: 'reflection' }).equals(empty)).toBe(true);
    expect(frame(noGlass, { view: 'fresnel' }).equals(Buffer.from(new Uint8Array(4 * W * H).map((_, i) => (i % 4 === 3 ? 255 : 0))))).toBe(true);
    expect(frame(noGlass, { view: 'final' }).equals(frame(noGlass, { view: 'scene' }))).toBe(true);
  });
});

describe('transparent objects blend back to front by the distance of their bounds\' centre from the eye', () => {
  // quad-scenes' 17×17 view, moved to (0.5, 0.3, 2): the centre pixel's ray runs down −Z through (0.5, 0.3). Three
  // quads 5 wide cover it, their centres chosen so that the order by squared distance, (1, 2, 0), differs from the
  // scene's, from its reverse and from the order of any one term's sign turned.
  const state: FrameState = { ...QUAD_STATE, colorSpace: 'none', cameraPosition: [0.5, 0.3, 2] };
  const centres = [[1, 1.5, 1], [2, 1.5, 0.5], [0, -1.5, 1]];
  const colours: [number, number, number][] = [[0.9, 0.1, 0.1], [0.1, 0.9, 0.1], [0.1, 0.2, 0.9]];
  const alphas = [0.5, 0.6, 0.7];
  const quads: SceneObject[] = centres.map(([x, y, z], i) => quad(x - 2.5, y - 2.5, x + 2.5, y + 2.5, z, material(colours[i], { kind: 'none' }, alphas[i])));
  const background: [number, number, number] = [0.2, 0.2, 0.2];

  it('each drawn over what is behind it: α·colour + (1 − α)·below, farthest first', () => {
    const got = new SoftwareRenderer().render({ glass: null, background, lights: [AMBIENT], objects: quads }, state);
    const c = (N * 8 + 8) * 4;
    let want = [...background];
    for (const i of [1, 2, 0]) want = want.map((b, k) => alphas[i] * colours[i][k] + (1 - alphas[i]) * b);
    for (let k = 0; k < 3; k++) expect(Math.abs(got[c + k] - 255 * want[k]), `channel ${k}`).toBeLessThanOrEqual(0.5 + 1e-4);
    // Any other order gives other bytes.
    for (const order of [[0, 1, 2], [2, 1, 0], [1, 0, 2], [2, 0, 1], [0, 2, 1]]) {
      let other = [...background];
      for (const i of order) other = other.map((b, k) => alphas[i] * colours[i][k] + (1 - alphas[i]) * b);
      expect(Math.max(...other.map((x, k) => Math.abs(255 * x - 255 * want[k])))).toBeGreaterThan(2);
    }
  });

  it('in the scene view and in the final frame over a glass beyond them, the same order', () => {
    const glassScene: Scene = { glass: { center: [0.5, 0.3, -2], normal: [0, 0, 1], size: [0.4, 0.4] }, background, lights: [AMBIENT], objects: quads };
    const c = (N * 8 + 8) * 4;
    const plain = new SoftwareRenderer().render({ ...glassScene, glass: null }, state).slice(c, c + 4);
    expect(new SoftwareRenderer().render(glassScene, { ...state, view: 'scene' }).slice(c, c + 4)).toEqual(plain);
    // Off the glass (a corner pixel) the final frame is the scene's.
    const corner = 4 * (N * 2 + 2);
    expect(new SoftwareRenderer().render(glassScene, state).slice(corner, corner + 4)).toEqual(new SoftwareRenderer().render({ ...glassScene, glass: null }, state).slice(corner, corner + 4));
  });
});

describe('transparent objects are sorted: their order in the scene does not show', () => {
  // The glass z = 0 seen head-on from z = 4: two half-transparent spheres on the eye's side, one behind the other (the
  // reflection shows them too), two beyond the glass likewise (seen through it; gathered into the rough glass's B̃).
  const sphere = (z: number, radius: number, colour: [number, number, number], opacity: number): SceneObject => ({
    geometry: { kind: 'sphere', radius }, bounds: { center: [0, 0, 0], radius },
    transform: { position: [0.5, 1, z], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    material: { ...scene.objects[1].material, diffuse: colour, ambient: colour, opacity },
  });
  const spheres = [sphere(2, 0.4, [0.9, 0.2, 0.1], 0.5), sphere(1, 0.7, [0.1, 0.8, 0.3], 0.6), sphere(-1, 0.6, [0.2, 0.3, 0.9], 0.5), sphere(-2.2, 1, [0.9, 0.8, 0.1], 0.7)];
  const state: Partial<FrameState> = { cameraPosition: [0.5, 1, 4], yaw: -90, pitch: 0 };
  const orders = [[0, 1, 2, 3], [3, 1, 0, 2], [1, 2, 3, 0]];
  for (const [name, over] of [['final', {}], ['final, rough', { roughness: 0.3 }], ['reflection', { view: 'reflection' }]] as const) {
    it(name, () => {
      const [a, ...others] = orders.map((o) => frame({ ...scene, objects: o.map((i) => spheres[i]) }, { ...state, ...over }));
      for (const b of others) expect(b.equals(a)).toBe(true);
      // The spheres show: without the first, another frame.
      expect(frame({ ...scene, objects: spheres.slice(1) }, { ...state, ...over }).equals(a)).toBe(false);
    });
  }
});

describe('opaque objects are depth-tested: their order in the scene does not show', () => {
  // The default cube inside a bigger box of another colour: only the bigger box shows, in the frame and in the reflection.
  const [cube] = scene.objects;
  const big: SceneObject = { ...cube, transform: { ...cube.transform, scale: [1.4, 1.4, 1.4] }, material: { ...cube.material, diffuse: [0.1, 0.8, 0.2] } };
  for (const view of ['final', 'reflection', 'scene'] as const) {
    it(`view ${view}, polished and rough`, () => {
      for (const roughness of [0, 0.3]) {
        const a = frame({ ...scene, objects: [big, cube] }, { view, roughness }), b = frame({ ...scene, objects: [cube, big] }, { view, roughness });
        expect(a.equals(b), `roughness ${roughness}`).toBe(true);
        expect(a.equals(frame({ ...scene, objects: [big] }, { view, roughness })), `roughness ${roughness}`).toBe(true);
      }
    });
  }
});

describe('rough glass: its settings from the frame state', () => {
  const rough = { roughness: 0.3 };
  it('quality: absent is medium, low and high are others; a fixed blur level is another frame', () => {
    const medium = frame(scene, { ...rough, roughnessQuality: 'medium' });
    expect(frame(scene, { ...rough, roughnessQuality: undefined }).equals(medium)).toBe(true);
    expect(frame(scene, { ...rough, roughnessQuality: 'low' }).equals(medium)).toBe(false);
    expect(frame(scene, { ...rough, roughnessQuality: 'high' }).equals(medium)).toBe(false);
    expect(frame(scene, { ...rough, fixedBlurLevel: 2 }).equals(medium)).toBe(false);
    expect(frame(scene, { ...rough, fixedBlurLevel: undefined }).equals(medium)).toBe(true);
  });
});

describe('timing', () => {
  it('adds the frame\'s time to total and the glass\'s to glass, the pixels unchanged', () => {
    const timing: SoftwareTiming = { vertex: 0, triangles: 0, glass: 0, total: 0, constantFragments: false };
    const r = new SoftwareRenderer();
    r.timing = timing;
    const t0 = performance.now();
    const out = Buffer.from(r.render(scene, SMALL, IMAGES));
    const dt = performance.now() - t0;
    expect(out.equals(frame(scene, {}))).toBe(true);
    expect(timing.glass).toBeGreaterThan(0);
    expect(timing.total).toBeGreaterThan(timing.glass);
    expect(timing.total).toBeLessThanOrEqual(dt);
    const { glass, total } = timing;
    const t1 = performance.now();
    r.render(noGlass, SMALL, IMAGES);
    const dt1 = performance.now() - t1;
    expect(timing.glass).toBe(glass);
    expect(timing.total).toBeGreaterThan(total);
    expect(timing.total - total).toBeLessThanOrEqual(dt1);
  });
});

describe('image textures', () => {
  const image: DecodedImage = { width: 2, height: 2, data: new Uint8Array([250, 20, 20, 255, 20, 250, 20, 255, 20, 20, 250, 255, 128, 128, 128, 255]) };
  const textured = withImage(scene, 'a.png');

  it('each image is made a texture once per colour space: a change to its data afterwards does not show', () => {
    const copy: DecodedImage = { ...image, data: image.data.slice() };
    const images = new Map([['a.png', copy]]);
    const r = new SoftwareRenderer();
    const first = Buffer.from(r.render(textured, SMALL, images));
    copy.data.reverse();
    expect(Buffer.from(r.render(textured, SMALL, images)).equals(first)).toBe(true);
    expect(frame(textured, {}, 1, images).equals(first)).toBe(false);
    // In the other colour space it is made from the data as it is then.
    const srgb = { ...SMALL, colorSpace: 'srgb' as const };
    expect(Buffer.from(r.render(textured, srgb, images)).equals(frame(textured, srgb, 1, images))).toBe(true);
  });

  it('without images, or one that cannot be read, the fallback: the checker, or plain with fallback none', () => {
    const checker = frame(withTexture(scene, { kind: 'procedural' }), {}), plain = frame(withTexture(scene, { kind: 'none' }), {});
    expect(checker.equals(plain)).toBe(false);
    expect(frame(textured, {}, 1, null).equals(checker)).toBe(true);
    expect(frame(withImage(scene, 'a.png', 'none'), {}, 1, null).equals(plain)).toBe(true);
    const broken = new Map([['a.png', { width: 0, height: 2, data: new Uint8Array(0) }]]);
    expect(frame(textured, {}, 1, broken).equals(checker)).toBe(true);
    expect(frame(withImage(scene, 'a.png', 'none'), {}, 1, broken).equals(plain)).toBe(true);
    expect(frame(textured, {}, 1, new Map([['a.png', image]])).equals(checker)).toBe(false);
  });
});

function withTexture(s: Scene, texture: SceneObject['material']['texture']): Scene {
  return { ...s, objects: s.objects.map((o) => ({ ...o, material: { ...o.material, texture } })) };
}

/**
 * Frames small-frames.test.ts does not draw, held to the bit as recorded here (its way: a change meant to move pixels
 * records them again, and says why): the rough glass's frame behind it drawn only when T > 0 (classic mixes B even at
 * T = 0), objects beyond the glass drawn into that frame opaque first, and a multisampled polished frame.
 */
describe('frames held to the bit', () => {
  const spheres = CASES.find((c) => c.name === 'half-transparent spheres in front of and across the glass')!;
  const recorded: [string, Scene, Partial<FrameState>, string][] = [
    ['default scene, rough 0.3, classic, T 0', scene, { width: 32, height: 18, roughness: 0.3, fresnel: 'classic', transparency: 0 }, 'f0333b3364e3fc111bd8d466'],
    ['spheres across the glass, rough 0.3, samples 4', spheres.scene, { width: 32, height: 18, ...spheres.state, roughness: 0.3, samples: 4 }, '38ec1be790d9baa8b762b9c1'],
    ['default scene, samples 4', scene, { width: 32, height: 18, samples: 4 }, '8d3ea19675332d73d577ecb7'],
  ];
  for (const [name, s, over, digest] of recorded) {
    it(name, () => expect(createHash('sha256').update(frame(s, over)).digest('hex').slice(0, 24)).toBe(digest));
  }
});

/** `s` with every object's texture the image at `url`. */
function withImage(s: Scene, url: string, fallback?: 'none'): Scene {
  return { ...s, objects: s.objects.map((o) => ({ ...o, material: { ...o.material, texture: { kind: 'image', url, ...(fallback ? { fallback } : {}) } } })) };
}
