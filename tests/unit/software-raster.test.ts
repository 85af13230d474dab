// The software rasterizer (docs/software-renderer.md#rasterisation): top-left fill rule pixel for pixel, shared edges drawn
// exactly once, perspective-correct interpolation, z-buffer order, near-plane clipping; and a row's run as each edge bounds it.
import { describe, expect, it } from 'vitest';
import { projectionMatrix } from '../../src/math/camera';
import { CLIP_DISTANCE, Rasterizer, VARYINGS, type FragmentShader } from '../../src/software/raster';
import { runEnd, runStart } from '../../src/software/edges';
import { SoftwareRenderer } from '../../src/software';
import type { FrameState } from '../../src/frame/types';
import type { Scene } from '../../src/scene/scene';
import { AMBIENT, material, STATE as QUAD_STATE, unitQuad, WHITE } from './helpers/quad-scenes';

const STRIDE = VARYINGS + 3;

/** Counts fragments per pixel and keeps the last fragment's first varying and id. */
class Recorder implements FragmentShader {
  readonly count: Uint32Array;
  readonly value: Float64Array;
  readonly id: Int32Array;
  current = 0;
  constructor(readonly width: number, readonly height: number) {
    this.count = new Uint32Array(width * height);
    this.value = new Float64Array(width * height);
    this.id = new Int32Array(width * height).fill(-1);
  }
  fragment(pixel: number, r: Rasterizer): void {
    this.count[pixel]++;
    const p = r.poly;
    this.value[pixel] = r.b0 * p[r.o0] + r.b1 * p[r.o1] + r.b2 * p[r.o2];
    this.id[pixel] = this.current;
  }
  covered(): string[] {
    const out: string[] = [];
    for (let i = 0; i < this.count.length; i++) if (this.count[i] > 0) out.push(`${i % this.width},${Math.floor(i / this.width)}`);
    return out;
  }
}

function rasterizer(width: number, height: number): Rasterizer {
  const r = new Rasterizer(width, height);
  r.stride = STRIDE;
  r.clearDepth();
  r.depthTest = false;
  r.derivatives = false;
  return r;
}

/** Vertices given in pixel coordinates (x right, y down) at NDC depth z, w = 1; varying 0 = `value`. */
function pixelVertices(width: number, height: number, points: readonly (readonly number[])[], z = 0, value = 0): Float64Array {
  const v = new Float64Array(points.length * STRIDE);
  points.forEach(([x, y], i) => {
    const o = i * STRIDE;
    v[o] = (2 * x) / width - 1;
    v[o + 1] = 1 - (2 * y) / height;
    v[o + 2] = z;
    v[o + 3] = 1;
    v[o + VARYINGS] = value;
  });
  return v;
}

function draw(r: Rasterizer, rec: Recorder, points: readonly (readonly number[])[], z = 0, value = 0): void {
  const v = pixelVertices(r.width, r.height, points, z, value);
  const idx = Array.from({ length: points.length }, (_, i) => i);
  r.drawTriangles(v, idx, idx.length, rec);
}

describe('top-left fill rule', () => {
  it('a unit square split on its diagonal: each centre on the diagonal goes to exactly one half', () => {
    // Square [0, 2]², diagonal from (2, 0) to (0, 2) through the centre (1.5, 0.5)? No: through
    // (0.5, 1.5) and (1.5, 0.5) — both centres lie exactly on it.
    const r = rasterizer(4, 4);
    const a = new Recorder(4, 4), b = new Recorder(4, 4);
    draw(r, a, [[0, 0], [2, 0], [0, 2]]);
    draw(r, b, [[2, 0], [2, 2], [0, 2]]);
    // The diagonal is a right edge of the upper-left triangle and a left edge of the other.
    expect(a.covered()).toEqual(['0,0']);
    expect(b.covered().sort()).toEqual(['0,1', '1,0', '1,1']);
  });

  it('a top edge through pixel centres is drawn, a bottom edge is not', () => {
    const r = rasterizer(4, 4);
    const below = new Recorder(4, 4), above = new Recorder(4, 4);
    draw(r, below, [[0, 0.5], [4, 0.5], [0, 4]]); // its top edge y = 0.5 runs through row 0's centres
    draw(r, above, [[0, 0.5], [4, -4], [4, 0.5]]); // the same line is its bottom edge
    expect(below.covered().filter((p) => p.endsWith(',0')).sort()).toEqual(['0,0', '1,0', '2,0', '3,0']);
    expect(above.covered().filter((p) => p.endsWith(',0'))).toEqual([]);
  });

  it('a left edge through pixel centres is drawn, a right edge is not', () => {
    const r = rasterizer(4, 4);
    const right = new Recorder(4, 4), left = new Recorder(4, 4);
    draw(r, right, [[1.5, 0], [4, 0], [1.5, 4]]); // its left edge x = 1.5 through column 1's centres
    draw(r, left, [[1.5, 0], [1.5, 4], [-3, 4]]); // the same line as its right edge
    expect(right.covered().filter((p) => p.startsWith('1,')).sort()).toEqual(['1,0', '1,1', '1,2', '1,3']);
    expect(left.covered().filter((p) => p.startsWith('1,'))).toEqual([]);
  });

  it('tiny triangles: one around a centre covers that pixel only, one beside every centre covers none', () => {
    const r = rasterizer(4, 4);
    const inside = new Recorder(4, 4), beside = new Recorder(4, 4), vertexOn = new Recorder(4, 4);
    draw(r, inside, [[2.4, 1.4], [2.7, 1.45], [2.45, 1.7]]);
    draw(r, beside, [[2.6, 1.6], [2.9, 1.6], [2.6, 1.9]]);
    // A vertex exactly on a centre: covered only where the rule says (here: two edges through it,
    // top and left, so yes).
    draw(r, vertexOn, [[1.5, 1.5], [1.9, 1.5], [1.5, 1.9]]);
    expect(inside.covered()).toEqual(['2,1']);
    expect(beside.covered()).toEqual([]);
    expect(vertexOn.covered()).toEqual(['1,1']);
  });

  it('the same pixels whichever vertex comes first: each edge the first, second and third in turn', () => {
    const rotations = (t: number[][]) => [t, [t[1], t[2], t[0]], [t[2], t[0], t[1]]];
    const row0 = (p: string) => p.endsWith(',0'), column1 = (p: string) => p.startsWith('1,');
    const cases: [string, number[][], (p: string) => boolean, string[]][] = [
      ['top edge', [[0, 0.5], [4, 0.5], [0, 4]], row0, ['0,0', '1,0', '2,0', '3,0']],
      ['bottom edge', [[0, 0.5], [4, -4], [4, 0.5]], row0, []],
      ['left edge', [[1.5, 0], [4, 0], [1.5, 4]], column1, ['1,0', '1,1', '1,2', '1,3']],
      ['right edge', [[1.5, 0], [1.5, 4], [-3, 4]], column1, []],
      // A right edge running down and right, y = x, through the centres (0.5, 0.5) and (1.5, 1.5):
      // neither drawn, (0.5, 1.5) alone is inside.
      ['right edge down and right', [[0, 0], [2, 2], [0, 2]], () => true, ['0,1']],
    ];
    const r = rasterizer(4, 4);
    for (const [name, triangle, where, want] of cases) {
      for (const [n, t] of rotations(triangle).entries()) {
        const rec = new Recorder(4, 4);
        draw(r, rec, t);
        expect(rec.covered().filter(where).sort(), `${name}, rotation ${n}`).toEqual(want);
      }
    }
  });

  it('either winding covers the same pixels (two-sided meshes, the mirrored pass)', () => {
    const r = rasterizer(8, 8);
    const cw = new Recorder(8, 8), ccw = new Recorder(8, 8);
    draw(r, cw, [[0.5, 0.5], [6.5, 1.5], [2.5, 7.5]]);
    draw(r, ccw, [[0.5, 0.5], [2.5, 7.5], [6.5, 1.5]]);
    expect(ccw.covered()).toEqual(cw.covered());
    expect(cw.covered().length).toBeGreaterThan(10);
  });
});

describe("a row's run: the pixels k where an edge's e + k·step ≥ 0 can hold, one wider either side", () => {
  // Steps are whole 1/256 px (edges.ts): ±256 here, an edge at 45° or one pixel a row.
  const PAST_ANY_SPAN = 1_000_000;

  it('starts where e + k·step first reaches 0, one early; at 0 where it holds already', () => {
    expect([runStart(0, 256), runStart(100, 256), runStart(100, 0), runStart(100, -256)]).toEqual([0, 0, 0, 0]);
    // −600 + 3 × 256 = 168 ≥ 0 first at k = 3; −512 + 2 × 256 = 0 at k = 2.
    expect([runStart(-600, 256), runStart(-512, 256)]).toEqual([2, 1]);
    // e < 0 with a step of 0 or one going down: never.
    expect(runStart(-10, 0)).toBeGreaterThan(PAST_ANY_SPAN);
    expect(runStart(-10, -256)).toBeGreaterThan(PAST_ANY_SPAN);
  });

  it('ends where e + k·step last holds, one late, capped at the span; −1 where it never does', () => {
    // 600 − 2 × 256 = 88 ≥ 0 last at k = 2; 512 − 2 × 256 = 0 at k = 2.
    expect([runEnd(600, -256, 10), runEnd(512, -256, 10), runEnd(600, -256, 2)]).toEqual([3, 3, 2]);
    expect([runEnd(-10, -256, 10), runEnd(-10, 0, 10)]).toEqual([-1, -1]);
    expect([runEnd(0, -256, 10), runEnd(0, 0, 10), runEnd(-600, 256, 10), runEnd(5, 256, 10)]).toEqual([1, 10, 10, 10]);
  });
});

describe('shared edges', () => {
  it('a fan of triangles around a point and a grid of quads: every pixel drawn at most once, none missed', () => {
    const W = 32, H = 32, r = rasterizer(W, H);
    const rec = new Recorder(W, H);
    // Fan around (16, 16) whose spokes end on pixel centres and corners alike, closing a polygon.
    const ring: number[][] = [];
    const n = 23;
    for (let k = 0; k < n; k++) {
      const a = (2 * Math.PI * k) / n;
      ring.push([Math.round(16 + 14 * Math.cos(a)) + (k % 2 === 0 ? 0.5 : 0), Math.round(16 + 14 * Math.sin(a)) + (k % 3 === 0 ? 0.5 : 0)]);
    }
    for (let k = 0; k < n; k++) draw(r, rec, [[16.5, 16.5], ring[k], ring[(k + 1) % n]]);
    // Inside the polygon (point-in-polygon by crossings; centres exactly on the rim excluded).
    expect(coverageFaults(rec, ring)).toEqual({ missed: 0, twice: 0 });

    // A jittered 9×9 vertex grid over [2, 30]², alternate diagonals; vertices on centres,
    // corners and arbitrary 1/256 positions.
    const grid = new Recorder(W, H);
    const p = (i: number, j: number) => [2 + 3.5 * i + (i % 3 === 1 ? 0.5 : i % 3 === 2 ? 0.37109375 : 0), 2 + 3.5 * j + ((i + j) % 2 ? 0.5 : 0.2)];
    for (let j = 0; j < 8; j++) {
      for (let i = 0; i < 8; i++) {
        const a = p(i, j), b = p(i + 1, j), c = p(i + 1, j + 1), d = p(i, j + 1);
        if ((i + j) % 2) { draw(r, grid, [a, b, c]); draw(r, grid, [a, c, d]); } else { draw(r, grid, [a, b, d]); draw(r, grid, [b, c, d]); }
      }
    }
    const outline = [...[0, 1, 2, 3, 4, 5, 6, 7, 8].map((i) => p(i, 0)), ...[1, 2, 3, 4, 5, 6, 7, 8].map((j) => p(8, j)),
      ...[7, 6, 5, 4, 3, 2, 1, 0].map((i) => p(i, 8)), ...[7, 6, 5, 4, 3, 2, 1].map((j) => p(0, j))];
    expect(coverageFaults(grid, outline)).toEqual({ missed: 0, twice: 0 });
  });

  it('a kt = 0.5 mesh of two triangles sharing a diagonal over a black background: no pixel blended twice or missed', () => {
    // A 2×2 quad facing the camera whose corners project onto pixel corners (4, 4) and (12, 12)
    // of a 16×16 image: the diagonal runs through the centres (k + ½, k + ½).
    const W = 16;
    const scene: Scene = {
      glass: null, background: [0, 0, 0], lights: [AMBIENT],
      objects: [unitQuad(material([0.8, 0.8, 0.8], { kind: 'image', url: 'white' }, 0.5))],
    };
    const state: FrameState = { ...QUAD_STATE, width: W, height: W, colorSpace: 'none' };
    const rgba = new SoftwareRenderer().render(scene, state, WHITE);
    const once = Math.round(0.8 * 0.5 * 255), twiceBlended = Math.round((0.8 * 0.5 + 0.4 * 0.5) * 255);
    let blendedTwice = 0, missed = 0, onDiagonal = 0;
    for (let y = 4; y < 12; y++) {
      for (let x = 4; x < 12; x++) {
        const v = rgba[4 * (y * W + x)];
        if (x === y) onDiagonal++;
        if (v === twiceBlended) blendedTwice++;
        else if (v !== once) missed++;
      }
    }
    expect(onDiagonal).toBe(8);
    expect({ blendedTwice, missed }).toEqual({ blendedTwice: 0, missed: 0 });
    // And nothing outside the quad.
    expect(rgba[4 * (3 * W + 3)]).toBe(0);
    expect(rgba[4 * (12 * W + 12)]).toBe(0);
  });
});

/** Pixels `rec` saw more than one fragment at, and pixels whose centre is strictly inside `outline` that it saw none at. */
function coverageFaults(rec: Recorder, outline: number[][]): { missed: number; twice: number } {
  let missed = 0, twice = 0;
  for (let y = 0; y < rec.height; y++) {
    for (let x = 0; x < rec.width; x++) {
      const c = rec.count[y * rec.width + x];
      if (c > 1) twice++;
      if (c === 0 && strictlyInside(outline, x + 0.5, y + 0.5)) missed++;
    }
  }
  return { missed, twice };
}

/** Even-odd test; points within 1e-9 of an edge count as outside. */
function strictlyInside(poly: number[][], x: number, y: number): boolean {
  let inside = false;
  for (let i = 0, j = poly.length - 1; i < poly.length; j = i++) {
    const [xi, yi] = poly[i], [xj, yj] = poly[j];
    const cross = (xj - xi) * (y - yi) - (yj - yi) * (x - xi);
    const dot = (x - xi) * (x - xj) + (y - yi) * (y - yj);
    if (Math.abs(cross) < 1e-9 && dot <= 0) return false;
    if ((yi > y) !== (yj > y) && x < ((xj - xi) * (y - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

/** Clip-space vertices of view-space points through a camera at the origin looking down −Z. */
function viewVertices(projection: Float64Array, points: readonly (readonly number[])[], values: readonly number[]): Float64Array {
  const v = new Float64Array(points.length * STRIDE);
  const m = projection;
  points.forEach(([x, y, z], i) => {
    const o = i * STRIDE;
    v[o] = m[0] * x + m[8] * z;
    v[o + 1] = m[5] * y + m[9] * z;
    v[o + 2] = m[10] * z + m[14];
    v[o + 3] = -z;
    v[o + CLIP_DISTANCE] = 0;
    v[o + VARYINGS] = values[i];
  });
  return v;
}

describe('perspective-correct interpolation', () => {
  it('a triangle at a steep angle: the interpolated view depth is the ray-cast one at every pixel', () => {
    const W = 64, H = 64, fov = 60, aspect = W / H;
    const t = Math.tan((fov * Math.PI) / 360);
    const projection = projectionMatrix(new Float64Array(16), fov, aspect, 0.1, 100);
    // Vertices chosen by pixel position (whole pixels: exactly on the 1/256 snapping grid, so the
    // drawn triangle is the analytic one) and depth: near at the bottom, 40× farther at the top.
    const at = (px: number, py: number, depth: number) =>
      [((2 * px) / W - 1) * t * aspect * depth, (1 - (2 * py) / H) * t * depth, -depth];
    const tri = [at(2, 62, 1), at(62, 62, 1), at(32, 3, 40)];
    const v = viewVertices(projection, tri, tri.map((p) => p[2]));
    const r = rasterizer(W, H);
    const rec = new Recorder(W, H);
    r.drawTriangles(v, [0, 1, 2], 3, rec);
    // The triangle's plane n·p = n·a; the ray (dx, dy, −1)·s meets it at s = n·a / n·(dx, dy, −1).
    const [a, b, c] = tri;
    const e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]], e2 = [c[0] - a[0], c[1] - a[1], c[2] - a[2]];
    const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const na = n[0] * a[0] + n[1] * a[1] + n[2] * a[2];
    let checked = 0, worst = 0, affineWorst = 0;
    for (let py = 0; py < H; py++) {
      for (let px = 0; px < W; px++) {
        if (rec.count[py * W + px] === 0) continue;
        const dx = ((2 * (px + 0.5)) / W - 1) * t * aspect, dy = (1 - (2 * (py + 0.5)) / H) * t;
        const depth = na / (n[0] * dx + n[1] * dy - n[2]);
        worst = Math.max(worst, Math.abs(rec.value[py * W + px] + depth) / depth);
        // What screen-affine interpolation would give, between the near row (1) and the apex (40).
        const affine = 1 + (39 * (62 - (py + 0.5))) / 59;
        affineWorst = Math.max(affineWorst, Math.abs(affine - depth) / depth);
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(1000);
    expect(affineWorst).toBeGreaterThan(1); // the test can tell the two apart
    expect(worst).toBeLessThan(1e-9);
  });
});

describe('z-buffer', () => {
  it('the nearer of two overlapping triangles wins in either drawing order; equal depth keeps the first', () => {
    for (const order of [[0, 1], [1, 0]]) {
      const r = rasterizer(8, 8);
      r.depthTest = true;
      r.depthWrite = true;
      const rec = new Recorder(8, 8);
      for (const k of order) {
        rec.current = k;
        draw(r, rec, [[0, 0], [8, 0], [0, 8]], k === 0 ? 0.5 : -0.25);
      }
      expect(rec.id[0]).toBe(1); // z = −0.25 is nearer
    }
    const r = rasterizer(8, 8);
    r.depthTest = true;
    const rec = new Recorder(8, 8);
    rec.current = 0;
    draw(r, rec, [[0, 0], [8, 0], [0, 8]], 0.1);
    rec.current = 1;
    draw(r, rec, [[0, 0], [8, 0], [0, 8]], 0.1);
    expect(rec.id[0]).toBe(0); // LESS, as GL's default
  });

  it('without depth write a later surface behind is still hidden by what was written', () => {
    const r = rasterizer(8, 8);
    r.depthTest = true;
    const rec = new Recorder(8, 8);
    draw(r, rec, [[0, 0], [8, 0], [0, 8]], 0);
    r.depthWrite = false;
    rec.current = 1;
    draw(r, rec, [[0, 0], [8, 0], [0, 8]], -0.5); // in front: drawn, writes nothing
    rec.current = 2;
    draw(r, rec, [[0, 0], [8, 0], [0, 8]], 0.5); // behind the first: hidden
    expect(rec.id[0]).toBe(1);
    expect(rec.count[0]).toBe(2);
  });
});

describe('near-plane clipping', () => {
  it('a floor triangle reaching behind the eye: coverage and interpolated values match ray casting', () => {
    const W = 48, H = 32, fov = 70;
    const projection = projectionMatrix(new Float64Array(16), fov, W / H, 0.1, 100);
    // In view space; the first two vertices lie behind the eye (z > 0), one far in front.
    const tri = [[-30, -0.05, 20], [30, -0.05, 20], [0, -0.05, -30]];
    const v = viewVertices(projection, tri, tri.map((p) => p[0])); // varying: view x
    const r = rasterizer(W, H);
    const rec = new Recorder(W, H);
    r.drawTriangles(v, [0, 1, 2], 3, rec);
    const t = Math.tan((fov * Math.PI) / 360), aspect = W / H;
    let mismatches = 0, worst = 0, covered = 0, nearerThanNear = 0;
    for (let py = 0; py < H; py++) {
      for (let px = 0; px < W; px++) {
        const nx = (2 * (px + 0.5)) / W - 1, ny = 1 - (2 * (py + 0.5)) / H;
        const dx = nx * t * aspect, dy = ny * t;
        // Hit of y = −0.05 along (dx, dy, −1) at view depth d = −0.05/dy (dy < 0): the bottom rows
        // of the image see it nearer than the near plane (0.1), where it must be clipped.
        const d = dy < 0 ? -0.05 / dy : Infinity;
        const x = dx * d, z = -d;
        const inTri = d >= 0.1 && d <= 100 && insideXZ(tri, x, z);
        if (d < 0.1 && insideXZ(tri, x, z)) nearerThanNear++;
        const got = rec.count[py * W + px] > 0;
        if (got) covered++;
        if (got !== inTri && !nearEdgeXZ(tri, x, z)) mismatches++;
        if (got && inTri) worst = Math.max(worst, Math.abs(rec.value[py * W + px] - x) / Math.max(1, Math.abs(x)));
      }
    }
    expect(covered).toBeGreaterThan(300);
    expect(nearerThanNear).toBeGreaterThan(50);
    expect(mismatches).toBe(0);
    // The vertices the clipper makes (on the near plane and the guard band, far off screen) are
    // snapped to 1/256 px like any other: that, not the interpolation, bounds the error.
    expect(worst).toBeLessThan(1e-2);
  });

  it('a triangle wholly behind the eye draws nothing', () => {
    const projection = projectionMatrix(new Float64Array(16), 60, 1, 0.1, 100);
    const r = rasterizer(8, 8), rec = new Recorder(8, 8);
    r.drawTriangles(viewVertices(projection, [[-1, -1, 1], [1, -1, 1], [0, 1, 1]], [0, 0, 0]), [0, 1, 2], 3, rec);
    expect(rec.covered()).toEqual([]);
  });
});

function insideXZ(tri: number[][], x: number, z: number): boolean {
  const s = (a: number[], b: number[]) => (b[0] - a[0]) * (z - a[2]) - (b[2] - a[2]) * (x - a[0]);
  const e0 = s(tri[0], tri[1]), e1 = s(tri[1], tri[2]), e2 = s(tri[2], tri[0]);
  return (e0 >= 0 && e1 >= 0 && e2 >= 0) || (e0 <= 0 && e1 <= 0 && e2 <= 0);
}

function nearEdgeXZ(tri: number[][], x: number, z: number): boolean {
  for (let i = 0; i < 3; i++) {
    const a = tri[i], b = tri[(i + 1) % 3];
    const len = Math.hypot(b[0] - a[0], b[2] - a[2]);
    const dist = Math.abs((b[0] - a[0]) * (z - a[2]) - (b[2] - a[2]) * (x - a[0])) / len;
    if (dist < 1e-6 * Math.max(1, Math.abs(x), Math.abs(z))) return true;
  }
  return false;
}
