// One sample of the reference (src/reference/sample-tracer.ts) in scenes small enough to work out by hand: objects lit by
// an ambient light only (colour = 0.2·Ka), the glass z = 0 seen head-on (Fresnel 0.04 at ior 1.5), transparency chains,
// the mirror path, ties with the glass plane, the debug views, and each sample's key.
import { afterEach, describe, expect, it } from 'vitest';
import { clipRange, setClipRange } from '../../src/reference/clip';
import { MAX_LAYERS, SampleTracer } from '../../src/reference/sample-tracer';
import { proceduralGrey, TextureSampler } from '../../src/reference/texture-sampler';
import { courseSceneRange } from '../../src/scene/course-depth';
import type { CourseCamera } from '../../src/math/course-camera';
import { GLASS_BODY } from '../../src/scene/default-scene';
import { srgbToLinear } from '../../src/math/srgb';
import type { FrameState } from '../../src/frame/types';
import type { Glass, Light, Material, Scene, SceneObject, Vec3 } from '../../src/scene/scene';
import { defaultFrameState } from './helpers/frame-state';
import { expectClose } from './helpers/math';

afterEach(() => setClipRange(0.1, 100));

/** From (0, 0, 5) looking down −z (yaw −90°), fov 90 (1 NDC unit = 1 unit at depth 1), square. */
const view = (over: Partial<FrameState> = {}): FrameState => defaultFrameState({
  width: 100, height: 100, fov: 90, cameraPosition: [0, 0, 5], yaw: -90, pitch: 0, projection: 'perspective', view: 'final',
  colorSpace: 'none', fresnel: 'schlick', ior: 1.5, transparency: 1, roughness: 0, courseCamera: null, target: null, ...over,
});

/** Ka = Kd, no specular, no texture: lit by AMBIENT alone the colour is 0.2·Ka. */
function material(ka: Vec3, over: Partial<Material> = {}): Material {
  return { ambient: ka, diffuse: ka, specular: [0, 0, 0], shininess: 1, opacity: 1, texture: { kind: 'none' }, mapping: 'uv', ...over };
}
const AMBIENT: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [0.2, 0.2, 0.2], diffuse: [0, 0, 0], specular: [0, 0, 0] };
const BG: Vec3 = [0.3, 0.6, 0.9];
const GLASS: Glass = { center: [0, 0, 0], normal: [0, 0, 1], size: [20, 20] };
const lit = (ka: Vec3) => ka.map((k) => 0.2 * k);

function sphere(position: Vec3, radius: number, ka: Vec3, over: Partial<Material> = {}, extra: Partial<SceneObject> = {}): SceneObject {
  return {
    geometry: { kind: 'sphere', radius }, material: material(ka, over), bounds: { center: [0, 0, 0], radius },
    transform: { position, rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 }, ...extra,
  };
}

/** A square 2h wide in the plane z (a mesh, seen from both sides), its bounds centred at `centre` (a mesh's bounds are its own). */
function quad(ka: Vec3, centre: Vec3, z = 0, h = 2, over: Partial<Material> = {}): SceneObject {
  return {
    geometry: {
      kind: 'mesh', key: 'quad',
      data: {
        positions: new Float32Array([-h, -h, z, h, -h, z, h, h, z, -h, h, z]), normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
        uvs: new Float32Array(8), indices: new Uint16Array([0, 1, 2, 0, 2, 3]),
      },
    },
    material: material(ka, over), bounds: { center: centre, radius: 3 },
    transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
  };
}

const scene = (objects: SceneObject[], glass: Glass | null = null, lights: Light[] = [AMBIENT]): Scene =>
  ({ glass, objects, lights, background: BG });

/** The sample at NDC (x, y): [colour, key]. */
function sample(t: SampleTracer, x = 0, y = 0, fx = 0.02, fy = 0.02): [number[], number] {
  const out = new Float64Array([9, 9, 9]);
  const key = t.sample(x, y, fx, fy, out);
  return [[...out], key];
}

const F = 0.04; // Schlick at normal incidence, ior 1.5: ((1.5 − 1)/(1.5 + 1))²
const mixRB = (r: readonly number[], b: readonly number[]) => r.map((x, k) => F * x + (1 - F) * b[k]);

describe('SampleTracer without a glass', () => {
  it('the object hit, shaded and clamped, its code as the key; the background and 0 elsewhere', () => {
    // Sphere code 1, glass 2, base 3.
    const t = new SampleTracer(scene([sphere([0, 0, 0], 1, [1, 0.5, 10])]), view(), 'point');
    expect(MAX_LAYERS).toBe(16);
    const [c, key] = sample(t);
    expectClose(c, [0.2, 0.1, 1], 1e-15);
    expect(key).toBe(1);
    expect(sample(t, 0.9, 0.9)).toEqual([BG, 0]);
  });

  it("view 'reflection' with no glass: the background", () => {
    expect(sample(new SampleTracer(scene([sphere([0, 0, 0], 1, [1, 1, 1])]), view({ view: 'reflection' }), 'point'))).toEqual([BG, 0]);
  });

  it('the background in linear light with srgb', () => {
    const t = new SampleTracer(scene([]), view({ colorSpace: 'srgb' }), 'point');
    expectClose(sample(t)[0], BG.map(srgbToLinear), 1e-15);
  });

  it('lit by the first four lights only', () => {
    const five = [AMBIENT, AMBIENT, AMBIENT, AMBIENT, AMBIENT];
    const t = new SampleTracer(scene([sphere([0, 0, 0], 1, [1, 0.5, 0.25])], null, five), view(), 'point');
    expectClose(sample(t)[0], [0.8, 0.4, 0.2], 1e-15);
  });

  it('the nearer of two objects, the earlier on a tie', () => {
    const near = sphere([0, 0, 1], 0.5, [1, 0, 0]), far = sphere([0, 0, -1], 0.5, [0, 1, 0]), same = sphere([0, 0, 1], 0.5, [0, 0, 1]);
    expect(sample(new SampleTracer(scene([far, near]), view(), 'point'))).toEqual([lit([1, 0, 0]), 2]);
    expect(sample(new SampleTracer(scene([near, far]), view(), 'point'))).toEqual([lit([1, 0, 0]), 1]);
    expect(sample(new SampleTracer(scene([same, near]), view(), 'point'))).toEqual([lit([0, 0, 1]), 1]);
    expect(sample(new SampleTracer(scene([far, near, same]), view(), 'point'))).toEqual([lit([1, 0, 0]), 2]);
  });

  it('a transparent object over what lies behind it; the key names both', () => {
    // Front 0.25 opaque, 0.2 white; behind (0, 0.2, 0): 0.05 + 0.75·(0, 0.2, 0). Codes front 1, behind 2, base 4.
    const front = sphere([0, 0, 2], 0.5, [1, 1, 1], { opacity: 0.25 }), behind = sphere([0, 0, -2], 0.5, [0, 1, 0]);
    const [c, key] = sample(new SampleTracer(scene([front, behind]), view(), 'point'));
    expectClose(c, [0.05, 0.2, 0.05], 1e-15);
    expect(key).toBe(1 + 4 * 2);
    // Over the background: 0.05 + 0.75·BG.
    const [d, k2] = sample(new SampleTracer(scene([front]), view(), 'point'));
    expectClose(d, BG.map((b) => 0.05 + 0.75 * b), 1e-15);
    expect(k2).toBe(1);
  });

  it('opacity 1 is opaque: nothing behind is traced', () => {
    const front = sphere([0, 0, 2], 0.5, [1, 1, 1], { opacity: 1 }), behind = sphere([0, 0, -2], 0.5, [0, 1, 0]);
    expect(sample(new SampleTracer(scene([front, behind]), view(), 'point'))).toEqual([lit([1, 1, 1]), 1]);
  });

  it(`the ${16}th surface along a ray is taken as opaque`, () => {
    // n half-transparent spheres of 0.2 in a row over a white background: with 16 the last is opaque and every blend
    // is 0.2·½ + 0.2·½ = 0.2; with 15 the last is blended over white (0.6) and the rest halve the excess: 0.2 + 0.8/2¹⁵.
    const row = (n: number) => Array.from({ length: n }, (_, k) => sphere([0, 0, 1 - 0.25 * k], 0.1, [1, 1, 1], { opacity: 0.5 }));
    const white = (objects: SceneObject[]): Scene => ({ ...scene(objects), background: [1, 1, 1] });
    expect(sample(new SampleTracer(white(row(16)), view(), 'point'))[0]).toEqual([0.2, 0.2, 0.2]);
    expect(sample(new SampleTracer(white(row(17)), view(), 'point'))[0]).toEqual([0.2, 0.2, 0.2]);
    expectClose(sample(new SampleTracer(white(row(15)), view(), 'point'))[0], [0.2 + 0.8 / 2 ** 15, 0.2 + 0.8 / 2 ** 15, 0.2 + 0.8 / 2 ** 15], 1e-15);
  });
});

describe('SampleTracer with the glass z = 0', () => {
  // Behind the glass a sphere (Ka (1, 0, 0)); on the eye's side, behind the camera, one the glass mirrors (Ka (0, 1, 0)).
  // Codes: behind 1, mirrored 2, glass 3, base 4.
  const behind = () => sphere([0, 0, -3], 1, [1, 0, 0]);
  const mirrored = (over: Partial<SceneObject> = {}) => sphere([0, 0, 8], 1, [0, 1, 0], {}, over);
  const B = lit([1, 0, 0]), R = lit([0, 1, 0]);

  it("final: F·R + (1 − F)·B at transparency 1; key glass + base·behind + base²·reflected", () => {
    const [c, key] = sample(new SampleTracer(scene([behind(), mirrored()], GLASS), view(), 'point'));
    expectClose(c, mixRB(R, B), 1e-15);
    expect(key).toBe(3 + 4 * 1 + 16 * 2);
  });

  it("transparency below 1 shows the glass body D = tex ⊙ tint·darkness, tex the procedural grey at the glass's UV", () => {
    // The ray meets the glass at its centre: UV (½, ½).
    const tex = new TextureSampler(proceduralGrey('none')).bilinear(0.5, 0.5);
    const D = GLASS_BODY.map((b) => tex * b);
    const [c] = sample(new SampleTracer(scene([behind(), mirrored()], GLASS), view({ transparency: 0.3 }), 'point'));
    expectClose(c, R.map((r, k) => F * r + (1 - F) * (0.3 * B[k] + 0.7 * D[k])), 1e-15);
  });

  it('the Fresnel model and index of the view', () => {
    // Classic: (1 − cos)³ = 0 head-on: B alone. Schlick at ior 2: 1/9.
    expectClose(sample(new SampleTracer(scene([behind(), mirrored()], GLASS), view({ fresnel: 'classic' }), 'point'))[0], B, 1e-15);
    const f = 1 / 9;
    expectClose(sample(new SampleTracer(scene([behind(), mirrored()], GLASS), view({ ior: 2 }), 'point'))[0],
      R.map((r, k) => f * r + (1 - f) * B[k]), 1e-15);
  });

  it("view 'scene': no glass; 'reflection': what the glass mirrors; 'fresnel': F where the glass is seen", () => {
    const s = scene([behind(), mirrored()], GLASS);
    expect(sample(new SampleTracer(s, view({ view: 'scene' }), 'point'))).toEqual([B, 1]);
    expect(sample(new SampleTracer(s, view({ view: 'reflection' }), 'point'))).toEqual([R, 2]);
    const [f, key] = sample(new SampleTracer(s, view({ view: 'fresnel' }), 'point'));
    expectClose(f, [F, F, F], 1e-15);
    expect(key).toBe(3);
  });

  it("view 'fresnel' through transparent objects, black behind an opaque one (its code as the key)", () => {
    const veil = sphere([0, 0, 2], 0.5, [1, 1, 1], { opacity: 0.5 });
    const [f, key] = sample(new SampleTracer(scene([veil, behind()], GLASS), view({ view: 'fresnel' }), 'point'));
    expectClose(f, [F, F, F], 1e-15);
    expect(key).toBe(3);
    // An opaque sphere between the veil and the glass: black, and the key is the first surface's, the veil's.
    const wall = sphere([0, 0, 1], 0.5, [1, 1, 1]);
    expect(sample(new SampleTracer(scene([veil, wall], GLASS), view({ view: 'fresnel' }), 'point'))).toEqual([[0, 0, 0], 1]);
    // No glass at all: black, the background's code.
    expect(sample(new SampleTracer(scene([]), view({ view: 'fresnel' }), 'point'))).toEqual([[0, 0, 0], 0]);
    // Past the glass's edge: black.
    expect(sample(new SampleTracer(scene([], { ...GLASS, size: [1, 1] }), view({ view: 'fresnel' }), 'point', undefined), 0.9, 0.9))
      .toEqual([[0, 0, 0], 0]);
  });

  it('an object kept out of the reflection, or on the far side of the glass, is not mirrored', () => {
    const [c, key] = sample(new SampleTracer(scene([behind(), mirrored({ reflected: false })], GLASS), view(), 'point'));
    expectClose(c, mixRB(BG, B), 1e-15);
    expect(key).toBe(3 + 4 * 1);
    // Only the sphere behind: the mirrored ray would meet it (from the mirrored eye at z = −5) but it is clipped.
    expect(sample(new SampleTracer(scene([behind()], GLASS), view({ view: 'reflection' }), 'point'))).toEqual([BG, 0]);
  });

  it('what is nearer than the glass hides it', () => {
    const front = sphere([0, 0, 2], 0.5, [0, 0, 1]);
    expect(sample(new SampleTracer(scene([behind(), front], GLASS), view(), 'point'))).toEqual([lit([0, 0, 1]), 2]);
  });

  it('a transparent object in front of the glass is blended over the glass\'s result, and is mirrored too', () => {
    // Codes veil 1, behind 2, mirrored 3, glass 4, base 5. The mirror shows the veil over the sphere at z = 8:
    // R' = 0.25·0.2 + 0.75·(0, 0.2, 0) = (0.05, 0.2, 0.05); the glass F·R' + (1 − F)·B; the veil over that.
    // Key: veil + 5·glass (what lies past the veil) + 25·veil (the first surface the glass mirrors).
    const veil = sphere([0, 0, 2], 0.5, [1, 1, 1], { opacity: 0.25 });
    const [c, key] = sample(new SampleTracer(scene([veil, behind(), mirrored()], GLASS), view(), 'point'));
    expectClose(c, mixRB([0.05, 0.2, 0.05], B).map((g) => 0.05 + 0.75 * g), 1e-15);
    expect(key).toBe(1 + 5 * 4 + 25 * 1);
  });

  it('in the mirror, a transparent object over the one past it', () => {
    // Mirrored path: the veil at z = 6 (Ka white, opacity ½) then the sphere at z = 8: R = 0.1 + ½·(0, 0.2, 0).
    const veil = sphere([0, 0, 6], 0.5, [1, 1, 1], { opacity: 0.5 });
    const [c, key] = sample(new SampleTracer(scene([behind(), veil, mirrored()], GLASS), view({ view: 'reflection' }), 'point'));
    expectClose(c, [0.1, 0.2, 0.1], 1e-15);
    expect(key).toBe(2);
  });

  it('a face in the glass plane: behind the glass when its object lies beyond, in front when on the eye\'s side', () => {
    // Codes quad 1, glass 2, base 3.
    const beyond = sample(new SampleTracer(scene([quad([1, 1, 0], [0, 0, -1])], GLASS), view(), 'point'));
    expectClose(beyond[0], mixRB(BG, lit([1, 1, 0])), 1e-15);
    expect(beyond[1]).toBe(2 + 3 * 1);
    expect(sample(new SampleTracer(scene([quad([1, 1, 0], [0, 0, 1])], GLASS), view(), 'point'))).toEqual([lit([1, 1, 0]), 1]);
  });

  it('a camera below the glass sees it from its − side: the mirror shows the − side', () => {
    // From (0, 0, −5) looking up +z (yaw 90°, pitch 0 … the camera's forward is (0, 0, 1)).
    const below = view({ cameraPosition: [0, 0, -5], yaw: 90 });
    const under = sphere([0, 0, -8], 1, [0, 0, 1]), over = sphere([0, 0, 3], 1, [1, 0, 0]);
    // Codes under 1, over 2, glass 3, base 4: B = over, R = under.
    const [c, key] = sample(new SampleTracer(scene([under, over], GLASS), below, 'point'));
    expectClose(c, mixRB(lit([0, 0, 1]), lit([1, 0, 0])), 1e-15);
    expect(key).toBe(3 + 4 * 2 + 16 * 1);
  });

  it('nothing behind the glass: the background through it', () => {
    const [c, key] = sample(new SampleTracer(scene([mirrored()], GLASS), view(), 'point'));
    // Codes: mirrored 1, glass 2, base 3.
    expectClose(c, mixRB(R, BG), 1e-15);
    expect(key).toBe(2 + 3 * 0 + 9 * 1);
  });

  it('an object kept out of the reflection is still seen through the glass', () => {
    const hidden = sphere([0, 0, -3], 1, [1, 0, 0], {}, { reflected: false });
    const [c, key] = sample(new SampleTracer(scene([hidden, mirrored()], GLASS), view(), 'point'));
    expectClose(c, mixRB(R, B), 1e-15);
    expect(key).toBe(3 + 4 * 1 + 16 * 2);
  });

  it('in the mirror, past a transparent object, an object kept out of the reflection is passed through', () => {
    // The veil at z = 6 over the sphere at z = 8, which is not reflected: R = 0.1 + ½·background.
    const veil = sphere([0, 0, 6], 0.5, [1, 1, 1], { opacity: 0.5 });
    const [c] = sample(new SampleTracer(scene([behind(), veil, mirrored({ reflected: false })], GLASS), view({ view: 'reflection' }), 'point'));
    expectClose(c, BG.map((b) => 0.1 + 0.5 * b), 1e-15);
  });

  it('depth decides, not the side of the object\'s centre, away from the glass plane', () => {
    // A quad at z = −1 whose bounds centre is on the eye's side: behind the glass all the same. Codes quad 1, glass 2, base 3.
    const [c, key] = sample(new SampleTracer(scene([quad([1, 1, 0], [0, 0, 1], -1)], GLASS), view(), 'point'));
    expectClose(c, mixRB(BG, lit([1, 1, 0])), 1e-15);
    expect(key).toBe(2 + 3 * 1);
  });

  it('within the tie band (1e-9 of t) the side of the object\'s centre decides; a centre in the plane counts as beyond', () => {
    // z = −1e-9: t = 5 + 1e-9, within 1e-9·5 of the glass's 5.
    expect(sample(new SampleTracer(scene([quad([1, 1, 0], [0, 0, 1], -1e-9)], GLASS), view(), 'point'))).toEqual([lit([1, 1, 0]), 1]);
    const inPlane = sample(new SampleTracer(scene([quad([1, 1, 0], [0, 0, 0])], GLASS), view(), 'point'));
    expectClose(inPlane[0], mixRB(BG, lit([1, 1, 0])), 1e-15);
    expect(inPlane[1]).toBe(2 + 3 * 1);
  });

  it('the mirror is shaded towards the mirrored eye', () => {
    // A quad at z = 8 (the eye's side) lit by L = −z (diffuse ½, specular 1; Kd 0.2, Ks 0.5, n = 2). The sample at NDC x = 0.2 meets the
    // glass at (1, 0, 0); its mirror ray from the mirrored eye (0, 0, −5) meets the quad at p = (2.6, 0, 8), normal −z
    // turned to face it. V = unit((0, 0, −5) − p), H = L + V, highlight ((n·H)/|H|)².
    const light: Light = { kind: 'directional', vector: [0, 0, -1], ambient: [0, 0, 0], diffuse: [0.5, 0.5, 0.5], specular: [1, 1, 1] };
    const ceiling = quad([0.2, 0.2, 0.2], [0, 0, 8], 8, 10, { specular: [0.5, 0.5, 0.5], shininess: 2 });
    const t = new SampleTracer(scene([ceiling], GLASS, [light]), view({ view: 'reflection' }), 'point');
    const v = [-2.6, 0, -13], len = Math.hypot(v[0], v[2]);
    const h = [v[0] / len, 0, v[2] / len - 1];
    const spec = (-h[2] / Math.hypot(h[0], h[2])) ** 2;
    const [c, key] = sample(t, 0.2, 0);
    // Kd·Id·(n·L) + Ks·Is·highlight = 0.2·0.5·1 + 0.5·highlight.
    const expected = 0.1 + 0.5 * spec;
    expect(expected).toBeLessThan(1);
    expectClose(c, [expected, expected, expected], 1e-12);
    expect(key).toBe(1);
  });

  it('rough glass: the microfacet samples bend the reflection off the mirrored sphere; without them, or polished, the smooth result', () => {
    // α = 1 (roughness 1), ξ = (0.2, 0): the microfacet normal 26.6° off z; the reflected ray leaves at 53° and misses
    // the sphere at z = 8 (R̃ = background); the refracted one still meets the wide box behind (B̃ = B).
    const wall: SceneObject = {
      ...sphere([0, 0, -12], 1, [1, 0, 0]), geometry: { kind: 'box', size: 20 }, bounds: { center: [0, 0, 0], radius: 18 },
    };
    const s = scene([wall, mirrored()], GLASS);
    const mf = { xi1: new Float64Array([0.2]), xi2: new Float64Array([0]), first: 0, count: 1 };
    const rough = new SampleTracer(s, view({ roughness: 1 }), 'point');
    rough.microfacets = mf;
    expectClose(sample(rough)[0], mixRB(BG, B), 1e-12);
    expectClose(sample(new SampleTracer(s, view({ roughness: 1 }), 'point'))[0], mixRB(R, B), 1e-15);
    // A microfacet normal along the glass's (ξ1 = 0): the mirror direction, so the sphere again.
    const flat = new SampleTracer(s, view({ roughness: 1 }), 'point');
    flat.microfacets = { xi1: new Float64Array([0]), xi2: new Float64Array([0]), first: 0, count: 1 };
    expectClose(sample(flat)[0], mixRB(R, B), 1e-12);
    // Polished: the smooth path exactly, microfacets or not.
    const polished = new SampleTracer(s, view({ roughness: 0 }), 'point');
    polished.microfacets = mf;
    expect(sample(polished)).toEqual(sample(new SampleTracer(s, view({ roughness: 0 }), 'point')));
  });

  it('a sample does not depend on the samples before it', () => {
    // A veil in front of the glass, a transparent sphere behind it and one mirrored; samples in the middle, at the veil's
    // edge, beside everything and off the glass, in every view, by one tracer and each by a fresh one.
    const s = scene([
      sphere([0, 0, 2], 0.5, [1, 1, 1], { opacity: 0.5 }), sphere([1.5, 0, -3], 1, [1, 0, 0], { opacity: 0.5 }), behind(), mirrored(),
    ], { ...GLASS, size: [6, 6] });
    const points: [number, number][] = [[0, 0], [0.3, 0], [0.05, 0.02], [0.9, 0.9], [0.2, 0], [0, 0], [0.99, 0]];
    for (const v of ['final', 'scene', 'reflection', 'fresnel'] as const) {
      const one = new SampleTracer(s, view({ view: v }), 'point');
      for (const [x, y] of points) {
        expect(sample(one, x, y), `${v} ${x}, ${y}`).toEqual(sample(new SampleTracer(s, view({ view: v }), 'point'), x, y));
      }
    }
  });
});

describe('SampleTracer: the camera and the texture', () => {
  it('orthographic: shaded with V = −direction, not towards the eye', () => {
    // Specular only (Ks 1, n = 2, light +z): at the hit (0.6, 0, 0.8) of the unit sphere, V = +z gives H ∥ (0, 0, 1):
    // (N·H)² = 0.64. The orthographic view of half-height 5 (the origin 5 away) puts x = 0.6 at NDC 0.12.
    const spec: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [0, 0, 0], diffuse: [0, 0, 0], specular: [1, 1, 1] };
    const ball = sphere([0, 0, 0], 1, [0, 0, 0], { specular: [1, 1, 1], shininess: 2 });
    const ortho = new SampleTracer(scene([ball], null, [spec]), view({ projection: 'orthographic' }), 'point');
    expectClose(sample(ortho, 0.12, 0)[0], [0.64, 0.64, 0.64], 1e-12);
    // In perspective the same point (NDC 0.6/4.2) sees V towards (0, 0, 5): H = V + L.
    const v = [-0.6 / Math.sqrt(18), 0, 4.2 / Math.sqrt(18)], h = [v[0], 0, v[2] + 1];
    const s = ((0.6 * h[0] + 0.8 * h[2]) / Math.hypot(h[0], h[2])) ** 2;
    const persp = new SampleTracer(scene([ball], null, [spec]), view(), 'point');
    expectClose(sample(persp, 0.6 / 4.2, 0)[0], [s, s, s], 1e-12);
  });

  it('orthographic: V is −forward whatever the forward (yaw −60°, pitch −20°)', () => {
    // The centre ray from the eye 5 back along forward meets the unit sphere at n = −forward = V. With L = +z,
    // H = n + L: (n·H)²/|H|² = (1 + n_z)²/(2 + 2n_z) = (1 + n_z)/2, n_z = −cos(−20°)·sin(−60°).
    const spec: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [0, 0, 0], diffuse: [0, 0, 0], specular: [1, 1, 1] };
    const ball = sphere([0, 0, 0], 1, [0, 0, 0], { specular: [1, 1, 1], shininess: 2 });
    const p = (-20 * Math.PI) / 180, y = (-60 * Math.PI) / 180;
    const f = [Math.cos(p) * Math.cos(y), Math.sin(p), Math.cos(p) * Math.sin(y)];
    const eye: Vec3 = [-5 * f[0], -5 * f[1], -5 * f[2]];
    const t = new SampleTracer(scene([ball], null, [spec]), view({ projection: 'orthographic', yaw: -60, pitch: -20, cameraPosition: eye }), 'point');
    const s = (1 - f[2]) / 2;
    expectClose(sample(t)[0], [s, s, s], 1e-12);
  });

  it('orthographic: sized by the glass centre, not by the origin', () => {
    // Glass centre (0, 0, −5), 10 from the eye: half-height 10·tan 45°; NDC x = 0.08 is x = 0.8 on the unit sphere at the
    // origin, n = (0.8, 0, 0.6): with V = +z and L = +z the highlight is 0.6² (the origin, 5 away, would put it at x = 0.4).
    const spec: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [0, 0, 0], diffuse: [0, 0, 0], specular: [1, 1, 1] };
    const ball = sphere([0, 0, 0], 1, [0, 0, 0], { specular: [1, 1, 1], shininess: 2 });
    const t = new SampleTracer(scene([ball], { center: [0, 0, -5], normal: [0, 0, 1], size: [0.01, 0.01] }, [spec]),
      view({ projection: 'orthographic' }), 'point');
    expectClose(sample(t, 0.08, 0)[0], [0.36, 0.36, 0.36], 1e-12);
  });

  it('orthographic, the eye on the glass\'s − side looking down onto its + side: the mirror keeps the + side', () => {
    // Glass through the origin, n = (0.6, 0, 0.8); eye (−4, 0, 2) (0.6·−4 + 0.8·2 = −0.8: the − side) looking down −z,
    // fov 120 (half-height 2·tan 60°). NDC x = 3/(2·tan 60°) starts at (−1, 0, 2), on the + side, and meets the glass at
    // (−1, 0, 0.75): its mirror ray leaves along (0.96, 0, 0.28) to a sphere 3 on, (1.88, 0, 1.59), on the + side.
    const g: Glass = { center: [0, 0, 0], normal: [0.6, 0, 0.8], size: [20, 20] };
    const ball = sphere([1.88, 0, 1.59], 0.5, [0, 1, 1]);
    const ortho = view({ projection: 'orthographic', cameraPosition: [-4, 0, 2], fov: 120, view: 'reflection' });
    const t = new SampleTracer(scene([ball], g), ortho, 'point');
    expect(sample(t, 3 / (2 * Math.tan(Math.PI / 3)), 0)).toEqual([lit([0, 1, 1]), 1]);
  });

  it('a texture footprint that had to be shortened adds base³ to the key', () => {
    // A procedural sphere seen through a footprint of the whole view: far more than 64 texels. Codes sphere 1, base 3.
    const ball = sphere([0, 0, 0], 1, [1, 1, 1], { texture: { kind: 'procedural' } });
    expect(sample(new SampleTracer(scene([ball]), view(), 'box'), 0, 0, 2, 2)[1]).toBe(1 + 27);
    expect(sample(new SampleTracer(scene([ball]), view(), 'box'), 0, 0, 0.002, 0.002)[1]).toBe(1);
    expect(sample(new SampleTracer(scene([ball]), view(), 'point'), 0, 0, 2, 2)[1]).toBe(1);
    // The flag is the sample's own: the next one starts clear.
    const t = new SampleTracer(scene([ball]), view(), 'box');
    expect(sample(t, 0, 0, 2, 2)[1]).toBe(28);
    expect(sample(t, 0, 0, 0.002, 0.002)[1]).toBe(1);
  });

  it("a course camera's near and far come from the scene; any other view's are the default 0.1 and 100", () => {
    const cam: CourseCamera = { c: [0, 0, 5], n: [0, 0, -1], u: [1, 0, 0], v: [0, 1, 0], d: 1, hx: 1, hy: 1 };
    const s = scene([sphere([0, 0, 0], 1, [1, 1, 1])]);
    new SampleTracer(s, view({ courseCamera: cam }), 'point');
    const range = courseSceneRange(cam, s, 0);
    expect(clipRange).toEqual({ near: range.near, far: range.far });
    expect(range.near).toBeGreaterThan(0.1);
    new SampleTracer(s, view(), 'point');
    expect(clipRange).toEqual({ near: 0.1, far: 100 });
  });
});
