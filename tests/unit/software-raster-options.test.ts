// The software rasterizer's switches and fields (src/software/raster.ts), each against values worked out by hand on
// tiny targets: culling and winding, the mask, depth (NDC z over w, its bias, write off), the perspective-correct
// barycentrics and their screen derivatives, the clipped polygon's fan and its face numbers, the user plane, a band
// of rows, the target's edges, a reused rasterizer's buffers, and multisampling against the same grid drawn a
// sample at a time.
import { describe, expect, it } from 'vitest';
import { CLIP_DISTANCE, Rasterizer, VARYINGS, type FragmentShader } from '../../src/software/raster';

/** What one fragment saw: its pixel (or sample), face, l0, l1, z, b0..b2 and the six derivatives. */
interface Fragment {
  pixel: number;
  face: number;
  l: [number, number];
  z: number;
  b: [number, number, number];
  dbdx: [number, number, number];
  dbdy: [number, number, number];
}

/** Records every fragment (unclamped pixel numbers included) and every repeated sample. */
class Log implements FragmentShader {
  readonly fragments: Fragment[] = [];
  readonly repeats: number[] = [];
  fragment(pixel: number, r: Rasterizer): void {
    this.fragments.push({
      pixel, face: r.face, l: [r.l0, r.l1], z: r.z, b: [r.b0, r.b1, r.b2], dbdx: [r.dbdx0, r.dbdx1, r.dbdx2], dbdy: [r.dbdy0, r.dbdy1, r.dbdy2],
    });
  }
  pixels(): number[] {
    return this.fragments.map((f) => f.pixel).sort((a, b) => a - b);
  }
  at(pixel: number): Fragment {
    const f = this.fragments.find((x) => x.pixel === pixel);
    expect(f, `a fragment at ${pixel}`).toBeDefined();
    return f!;
  }
}

/** A shader with `repeat`, logging both. */
class RepeatLog extends Log {
  repeat(sample: number): void {
    this.repeats.push(sample);
  }
}

/**
 * Clip-space vertices (stride VARYINGS) from points [x, y] in pixels of a width × height target (y down), each with
 * an optional NDC z, w and user clip distance: clip = (ndc·w, w).
 */
function vertices(width: number, height: number, points: readonly (readonly number[])[]): Float64Array {
  const v = new Float64Array(points.length * VARYINGS);
  points.forEach(([x, y, z = 0, w = 1, d = 0], i) => {
    const o = i * VARYINGS;
    v[o] = ((2 * x) / width - 1) * w;
    v[o + 1] = (1 - (2 * y) / height) * w;
    v[o + 2] = z * w;
    v[o + 3] = w;
    v[o + CLIP_DISTANCE] = d;
  });
  return v;
}

function target(width: number, height: number): Rasterizer {
  const r = new Rasterizer(width, height);
  r.clearDepth();
  return r;
}

function draw(r: Rasterizer, log: Log, points: readonly (readonly number[])[]): Log {
  const idx = points.map((_, i) => i);
  r.drawTriangles(vertices(r.width, r.height, points), idx, idx.length, log);
  return log;
}

/** The pixel numbers of a width-wide target whose centres satisfy `inside(x + ½, y + ½)`, over columns/rows given. */
function pixelsWhere(width: number, height: number, inside: (x: number, y: number) => boolean): number[] {
  const out: number[] = [];
  for (let y = 0; y < height; y++) for (let x = 0; x < width; x++) if (inside(x + 0.5, y + 0.5)) out.push(y * width + x);
  return out;
}

// Pixel coordinates: (0, 0) → (8, 0) → (0, 8) runs clockwise in NDC (y up), the reverse counter-clockwise.
const CW = [[0, 0], [8, 0], [0, 8]];
const CCW = [[0, 0], [0, 8], [8, 0]];

describe('defaults of a new Rasterizer: depth test on, no culling, counter-clockwise front, no user plane, derivatives on', () => {
  it('draws both windings, keeps the nearer surface, ignores the user distance, computes derivatives', () => {
    const r = target(8, 8);
    expect(draw(r, new Log(), CW).fragments).toHaveLength(28);
    // The same pixels again at the same depth: LESS fails everywhere (the depth test is on).
    expect(draw(r, new Log(), CCW).fragments).toHaveLength(0);
    const fresh = target(8, 8);
    // A negative user distance at every vertex: ignored unless userClip is set.
    const log = draw(fresh, new Log(), [[0, 0, 0, 1, -1], [0, 8, 0, 1, -1], [8, 0, 0, 1, -1]]);
    expect(log.fragments).toHaveLength(28);
    expect(log.at(0).dbdx).not.toEqual([0, 0, 0]);
    // Culling back faces with the default front (counter-clockwise): the clockwise triangle goes.
    const culled = target(8, 8);
    culled.cull = 'back';
    expect(draw(culled, new Log(), CW).fragments).toHaveLength(0);
    expect(draw(culled, new Log(), CCW).fragments).toHaveLength(28);
  });
});

describe('culling', () => {
  it("'back' keeps the front winding only; frontCCW false (the mirrored pass) swaps which that is", () => {
    // 28 centres: x + y < 8 with x, y at k + ½ gives 7 + 6 + … + 1 (the 8 on the hypotenuse, a right edge, are left out).
    for (const [frontCCW, kept, dropped] of [[true, CCW, CW], [false, CW, CCW]] as const) {
      const r = target(8, 8);
      r.cull = 'back';
      r.frontCCW = frontCCW;
      r.depthTest = false;
      expect(draw(r, new Log(), kept).fragments, `frontCCW ${frontCCW}`).toHaveLength(28);
      expect(draw(r, new Log(), dropped).fragments, `frontCCW ${frontCCW}`).toHaveLength(0);
    }
  });
});

describe('the mask', () => {
  it('draws only pixels whose mask byte is not 0', () => {
    const r = target(4, 4);
    r.mask = new Uint8Array(16);
    r.mask[5] = 1;
    r.mask[10] = 255;
    expect(draw(r, new Log(), [[-1, -1], [9, -1], [-1, 9]]).pixels()).toEqual([5, 10]);
  });
});

describe('depth: NDC z = z/w interpolated linearly in the screen, rounded to float32, plus the bias', () => {
  // Vertex 0 at (0, 0) with NDC z ½ and w 1, vertex 1 at (8, 0) with z −¼ and w 2, vertex 2 at (0, 8) with z ¾ and
  // w 4. At pixel (2, 3), centre (2.5, 3.5), the screen barycentrics are λ1 = 2.5/8, λ2 = 3.5/8, λ0 = ¼.
  const TRI = [[0, 0, 0.5, 1], [8, 0, -0.25, 2], [0, 8, 0.75, 4]];
  const P = 3 * 8 + 2;

  it('stores ¼·½ + 0.3125·(−¼) + 0.4375·¾ = 0.375 at (2, 3), and z + bias with a bias', () => {
    const r = target(8, 8);
    const log = draw(r, new Log(), TRI);
    expect(log.at(P).z).toBe(0.375);
    expect(r.depth[P]).toBe(0.375);
    expect(log.at(P).l).toEqual([0.25, 0.3125]);
    const biased = target(8, 8);
    biased.depthBias = 1 / 1024;
    expect(draw(biased, new Log(), TRI).at(P).z).toBe(0.375 + 1 / 1024);
    expect(biased.depth[P]).toBe(0.375 + 1 / 1024);
    // Rounded as float32: z = 0.1 at every vertex stores fround(0.1), and the same again fails LESS.
    const f = target(8, 8);
    expect(draw(f, new Log(), [[0, 0, 0.1], [8, 0, 0.1], [0, 8, 0.1]]).at(0).z).toBe(Math.fround(0.1));
    expect(draw(f, new Log(), [[0, 0, 0.1], [8, 0, 0.1], [0, 8, 0.1]]).fragments).toHaveLength(0);
  });

  it('with depthWrite off the test still runs and the buffer keeps what it held', () => {
    const r = target(8, 8);
    draw(r, new Log(), [[0, 0, 0.5], [8, 0, 0.5], [0, 8, 0.5]]);
    r.depthWrite = false;
    expect(draw(r, new Log(), [[0, 0, -0.5], [8, 0, -0.5], [0, 8, -0.5]]).fragments).toHaveLength(28);
    expect(r.depth[0]).toBe(0.5);
    expect(draw(r, new Log(), [[0, 0, 0.75], [8, 0, 0.75], [0, 8, 0.75]]).fragments).toHaveLength(0);
    // Depth test off: drawn behind too, and nothing written either.
    r.depthTest = false;
    expect(draw(r, new Log(), [[0, 0, 0.75], [8, 0, 0.75], [0, 8, 0.75]]).fragments).toHaveLength(28);
    expect(r.depth[0]).toBe(0.5);
  });
});

describe('barycentrics and their derivatives per pixel', () => {
  it('w = 1: b are the screen barycentrics, db/dx and db/dy the steps of an 8-pixel right triangle, ±1/8', () => {
    // b1 = x/8, b2 = y/8, b0 = 1 − b1 − b2 at the centre (2.5, 3.5); all dyadic, so exact.
    const f = draw(target(8, 8), new Log(), CW).at(3 * 8 + 2);
    expect(f.b).toEqual([0.25, 0.3125, 0.4375]);
    expect(f.dbdx.map((d) => d + 0)).toEqual([-0.125, 0.125, 0]); // + 0: −0 as 0
    expect(f.dbdy.map((d) => d + 0)).toEqual([-0.125, 0, 0.125]);
  });

  it('w = 1, 2, 4: b_v = (λ_v/w_v) / Σ λ_u/w_u, and the derivatives match its finite differences', () => {
    const w = [1, 2, 4];
    // The perspective-correct barycentrics at screen point (x, y) of the triangle (0, 0), (8, 0), (0, 8).
    const b = (x: number, y: number) => {
      const l = [1 - x / 8 - y / 8, x / 8, y / 8].map((li, v) => li / w[v]);
      const s = l[0] + l[1] + l[2];
      return l.map((a) => a / s);
    };
    const log = draw(target(8, 8), new Log(), [[0, 0, 0, 1], [8, 0, 0, 2], [0, 8, 0, 4]]);
    expect(log.fragments).toHaveLength(28);
    const h = 1e-4;
    for (const f of log.fragments) {
      const x = (f.pixel % 8) + 0.5, y = Math.floor(f.pixel / 8) + 0.5;
      const want = b(x, y), px = b(x + h, y), mx = b(x - h, y), py = b(x, y + h), my = b(x, y - h);
      for (let v = 0; v < 3; v++) {
        expect(f.b[v]).toBeCloseTo(want[v], 12);
        expect(f.dbdx[v]).toBeCloseTo((px[v] - mx[v]) / (2 * h), 6);
        expect(f.dbdy[v]).toBeCloseTo((py[v] - my[v]) / (2 * h), 6);
      }
    }
    // At (2.5, 3.5): λ/w = ¼, 0.3125/2, 0.4375/4, whose sum 0.515625 divides them: 16/33, 10/33, 7/33.
    const at = log.at(3 * 8 + 2).b;
    expect(at[0]).toBeCloseTo(16 / 33, 14);
    expect(at[1]).toBeCloseTo(10 / 33, 14);
    expect(at[2]).toBeCloseTo(7 / 33, 14);
  });

  it('a triangle with no edge along an axis, w = 2, 4, ½: the same against the finite differences', () => {
    const p = [[1, 0], [8, 2], [0, 7]], w = [2, 4, 0.5];
    // Screen barycentrics: λ_v = the area opposite v over the whole (51: 7·7 − 2·(−1)), then perspective-corrected.
    const cross = (a: number[], c: number[], x: number, y: number) => (c[0] - a[0]) * (y - a[1]) - (c[1] - a[1]) * (x - a[0]);
    const b = (x: number, y: number) => {
      const l = [cross(p[1], p[2], x, y), cross(p[2], p[0], x, y), cross(p[0], p[1], x, y)].map((e, v) => e / 51 / w[v]);
      const s = l[0] + l[1] + l[2];
      return l.map((a) => a / s);
    };
    const log = draw(target(8, 8), new Log(), p.map(([x, y], v) => [x, y, 0, w[v]]));
    expect(log.fragments.length).toBeGreaterThan(20);
    const h = 1e-4;
    for (const f of log.fragments) {
      const x = (f.pixel % 8) + 0.5, y = Math.floor(f.pixel / 8) + 0.5;
      const want = b(x, y), px = b(x + h, y), mx = b(x - h, y), py = b(x, y + h), my = b(x, y - h);
      for (let v = 0; v < 3; v++) {
        expect(f.b[v]).toBeCloseTo(want[v], 12);
        expect(f.dbdx[v]).toBeCloseTo((px[v] - mx[v]) / (2 * h), 6);
        expect(f.dbdy[v]).toBeCloseTo((py[v] - my[v]) / (2 * h), 6);
      }
    }
  });

  it('derivatives off: b set, derivatives left as they were; barycentrics off: only l0, l1 and z, until perspective()', () => {
    const r = target(8, 8);
    r.derivatives = false;
    const f = draw(r, new Log(), CW).at(3 * 8 + 2);
    expect(f.b).toEqual([0.25, 0.3125, 0.4375]);
    expect([...f.dbdx, ...f.dbdy]).toEqual([0, 0, 0, 0, 0, 0]);
    const lazy = target(8, 8);
    lazy.barycentrics = false;
    let after: number[] = [];
    const log = new Log();
    lazy.drawTriangles(vertices(8, 8, [[0, 0, 0, 1], [8, 0, 0, 2], [0, 8, 0, 4]]), [0, 1, 2], 3, {
      fragment(pixel, rr) {
        log.fragment(pixel, rr);
        if (pixel === 3 * 8 + 2) { rr.perspective(); after = [rr.b0, rr.b1, rr.b2]; }
      },
    });
    const g = log.at(3 * 8 + 2);
    expect(g.b).toEqual([0, 0, 0]);
    expect(g.l).toEqual([0.25, 0.3125]);
    expect(after[1]).toBeCloseTo(10 / 33, 14);
  });
});

describe('triangles and their numbers', () => {
  it("face = index of the triangle in the draw × 10 + its place in the clipped polygon's fan", () => {
    // Clip space: A (−1, −1), B (1, −1) on the screen's bottom corners, C (0, 1) behind the near plane (z = −2, w = 1).
    // Clipped at z + w = 0, halfway along B→C and C→A: a trapezoid A, B, (½, 0), (−½, 0) — two fan triangles,
    // pixel rows 4–7 of an 8×8 target between x = 2 − (y − 4)/2 and 6 + (y − 4)/2: 4 + 6 + 6 + 8 = 24 centres.
    const v = new Float64Array(6 * VARYINGS);
    const put = (i: number, x: number, y: number, z: number) => { v.set([x, y, z, 1], i * VARYINGS); };
    put(0, -1, -1, 0); put(1, 1, -1, 0); put(2, 0, 1, -2);
    put(3, -1, 1, 0.5); put(4, -0.5, 1, 0.5); put(5, -1, 0.5, 0.5); // pixels (0, 0), (2, 0), (0, 2): unclipped
    const r = target(8, 8);
    const log = new Log();
    r.drawTriangles(v, [3, 4, 5, 0, 1, 2], 6, log);
    const faces = new Map<number, number>();
    for (const f of log.fragments) faces.set(f.face, (faces.get(f.face) ?? 0) + 1);
    // The first, unclipped: face 0, over the one centre (½, ½) with x + y < 2 (those on its hypotenuse are left out).
    expect([...faces.keys()].sort((a, b) => a - b)).toEqual([0, 10, 11]);
    expect(faces.get(0)).toBe(1);
    expect(faces.get(10)! + faces.get(11)!).toBe(24);
    expect(log.pixels()).toEqual([0, ...pixelsWhere(8, 8, (x, y) => y > 4 && x > 2 - (y - 4) / 2 && x < 6 + (y - 4) / 2)]);
  });

  it('a triangle clipped to a triangle (one vertex in front of the near plane) is drawn', () => {
    // A (0, 1) in front; B (−1, −1), C (1, −1) behind (z = −2): cut halfway, at (−½, 0) and (½, 0): pixel rows 0–3
    // between x = 4 − y/2 … 4 + y/2 (apex at the top centre): 0 + 2 + 2 + 4 = 8? Centres y + ½: rows 0..3 give
    // half-widths ¼, ¾, 1¼, 1¾: 0, 2, 2, 4 centres.
    const v = new Float64Array(3 * VARYINGS);
    v.set([0, 1, 0, 1], 0); v.set([-1, -1, -2, 1], VARYINGS); v.set([1, -1, -2, 1], 2 * VARYINGS);
    const r = target(8, 8);
    const log = new Log();
    r.drawTriangles(v, [0, 1, 2], 3, log);
    expect(log.pixels()).toEqual(pixelsWhere(8, 8, (x, y) => y < 4 && Math.abs(x - 4) < y / 2));
    expect(log.fragments).toHaveLength(8);
    // A negative user distance at every vertex with userClip off: clipped at the near plane only, the same pixels.
    const d = v.slice();
    for (let i = 0; i < 3; i++) d[i * VARYINGS + CLIP_DISTANCE] = -1;
    const plain = new Log();
    target(8, 8).drawTriangles(d, [0, 1, 2], 3, plain);
    expect(plain.pixels()).toEqual(log.pixels());
  });

  it('draws `count` indices only: a partial triangle after the last whole one, and indices past count, are left', () => {
    const v = vertices(8, 8, [[0, 0], [8, 0], [0, 8], [8, 8]]);
    const r = target(8, 8);
    r.depthTest = false;
    const log = new Log();
    // count 5: one triangle (0, 1, 2); indices 3..8 (the other half of the square) not drawn.
    r.drawTriangles(v, [0, 1, 2, 1, 3, 2, 1, 3, 2], 5, log);
    expect(log.fragments).toHaveLength(28);
    expect(new Set(log.fragments.map((f) => f.face))).toEqual(new Set([0]));
  });

  it('reads vertices by index × stride: the second triangle of a list drawn from vertices 3, 1, 2', () => {
    // The square's lower-right half (8, 8), (8, 0), (0, 8): x + y ≥ 8, the diagonal's centres (k + ½, 7½ − k) included
    // (a left edge of this half, a right edge of the other).
    const v = vertices(8, 8, [[0, 0], [8, 0], [0, 8], [8, 8]]);
    const r = target(8, 8);
    r.depthTest = false;
    const log = new Log();
    r.drawTriangles(v, [3, 1, 2], 3, log);
    expect(log.pixels()).toEqual(pixelsWhere(8, 8, (x, y) => x + y >= 8));
  });
});

describe('the user clip plane', () => {
  it('with userClip, keeps where the interpolated distance is ≥ 0 (here NDC x: the right half)', () => {
    const big = [[0, 0, 0, 1, -1], [16, 0, 0, 1, 3], [0, 16, 0, 1, -1]];
    const r = target(8, 8);
    r.userClip = true;
    expect(draw(r, new Log(), big).pixels()).toEqual(pixelsWhere(8, 8, (x) => x > 4));
    expect(draw(target(8, 8), new Log(), big).fragments).toHaveLength(64);
  });
});

describe('a band of rows (top, bottom)', () => {
  /** Rows of a 40×30 target (or samples, multisampled) drawn with rows top..bottom and the given triangles. */
  function rows(shadeEvery: number, top: number, bottom: number, points: number[][]): number[] {
    const r = new Rasterizer(40, 30);
    r.shadeEvery = shadeEvery;
    r.top = top;
    r.bottom = bottom;
    r.depthTest = false;
    const log = new RepeatLog();
    draw(r, log, points);
    const out = new Array<number>(30).fill(0);
    for (const p of [...log.fragments.map((f) => f.pixel), ...log.repeats]) out[Math.floor(p / 40)]++;
    return out;
  }
  const SCREEN = [[-1, -1], [41, -1], [41, 31], [-1, -1], [41, 31], [-1, 31]];

  for (const n of [1, 2]) {
    it(`rows top..bottom − 1 only, each whole (shadeEvery ${n}); a triangle in the band's first or last row alone is drawn`, () => {
      expect(rows(n, 2, 20, SCREEN)).toEqual(Array.from({ length: 30 }, (_, y) => (y >= 2 && y < 20 ? 40 : 0)));
      // A sliver over row 2 (y 2.1..2.9) and one over row 19: drawn; the same sliver one row outside: not.
      const sliver = (y: number) => [[0, y + 0.1], [40, y + 0.1], [40, y + 0.9], [0, y + 0.1], [40, y + 0.9], [0, y + 0.9]];
      expect(rows(n, 2, 20, sliver(2))[2]).toBe(40);
      expect(rows(n, 2, 20, sliver(19))[19]).toBe(40);
      expect(rows(n, 2, 20, sliver(1)).reduce((a, b) => a + b)).toBe(0);
      expect(rows(n, 2, 20, sliver(20)).reduce((a, b) => a + b)).toBe(0);
      // A band from row n (hi = 1 − 2(n − 1)/H: 1 itself at n = 1).
      expect(rows(n, n, 30, SCREEN)).toEqual(Array.from({ length: 30 }, (_, y) => (y >= n ? 40 : 0)));
    });
  }

  it('clearDepth clears the band only, and the whole frame without one', () => {
    const r = new Rasterizer(4, 6);
    r.top = 2;
    r.bottom = 4;
    r.clearDepth();
    expect([...r.depth]).toEqual([...new Array(8).fill(0), ...new Array(8).fill(Infinity), ...new Array(8).fill(0)]);
    r.top = 0;
    r.bottom = Infinity;
    r.clearDepth();
    expect([...r.depth]).toEqual(new Array(24).fill(Infinity));
  });
});

describe("the target's edges", () => {
  it('a triangle reaching past every side draws the pixels inside the target only, none wrapped to the next row', () => {
    // x ≥ 2.2 and left of the line from (30, −10) to (2.2, 30), which lies right of the 8×8 target: columns 2–7.
    const r = target(8, 8);
    r.depthTest = false;
    expect(draw(r, new Log(), [[2.2, -10], [30, -10], [2.2, 30]]).pixels()).toEqual(pixelsWhere(8, 8, (x) => x > 2.2));
    // Past the left and bottom sides too.
    expect(draw(r, new Log(), [[-10, 5.2], [30, 5.2], [-10, 30]]).pixels()).toEqual(pixelsWhere(8, 8, (_x, y) => y > 5.2));
  });
});

describe('a rasterizer reused', () => {
  it('keeps its depth buffer while large enough, grows it when not', () => {
    const r = new Rasterizer(8, 8);
    const before = r.depth;
    r.resize(4, 4);
    r.resize(8, 8);
    expect(r.depth).toBe(before);
    r.resize(16, 8);
    expect(r.depth.length).toBeGreaterThanOrEqual(128);
    expect(new Rasterizer().depth.length).toBe(0);
    expect([new Rasterizer().width, new Rasterizer().height]).toEqual([0, 0]);
  });

  it('draws with a larger stride after a smaller one as a fresh rasterizer does', () => {
    const pts = [[0.5, 0.5], [7.5, 1.5], [2.5, 7.5]];
    // Stride 20: the varyings' last float (vertex offset 19) holds 1, 2, 3, interpolated per fragment.
    const wide = (stride: number) => {
      const v = vertices(8, 8, pts), out = new Float64Array(3 * stride);
      for (let i = 0; i < 3; i++) {
        out.set(v.subarray(i * VARYINGS, (i + 1) * VARYINGS), i * stride);
        out[i * stride + stride - 1] = i + 1;
      }
      return out;
    };
    const last = (r: Rasterizer) => r.b0 * r.poly[r.o0 + 14] + r.b1 * r.poly[r.o1 + 14] + r.b2 * r.poly[r.o2 + 14];
    const fresh = target(8, 8);
    fresh.stride = 20;
    const want: number[] = [];
    fresh.drawTriangles(wide(20), [0, 1, 2], 3, { fragment: (_p, r) => { want.push(last(r)); } });
    const reused = target(8, 8);
    reused.drawTriangles(wide(VARYINGS), [0, 1, 2], 3, new Log());
    reused.clearDepth();
    reused.stride = 20;
    const got: number[] = [];
    reused.drawTriangles(wide(20), [0, 1, 2], 3, { fragment: (_p, r) => { got.push(last(r)); } });
    expect(got.length).toBeGreaterThan(10);
    expect(Math.min(...want)).toBeGreaterThan(1);
    expect(Math.max(...want)).toBeLessThan(3);
    expect(got).toEqual(want);
  });
});

describe('multisampling (shadeEvery n): the same samples and depths as the grid drawn a sample at a time', () => {
  it('pixelOf numbers a sample by its pixel: itself at n = 1', () => {
    const r = new Rasterizer(8, 8);
    expect(r.pixelOf(29)).toBe(29);
    r.shadeEvery = 2; // sample (5, 3) of 8 × 8 lies in pixel (2, 1) of 4 × 4
    expect(r.pixelOf(3 * 8 + 5)).toBe(1 * 4 + 2);
    const t = new Rasterizer(9, 9);
    t.shadeEvery = 3; // sample (7, 4) of 9 × 9: pixel (2, 1) of 3 × 3
    expect(t.pixelOf(4 * 9 + 7)).toBe(1 * 3 + 2);
  });

  // Triangles in sample coordinates over a 13 × 13 sample grid (the last pixel of each row and column partial for
  // n = 2 and 3), at various depths, some past the grid's sides.
  const TRIANGLES = [
    [[-3, -2, 0.5], [16, 1.3, 0.2], [2.7, 15, 0.9]],
    [[4.1, 0.6, 0.1], [12.9, 9.4, -0.3], [1.2, 11.8, 0.4]],
    [[13.5, 3.2, -0.5], [6.6, 14.9, 0.3], [9.3, -1.7, 0.35]],
    [[0.3, 12.4, 0.0], [20, 12.6, -0.6], [6.5, 6.5, 0.15]],
    // Edges through sample centres, each of the three edge functions in turn a top or left edge (drawn on it) and a
    // right or bottom one (not): the square (2.5, 4.5)–(10.5, 12.5) cut on its 45° diagonal, in two vertex orders.
    [[10.5, 4.5, -0.8], [2.5, 12.5, -0.8], [2.5, 4.5, -0.8]],
    [[10.5, 12.5, -0.85], [2.5, 12.5, -0.85], [10.5, 4.5, -0.85]],
    [[10.5, 4.5, -0.86], [10.5, 12.5, -0.86], [2.5, 12.5, -0.86]],
    // Then one triangle twice at the same depth (LESS: not drawn the second time).
    [[2.5, 4.5, -0.9], [10.5, 4.5, -0.9], [2.5, 12.5, -0.9]],
    [[2.5, 4.5, -0.9], [10.5, 4.5, -0.9], [2.5, 12.5, -0.9]],
  ];

  /** Per sample: the last triangle written there (−1: none) and how often any was; the depth buffer; fragments per triangle and pixel. */
  function run(n: number, mask: Uint8Array | null, repeat: boolean, depthTest = true) {
    const W = 13, r = target(W, W);
    r.depthTest = depthTest;
    r.shadeEvery = n;
    r.mask = mask;
    r.depthBias = 1 / 64;
    const owner = new Int32Array(W * W).fill(-1), writes = new Uint32Array(W * W), stray: number[] = [];
    const shadedPerPixel = new Map<string, number>();
    const centres: { t: number; sample: number; l: [number, number] }[] = [];
    let t = 0;
    const fragment = (sample: number, rr: Rasterizer) => {
      if (sample < 0 || sample >= W * W) stray.push(sample);
      owner[sample] = t; writes[sample]++;
      const key = `${t}:${rr.pixelOf(sample)}`;
      shadedPerPixel.set(key, (shadedPerPixel.get(key) ?? 0) + 1);
      centres.push({ t, sample, l: [rr.l0, rr.l1] });
    };
    const shader: FragmentShader = repeat
      ? { fragment, repeat: (s) => { if (s < 0 || s >= W * W) stray.push(s); owner[s] = t; writes[s]++; } }
      : { fragment };
    for (; t < TRIANGLES.length; t++) r.drawTriangles(vertices(W, W, TRIANGLES[t]), [0, 1, 2], 3, shader);
    return { owner, writes, depth: r.depth.slice(0, W * W), shadedPerPixel, centres, stray };
  }

  for (const n of [2, 3]) {
    for (const masked of [false, true]) {
      it(`n = ${n}${masked ? ', masked' : ''}: every sample as at n = 1; one shading per pixel and triangle, at the pixel's centre`, () => {
        const mask = masked ? Uint8Array.from({ length: 169 }, (_, i) => ((i * 7) % 5 === 0 ? 0 : 1)) : null;
        const one = run(1, mask, true), many = run(n, mask, true);
        expect([...many.owner]).toEqual([...one.owner]);
        expect([...many.writes]).toEqual([...one.writes]);
        expect([...many.depth]).toEqual([...one.depth]);
        expect([one.stray, many.stray]).toEqual([[], []]);
        expect(one.owner.includes(TRIANGLES.length - 1)).toBe(false);
        expect([...one.writes].filter((w) => w > 0).length).toBeGreaterThan(100);
        expect(Math.max(...many.shadedPerPixel.values())).toBe(1);
        // The centre of the pixel holding sample s: ((x/n | 0) + ½)·n in samples; l0, l1 the screen barycentrics
        // of vertices 0 and 1 there (the snapped vertices are the given ones to within 1/512 of a sample).
        for (const { t, sample, l } of many.centres) {
          const [a, b, c] = TRIANGLES[t];
          const cx = (Math.floor((sample % 13) / n) + 0.5) * n, cy = (Math.floor(sample / 13 / n) + 0.5) * n;
          const area = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
          const l0 = ((b[0] - cx) * (c[1] - cy) - (b[1] - cy) * (c[0] - cx)) / area;
          const l1 = ((c[0] - cx) * (a[1] - cy) - (c[1] - cy) * (a[0] - cx)) / area;
          // The rasterizer may take the vertices in another order (b, c swapped): compare as a set of {l0, l1, l2}.
          const got = [l[0], l[1], 1 - l[0] - l[1]].sort((p, q) => p - q), want = [l0, l1, 1 - l0 - l1].sort((p, q) => p - q);
          for (let k = 0; k < 3; k++) expect(got[k]).toBeCloseTo(want[k], 2);
        }
      });
    }
  }

  it('depth test off: every covered sample written by each triangle in turn, none past the grid (13 × 13: partial pixels)', () => {
    for (const n of [2, 3]) {
      const one = run(1, null, true, false), many = run(n, null, true, false);
      expect([...many.owner]).toEqual([...one.owner]);
      expect([...many.writes]).toEqual([...one.writes]);
      expect([one.stray, many.stray]).toEqual([[], []]);
      expect(one.owner.includes(TRIANGLES.length - 1)).toBe(true);
    }
  });

  it('without `repeat` every covered sample is shaded (at its pixel centre); depth write off leaves the buffer', () => {
    const one = run(1, null, true), many = run(2, null, false);
    expect([...many.owner]).toEqual([...one.owner]);
    expect([...many.writes]).toEqual([...one.writes]);
    const r = target(8, 8);
    r.shadeEvery = 2;
    r.depthWrite = false;
    draw(r, new Log(), [[0, 0, 0.5], [8, 0, 0.5], [0, 8, 0.5]]);
    expect([...r.depth.slice(0, 64)]).toEqual(new Array(64).fill(Infinity));
  });

  it('derivatives per pixel: n samples per step (w = 1, an 8-sample right triangle, n = 2: ±2/8)', () => {
    const r = target(8, 8);
    r.shadeEvery = 2;
    const log = draw(r, new RepeatLog(), CW);
    // Pixel (1, 1)'s samples (2..3, 2..3): shaded at the pixel centre (3, 3) in samples: b = 1 − 6/8, 3/8, 3/8.
    const f = log.at(2 * 8 + 2);
    expect(f.b).toEqual([0.25, 0.375, 0.375]);
    expect(f.dbdx.map((d) => d + 0)).toEqual([-0.25, 0.25, 0]);
    expect(f.dbdy.map((d) => d + 0)).toEqual([-0.25, 0, 0.25]);
    expect(log.repeats).toEqual(expect.arrayContaining([2 * 8 + 3, 3 * 8 + 2, 3 * 8 + 3]));
  });
});
