// The reference renders any Scene value: transforms, meshes, lights, opacity, images, glass anywhere, no glass.
import { describe, expect, it } from 'vitest';
import { createHash } from 'node:crypto';
import {
  glassReflectsCube, glassReflectsObject, renderReference, renderScene, type ReferenceImage, type ReferenceOptions, type SceneImages, type ReferenceState, type ViewState,
} from '../../src/reference';
import { defaultScene } from '../../src/scene/default-scene';
import type { Geometry, Light, Material, Scene, SceneObject, Vec3 } from '../../src/scene/scene';
import { projectToPixels } from './helpers/math';
import { defaultFrameState } from './helpers/frame-state';

const DEFAULT_VIEW: ReferenceState = defaultFrameState({ width: 96, height: 54, time: 1.25, colorSpace: 'none' });
/** Looking down −Z from (0, 0, 10). */
const FRONT: ViewState = defaultFrameState({
  width: 160, height: 120, fov: 40, cameraPosition: [0, 0, 10], yaw: -90, pitch: 0, colorSpace: 'none', view: 'scene',
});
const WHITE = new Map([['white.png', { width: 1, height: 1, data: new Uint8Array([255, 255, 255, 255]) }]]);
const MATTE: Material = {
  ambient: [0.1, 0.1, 0.1], diffuse: [0.5, 0.4, 0.3], specular: [0, 0, 0], shininess: 32, opacity: 1,
  texture: { kind: 'image', url: 'white.png' }, mapping: 'uv',
};
const SUN: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [1, 1, 1], diffuse: [1, 1, 1], specular: [1, 1, 1] };

/** renderScene with the white 1×1 image available by default (MATTE reads it: texture 1 everywhere). */
const render = (s: Scene, v: ViewState, images: SceneImages = WHITE, options: ReferenceOptions = {}): ReferenceImage =>
  renderScene(s, v, images, options);

function object(geometry: Geometry, over: Partial<SceneObject['transform']> = {}, material: Partial<Material> = {}): SceneObject {
  return {
    geometry, material: { ...MATTE, ...material }, bounds: { center: [0, 0, 0], radius: 1 },
    transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0, ...over },
  };
}
function scene(objects: SceneObject[], lights: Light[] = [SUN], glass: Scene['glass'] = null): Scene {
  return { glass, objects, lights, background: [0.1, 0.2, 0.3] };
}
/** A w×h quad in the plane z = 0, normals +Z, counter-clockwise seen from +Z. */
function quad(w: number, h: number, normal: Vec3 = [0, 0, 1]): Geometry {
  return {
    kind: 'mesh', key: 'quad',
    data: {
      positions: new Float32Array([-w / 2, -h / 2, 0, w / 2, -h / 2, 0, w / 2, h / 2, 0, -w / 2, h / 2, 0]),
      normals: new Float32Array([...normal, ...normal, ...normal, ...normal]),
      uvs: new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]),
      indices: new Uint16Array([0, 1, 2, 0, 2, 3]),
    },
  };
}
const project = projectToPixels;
const pixel = (img: { rgb: Float64Array; width: number }, x: number, y: number): number[] =>
  Array.from(img.rgb.subarray(3 * (y * img.width + x), 3 * (y * img.width + x) + 3));
/** Bounding box [x0, y0, x1, y1] (pixel edges) of the pixels whose key is not the background. */
function keyBox(img: { keys: Int32Array; width: number; height: number }): number[] {
  let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
  for (let i = 0; i < img.keys.length; i++) {
    if (img.keys[i] === 0) continue;
    const x = i % img.width, y = Math.floor(i / img.width);
    x0 = Math.min(x0, x); y0 = Math.min(y0, y); x1 = Math.max(x1, x + 1); y1 = Math.max(y1, y + 1);
  }
  return [x0, y0, x1, y1];
}

describe('the default scene', () => {
  it('render(defaultScene) is renderReference, byte for byte, in every view', () => {
    for (const view of ['final', 'scene', 'reflection', 'fresnel'] as const) {
      const a = renderReference({ ...DEFAULT_VIEW, view });
      const b = render(defaultScene(DEFAULT_VIEW.cubeDistance, DEFAULT_VIEW.spin), { ...DEFAULT_VIEW, view });
      expect(Buffer.from(b.rgb.buffer).equals(Buffer.from(a.rgb.buffer))).toBe(true);
      expect(b.keys).toEqual(a.keys);
      expect(b.regions).toEqual(a.regions);
    }
  });

  it('renders exactly what the analytic-only reference rendered (hashes recorded before the scene model)', () => {
    // sha256(rgba ‖ keys) of the reference at 9b67c87, the last commit before renderScene.
    const recorded: Record<string, string> = {
      'final 1': '662201580ef7604d', 'final 2': '7f1f333e11cc67e0', 'scene 1': '016ff4b3a4995938', 'scene 2': 'f275b2c72f40793a',
      'reflection 1': '7009db73f892847a', 'reflection 2': '77111f0bfd8db6f5', 'fresnel 1': '28215ae0b5c3ce01', 'fresnel 2': '1a43ac5485707b46',
    };
    for (const [name, hash] of Object.entries(recorded)) {
      const [view, n] = name.split(' ');
      const img = renderReference({ ...DEFAULT_VIEW, view: view as ReferenceState['view'] }, { samplesPerAxis: Number(n) });
      const got = createHash('sha256').update(img.rgba).update(new Uint8Array(img.keys.buffer)).digest('hex').slice(0, 16);
      expect(got, name).toBe(hash);
    }
  });

  it('keeps the codes glassReflectsCube reads: cube faces 1..6, sphere 7, glass 8', () => {
    const img = renderReference(DEFAULT_VIEW);
    expect([img.codes!.first[0], img.codes!.first[1], img.codes!.glass, img.codes!.base]).toEqual([1, 7, 8, 9]);
    let cube = 0;
    for (const key of img.keys) {
      expect(glassReflectsCube(key)).toBe(glassReflectsObject(key, img.codes!, 0));
      if (glassReflectsCube(key)) cube++;
    }
    expect(cube).toBeGreaterThan(20);
  });
});

describe('transforms', () => {
  /** Rz·Ry·Rx (degrees, X first) · diag(scale) applied to p, then translated: written out by hand. */
  function place(p: number[], pos: number[], rot: number[], scale: number[]): number[] {
    const [ax, ay, az] = rot.map((r) => (r * Math.PI) / 180);
    let [x, y, z] = [p[0] * scale[0], p[1] * scale[1], p[2] * scale[2]];
    [y, z] = [y * Math.cos(ax) - z * Math.sin(ax), y * Math.sin(ax) + z * Math.cos(ax)];
    [x, z] = [x * Math.cos(ay) + z * Math.sin(ay), -x * Math.sin(ay) + z * Math.cos(ay)];
    [x, y] = [x * Math.cos(az) - y * Math.sin(az), x * Math.sin(az) + y * Math.cos(az)];
    return [x + pos[0], y + pos[1], z + pos[2]];
  }

  const cases: [string, number[], number[], number[]][] = [
    ['translated', [1, -0.5, 0.5], [0, 0, 0], [1, 1, 1]],
    ['about X', [0.3, 0.2, 0], [35, 0, 0], [1.6, 0.8, 0.5]],
    ['about Y', [-0.4, 0, 1], [0, 50, 0], [1.6, 0.8, 0.5]],
    ['about Z', [0, 0.3, 0], [0, 0, 30], [1.6, 0.8, 0.5]],
    ['X, Y and Z', [0.5, 0.5, -1], [20, -35, 60], [1.2, 0.5, 0.9]],
  ];
  for (const [name, pos, rot, scale] of cases) {
    it(`a box ${name} with scale ${scale.join(' ')} fills the box of its projected corners`, () => {
      const img = render(scene([object({ kind: 'box', size: 1 }, { position: pos as unknown as Vec3, rotation: rot as unknown as Vec3, scale: scale as unknown as Vec3 })]), FRONT);
      let x0 = Infinity, y0 = Infinity, x1 = -Infinity, y1 = -Infinity;
      for (const c of [-0.5, 0.5].flatMap((x) => [-0.5, 0.5].flatMap((y) => [-0.5, 0.5].map((z) => [x, y, z])))) {
        const [px, py] = project(FRONT, place(c, pos, rot, scale));
        x0 = Math.min(x0, px); y0 = Math.min(y0, py); x1 = Math.max(x1, px); y1 = Math.max(y1, py);
      }
      const got = keyBox(img);
      // Pixels whose centre is inside: the box edges lie within one pixel of the projected ones.
      [x0, y0, x1, y1].forEach((e, i) => expect(Math.abs(got[i] - e), `edge ${i}: ${got[i]} vs ${e}`).toBeLessThan(1));
    });
  }

  it('a sphere lands at its projected centre with its projected radius', () => {
    const pos = [-0.8, 0.6, 1];
    const img = render(scene([object({ kind: 'sphere', radius: 0.5 }, { position: pos as unknown as Vec3, rotation: [10, 20, 30] })]), FRONT);
    let n = 0, sx = 0, sy = 0;
    for (let i = 0; i < img.keys.length; i++) {
      if (img.keys[i] === 0) continue;
      n++; sx += (i % img.width) + 0.5; sy += Math.floor(i / img.width) + 0.5;
    }
    const [cx, cy] = project(FRONT, pos);
    expect(Math.hypot(sx / n - cx, sy / n - cy)).toBeLessThan(0.3);
    const r = Math.sqrt(n / Math.PI);
    const [ex] = project(FRONT, [pos[0] + 0.5 * 9 / Math.sqrt(80), pos[1], pos[2]]); // silhouette radius at distance 9
    expect(Math.abs(r - (ex - cx))).toBeLessThan(0.3);
  });
});

describe('meshes', () => {
  it('are lit two-sided: a quad seen from behind its normals is lit as from the front', () => {
    const behind: ViewState = { ...FRONT, cameraPosition: [0, 0, -10], yaw: 90 };
    const light: Light = { ...SUN, vector: [0, 0, -1] }; // on the viewer's side, behind the normals
    const img = render(scene([object(quad(4, 4))], [light]), behind);
    // N turned towards the viewer: N·L = 1, so Ka·Ia + Kd·Id.
    expect(pixel(img, 80, 60)).toEqual([0.1 + 0.5, 0.1 + 0.4, 0.1 + 0.3].map((x) => expect.closeTo(x, 12)));
  });

  it('the Gaussian surface is drawn through its BVH where its peak projects', () => {
    const top: ViewState = { ...FRONT, cameraPosition: [0, 6, 0.001], yaw: -90, pitch: -89.9 };
    const img = render(scene([object({ kind: 'gaussian', resolution: 40 }, { position: [0, -1, 0] })], [{ ...SUN, vector: [0, 1, 0] }]), top);
    const [px, py] = project(top, [0, 0, 0]);
    const at = pixel(img, Math.floor(px), Math.floor(py));
    expect(at[0]).toBeCloseTo(0.6, 2); // the peak's normal is +Y: Ka·Ia + Kd·Id·1
    expect(img.keys[Math.floor(py) * img.width + Math.floor(px)]).toBe(1);
  });
});

describe('lights', () => {
  const floor = object(quad(20, 20), { rotation: [-90, 0, 0] }, { ambient: [0, 0, 0] }); // plane y = 0, normal +Y
  const down: ViewState = { ...FRONT, width: 401, height: 401, fov: 90, cameraPosition: [0, 4, 0], yaw: -90, pitch: -89.9 };
  /** The world point under pixel (x, y) on the floor y = 0: through the pixel centre. */
  const brightness = (img: { rgb: Float64Array; width: number }, p: number[]): number => {
    const [x, y] = project(down, p);
    return pixel(img, Math.floor(x), Math.floor(y))[0] / 0.5;
  };

  it('a point light: N·L falls off with direction, not with distance', () => {
    const point = (h: number): Light => ({ ...SUN, kind: 'point', vector: [0, h, 0] });
    const near = render(scene([floor], [point(1)]), down);
    const far = render(scene([floor], [point(3)]), down);
    expect(brightness(near, [0, 0, 0])).toBeCloseTo(1, 2); // straight below: cos 0, at either height
    expect(brightness(far, [0, 0, 0])).toBeCloseTo(1, 2);
    expect(brightness(near, [1, 0, 0])).toBeCloseTo(1 / Math.SQRT2, 2); // cos 45°
    expect(brightness(far, [1, 0, 0])).toBeCloseTo(3 / Math.sqrt(10), 2);
    expect(brightness(near, [0, 0, 2])).toBeCloseTo(1 / Math.sqrt(5), 2);
  });

  it('a directional light lights the whole floor alike', () => {
    const img = render(scene([floor], [{ ...SUN, vector: [0, 2, 0] }]), down);
    for (const p of [[0, 0, 0], [1, 0, 0], [0, 0, 2], [-2, 0, -2]]) expect(brightness(img, p)).toBeCloseTo(1, 9);
  });

  it('two lights add: each adds its ambient, diffuse and specular term', () => {
    const shiny = object({ kind: 'sphere', radius: 1 }, {}, { specular: [0.2, 0.2, 0.2], diffuse: [0.3, 0.3, 0.3], ambient: [0.05, 0.05, 0.05] });
    const a: Light = { kind: 'directional', vector: [1, 1, 1], ambient: [0.2, 0.1, 0], diffuse: [0.5, 0.2, 0.1], specular: [1, 0.5, 0] };
    const b: Light = { kind: 'point', vector: [-2, 1, 3], ambient: [0, 0.1, 0.3], diffuse: [0.1, 0.4, 0.6], specular: [0, 0.5, 1] };
    const one = render(scene([shiny], [a]), FRONT), two = render(scene([shiny], [b]), FRONT);
    const both = render(scene([shiny], [a, b]), FRONT);
    let lit = 0;
    for (let i = 0; i < both.keys.length; i++) {
      if (both.keys[i] === 0) continue;
      lit++;
      for (let k = 0; k < 3; k++) expect(both.rgb[3 * i + k]).toBeCloseTo(one.rgb[3 * i + k] + two.rgb[3 * i + k], 12);
    }
    expect(lit).toBeGreaterThan(500);
  });
});

describe('opacity', () => {
  it('0.5 over the background: colour·½ + background·½', () => {
    const lit = [0.1 + 0.5, 0.1 + 0.4, 0.1 + 0.3];
    const img = render(scene([object(quad(4, 4), {}, { opacity: 0.5 })]), FRONT);
    expect(pixel(img, 80, 60)).toEqual(lit.map((c, k) => expect.closeTo(c * 0.5 + [0.1, 0.2, 0.3][k] * 0.5, 12)));
  });

  it('0.5 over an opaque object behind it, whichever comes first in the scene', () => {
    const glassy = object(quad(4, 4), { position: [0, 0, 1] }, { opacity: 0.5 });
    const wall = object(quad(8, 8), { position: [0, 0, -1] }, { diffuse: [0, 0.8, 0] });
    const lit = [0.6, 0.5, 0.4], wallLit = [0.1, 0.9, 0.1];
    const expected = lit.map((c, k) => expect.closeTo(c * 0.5 + wallLit[k] * 0.5, 12));
    expect(pixel(render(scene([glassy, wall]), FRONT), 80, 60)).toEqual(expected);
    expect(pixel(render(scene([wall, glassy]), FRONT), 80, 60)).toEqual(expected);
    // At ¼ the weights are told apart: colour·¼ + behind·¾.
    const quarter = { ...glassy, material: { ...glassy.material, opacity: 0.25 } };
    expect(pixel(render(scene([quarter, wall]), FRONT), 80, 60)).toEqual(lit.map((c, k) => expect.closeTo(c * 0.25 + wallLit[k] * 0.75, 12)));
  });
});

describe('textures', () => {
  it('an image missing from the map falls back to the procedural texture, without a crash', () => {
    const s = (texture: Material['texture']): Scene => scene([object({ kind: 'box', size: 2 }, { rotation: [20, 30, 0] }, { texture })]);
    const missing = render(s({ kind: 'image', url: 'nowhere.png' }), FRONT, WHITE);
    const procedural = render(s({ kind: 'procedural' }), FRONT);
    expect(missing.rgb).toEqual(procedural.rgb);
  });

  it('an image is read with v = 0 on its bottom row (OBJ convention)', () => {
    // 1×4 image: top two rows red, bottom two blue. The quad's lower half (v < ½) shows the bottom rows.
    const red = [255, 0, 0, 255], blue = [0, 0, 255, 255];
    const images = new Map([['rb.png', { width: 1, height: 4, data: new Uint8Array([...red, ...red, ...blue, ...blue]) }]]);
    const flat: Material = { ...MATTE, ambient: [1, 1, 1], diffuse: [0, 0, 0], texture: { kind: 'image', url: 'rb.png' } };
    const img = render(scene([{ ...object(quad(4, 4)), material: flat }]), FRONT, images);
    const [, top] = project(FRONT, [0, 1, 0]), [, bottom] = project(FRONT, [0, -1, 0]); // v = ¾ and ¼
    expect(pixel(img, 80, Math.floor(top))).toEqual([1, 0, 0]);
    expect(pixel(img, 80, Math.floor(bottom))).toEqual([0, 0, 1]);
  });

  it('each mapping mode textures a sphere (box-filtered too), differently from uv', () => {
    const images = new Map([['grad.png', { width: 4, height: 4, data: Uint8Array.from({ length: 64 }, (_, i) => (i % 4 === 3 ? 255 : (i * 37) % 256)) }]]);
    const draw = (mapping: Material['mapping']): Float64Array =>
      render(scene([object({ kind: 'sphere', radius: 1 }, { rotation: [0, 30, 0] }, { mapping, texture: { kind: 'image', url: 'grad.png' } })]), FRONT, images, { samplesPerAxis: 2 }).rgb;
    const maxDiff = (a: Float64Array, b: Float64Array): number => a.reduce((m, x, i) => Math.max(m, Math.abs(x - b[i])), 0);
    const uv = draw('uv');
    // The sphere's own UVs are the spherical mapping (docs/scene-model.md#texture-mappings) (up to rounding and the seam's pixels).
    const spherical = draw('spherical');
    let off = 0;
    for (let i = 0; i < uv.length; i++) if (Math.abs(uv[i] - spherical[i]) > 1e-9) off++;
    expect(off).toBeLessThan(6);
    for (const m of ['triplanar', 'cylindrical'] as const) {
      const rgb = draw(m);
      expect(rgb.every(Number.isFinite)).toBe(true);
      expect(maxDiff(rgb, uv)).toBeGreaterThan(0.05);
    }
  });
});

describe('glass anywhere', () => {
  const ball = (y: number): SceneObject => object({ kind: 'sphere', radius: 0.5 }, { position: [0.3, y, 0] });
  const floorGlass: Scene['glass'] = { center: [0, 0, 0], normal: [0, 1, 0], size: [8, 8] };
  const view: ViewState = { ...FRONT, cameraPosition: [0, 2, 6], yaw: -90, pitch: -25, view: 'reflection' };

  it('a glass floor reflects a ball above it where a ball mirrored below it is seen directly', () => {
    const reflected = render(scene([ball(1)], [SUN], floorGlass), view);
    const mirrored = render(scene([ball(-1)]), { ...view, view: 'scene' });
    let count = 0, differ = 0;
    for (let i = 0; i < reflected.keys.length; i++) {
      const a = reflected.keys[i] !== 0, b = mirrored.keys[i] !== 0;
      count += Number(a);
      differ += Number(a !== b);
    }
    expect(count).toBeGreaterThan(300);
    expect(differ).toBe(0);
    // And the final image shows it on the glass.
    const final = render(scene([ball(1)], [SUN], floorGlass), { ...view, view: 'final' });
    let onGlass = 0;
    for (let i = 0; i < final.keys.length; i++) {
      if (glassReflectsObject(final.keys[i], final.codes!, 0)) {
        onGlass++;
        expect(mirrored.keys[i]).not.toBe(0);
      }
    }
    expect(onGlass).toBeGreaterThan(count / 2);
  });

  it('glass null: no glass at all, the final image is the scene', () => {
    const s = scene([ball(0.5)]);
    const final = render(s, { ...view, view: 'final' }), plain = render(s, { ...view, view: 'scene' });
    expect(final.rgb).toEqual(plain.rgb);
    expect(final.keys).toEqual(plain.keys);
    expect(final.codes!.glass).toBe(2);
    expect(final.keys.every((k) => k % final.codes!.base !== final.codes!.glass)).toBe(true);
    const reflection = render(s, view);
    for (let i = 0; i < reflection.width * reflection.height; i++) expect(pixel(reflection, i, 0)).toEqual([0.1, 0.2, 0.3]);
  });
});
