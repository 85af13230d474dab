// The software object shader (src/software/object-shader.ts) drawn directly, without a renderer: a 4×4 target the
// quad [−1, 1]² (z = 0, object space) fills, seen through an identity projection, so every value a fragment reads is
// affine in the screen and can be worked by hand: the vertex stage's transforms, Phong per pixel against Gouraud and
// flat per vertex (or per face's centroid), the texture's lookup per mapping (a recording texture), the clamp,
// emissive, two-sided lighting, straight alpha blending, the distance codes per sample, the timing run, and the
// frame-to-frame cache (a frame after a change shades as a fresh shader does).
import { afterEach, describe, expect, it, vi } from 'vitest';
import { pbrMaterial } from './helpers/pbr-scenes';
import { cylindricalUV, sphericalUV } from '../../src/scene/mapping';
import type { MeshData } from '../../src/scene/geometry/mesh-data';
import type { Bounds, Mapping, Material } from '../../src/scene/scene';
import type { Shading } from '../../src/frame/types';
import { Lights } from '../../src/software/lighting';
import { MipTexture } from '../../src/software/mip-texture';
import { ObjectCache } from '../../src/software/object-cache';
import { ObjectShader, OBJECT_STRIDE, type ObjectDraw, type SoftwareTiming } from '../../src/software/object-shader';
import { Rasterizer, VARYINGS } from '../../src/software/raster';

const W = 4, H = 4;
// Pixel (i, j)'s centre: x = (2i + 1)/4 − 1, y = 1 − (2j + 1)/4 (NDC = world = object space with the defaults below).
const px = (i: number) => (2 * i + 1) / W - 1, py = (j: number) => 1 - (2 * j + 1) / H;
const PIXELS: number[][] = [];
for (let j = 0; j < H; j++) for (let i = 0; i < W; i++) PIXELS.push([i, j]);

/** The quad as two triangles (0 1 2, 0 2 3); normals and UVs per corner (UV = ((x + 1)/2, (y + 1)/2) unless given). */
function quad(normals?: number[][], uvs = true): MeshData {
  const corners = [[-1, -1], [1, -1], [1, 1], [-1, 1]];
  return {
    positions: Float32Array.from(corners.flatMap(([x, y]) => [x, y, 0])),
    normals: normals ? Float32Array.from(normals.flat()) : new Float32Array(0),
    uvs: uvs ? Float32Array.from(corners.flatMap(([x, y]) => [(x + 1) / 2, (y + 1) / 2])) : new Float32Array(0),
    indices: Uint16Array.from([0, 1, 2, 0, 2, 3]),
  };
}
const UP = [[0, 0, 1], [0, 0, 1], [0, 0, 1], [0, 0, 1]];

const identity4 = () => Float64Array.from([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]);
const identity3 = () => Float64Array.from([1, 0, 0, 0, 1, 0, 0, 0, 1]);
/** projection × view for eye-relative points: clip = (rx, ry, rz + 2, 1), the quad (rz = −2 from the eye at z = 2) at NDC z 0. */
const VP = () => { const m = identity4(); m[14] = 2; return m; };

interface LightSpec { vector: number[]; point?: boolean; ambient?: number[]; diffuse?: number[]; specular?: number[] }
function lights(list: LightSpec[]): Lights {
  const l = new Lights();
  l.count = list.length;
  list.forEach((s, i) => {
    l.vector.set(s.vector, 3 * i);
    l.point[i] = s.point ? 1 : 0;
    l.ambient.set(s.ambient ?? [0, 0, 0], 3 * i);
    l.diffuse.set(s.diffuse ?? [0, 0, 0], 3 * i);
    l.specular.set(s.specular ?? [0, 0, 0], 3 * i);
  });
  return l;
}
/** Ambient light 1 on ka 1, nothing else: a = 1, s = 0, the colour is the texture's. */
const AMBIENT_ONLY = () => lights([{ vector: [0, 0, 1], ambient: [1, 1, 1] }]);

function material(m: Partial<Material> = {}): Material {
  return {
    ambient: [1, 1, 1], diffuse: [0, 0, 0], specular: [0, 0, 0], shininess: 1, opacity: 1,
    texture: { kind: 'procedural' }, mapping: 'uv', ...m,
  };
}
const WHITE = new MipTexture(1, 1, 1, new Float32Array([1]));

function draw(o: Partial<ObjectDraw> = {}): ObjectDraw {
  return {
    mesh: quad(UP), model: identity4(), normal: identity3(), eye: [0, 0, 2], view: [0, 0, 1, 0], viewProjection: VP(),
    clipPlane: null, material: material(), bounds: { center: [0, 0, 0], radius: 1 }, texture: WHITE, twoSided: false,
    shading: 'phong', lights: AMBIENT_ONLY(), cache: null, index: 0, maps: { metalRough: null, occlusion: null, emissive: null, normal: null, alpha: null }, ...o,
  };
}

function rasterizer(n = 1): Rasterizer {
  const r = new Rasterizer(W * n, H * n);
  r.shadeEvery = n;
  r.clearDepth();
  return r;
}

/** One draw over a fresh target filled with `fill`; the colour buffer. */
function render(d: ObjectDraw, fill = -1, n = 1): Float32Array {
  const s = new ObjectShader(), r = rasterizer(n);
  s.colour = new Float32Array(3 * W * H * n * n).fill(fill);
  s.render(d, r);
  return s.colour;
}

const at = (c: Float32Array, i: number, j: number, w = W) => [c[3 * (j * w + i)], c[3 * (j * w + i) + 1], c[3 * (j * w + i) + 2]];
const expectRgb = (got: number[], want: number[], label = '') => want.forEach((x, k) => expect(got[k], `${label} ${k}`).toBeCloseTo(x, 6));

/** Blinn-Phong of one directional light (unit l), written out: [a, s] per channel for unit n and v. */
function blinn(n: number[], l: number[], v: number[], m: Material, light: Required<LightSpec>): number[] {
  const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const nl = dot(n, l);
  const h = [l[0] + v[0], l[1] + v[1], l[2] + v[2]], hl = Math.hypot(h[0], h[1], h[2]);
  const spec = nl > 0 ? Math.max(dot(n, h) / hl, 0) ** m.shininess : 0;
  const a = [0, 1, 2].map((k) => m.ambient[k] * light.ambient[k] + m.diffuse[k] * light.diffuse[k] * Math.max(nl, 0));
  return [...a, ...[0, 1, 2].map((k) => m.specular[k] * light.specular[k] * spec)];
}
const unit = (v: number[]) => { const l = Math.hypot(v[0], v[1], v[2]); return v.map((x) => x / l); };

const LIGHT0 = { vector: [0.6, 0, 0.8], ambient: [0.2, 0.2, 0.2], diffuse: [0.5, 0.5, 0.5], specular: [0.3, 0.3, 0.3] };

afterEach(() => { vi.restoreAllMocks(); });

describe('ObjectShader.render: the vertex stage and the rasterizer', () => {
  it('sets the stride, the user clip and the derivatives on the rasterizer, and fills the quad', () => {
    const s = new ObjectShader(), r = rasterizer();
    r.derivatives = false;
    r.userClip = true;
    s.colour = new Float32Array(3 * W * H).fill(-1);
    s.render(draw(), r);
    expect([r.stride, r.userClip, r.derivatives]).toEqual([OBJECT_STRIDE, false, true]);
    // Position (3), normal (3), UV (2), object position (3) and normal (3), tangent (4), colour (3).
    expect(OBJECT_STRIDE).toBe(VARYINGS + 21);
    // Ambient only, white: every pixel 1.
    for (const [i, j] of PIXELS) expect(at(s.colour, i, j)).toEqual([1, 1, 1]);
    // A clip plane sets userClip.
    s.render(draw({ clipPlane: [0, 0, 0, 1] }), r);
    expect(r.userClip).toBe(true);
  });

  it('grows its vertex buffer for a bigger mesh (a quad after a triangle)', () => {
    const s = new ObjectShader(), r = rasterizer();
    s.colour = new Float32Array(3 * W * H).fill(-1);
    const tri = quad(UP);
    tri.indices = Uint16Array.from([0, 1, 2]);
    tri.positions = tri.positions.slice(0, 9);
    s.render(draw({ mesh: tri }), r);
    expect(at(s.colour, 0, 0)).toEqual([-1, -1, -1]); // above the diagonal y = x: not the triangle's
    expect(at(s.colour, 3, 3)).toEqual([1, 1, 1]);
    r.clearDepth();
    s.render(draw(), r);
    expect(at(s.colour, 0, 0)).toEqual([1, 1, 1]);
  });

  it('clips to the user plane through eye-relative points: plane·(rel, 1) ≥ 0', () => {
    // (1, 1, 1, 1.25)·(x, y, −2, 1) = x + y − 0.75: kept where x + y > 0.75 (never 0 at a centre: x + y is a multiple of ½).
    const c = render(draw({ clipPlane: [1, 1, 1, 1.25] }));
    for (const [i, j] of PIXELS) expect(at(c, i, j)[0], `${i},${j}`).toBe(px(i) + py(j) > 0.75 ? 1 : -1);
  });

  it('transforms positions by the model matrix and the eye, normals by the normal matrix (a turn about z)', () => {
    // Model: 90° about z ((x, y) → (−y, x)) and up 0.5 in z, the eye at z 2.5: rel = (−y, x, −2) again, the quad on itself.
    const model = identity4();
    model[0] = 0; model[1] = 1; model[4] = -1; model[5] = 0; model[14] = 0.5;
    const normal = Float64Array.from([0, 1, 0, -1, 0, 0, 0, 0, 1]);
    // Object normals (x, 0, 1) at the corners (x = ±1): interpolated, (x, 0, 1) at an object point x; turned, (0, x, 1)
    // at the world point (−y_o, x_o): N = (0, Y, 1)/√(1 + Y²) at world Y. Light (0, 0, 1), V = (0, 0, 1) (orthographic):
    // N·L = N·H = 1/√(1 + Y²); diffuse kd·Id = 0.5, specular ks·Is = 0.25, shininess 2: a = 0.5c, s = 0.25c².
    const nrm = [[-1, 0, 1], [1, 0, 1], [1, 0, 1], [-1, 0, 1]];
    const d = draw({
      mesh: quad(nrm), model, normal, eye: [0, 0, 2.5],
      material: material({ ambient: [0, 0, 0], diffuse: [1, 1, 1], specular: [1, 1, 1], shininess: 2 }),
      lights: lights([{ vector: [0, 0, 1], diffuse: [0.5, 0.5, 0.5], specular: [0.25, 0.25, 0.25] }]),
    });
    const c = render(d);
    for (const [i, j] of PIXELS) {
      const Y = py(j), k = 1 / Math.sqrt(1 + Y * Y);
      expectRgb(at(c, i, j), [0.5 * k + 0.25 * k * k, 0.5 * k + 0.25 * k * k, 0.5 * k + 0.25 * k * k], `${i},${j}`);
    }
    // At Y = ±0.75: c = 0.8, 0.4 + 0.16.
    expect(at(c, 0, 0)[0]).toBeCloseTo(0.56, 6);
  });
});

describe('Phong, Gouraud and flat', () => {
  // The left corners' normals (0, 0, 2), the right ones' (3, 0, 0) (not unit: normalized per vertex or per pixel).
  const SIDES = [[0, 0, 2], [3, 0, 0], [3, 0, 0], [0, 0, 2]];
  const L = [0.6, 0, 0.8];
  const LIGHT = { vector: L, point: false, ambient: [0.1, 0.2, 0.3], diffuse: [0.5, 0.6, 0.7], specular: [0.4, 0.3, 0.2] };
  const MAT = material({ ambient: [1, 0.5, 0.25], diffuse: [0.8, 0.6, 0.4], specular: [1, 1, 0.5], shininess: 2 });
  const sum = (v: number[]) => [v[0] + v[3], v[1] + v[4], v[2] + v[5]];

  it('phong normalizes the interpolated normal per pixel (orthographic V)', () => {
    const c = render(draw({ mesh: quad(SIDES), shading: 'phong', material: MAT, lights: lights([LIGHT]) }));
    // At x: the normal (0, 0, 2)(1 − t) + (3, 0, 0)t with t = (x + 1)/2, normalized.
    for (const [i, j] of PIXELS) {
      const t = (px(i) + 1) / 2, n = unit([3 * t, 0, 2 * (1 - t)]);
      expectRgb(at(c, i, j), sum(blinn(n, L, [0, 0, 1], MAT, LIGHT)), `${i},${j}`);
    }
  });

  it('phong with V toward the eye point (view w = 1): V = −rel/|rel|, rel = (x, y, −2)', () => {
    const c = render(draw({ mesh: quad(SIDES), view: [0, 0, 0, 1], shading: 'phong', material: MAT, lights: lights([LIGHT]) }));
    for (const [i, j] of PIXELS) {
      const t = (px(i) + 1) / 2, n = unit([3 * t, 0, 2 * (1 - t)]), v = unit([-px(i), -py(j), 2]);
      expectRgb(at(c, i, j), sum(blinn(n, L, v, MAT, LIGHT)), `${i},${j}`);
    }
  });

  it('gouraud lights each vertex (its normal normalized) and interpolates the two sums', () => {
    const c = render(draw({ mesh: quad(SIDES), shading: 'gouraud', material: MAT, lights: lights([LIGHT]) }));
    // Left corners: N = (0, 0, 1): N·L = 0.8, N·H = 1.8/√3.6, (N·H)² = 0.9; right: N = (1, 0, 0): 0.6, (N·H)² = 0.1.
    const left = blinn([0, 0, 1], L, [0, 0, 1], MAT, LIGHT), right = blinn([1, 0, 0], L, [0, 0, 1], MAT, LIGHT);
    expect(left[3]).toBeCloseTo(0.4 * 0.9, 12);
    expect(right[3]).toBeCloseTo(0.4 * 0.1, 12);
    for (const [i, j] of PIXELS) {
      const t = (px(i) + 1) / 2;
      expectRgb(at(c, i, j), sum(left.map((x, k) => x * (1 - t) + right[k] * t)), `${i},${j}`);
    }
  });

  it('gouraud with V toward the eye point: per vertex, (−x, −y, 2)/√6 at the corners', () => {
    const mesh = quad(SIDES), c = render(draw({ mesh, view: [0, 0, 0, 1], shading: 'gouraud', material: MAT, lights: lights([LIGHT]) }));
    const corner = (k: number) => {
      const x = mesh.positions[3 * k], y = mesh.positions[3 * k + 1];
      return blinn(unit(SIDES[k]), L, unit([-x, -y, 2]), MAT, LIGHT);
    };
    const v = [0, 1, 2, 3].map(corner);
    // Pixel (3, 3) (x = 0.75, y = −0.75) lies in triangle 0 1 2 (y < x): x = −b0 + b1 + b2, y = −b0 − b1 + b2 give
    // x − y = 2b1 = 1.5 and x + y = 2(b2 − b0) = 0: barycentrics (0.125, 0.75, 0.125).
    const b = [0.125, 0.75, 0.125];
    expectRgb(at(c, 3, 3), sum(v[0].map((_, k) => b[0] * v[0][k] + b[1] * v[1][k] + b[2] * v[2][k])));
    // Pixel (0, 0) (−0.75, 0.75) in triangle 0 2 3: (0.125, 0.125, 0.75) of corners 0, 2, 3 (likewise).
    expectRgb(at(c, 0, 0), sum(v[0].map((_, k) => 0.125 * v[0][k] + 0.125 * v[2][k] + 0.75 * v[3][k])));
  });

  it('gouraud and phong without normals, or with fewer than the vertices: N = 0 lights ambient only (N·L = 0)', () => {
    for (const shading of ['gouraud', 'phong'] as Shading[]) {
      const c = render(draw({ mesh: quad(), shading, material: MAT, lights: lights([LIGHT]) }));
      expectRgb(at(c, 1, 2), [0.1, 0.1, 0.075], shading); // ka·Ia
      // Normals for one vertex of four: none used.
      const partial = { ...quad(), normals: Float32Array.from([0, 0, 1]) };
      expectRgb(at(render(draw({ mesh: partial, shading, material: MAT, lights: lights([LIGHT]) })), 1, 2), [0.1, 0.1, 0.075], shading);
    }
  });

  it('UVs for fewer than the vertices: none used (u = v = 0)', () => {
    const tex = new MipTexture(1, 4, 4, Float32Array.from({ length: 16 }, (_, p) => p / 16));
    const partial = { ...quad(UP), uvs: Float32Array.from([0.6, 0.6, 0.6, 0.6]) };
    // (0, 0): texels 0, 3, 12, 15 a quarter each.
    expect(at(render(draw({ texture: tex, mesh: partial })), 2, 2)[0]).toBeCloseTo((0 + 3 + 12 + 15) / 64, 6);
  });

  /** The quad as a flat mesh: six vertices, each triangle's centroid on its own three (flat.ts). */
  function flatQuad(withCentroids = true): MeshData {
    const corners = [[-1, -1], [1, -1], [1, 1], [-1, -1], [1, 1], [-1, 1]];
    const centroid = (t: number) => [0, 1, 2].map((k) => [0, 1, 2].reduce((acc, v) => acc + (corners[3 * t + v][k] ?? 0) / 3, 0));
    return {
      positions: Float32Array.from(corners.flatMap(([x, y]) => [x, y, 0])),
      normals: Float32Array.from(corners.flatMap(() => [0, 0, 1])),
      uvs: new Float32Array(12),
      indices: Uint16Array.from([0, 1, 2, 3, 4, 5]),
      centroids: withCentroids ? Float32Array.from([0, 0, 0, 1, 1, 1].flatMap((t) => centroid(t))) : undefined,
    };
  }
  // A point light 1 above the quad's (1, 0) (eye-relative (1, 0, −1)), diffuse only: a = Kd·Id·N·L, N = (0, 0, 1).
  const POINT = { vector: [1, 0, -1], point: true, ambient: [0, 0, 0], diffuse: [1, 1, 1], specular: [0, 0, 0] };
  const DIFFUSE = material({ ambient: [0, 0, 0], diffuse: [1, 1, 1] });
  /** N·L at eye-relative p = (x, y, −2) from the light at (1, 0, −1): 1/|(1 − x, −y, 1)|. */
  const nlAt = (x: number, y: number) => 1 / Math.hypot(1 - x, y, 1);

  it('flat lights each face at its centroid: one value over the triangle', () => {
    const c = render(draw({ mesh: flatQuad(), shading: 'flat', material: DIFFUSE, lights: lights([POINT]) }));
    // Triangle 0 (below the diagonal y = x): centroid (1/3, −1/3); triangle 1: (−1/3, 1/3).
    const lower = nlAt(1 / 3, -1 / 3), upper = nlAt(-1 / 3, 1 / 3);
    expect(lower).not.toBeCloseTo(upper, 3);
    for (const [i, j] of PIXELS) {
      if (px(i) === py(j)) continue; // on the diagonal: either triangle
      const want = py(j) < px(i) ? lower : upper;
      expectRgb(at(c, i, j), [want, want, want], `${i},${j}`);
    }
  });

  it('without centroids, or gouraud with them, the vertices are lit', () => {
    for (const d of [draw({ mesh: flatQuad(false), shading: 'flat' }), draw({ mesh: flatQuad(), shading: 'gouraud' })]) {
      const c = render({ ...d, material: DIFFUSE, lights: lights([POINT]) });
      // Pixel (3, 3) (0.75, −0.75): triangle 0 at barycentrics (0.125, 0.75, 0.125) of its corners (−1, −1), (1, −1), (1, 1).
      const want = 0.125 * nlAt(-1, -1) + 0.75 * nlAt(1, -1) + 0.125 * nlAt(1, 1);
      expectRgb(at(c, 3, 3), [want, want, want], d.shading);
    }
  });

  it('flat with the model turned: the centroid goes through the model matrix and the eye', () => {
    // 90° about z and up 0.5, the eye at 2.5 (as above): the centroid (1/3, −1/3) of triangle 0 lands at (1/3, 1/3).
    const model = identity4();
    model[0] = 0; model[1] = 1; model[4] = -1; model[5] = 0; model[14] = 0.5;
    const c = render(draw({
      mesh: flatQuad(), shading: 'flat', model, eye: [0, 0, 2.5], material: DIFFUSE, lights: lights([POINT]),
    }));
    // Triangle 0's corners (−1, −1), (1, −1), (1, 1) land at (1, −1), (1, 1), (−1, 1): above the diagonal y = −x.
    const want = nlAt(1 / 3, 1 / 3);
    expectRgb(at(c, 3, 0), [want, want, want]);
    const other = nlAt(-1 / 3, -1 / 3);
    expectRgb(at(c, 0, 3), [other, other, other]);
  });

  it('two-sided lighting turns a normal facing away toward the viewer; one-sided leaves it unlit', () => {
    const DOWN = [[0, 0, -1], [0, 0, -1], [0, 0, -1], [0, 0, -1]];
    const light = { ...LIGHT, vector: [0, 0, 1] };
    for (const shading of ['phong', 'gouraud'] as Shading[]) {
      const one = render(draw({ mesh: quad(DOWN), shading, material: MAT, lights: lights([light]) }));
      expectRgb(at(one, 2, 1), [0.1, 0.1, 0.075], shading); // ka·Ia only
      const two = render(draw({ mesh: quad(DOWN), shading, material: MAT, lights: lights([light]), twoSided: true }));
      // N = (0, 0, 1) = L = V: ka·Ia + kd·Id + ks·Is.
      expectRgb(at(two, 2, 1), [0.1 + 0.4 + 0.4, 0.1 + 0.36 + 0.3, 0.075 + 0.28 + 0.1], shading);
    }
  });
});

describe('the colour: texture, emissive, the clamp, alpha', () => {
  it('multiplies a by the texture and adds s; emissive added; each channel clamped to [0, 1]', () => {
    const tex = new MipTexture(3, 1, 1, new Float32Array([0.5, 0.25, 2]));
    const l = lights([{ vector: [0, 0, 1], ambient: [1, 1, 1], specular: [0.1, 0.2, 0.3] }]);
    const m = material({ ambient: [1, 2, -1], specular: [1, 1, 1] });
    // a = (1, 2, −1), s = (0.1, 0.2, 0.3) (N·H = 1): tex·a + s = (0.6, 0.7, −1.7).
    expectRgb(at(render(draw({ texture: tex, lights: l, material: m })), 1, 1), [0.6, 0.7, 0]);
    // Emissive (0.3, 0.4, 2.2): (0.9, 1.1, 0.5) → (0.9, 1, 0.5).
    expectRgb(at(render(draw({ texture: tex, lights: l, material: { ...m, emissive: [0.3, 0.4, 2.2] } })), 1, 1), [0.9, 1, 0.5]);
    // Over 1 and under 0 in the other channels: a = (−1, 3, 1) → (−0.4, 0.95, 2.3) → (0, 0.95, 1).
    expectRgb(at(render(draw({ texture: tex, lights: l, material: { ...m, ambient: [-1, 3, 1] } })), 1, 1), [0, 0.95, 1]);
    // And the other way round: a = (3, −1, 0.5) → (1.6, −0.05, 1.3) → (1, 0, 1).
    expectRgb(at(render(draw({ texture: tex, lights: l, material: { ...m, ambient: [3, -1, 0.5] } })), 1, 1), [1, 0, 1]);
  });

  it('blends straight alpha below opacity 1: colour·α + framebuffer·(1 − α); α < 0 keeps the framebuffer', () => {
    const tex = new MipTexture(3, 1, 1, new Float32Array([1, 0.5, 0]));
    const over = (opacity: number) => {
      const s = new ObjectShader(), r = rasterizer();
      s.colour = new Float32Array(3 * W * H);
      for (let p = 0; p < W * H; p++) s.colour.set([0.2, 0.4, 0.8], 3 * p);
      s.render(draw({ texture: tex, material: material({ opacity }) }), r);
      return at(s.colour, 2, 2);
    };
    // 0.25: (1·0.25 + 0.2·0.75, 0.5·0.25 + 0.4·0.75, 0 + 0.8·0.75) = (0.4, 0.425, 0.6).
    expectRgb(over(0.25), [0.4, 0.425, 0.6]);
    expectRgb(over(1), [1, 0.5, 0]);
    expectRgb(over(1.5), [1, 0.5, 0]);
    expectRgb(over(0), [0.2, 0.4, 0.8]);
    expectRgb(over(-0.5), [0.2, 0.4, 0.8]); // α clamped to 0 (unclamped: 1.5·fb − 0.5·colour)
  });
});

describe("the texture's lookup per mapping", () => {
  /** A texture that records each lookup [u, v, ∂u/∂x, ∂v/∂x, ∂u/∂y, ∂v/∂y] and returns (u, v, ½). */
  function recorder(): { texture: MipTexture; seen: number[][] } {
    const seen: number[][] = [];
    const texture = { sample(l: Float64Array, out: Float64Array) { seen.push([...l]); out[0] = l[0]; out[1] = l[1]; out[2] = 0.5; } };
    return { texture: texture as unknown as MipTexture, seen };
  }
  const byPixel = (seen: number[][], key: (l: number[]) => number[]) => {
    const out = new Map<string, number[]>();
    for (const l of seen) out.set(key(l).join(','), l);
    return out;
  };
  const expectClose = (got: number[], want: number[], label: string) =>
    want.forEach((x, k) => expect(got[k], `${label} ${k}`).toBeCloseTo(x, 9));

  it('uv: the interpolated UV and its screen derivatives (¼ per pixel in u, −¼ in v)', () => {
    const { texture, seen } = recorder();
    const c = render(draw({ texture }));
    expect(seen.length).toBe(W * H);
    for (const [i, j] of PIXELS) {
      const u = (i + 0.5) / W, v = 1 - (j + 0.5) / H;
      expectRgb(at(c, i, j), [u, v, 0.5], `${i},${j}`);
      const l = seen.find((s) => Math.abs(s[0] - u) < 1e-9 && Math.abs(s[1] - v) < 1e-9);
      expect(l, `${i},${j}`).toBeDefined();
      expectClose(l!, [u, v, 0.25, 0, 0, -0.25], `${i},${j}`);
    }
  });

  it('uv on a real texture: pixel (i, j) reads texel (i, 3 − j); without UVs, u = v = 0 (the four corner texels)', () => {
    const data = Float32Array.from({ length: 16 }, (_, p) => p / 16);
    const tex = new MipTexture(1, 4, 4, data);
    const c = render(draw({ texture: tex }));
    for (const [i, j] of PIXELS) expect(at(c, i, j)[0], `${i},${j}`).toBeCloseTo(data[(3 - j) * 4 + i], 6);
    const none = render(draw({ texture: tex, mesh: quad(UP, false) }));
    // (0, 0): s = t = −½, REPEAT: texels 0, 3, 12, 15 a quarter each.
    expect(at(none, 2, 2)[0]).toBeCloseTo((0 + 3 + 12 + 15) / 64, 6);
  });

  it('triplanar: the projections whose weight is > 0, each with its UV, derivatives × 1/2r, weighted', () => {
    const { texture, seen } = recorder();
    // Bounds centre (0, 0, 0.5), r = 2: s = ¼. Normals (1, 0, 1) everywhere: weights ½ along X, ½ along Z, 0 along Y.
    const bounds: Bounds = { center: [0, 0, 0.5], radius: 2 };
    const mesh = quad([[1, 0, 1], [1, 0, 1], [1, 0, 1], [1, 0, 1]]);
    const c = render(draw({ texture, bounds, mesh, material: material({ mapping: 'triplanar' }) }));
    expect(seen.length).toBe(2 * W * H); // the Y projection (weight 0) not read
    for (const [i, j] of PIXELS) {
      const x = px(i), y = py(j);
      // Along X: (½ + (z − 0.5)/4, ½ + y/4) = (0.375, ½ + y/4), derivatives (0, 0; 0, −⅛) (∂y/∂y = −½ a pixel).
      const X = [0.375, 0.5 + y / 4, 0, 0, 0, -0.125];
      // Along Z: (½ + x/4, ½ + y/4), derivatives (⅛, 0; 0, −⅛).
      const Z = [0.5 + x / 4, 0.5 + y / 4, 0.125, 0, 0, -0.125];
      const found = byPixel(seen, (l) => [l[0].toFixed(6), l[1].toFixed(6)].map(Number));
      expectClose(found.get([X[0], X[1]].map((v) => Number(v.toFixed(6))).join(','))!, X, `X ${i},${j}`);
      expectClose(found.get([Z[0], Z[1]].map((v) => Number(v.toFixed(6))).join(','))!, Z, `Z ${i},${j}`);
      // ½·(u, v, ½) of each: (½(0.375 + ½ + x/4), ½ + y/4, ½).
      expectRgb(at(c, i, j), [(0.375 + 0.5 + x / 4) / 2, 0.5 + y / 4, 0.5], `${i},${j}`);
    }
  });

  it('triplanar with the normal along z alone: one projection, weight 1', () => {
    const { texture, seen } = recorder();
    const c = render(draw({ texture, material: material({ mapping: 'triplanar' }) }));
    expect(seen.length).toBe(W * H);
    // r = 1: s = ½; u = ½ + x/2 = (i + ½)/4, v = ½ + y/2.
    expectRgb(at(c, 1, 2), [0.5 + px(1) / 2, 0.5 + py(2) / 2, 0.5]);
  });

  for (const mapping of ['cylindrical', 'spherical'] as Mapping[]) {
    it(`${mapping}: the UV at q, derivatives by one-pixel differences in x and y, u's taken the short way round the seam`, () => {
      const map = mapping === 'cylindrical' ? cylindricalUV : sphericalUV;
      // Centre (0, 0, 1) behind the quad: the seam (−Z from the centre) runs down x = 0, between columns 1 and 2.
      const bounds: Bounds = { center: [0, 0, 1], radius: 2 };
      const { texture, seen } = recorder();
      render(draw({ texture, bounds, material: material({ mapping }) }));
      expect(seen.length).toBe(W * H);
      const uvAt = (x: number, y: number) => map(new Float64Array(2), [x, y, 0], bounds);
      const wrap = (d: number) => d - Math.round(d);
      for (const [i, j] of PIXELS) {
        const x = px(i), y = py(j), q = uvAt(x, y), qx = uvAt(x + 0.5, y), qy = uvAt(x, y - 0.5);
        const want = [q[0], q[1], wrap(qx[0] - q[0]), qx[1] - q[1], wrap(qy[0] - q[0]), qy[1] - q[1]];
        const l = seen.find((s) => Math.abs(s[0] - q[0]) < 1e-9 && Math.abs(s[1] - q[1]) < 1e-9);
        expect(l, `${i},${j}`).toBeDefined();
        expectClose(l!, want, `${i},${j}`);
      }
      // Column 1 → 2 crosses the seam: u goes from about 0.04 to 0.96, a step of about −0.08 the short way.
      const l1 = seen.find((s) => Math.abs(s[0] - uvAt(px(1), py(0))[0]) < 1e-9)!;
      expect(l1[2]).toBeLessThan(0);
      expect(l1[2]).toBeGreaterThan(-0.1);
    });
  }

  it('cylindrical and spherical read positions in object space (before the model matrix)', () => {
    const bounds: Bounds = { center: [0, 0, 1], radius: 2 };
    const model = identity4();
    model[0] = 0; model[1] = 1; model[4] = -1; model[5] = 0;
    const a = recorder(), b = recorder();
    render(draw({ texture: a.texture, bounds, material: material({ mapping: 'cylindrical' }) }));
    render(draw({ texture: b.texture, bounds, model, material: material({ mapping: 'cylindrical' }) }));
    // The turned quad covers the same pixels; the pixel at world (X, Y) is object (Y, −X): its u = ½ + atan2(Y, −1)/2π.
    const us = (s: number[][]) => s.map((l) => l[0].toFixed(9)).sort();
    expect(us(b.seen)).toEqual(us(a.seen.map((l) => l))); // the set of object points is the same quad
    const want = cylindricalUV(new Float64Array(2), [py(0), -px(0), 0], bounds);
    expect(b.seen.some((l) => Math.abs(l[0] - want[0]) < 1e-9 && Math.abs(l[1] - want[1]) < 1e-9)).toBe(true);
  });
});

describe('distance codes and multisampling', () => {
  it('writes h/(1 + h) of the world point (model over the object position) per sample, 0 where h ≤ 0', () => {
    const model = identity4();
    model[0] = 0; model[1] = 1; model[4] = -1; model[5] = 0; model[14] = 0.5;
    const s = new ObjectShader(), r = rasterizer();
    s.colour = new Float32Array(3 * W * H);
    s.codes = new Float32Array(W * H).fill(7);
    // Plane (1, 2, 4, −1.5): h = X + 2Y + 4·0.5 − 1.5 = X + 2Y + 0.5 at the world point (X, Y, 0.5).
    s.codePlane.set([1, 2, 4, -1.5]);
    s.render(draw({ model, eye: [0, 0, 2.5] }), r);
    for (const [i, j] of PIXELS) {
      const h = px(i) + 2 * py(j) + 0.5;
      expect(s.codes[j * W + i], `${i},${j}`).toBeCloseTo(h > 0 ? h / (1 + h) : 0, 6);
    }
    // (3, 0): h = 0.75 + 1.5 + 0.5 = 2.75: 2.75/3.75.
    expect(s.codes[3]).toBeCloseTo(2.75 / 3.75, 6);
    expect(s.codes[12]).toBe(0); // h = −0.75 − 1.5 + 0.5 < 0
  });

  it('multisampled 2×2: one fragment a pixel, its colour and code repeated at the other samples; transparent too', () => {
    const s = new ObjectShader(), r = rasterizer(2);
    s.colour = new Float32Array(3 * 4 * W * H).fill(0.5);
    s.codes = new Float32Array(4 * W * H).fill(7);
    s.codePlane.set([1, 0, 0, 1]); // h = X + 1
    const texture = new MipTexture(3, 1, 1, new Float32Array([1, 0, 0.25]));
    const spy = vi.spyOn(s, 'fragment');
    s.render(draw({ texture, material: material({ opacity: 0.5 }) }), r);
    // Once a pixel and triangle: the four pixels on the diagonal have samples of both triangles.
    expect(spy).toHaveBeenCalledTimes(W * H + 4);
    for (let y = 0; y < 2 * H; y++) {
      for (let x = 0; x < 2 * W; x++) {
        const h = px(x >> 1) + 1; // the pixel's centre, where it was shaded
        expect(s.codes[y * 2 * W + x], `${x},${y}`).toBeCloseTo(h / (1 + h), 6);
        // ½·(1, 0, 0.25) + ½·0.5.
        expectRgb(at(s.colour, x, y, 2 * W), [0.75, 0.25, 0.375], `${x},${y}`);
      }
    }
  });
});

describe('the timing run', () => {
  it('adds the vertex stage and the triangles to the times; constant fragments write 0.5 and leave the cache alone', () => {
    const now = vi.spyOn(performance, 'now');
    [10, 13, 20].forEach((t) => now.mockReturnValueOnce(t));
    const timing: SoftwareTiming = { vertex: 1, triangles: 2, glass: 0, total: 0, constantFragments: true };
    const s = new ObjectShader(), r = rasterizer();
    s.timing = timing;
    s.colour = new Float32Array(3 * W * H).fill(-1);
    const cache = new ObjectCache(), begin = vi.spyOn(cache, 'begin');
    s.render(draw({ cache, material: material({ ambient: [0.2, 0.2, 0.2] }) }), r);
    expect([timing.vertex, timing.triangles]).toEqual([1 + 3, 2 + 7]);
    expect(at(s.colour, 1, 3)).toEqual([0.5, 0.5, 0.5]);
    expect(begin).not.toHaveBeenCalled();
    // Shaded fragments with timing on: the ambient 0.2, and the cache begun.
    timing.constantFragments = false;
    now.mockReturnValue(30);
    r.clearDepth();
    s.render(draw({ cache, material: material({ ambient: [0.2, 0.2, 0.2] }) }), r);
    expectRgb(at(s.colour, 1, 3), [0.2, 0.2, 0.2]);
    expect(begin).toHaveBeenCalledTimes(1);
    expect([timing.vertex, timing.triangles]).toEqual([4, 9]);
  });
});

describe('the frame-to-frame cache', () => {
  const TEX = new MipTexture(3, 2, 2, Float32Array.from([0.9, 0.1, 0.2, 0.3, 0.8, 0.4, 0.5, 0.6, 0.7, 0.2, 0.3, 0.9]));
  const LIT = () => lights([{ vector: [0.6, 0, 0.8], ambient: [0.2, 0.2, 0.2], diffuse: [0.5, 0.5, 0.5], specular: [0.3, 0.3, 0.3] }]);
  const base = (o: Partial<ObjectDraw> = {}) => draw({
    texture: TEX, lights: LIT(), mesh: SHARED, material: material({ diffuse: [0.7, 0.6, 0.5], specular: [1, 1, 1], shininess: 4 }),
    view: [0, 0, 0, 1], ...o,
  });
  // Normals not affine over the quad: its two triangulations shade differently.
  // Corner 2's faces away from the viewer (two-sided lighting turns it).
  const SHARED = quad([[0, 0, 1], [0.3, 0, 1], [0.6, 0.5, -1], [0, 0.2, 1]]);
  interface Frame { d: ObjectDraw; n?: number; cull?: 'none' | 'back'; frontCCW?: boolean; width?: number; height?: number }

  /** The colour buffer after each frame in turn, one shader, rasterizer and cache; `cache` on every draw. */
  function frames(list: Frame[], cache = new ObjectCache()): Float32Array {
    const s = new ObjectShader();
    let r = rasterizer();
    for (const f of list) {
      const n = f.n ?? 1, w = f.width ?? W, h = f.height ?? H;
      if (r.shadeEvery !== n || r.width !== w * n || r.height !== h * n) {
        r = new Rasterizer(w * n, h * n);
        r.shadeEvery = n;
      }
      r.cull = f.cull ?? 'none';
      r.frontCCW = f.frontCCW ?? true;
      r.clearDepth();
      s.colour = new Float32Array(3 * w * h * n * n).fill(-1);
      s.render({ ...f.d, cache }, r);
    }
    return s.colour;
  }
  const fresh = (f: Frame) => frames([f], new ObjectCache());

  it('reads its colours back in the third unchanged frame (entries kept in the second), per pixel and triangle', () => {
    const cache = new ObjectCache(), d = base();
    frames([{ d }, { d }], cache);
    expect(cache.current).not.toBe(0);
    // Overwrite the kept colours: the third frame shows them where it reads them.
    for (let p = 0; p < W * H; p++) cache.rgb.set([0.11, 0.22, 0.33], 3 * p);
    const c = frames([{ d }], cache);
    for (const [i, j] of PIXELS) expect(at(c, i, j), `${i},${j}`).toEqual([0.11, 0.22, 0.33].map(Math.fround));
    // Unchanged frames without tampering give the fresh frame's pixels.
    expect(frames([{ d }, { d }, { d }])).toEqual(fresh({ d }));
  });

  it('multisampled: the entry is the pixel, its colour repeated at its samples', () => {
    const cache = new ObjectCache(), d = base();
    frames([{ d, n: 2 }, { d, n: 2 }], cache);
    for (let p = 0; p < W * H; p++) cache.rgb.set([0.11, 0.22, 0.33], 3 * p);
    const c = frames([{ d, n: 2 }], cache);
    // Off the diagonal y = x (whose pixels keep one triangle's entry: the other's samples shade again).
    for (let y = 0; y < 2 * H; y++) {
      for (let x = 0; x < 2 * W; x++) {
        if ((x >> 1) + (y >> 1) === 3) continue; // i + j = 3: y = x
        expect(at(c, x, y, 2 * W), `${x},${y}`).toEqual([0.11, 0.22, 0.33].map(Math.fround));
      }
    }
  });

  it('begins the draw with its index, key, objects and the count of pixels (samples / n²)', () => {
    const cache = new ObjectCache(), begin = vi.spyOn(cache, 'begin');
    const s = new ObjectShader(), r = new Rasterizer(8, 12);
    r.shadeEvery = 2;
    r.clearDepth();
    s.colour = new Float32Array(3 * 96);
    // The environment and the maps are keyed by identity: markers stand for them.
    const lit = AMBIENT_ONLY(), env = {} as NonNullable<Lights['environment']>;
    lit.environment = env;
    const maps = { metalRough: {} as MipTexture, occlusion: {} as MipTexture, emissive: {} as MipTexture, normal: {} as MipTexture, alpha: null };
    s.render(base({ cache, index: 3, lights: lit, maps }), r);
    // 8×12 samples at 2×2 a pixel: 4×6 = 24 pixels.
    expect(begin).toHaveBeenCalledWith(3, expect.any(Float64Array), expect.any(Array), 24);
    const objects = begin.mock.calls[0][2] as unknown[];
    expect(objects.length).toBe(17);
    expect(objects[0]).toBe(SHARED);
    // The mesh's tangents and colours (none here), then the texture, shading, mapping and glTF material (none).
    expect(objects.slice(6, 12)).toEqual([undefined, undefined, TEX, 'phong', 'uv', undefined]);
    [env, maps.metalRough, maps.occlusion, maps.emissive, maps.normal].forEach((o, k) => expect(objects[12 + k], `object ${12 + k}`).toBe(o));
  });

  it('is not used by transparent draws, by draws that write distance codes, or by the constant-fragment timing run', () => {
    const cache = new ObjectCache(), begin = vi.spyOn(cache, 'begin');
    const d = base({ material: material({ opacity: 0.99 }) });
    frames([{ d }, { d }, { d }], cache);
    expect(begin).not.toHaveBeenCalled();
    frames([{ d: base({ material: material({ opacity: 1 }) }) }], cache);
    expect(begin).toHaveBeenCalledTimes(1);
    // Codes: three unchanged frames write every sample's code (a cached pixel would repeat the last code shaded).
    const s = new ObjectShader(), r = rasterizer();
    s.codes = new Float32Array(W * H);
    s.codePlane.set([1, 0, 0, 1]);
    const c2 = new ObjectCache();
    for (let f = 0; f < 3; f++) {
      s.codes.fill(7);
      s.colour = new Float32Array(3 * W * H);
      r.clearDepth();
      s.render(base({ cache: c2 }), r);
    }
    expect(c2.current).toBe(0);
    for (const [i, j] of PIXELS) expect(s.codes[j * W + i]).toBeCloseTo((px(i) + 1) / (px(i) + 2), 6);
  });

  it('a later draw without the cache does not read the earlier draw\'s entries', () => {
    // Object 0 cached over the quad (three frames: its entries kept and read), then object 1 over it, transparent,
    // with the same triangles: it shades its own colour.
    const cache = new ObjectCache(), s = new ObjectShader(), r = rasterizer();
    const opaque = base({ cache });
    const glassy = base({ cache: null, index: 1, texture: WHITE, material: material({ opacity: 0.5, ambient: [0, 0, 0] }) });
    for (let f = 0; f < 3; f++) {
      s.colour = new Float32Array(3 * W * H);
      r.clearDepth();
      s.render(opaque, r);
      const under = at(s.colour, 2, 1);
      r.clearDepth();
      s.render(glassy, r);
      // Black at α ½ over it: half of it.
      expectRgb(at(s.colour, 2, 1), under.map((x) => x / 2), `frame ${f}`);
    }
  });

  // Each change of one value after two unchanged frames (the second kept every entry): the third frame shades as a
  // fresh shader does. Under two settings: plain, and with a clip plane (keeping all), emissive and a second light.
  interface Setting { o?: Partial<ObjectDraw>; mat?: Partial<Material>; ls?: (list: LightSpec[]) => LightSpec[]; f?: Partial<Frame> }
  const MAT0: Partial<Material> = { diffuse: [0.7, 0.6, 0.5], specular: [1, 1, 1], shininess: 4 };
  const LIGHT1 = { vector: [0.48, 0.6, 0.64], ambient: [0.05, 0.05, 0.05], diffuse: [0.2, 0.1, 0.3], specular: [0.1, 0.2, 0.1] };
  const SETTINGS: [string, Setting][] = [
    ['plain', {}],
    ['with a clip plane, emissive and a second light', {
      o: { clipPlane: [0, 0, 0, 1] }, mat: { emissive: [0.05, 0.04, 0.03] }, ls: () => [LIGHT0, LIGHT1],
    }],
  ];
  /** The frame of `extra` under the settings `from` and then `change` (each later one wins). */
  const frameOf = (extra: Setting, ...more: Setting[]): Frame => {
    const all = [extra, ...more];
    let list: LightSpec[] = [LIGHT0];
    for (const x of all) if (x.ls) list = x.ls(list);
    const d = base(Object.assign({}, ...all.map((x) => x.o ?? {})));
    d.material = material(Object.assign({ ...MAT0 }, ...all.map((x) => x.mat ?? {})));
    d.lights = lights(list);
    return Object.assign({ d }, ...all.map((x) => x.f ?? {}));
  };
  /** The last light changed. */
  const lastLight = (o: Partial<LightSpec>) => (list: LightSpec[]) => list.map((l, k) => (k === list.length - 1 ? { ...l, ...o } : l));
  const turned = identity4();
  turned[0] = 0; turned[1] = 1; turned[4] = -1; turned[5] = 0;
  const withVP = (k: number, x: number) => { const m = VP(); m[k] = x; return m; };
  const TRI: Setting = { mat: { mapping: 'triplanar' } };
  // [name, change, the setting of the first two frames (besides the base)].
  const changes: [string, Setting, Setting?][] = [
    ['model', { o: { model: turned, normal: Float64Array.from([0, 1, 0, -1, 0, 0, 0, 0, 1]) } }],
    ['model alone (z)', { o: { model: (() => { const m = identity4(); m[14] = 0.25; return m; })() } }],
    ['normal matrix', { o: { normal: Float64Array.from([1, 0, 0, 0, 1, 0, 0, 0, 0.5]) } }],
    ['normal matrix, last value', { o: { normal: Float64Array.from([1, 0, 0.5, 0, 1, 0, 0, 0, 1]) } }],
    ['view-projection', { o: { viewProjection: withVP(15, 1.25) } }],
    ['eye', { o: { eye: [0, 0, 2.5], viewProjection: withVP(14, 2.5) } }],
    ['eye x', { o: { eye: [0.25, 0, 2], viewProjection: withVP(12, 0.25) } }],
    ['view vector', { o: { view: [0, 0, 1, 0] } }],
    ['view vector, w alone', { o: { view: [0, 0, 0, 0] } }],
    ['view vector, x', { o: { view: [0.6, 0, 0.8, 0] } }],
    ['clip plane, none → one', { o: { clipPlane: [1, 0, 0, 0] } }],
    ['bounds centre x (triplanar)', { ...TRI, o: { bounds: { center: [0.1, 0, 0], radius: 1 } } }, TRI],
    ['bounds centre y (triplanar)', { ...TRI, o: { bounds: { center: [0, 0.1, 0], radius: 1 } } }, TRI],
    ['bounds centre z (triplanar)', { ...TRI, o: { bounds: { center: [0, 0, 0.3], radius: 1 } } }, TRI],
    ['bounds radius (triplanar)', { ...TRI, o: { bounds: { center: [0, 0, 0], radius: 3 } } }, TRI],
    ['ambient', { mat: { ambient: [1, 1, 0.5] } }],
    ['diffuse', { mat: { diffuse: [0.7, 0.6, 0.25] } }],
    ['specular', { mat: { specular: [1, 1, 0.5] } }],
    ['shininess', { mat: { shininess: 8 } }],
    ['emissive', { mat: { emissive: [0.05, 0.04, 0.1] } }],
    ['two-sided', { o: { twoSided: true } }],
    ['grid: multisampled (as many pixels)', { f: { n: 2 } }],
    ['grid: 8×2 pixels (as many)', { f: { width: 8, height: 2 } }],
    ['grid: width alone (fewer pixels)', { f: { width: 4 } }, { f: { width: 8 } }],
    ['grid: height alone (fewer pixels)', { f: { height: 4 } }, { f: { height: 8 } }],
    ['grid: multisampling alone (the same samples, fewer pixels)', { f: { width: 4, height: 4, n: 2 } }, { f: { width: 8, height: 8 } }],
    ['winding', { f: { frontCCW: false, cull: 'back' } }],
    ['a light more', { ls: (l) => [...l, { vector: [0, 1, 0], diffuse: [0.5, 0, 0] }] }],
    ['light vector z', { ls: lastLight({ vector: [0.6, 0, 0.7] }) }],
    ['light vector x', { ls: (l) => l.map((x) => ({ ...x, vector: [0.5, x.vector[1], x.vector[2]] })) }],
    ['light kind', { ls: lastLight({ point: true }) }],
    ['light ambient', { ls: lastLight({ ambient: [0.2, 0.2, 0.5] }) }],
    ['light diffuse', { ls: lastLight({ diffuse: [0.5, 0.5, 0.9] }) }],
    ['light specular', { ls: lastLight({ specular: [0.3, 0.3, 0.9] }) }],
    ['mesh positions', { o: { mesh: { ...SHARED, positions: SHARED.positions.map((v, k) => (k === 0 ? -0.5 : v)) } } }],
    ['mesh normals', { o: { mesh: { ...SHARED, normals: SHARED.normals.map((v, k) => (k === 0 ? 1 : v)) } } }],
    ['mesh uvs', { o: { mesh: { ...SHARED, uvs: SHARED.uvs.map((v) => v / 2) } } }],
    ['mesh indices', { o: { mesh: { ...SHARED, indices: Uint16Array.from([0, 1, 3, 1, 2, 3]) } } }],
    ['texture', { o: { texture: WHITE } }],
    ['shading', { o: { shading: 'gouraud' } }],
    ['mapping', { mat: { mapping: 'spherical' } }],
    // A glTF material (docs/pbr.md#the-scenes-lights): kept by identity, as meshes and textures are (scene values are never written in place).
    ['glTF material', { mat: { pbr: pbrMaterial({ baseColor: [0.9, 0.5, 0.2, 1], metallic: 0.5, roughness: 0.4 }) } }],
  ];
  describe.each(SETTINGS)('%s', (_, extra) => {
    it.each(changes)('a change of %s: the third frame as a fresh shader, and different from the unchanged one', (_, change, from = {}) => {
      const before = frameOf(extra, from), after = frameOf(extra, from, change);
      const old = fresh(before), want = fresh(after);
      if (want.length === old.length) expect(want).not.toEqual(old);
      expect(frames([before, before, after])).toEqual(want);
    });
  });

  it('a change of the mesh object, centroids or clip plane values: the third frame as a fresh shader', () => {
    // Flat meshes that differ only in their centroids (and a copy of the mesh object with the same arrays).
    const flat = (cx: number): MeshData => ({ ...SHARED, centroids: Float32Array.from({ length: 12 }, (_, k) => (k % 3 === 0 ? cx : 0)) });
    const pl = base({ mesh: { ...SHARED, centroids: undefined }, lights: lights([{ ...LIGHT0, vector: [1, 0, -1], point: true }]) });
    const a = flat(0.5), b = { ...a, centroids: flat(-0.5).centroids };
    const fa = { d: { ...pl, mesh: a, shading: 'flat' as Shading } }, fb = { d: { ...pl, mesh: b, shading: 'flat' as Shading } };
    expect(fresh(fb)).not.toEqual(fresh(fa));
    expect(frames([fa, fa, fb])).toEqual(fresh(fb));
    // The plane's values (a plane both times).
    const c1 = { d: base({ clipPlane: [1, 0, 0, 0] }) }, c2 = { d: base({ clipPlane: [1, 0, 0, 0.5] }) };
    const c3 = { d: base({ clipPlane: [1, 0, 0.25, 0] }) };
    expect(fresh(c2)).not.toEqual(fresh(c1));
    expect(frames([c1, c1, c2])).toEqual(fresh(c2));
    expect(fresh(c3)).not.toEqual(fresh(c1));
    expect(frames([c1, c1, c3])).toEqual(fresh(c3));
    // A plane, then none.
    expect(frames([c1, c1, { d: base() }])).toEqual(fresh({ d: base() }));
  });
});

// One triangle of generic values (no ±1, no zero, no symmetry) through a stand-in rasterizer: the vertex buffer the
// shader hands over, and fragment() called with chosen barycentrics, against the formulas written out.
describe('generic values: the vertex buffer and one fragment, against the formulas', () => {
  const P = [[0.3, -0.7, 0.45], [1.2, 0.25, -0.6], [-0.8, 0.9, 0.35]];
  const N = [[0.2, -0.4, 0.9], [-0.5, 0.3, 0.7], [0.6, 0.35, 0.45]];
  const UVS = [[0.15, 0.8], [0.7, 0.35], [0.4, 0.05]];
  const C = [[0.2, 0.3, -0.1], [0.25, 0.35, -0.15], [0.3, 0.4, -0.2]];
  const MODEL = Float64Array.from([1.1, 0.2, -0.3, 0, 0.4, 0.9, 0.5, 0, -0.2, 0.3, 1.3, 0, 0.7, -0.4, 0.25, 1]);
  const NORMAL = Float64Array.from([0.9, 0.1, -0.2, 0.3, 1.1, 0.4, -0.5, 0.2, 0.8]);
  const GVP = Float64Array.from([0.8, 0.1, -0.2, 0.05, 0.15, 0.9, 0.3, -0.1, -0.25, 0.2, -1.1, -0.9, 0.3, -0.2, 0.6, 1.7]);
  const EYE = [0.3, -0.2, 2.1], PLANE = [0.2, -0.5, 0.7, 0.4];
  const mesh = (centroids = false): MeshData => ({
    positions: Float32Array.from(P.flat()), normals: Float32Array.from(N.flat()), uvs: Float32Array.from(UVS.flat()),
    indices: Uint16Array.from([0, 1, 2]), centroids: centroids ? Float32Array.from(C.flat()) : undefined,
  });
  const f32 = (x: number) => Math.fround(x);
  /** The model matrix over an object point (float32 as the mesh holds it), minus the eye. */
  const rel = (q: number[], e = EYE) =>
    [0, 1, 2].map((r) => MODEL[r] * f32(q[0]) + MODEL[4 + r] * f32(q[1]) + MODEL[8 + r] * f32(q[2]) + MODEL[12 + r] - e[r]);
  const world = (q: number[]) => rel(q, [0, 0, 0]);
  const turn = (n: number[]) => [0, 1, 2].map((r) => NORMAL[r] * f32(n[0]) + NORMAL[3 + r] * f32(n[1]) + NORMAL[6 + r] * f32(n[2]));

  interface Stub extends Rasterizer { seen: Float64Array }
  function stub(): Stub {
    const r = new Rasterizer(8, 4) as Stub;
    r.drawTriangles = (v: Float64Array) => { r.seen = v.slice(0, 3 * OBJECT_STRIDE); };
    return r;
  }
  const LIGHT = {
    vector: [0.48, 0.6, 0.64], point: false, ambient: [0.15, 0.1, 0.05], diffuse: [0.6, 0.5, 0.4], specular: [0.5, 0.4, 0.3],
  };
  const MAT = material({ ambient: [0.9, 0.8, 0.7], diffuse: [0.7, 0.6, 0.5], specular: [0.4, 0.5, 0.6], shininess: 3 });
  const gdraw = (o: Partial<ObjectDraw> = {}) => draw({
    mesh: mesh(), model: MODEL, normal: NORMAL, eye: EYE, viewProjection: GVP, clipPlane: PLANE, material: MAT, lights: lights([LIGHT]),
    view: [0, 0, 0, 1], ...o,
  });

  it('writes clip space, the user distance, and per shading the varyings of each vertex', () => {
    for (const shading of ['phong', 'gouraud'] as Shading[]) {
      const s = new ObjectShader(), r = stub();
      s.render(gdraw({ shading }), r);
      for (let k = 0; k < 3; k++) {
        const o = k * OBJECT_STRIDE, v = o + VARYINGS, q = rel(P[k]), got = [...r.seen.subarray(o, o + OBJECT_STRIDE)];
        const clip = [0, 1, 2, 3].map((row) => GVP[row] * q[0] + GVP[4 + row] * q[1] + GVP[8 + row] * q[2] + GVP[12 + row]);
        clip.forEach((x, c) => expect(got[c], `${shading} ${k} clip ${c}`).toBeCloseTo(x, 12));
        expect(got[4]).toBeCloseTo(PLANE[0] * q[0] + PLANE[1] * q[1] + PLANE[2] * q[2] + PLANE[3], 12);
        const n = turn(N[k]);
        if (shading === 'phong') {
          [...q, ...n].forEach((x, c) => expect(r.seen[v + c], `${k} rel/normal ${c}`).toBeCloseTo(x, 12));
        } else {
          const want = blinn(unit(n), LIGHT.vector, unit(q.map((x) => -x)), MAT, LIGHT);
          want.forEach((x, c) => expect(r.seen[v + c], `${k} sums ${c}`).toBeCloseTo(x, 12));
        }
        [...UVS[k], ...P[k], ...N[k]].forEach((x, c) => expect(r.seen[v + 6 + c], `${k} uv/obj ${c}`).toBeCloseTo(f32(x), 12));
      }
    }
  });

  it('gouraud orthographic lights with the view vector; flat at each vertex\'s centroid', () => {
    const ortho = [0.36, 0.48, 0.8, 0];
    const s = new ObjectShader(), r = stub();
    s.render(gdraw({ shading: 'gouraud', view: ortho }), r);
    for (let k = 0; k < 3; k++) {
      const want = blinn(unit(turn(N[k])), LIGHT.vector, ortho, MAT, LIGHT);
      want.forEach((x, c) => expect(r.seen[k * OBJECT_STRIDE + VARYINGS + c], `${k} ${c}`).toBeCloseTo(x, 12));
    }
    // Flat with a point light at eye-relative (0.5, 1.5, −1): L and V from the centroid's eye-relative point.
    const point = { ...LIGHT, vector: [0.5, 1.5, -1], point: true };
    const f = new ObjectShader(), rf = stub();
    f.render(gdraw({ shading: 'flat', mesh: mesh(true), lights: lights([point]) }), rf);
    for (let k = 0; k < 3; k++) {
      const c = rel(C[k]), l = unit([0.5 - c[0], 1.5 - c[1], -1 - c[2]]);
      const want = blinn(unit(turn(N[k])), l, unit(c.map((x) => -x)), MAT, point);
      want.forEach((x, j) => expect(rf.seen[k * OBJECT_STRIDE + VARYINGS + j], `${k} ${j}`).toBeCloseTo(x, 12));
    }
  });

  /** fragment() at barycentrics B with derivatives DX, DY over the vertex buffer the shader wrote. */
  const B = [0.2, 0.3, 0.5], DX = [0.011, -0.023, 0.007], DY = [-0.031, 0.013, 0.019];
  function fragment(d: ObjectDraw, codes = false): { s: ObjectShader; r: Stub } {
    const s = new ObjectShader(), r = stub();
    s.colour = new Float32Array(3 * 32).fill(0.5);
    if (codes) {
      s.codes = new Float32Array(32);
      s.codePlane.set([0.3, -0.6, 0.5, 0.9]);
    }
    s.render(d, r);
    r.poly = r.seen;
    [r.o0, r.o1, r.o2] = [VARYINGS, OBJECT_STRIDE + VARYINGS, 2 * OBJECT_STRIDE + VARYINGS]; // each vertex's varyings
    [r.b0, r.b1, r.b2] = B;
    [r.dbdx0, r.dbdx1, r.dbdx2] = DX;
    [r.dbdy0, r.dbdy1, r.dbdy2] = DY;
    s.fragment(5, r);
    return { s, r };
  }
  const mix = (w: number[], vs: number[][]) => vs[0].map((_, c) => w[0] * vs[0][c] + w[1] * vs[1][c] + w[2] * vs[2][c]);
  function recorder(): { texture: MipTexture; seen: number[][] } {
    const seen: number[][] = [];
    const texture = { sample(l: Float64Array, out: Float64Array) { seen.push([...l]); out[0] = 0.6; out[1] = 0.3; out[2] = 0.45; } };
    return { texture: texture as unknown as MipTexture, seen };
  }

  it('phong: the interpolated point and normal (normalized), V toward the eye; the UV lookup with its derivatives', () => {
    const { texture, seen } = recorder();
    const { s } = fragment(gdraw({ texture, material: { ...MAT, emissive: [0.01, 0.02, 0.03] } }));
    const q = mix(B, P.map((p) => rel(p))), n = unit(mix(B, N.map(turn)));
    const sums = blinn(n, LIGHT.vector, unit(q.map((x) => -x)), MAT, LIGHT);
    const tex = [0.6, 0.3, 0.45], e = [0.01, 0.02, 0.03];
    expectRgb(at(s.colour, 5, 0, 8), [0, 1, 2].map((c) => Math.min(1, tex[c] * sums[c] + sums[3 + c] + e[c])));
    const uv = UVS.map((u) => u.map(f32));
    const want = [...mix(B, uv), ...mix(DX, uv), ...mix(DY, uv)];
    expect(seen.length).toBe(1);
    want.forEach((x, c) => expect(seen[0][c], `lookup ${c}`).toBeCloseTo(x, 12));
  });

  it('phong orthographic: V is the view vector', () => {
    const view = [0.36, 0.48, 0.8, 0];
    const { s } = fragment(gdraw({ view, texture: WHITE }));
    const n = unit(mix(B, N.map(turn)));
    const sums = blinn(n, LIGHT.vector, view, MAT, LIGHT);
    expectRgb(at(s.colour, 5, 0, 8), [0, 1, 2].map((c) => sums[c] + sums[3 + c]));
  });

  it('gouraud: the three sums interpolated', () => {
    const { s, r } = fragment(gdraw({ shading: 'gouraud', texture: new MipTexture(3, 1, 1, new Float32Array([0.6, 0.3, 0.45])) }));
    const sums = mix(B, [0, 1, 2].map((k) => [...r.seen.subarray(k * OBJECT_STRIDE + VARYINGS, k * OBJECT_STRIDE + VARYINGS + 6)]));
    const tex = [0.6, 0.3, 0.45];
    expectRgb(at(s.colour, 5, 0, 8), [0, 1, 2].map((c) => tex[c] * sums[c] + sums[3 + c]));
  });

  it('the distance code of the interpolated world point', () => {
    const { s } = fragment(gdraw({ texture: WHITE }), true);
    const w = world(mix(B, P)), pl = [0.3, -0.6, 0.5, 0.9];
    // mix of float32 positions: world() rounds each again (already float32: unchanged).
    const h = pl[0] * w[0] + pl[1] * w[1] + pl[2] * w[2] + pl[3];
    expect(h).toBeGreaterThan(0);
    expect(s.codes![5]).toBeCloseTo(h / (1 + h), 6);
    // The plane turned: h < 0 gives 0.
    const t = new ObjectShader(), r = stub();
    t.colour = new Float32Array(96);
    t.codes = new Float32Array(32).fill(7);
    t.codePlane.set([-0.3, 0.6, -0.5, -0.9]);
    t.render(gdraw({ texture: WHITE }), r);
    r.poly = r.seen;
    [r.o0, r.o1, r.o2] = [VARYINGS, OBJECT_STRIDE + VARYINGS, 2 * OBJECT_STRIDE + VARYINGS]; // each vertex's varyings
    [r.b0, r.b1, r.b2] = B;
    t.fragment(5, r);
    expect(t.codes[5]).toBe(0);
  });

  it('triplanar: q, the normal and their derivatives interpolated; each projection with weight > 0', () => {
    const { texture, seen } = recorder();
    const bounds: Bounds = { center: [0.1, -0.2, 0.15], radius: 1.6 };
    fragment(gdraw({ texture, bounds, material: { ...MAT, mapping: 'triplanar' } }));
    const q = mix(B, P.map((p) => p.map(f32))), n = mix(B, N.map((p) => p.map(f32)));
    const dqx = mix(DX, P.map((p) => p.map(f32))), dqy = mix(DY, P.map((p) => p.map(f32)));
    const s = 1 / 3.2, U = [2, 0, 0], V = [1, 2, 1];
    expect(seen.length).toBe(3);
    for (let i = 0; i < 3; i++) {
      const want = [0.5 + (q[U[i]] - bounds.center[U[i]]) * s, 0.5 + (q[V[i]] - bounds.center[V[i]]) * s,
        dqx[U[i]] * s, dqx[V[i]] * s, dqy[U[i]] * s, dqy[V[i]] * s];
      want.forEach((x, c) => expect(seen[i][c], `${i} ${c}`).toBeCloseTo(x, 12));
    }
    // The colour: Σ wᵢ·texᵢ with a = 1 (ambient only), each tex (u/2, v/2, ¼); weights |nᵢ|⁴/Σ|n|⁴ of the interpolated
    // object normal.
    const r2 = recorder();
    r2.texture.sample = (l: Float64Array, out: Float64Array) => { out[0] = l[0] / 2; out[1] = l[1] / 2; out[2] = 0.25; };
    const plain = material({ mapping: 'triplanar' });
    const { s: shaded } = fragment(gdraw({ texture: r2.texture, bounds, lights: AMBIENT_ONLY(), material: plain }));
    const w4 = n.map((x) => x ** 4), sum4 = w4[0] + w4[1] + w4[2];
    const uvOf = (i: number) => [0.5 + (q[U[i]] - bounds.center[U[i]]) * s, 0.5 + (q[V[i]] - bounds.center[V[i]]) * s];
    const want = [0, 1].map((c) => [0, 1, 2].reduce((acc, i) => acc + (w4[i] / sum4) * uvOf(i)[c] / 2, 0));
    expectRgb(at(shaded.colour, 5, 0, 8), [...want, 0.25]);
  });

  for (const mapping of ['cylindrical', 'spherical'] as Mapping[]) {
    it(`${mapping}: the UV at q, at q + ∂q/∂x and at q + ∂q/∂y`, () => {
      const map = mapping === 'cylindrical' ? cylindricalUV : sphericalUV;
      const { texture, seen } = recorder();
      const bounds: Bounds = { center: [0.1, -0.2, 0.15], radius: 1.6 };
      fragment(gdraw({ texture, bounds, material: { ...MAT, mapping } }));
      const obj = P.map((p) => p.map(f32));
      const q = mix(B, obj), dqx = mix(DX, obj), dqy = mix(DY, obj);
      const uv = map(new Float64Array(2), q, bounds);
      const ux = map(new Float64Array(2), q.map((x, c) => x + dqx[c]), bounds);
      const uy = map(new Float64Array(2), q.map((x, c) => x + dqy[c]), bounds);
      const wrap = (d: number) => d - Math.round(d);
      const want = [uv[0], uv[1], wrap(ux[0] - uv[0]), ux[1] - uv[1], wrap(uy[0] - uv[0]), uy[1] - uv[1]];
      want.forEach((x, c) => expect(seen[0][c], `${c}`).toBeCloseTo(x, 12));
    });
  }
});
