// Triangles in clip space → pixels: Sutherland–Hodgman clipping in clip space, edge functions on
// a fixed-point grid with the top-left fill rule, a Float32 z-buffer, perspective-correct
// barycentrics (and their screen derivatives, for texture LOD). Knows nothing of shading.
import { ALL, copyVertex, inside, outsideRows, planeDistance, PLANES, USER, CLIP_W, CLIP_DISTANCE, VARYINGS } from './clip';
import { edgeFunctions, HALF, runEnd, runStart, SUB } from './edges';

export { CLIP_W, CLIP_DISTANCE, VARYINGS };
export { SUBPIXEL_BITS } from './edges';

/** A clipped triangle has at most 3 + one vertex per plane (near, far, 4 guard, user). */
const MAX_POLY = 10;
export type CullMode = 'none' | 'back';

/** Called for every pixel that passes the mask and the depth test; reads the rasterizer's fields. */
export interface FragmentShader {
  /** False: the fragment is discarded (glTF's alpha mask): nothing written, and its depth taken back. */
  fragment(pixel: number, r: Rasterizer): boolean | void;
  /** Multisampling (Rasterizer.shadeEvery > 1): writes the result of the last `fragment` call at `sample`, another covered
   *  sample of the same pixel and triangle (blending with what that sample holds). Absent: `fragment` is called for every sample. */
  repeat?(sample: number): void;
}

export class Rasterizer {
  width = 0;
  height = 0;
  /** NDC depth per pixel (LESS test), +∞ when cleared. */
  depth: Float32Array;
  depthTest = true;
  depthWrite = true;
  /** Added to every fragment's NDC depth (the glass is pushed back a hair, as polygonOffset does). */
  depthBias = 0;
  // Stryker disable next-line StringLiteral: only 'back' culls; any other value draws both windings as 'none' does
  cull: CullMode = 'none';
  /** Front faces are counter-clockwise in NDC (GL's default); false in the mirrored pass. */
  frontCCW = true;
  /** Clip against the user clip distance (slot CLIP_DISTANCE) as well. */
  userClip = false;
  /** Only pixels whose mask byte is non-zero are drawn (the glass's footprint); null: all. */
  mask: Uint8Array | null = null;
  /** Compute dbdx/dbdy per fragment (texture LOD needs them), scaled by `footprint`: 1 per cell of the grid, 1/side in a strata frame (docs/refinement.md#footprints). */
  derivatives = true;
  footprint = 1;
  /** Compute b0..b2 (and derivatives) before each fragment; false: only l0, l1 and z are set, and a shader that needs them
   *  after all calls perspective() (the glass's footprint never does, a cached glass pixel need not): no division for it. */
  barycentrics = true;
  /** Floats per vertex in the buffers drawn (≥ VARYINGS). */
  stride = VARYINGS;
  /**
   * Multisampling, as MSAA does it: the target is a grid of n×n samples per pixel (n =
   * `shadeEvery`; width and height count samples), coverage and depth are decided per sample, and
   * a triangle is shaded once per pixel — at its first covered sample that passes, with the
   * pixel's derivatives — its result repeated at the pixel's other passing samples. 1: every
   * sample is a pixel of its own (no multisampling, or supersampling when the caller sizes so).
   */
  shadeEvery = 1;
  // The rows drawn, [top, bottom) (a band of the frame; multiples of shadeEvery): each triangle's
  // box is clamped to them, its edge functions exact integers at the box's corner, so a row is
  // drawn bit for bit as in the whole frame.
  top = 0;
  bottom = Infinity;

  // Per fragment, for the shader: the clipped vertices (`poly`), the triangle's three vertex
  // offsets into it, the perspective-correct barycentrics and their derivatives per pixel.
  poly: Float64Array;
  o0 = 0; o1 = 0; o2 = 0;
  b0 = 0; b1 = 0; b2 = 0;
  dbdx0 = 0;
  dbdx1 = 0;
  dbdx2 = 0;
  dbdy0 = 0;
  dbdy1 = 0;
  dbdy2 = 0;
  /** NDC depth of the fragment (bias included), and its screen barycentrics of vertices 0 and 1. */
  z = 0;
  l0 = 0;
  l1 = 0;
  /** Which triangle the fragment is of: its index in the draw × MAX_POLY + its place in the clipped polygon's fan (the same
   *  in every frame that draws the same vertices). */
  face = 0;

  private scratch: Float64Array;
  private readonly dist = new Float64Array(MAX_POLY);
  // Snapped screen positions (fixed point, y down), 1/w and NDC z of the polygon's vertices.
  private readonly fx = new Float64Array(MAX_POLY);
  private readonly fy = new Float64Array(MAX_POLY);
  private readonly iw = new Float64Array(MAX_POLY);
  private readonly nz = new Float64Array(MAX_POLY);
  /** The triangle's edge functions, their steps and biases (edges()). */
  private readonly edge = new Float64Array(12);
  // The triangle being drawn: its vertices' 1/w and d(λ_v/w_v)/dx, /dy per pixel, and their sums.
  private w0 = 0;
  private w1 = 0;
  private w2 = 0;
  private ax = 0;
  private bx = 0;
  private cx = 0;
  private ay = 0;
  private by = 0;
  private cy = 0;
  private sumX = 0;
  private sumY = 0;

  constructor(maxWidth = 0, maxHeight = 0) {
    this.depth = new Float32Array(0);
    this.poly = new Float64Array(0);
    this.scratch = new Float64Array(0);
    if (maxWidth > 0) this.resize(maxWidth, maxHeight);
  }

  /** The pixel `sample` lies in, numbered on the grid of pixels (itself unless multisampled). */
  pixelOf(sample: number): number {
    const n = this.shadeEvery, W = this.width;
    if (n === 1) return sample;
    const y = (sample / W) | 0, x = sample - y * W;
    return ((y / n) | 0) * (W / n) + ((x / n) | 0);
  }

  /** Sets the target size; the depth buffer grows as needed (never per frame once large enough). */
  resize(width: number, height: number): void {
    this.width = width;
    this.height = height;
    if (this.depth.length < width * height) this.depth = new Float32Array(width * height);
  }

  clearDepth(): void {
    const W = this.width;
    this.depth.fill(Infinity, this.top * W, Math.min(this.bottom, this.height) * W);
  }

  /** Draws `count` indices' triangles of `vertices` (layout above, `this.stride` floats each). Pixel (i, j) is sampled at
   *  its centre (i + ½, j + ½), row 0 at the top. */
  drawTriangles(vertices: Float64Array, indices: ArrayLike<number>, count: number, shader: FragmentShader): void {
    const s = this.stride;
    if (this.poly.length < MAX_POLY * s) {
      this.poly = new Float64Array(MAX_POLY * s);
      this.scratch = new Float64Array(MAX_POLY * s);
    }
    // Stryker disable next-line ConditionalExpression,LogicalOperator,EqualityOperator: `banded` only lets a triangle wholly above or below the rows drawn be skipped early; the box clamped to top..bottom draws none of it anyway
    const user = this.userClip, H = this.height, banded = this.top > 0 || this.bottom < H;
    // A band's triangles wholly more than a row above or below it are left before clipping.
    const hi = 1 - (2 * (this.top - 1)) / H, lo = 1 - (2 * (this.bottom + 1)) / H;
    for (let t = 0; t + 2 < count; t += 3) {
      this.face = (t / 3) * MAX_POLY;
      const a = indices[t] * s, b = indices[t + 1] * s, c = indices[t + 2] * s;
      // Stryker disable next-line LogicalOperator: unbanded, hi and lo lie a row beyond the target's top and bottom, and a triangle wholly past them covers no pixel centre
      if (banded && outsideRows(vertices, a, b, c, hi, lo)) continue;
      // Trivial accept: every vertex inside every plane; trivial reject: all outside one.
      const inA = inside(vertices, a, user), inB = inside(vertices, b, user), inC = inside(vertices, c, user);
      // Stryker disable next-line BlockStatement: the trivial accept is a shortcut: the clipping below skips every plane all three vertices are inside and draws the same triangle
      if ((inA & inB & inC) === ALL) {
        copyVertex(vertices, a, this.poly, 0, s);
        copyVertex(vertices, b, this.poly, s, s);
        copyVertex(vertices, c, this.poly, 2 * s, s);
        this.polygon(3, shader);
        continue;
      }
      if (((inA | inB | inC) & ALL) !== ALL) continue;
      copyVertex(vertices, a, this.poly, 0, s);
      copyVertex(vertices, b, this.poly, s, s);
      copyVertex(vertices, c, this.poly, 2 * s, s);
      let n = 3;
      for (let plane = 0; plane < PLANES && n >= 3; plane++) {
        if (plane === USER && !user) continue;
        const bit = 1 << plane;
        if ((inA & inB & inC & bit) !== 0) continue;
        n = this.clip(n, plane);
      }
      if (n >= 3) this.polygon(n, shader);
    }
  }

  /**
   * One Sutherland–Hodgman step of `poly` (n vertices) against `plane`, back into `poly`. A
   * crossing is always interpolated from the inside vertex towards the outside one, so an edge
   * shared by two triangles is cut at the bitwise same point in both (no seam at the near plane).
   */
  private clip(n: number, plane: number): number {
    const s = this.stride, src = this.poly, dst = this.scratch, d = this.dist;
    for (let i = 0; i < n; i++) d[i] = planeDistance(src, i * s, plane);
    let m = 0;
    for (let i = 0; i < n; i++) {
      const j = i + 1 === n ? 0 : i + 1;
      const di = d[i], dj = d[j];
      const inI = di >= 0, inJ = dj >= 0;
      if (inI) copyVertex(src, i * s, dst, m++ * s, s);
      if (inI !== inJ) {
        const from = inI ? i : j, to = inI ? j : i;
        const df = d[from], dt = d[to];
        const f = df / (df - dt);
        const o = m++ * s, p = from * s, q = to * s;
        for (let k = 0; k < s; k++) dst[o + k] = src[p + k] + f * (src[q + k] - src[p + k]);
      }
    }
    this.scratch = src;
    this.poly = dst;
    return m;
  }

  /** Projects, snaps and culls the clipped polygon, then rasterizes it as a fan. */
  private polygon(n: number, shader: FragmentShader): void {
    const s = this.stride, p = this.poly;
    const sx = (this.width / 2) * SUB, sy = (this.height / 2) * SUB;
    for (let i = 0; i < n; i++) {
      const o = i * s;
      const iw = 1 / p[o + CLIP_W];
      this.iw[i] = iw;
      this.fx[i] = Math.round((p[o] * iw + 1) * sx);
      this.fy[i] = Math.round((1 - p[o + 1] * iw) * sy);
      this.nz[i] = p[o + 2] * iw;
    }
    for (let i = 1; i + 1 < n; i++, this.face++) this.triangle(0, i, i + 1, shader);
  }

  /** One triangle of the polygon (vertex numbers i, j, k): culled, ordered to a positive area, boxed, scanned. */
  private triangle(i: number, j: number, k: number, shader: FragmentShader): void {
    const { fx, fy } = this;
    let area = (fx[j] - fx[i]) * (fy[k] - fy[i]) - (fy[j] - fy[i]) * (fx[k] - fx[i]);
    if (area === 0) return;
    if (this.cull === 'back') {
      // In y-down screen space a counter-clockwise NDC triangle has negative area.
      const front = this.frontCCW ? area < 0 : area > 0;
      if (!front) return;
    }
    if (area < 0) { const t = j; j = k; k = t; area = -area; }
    const x0 = fx[i], y0 = fy[i], x1 = fx[j], y1 = fy[j], x2 = fx[k], y2 = fy[k];
    // Bounding box of pixel centres (c = p·SUB + HALF) inside it, clamped to the target.
    const px0 = Math.max(0, Math.ceil((Math.min(x0, x1, x2) - HALF) / SUB));
    const px1 = Math.min(this.width - 1, Math.floor((Math.max(x0, x1, x2) - HALF) / SUB));
    const py0 = Math.max(this.top, Math.ceil((Math.min(y0, y1, y2) - HALF) / SUB));
    const py1 = Math.min(this.height - 1, this.bottom - 1, Math.floor((Math.max(y0, y1, y2) - HALF) / SUB));
    // Stryker disable next-line LogicalOperator: an empty box is a shortcut: the scans below visit no pixel of a box empty either way (top and bottom are multiples of shadeEvery)
    if (px0 > px1 || py0 > py1) return;
    if (this.shadeEvery > 1) this.scanPixels(i, j, k, area, px0, px1, py0, py1, shader);
    else this.scan(i, j, k, area, px0, px1, py0, py1, shader);
  }

  /**
   * The triangle's interpolation: its vertices' varyings offsets and 1/w, and the derivatives of
   * λ_v/w_v per step of the edge functions (`sx*`, `sy*`: one pixel, or one shaded pixel).
   */
  private interpolate(i: number, j: number, k: number, inv: number, sx0: number, sx1: number, sx2: number, sy0: number, sy1: number, sy2: number): void {
    const s = this.stride;
    this.o0 = i * s + VARYINGS;
    this.o1 = j * s + VARYINGS;
    this.o2 = k * s + VARYINGS;
    const w0 = (this.w0 = this.iw[i]), w1 = (this.w1 = this.iw[j]), w2 = (this.w2 = this.iw[k]);
    this.ax = sx0 * inv * w0; this.bx = sx1 * inv * w1; this.cx = sx2 * inv * w2;
    this.ay = sy0 * inv * w0; this.by = sy1 * inv * w1; this.cy = sy2 * inv * w2;
    this.sumX = this.ax + this.bx + this.cx;
    this.sumY = this.ay + this.by + this.cy;
  }

  /**
   * Shades the fragment whose l0, l1 and z the caller set (fields, not arguments: doubles passed
   * to a call that is not inlined are boxed, one allocation per fragment), perspective-correcting
   * them first unless `barycentrics` is off.
   */
  private shade(pixel: number, shader: FragmentShader): boolean {
    if (this.barycentrics) this.perspective();
    return shader.fragment(pixel, this) !== false;
  }

  /** b0..b2 (and, with `derivatives`, their derivatives per pixel) from l0 and l1. */
  perspective(): void {
    const l0 = this.l0, l1 = this.l1;
    const a0 = l0 * this.w0, a1 = l1 * this.w1, a2 = (1 - l0 - l1) * this.w2;
    const q = 1 / (a0 + a1 + a2);
    const b0 = a0 * q, b1 = a1 * q, b2 = a2 * q;
    this.b0 = b0; this.b1 = b1; this.b2 = b2;
    if (this.derivatives) {
      const sumX = this.sumX, sumY = this.sumY;
      const f = q * this.footprint;
      this.dbdx0 = (this.ax - b0 * sumX) * f; this.dbdx1 = (this.bx - b1 * sumX) * f; this.dbdx2 = (this.cx - b2 * sumX) * f;
      this.dbdy0 = (this.ay - b0 * sumY) * f; this.dbdy1 = (this.by - b1 * sumY) * f; this.dbdy2 = (this.cy - b2 * sumY) * f;
    }
  }

  /**
   * The pixels of triangle (i, j, k), ordered so that its edge functions' `area` is positive,
   * whose centres lie in it (top-left rule) within the box px0..px1 × py0..py1: depth-tested,
   * their barycentrics (and derivatives) set, and shaded.
   */
  private scan(i: number, j: number, k: number, area: number, px0: number, px1: number, py0: number, py1: number, shader: FragmentShader): void {
    const e = edgeFunctions(this.edge, this.fx, this.fy, i, j, k, px0, py0);
    let row0 = e[0], row1 = e[1], row2 = e[2];
    const stepX0 = e[3], stepX1 = e[4], stepX2 = e[5], stepY0 = e[6], stepY1 = e[7], stepY2 = e[8];
    const bias0 = e[9], bias1 = e[10], bias2 = e[11];

    const inv = 1 / area;
    const z0 = this.nz[i], z1 = this.nz[j], z2 = this.nz[k];
    this.interpolate(i, j, k, inv, stepX0, stepX1, stepX2, stepY0, stepY1, stepY2);
    const { depth, mask, depthTest, depthWrite, depthBias } = this;
    const width = this.width;

    const span = px1 - px0;
    for (let y = py0; y <= py1; y++, row0 += stepY0, row1 += stepY1, row2 += stepY2) {
      // The row's covered run [k0, k1] (pixels from px0), solved per edge from e + bias + k·step ≥ 0
      // and widened by one: the exact integer test below still decides every pixel.
      let k0 = 0, k1 = span;
      // Stryker disable MethodExpression,ArithmeticOperator: a run only widened (k0 lower, k1 higher, the bias ±1 against steps of 256) scans more pixels of the box, each still decided by the exact test below
      k0 = Math.max(k0, runStart(row0 + bias0, stepX0)); k1 = Math.min(k1, runEnd(row0 + bias0, stepX0, span));
      k0 = Math.max(k0, runStart(row1 + bias1, stepX1)); k1 = Math.min(k1, runEnd(row1 + bias1, stepX1, span));
      k0 = Math.max(k0, runStart(row2 + bias2, stepX2)); k1 = Math.min(k1, runEnd(row2 + bias2, stepX2, span));
      // Stryker restore MethodExpression,ArithmeticOperator
      if (k0 > k1) continue;
      let e0 = row0 + k0 * stepX0, e1 = row1 + k0 * stepX1, e2 = row2 + k0 * stepX2;
      const base = y * width;
      for (let x = px0 + k0, xEnd = px0 + k1; x <= xEnd; x++) {
        if (e0 + bias0 >= 0 && e1 + bias1 >= 0 && e2 + bias2 >= 0) {
          const pixel = base + x;
          if (mask === null || mask[pixel] !== 0) {
            const l0 = e0 * inv, l1 = e1 * inv, l2 = 1 - l0 - l1;
            // Rounded as the Float32 buffer stores it, so equal depths compare equal (LESS fails).
            const z = Math.fround(l0 * z0 + l1 * z1 + l2 * z2 + depthBias);
            if (!depthTest || z < depth[pixel]) {
              const before = depth[pixel];
              if (depthWrite) depth[pixel] = z;
              this.l0 = l0; this.l1 = l1; this.z = z;
              if (!this.shade(pixel, shader)) depth[pixel] = before;
            }
          }
        }
        e0 += stepX0; e1 += stepX1; e2 += stepX2;
      }
    }
  }
  /**
   * `scan` for a multisampled target (shadeEvery = n > 1): the box's samples visited pixel by
   * pixel (n×n at a time), each sample covered by the top-left rule and depth-tested on its own;
   * the first that passes is shaded, with derivatives per pixel (n samples), the others take
   * `repeat`, or are cut with it (a GPU's discard). Rows of pixels are bounded by the union of their sample rows' runs.
   */
  private scanPixels(i: number, j: number, k: number, area: number, px0: number, px1: number, py0: number, py1: number, shader: FragmentShader): void {
    const n = this.shadeEvery;
    // The box in whole pixels; samples outside the triangle's box fail the edge test anyway.
    const qx0 = Math.floor(px0 / n) * n, qy0 = Math.floor(py0 / n) * n;
    const qx1 = Math.floor(px1 / n) * n + n - 1, qy1 = Math.floor(py1 / n) * n + n - 1;
    const e = edgeFunctions(this.edge, this.fx, this.fy, i, j, k, qx0, qy0);
    let row0 = e[0], row1 = e[1], row2 = e[2];
    const stepX0 = e[3], stepX1 = e[4], stepX2 = e[5], stepY0 = e[6], stepY1 = e[7], stepY2 = e[8];
    const bias0 = e[9], bias1 = e[10], bias2 = e[11];

    const inv = 1 / area;
    const z0 = this.nz[i], z1 = this.nz[j], z2 = this.nz[k];
    // Derivatives per pixel: n samples per step.
    this.interpolate(i, j, k, inv, n * stepX0, n * stepX1, n * stepX2, n * stepY0, n * stepY1, n * stepY2);
    const { depth, mask, depthTest, depthWrite, depthBias } = this;
    const width = this.width, height = this.height;
    const repeat = shader.repeat !== undefined;
    const span = qx1 - qx0;
    // From a pixel's first sample to its centre: (n − 1)/2 samples along each axis.
    const h = (n - 1) / 2;
    const centre0 = h * (stepX0 + stepY0), centre1 = h * (stepX1 + stepY1);

    for (let y = qy0; y <= qy1 && y < height; y += n, row0 += n * stepY0, row1 += n * stepY1, row2 += n * stepY2) {
      let k0 = span + 1, k1 = -1;
      for (let sy = 0; sy < n; sy++) {
        const r0 = row0 + sy * stepY0 + bias0, r1 = row1 + sy * stepY1 + bias1, r2 = row2 + sy * stepY2 + bias2;
        const a = Math.max(0, runStart(r0, stepX0), runStart(r1, stepX1), runStart(r2, stepX2));
        const b = Math.min(span, runEnd(r0, stepX0, span), runEnd(r1, stepX1, span), runEnd(r2, stepX2, span));
        if (a <= b) { if (a < k0) k0 = a; if (b > k1) k1 = b; }
      }
      if (k0 > k1) continue;
      // Whole pixels covering the run.
      const xFirst = qx0 + Math.floor(k0 / n) * n, xLast = Math.min(qx0 + k1, width - 1);
      for (let px = xFirst; px <= xLast; px += n) {
        let shaded = false, cut = false;
        const dx = px - qx0;
        for (let sy = 0; sy < n; sy++) {
          const yy = y + sy;
          if (yy >= height) break;
          let e0 = row0 + sy * stepY0 + dx * stepX0, e1 = row1 + sy * stepY1 + dx * stepX1, e2 = row2 + sy * stepY2 + dx * stepX2;
          const base = yy * width;
          for (let sx = 0; sx < n; sx++, e0 += stepX0, e1 += stepX1, e2 += stepX2) {
            const x = px + sx;
            if (x >= width || e0 + bias0 < 0 || e1 + bias1 < 0 || e2 + bias2 < 0) continue;
            const sample = base + x;
            if (mask !== null && mask[sample] === 0) continue;
            const l0 = e0 * inv, l1 = e1 * inv, l2 = 1 - l0 - l1;
            const z = Math.fround(l0 * z0 + l1 * z1 + l2 * z2 + depthBias);
            if ((depthTest && !(z < depth[sample])) || cut) continue;
            const before = depth[sample];
            if (depthWrite) depth[sample] = z;
            if (shaded && repeat) {
              shader.repeat!(sample);
              continue;
            }
            shaded = true;
            // Shaded at the pixel's centre, as a GPU interpolates without `centroid` (off the
            // triangle at its edges): a sample's offset would shift textures by a part of a pixel.
            this.l0 = (row0 + dx * stepX0 + centre0) * inv; this.l1 = (row1 + dx * stepX1 + centre1) * inv; this.z = z;
            if (!this.shade(sample, shader)) { depth[sample] = before; cut = true; }
          }
        }
      }
    }
  }
}
