// Triangles in clip space → pixels: Sutherland–Hodgman clipping in clip space, edge functions on
// a fixed-point grid with the top-left fill rule, a Float32 z-buffer, perspective-correct
// barycentrics (and their screen derivatives, for texture LOD). Knows nothing of shading.

/**
 * Vertex layout in the buffers drawn: clip x, y, z, w, then a user clip distance (kept where
 * ≥ 0; used when `userClip` is set), then the shader's varyings. Clipping interpolates them all.
 */
export const CLIP_W = 3;
export const CLIP_DISTANCE = 4;
export const VARYINGS = 5;

/** Sub-pixel precision of the snapped vertices: 1/256 px, as GPUs commonly use (8 bits). */
export const SUBPIXEL_BITS = 8;
const SUB = 1 << SUBPIXEL_BITS;
const HALF = SUB >> 1;
/**
 * Guard band: x and y are clipped to ±GUARD·w (NDC ±4), so snapped coordinates stay below
 * 2^23 for grids up to 8192 px and every edge-function product is an exact integer in a double.
 */
const GUARD = 4;
/** A clipped triangle has at most 3 + one vertex per plane (near, far, 4 guard, user). */
const MAX_POLY = 10;

export type CullMode = 'none' | 'back';

/** Called for every pixel that passes the mask and the depth test; reads the rasterizer's fields. */
export interface FragmentShader {
  fragment(pixel: number, r: Rasterizer): void;
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
  cull: CullMode = 'none';
  /** Front faces are counter-clockwise in NDC (GL's default); false in the mirrored pass. */
  frontCCW = true;
  /** Clip against the user clip distance (slot CLIP_DISTANCE) as well. */
  userClip = false;
  /** Only pixels whose mask byte is non-zero are drawn (the glass's footprint); null: all. */
  mask: Uint8Array | null = null;
  /** Compute dbdx/dbdy per fragment (texture LOD needs them). */
  derivatives = true;
  /** Floats per vertex in the buffers drawn (≥ VARYINGS). */
  stride = VARYINGS;

  // Per fragment, for the shader: the clipped vertices (`poly`), the triangle's three vertex
  // offsets into it, the perspective-correct barycentrics and their derivatives per pixel.
  poly: Float64Array;
  o0 = 0;
  o1 = 0;
  o2 = 0;
  b0 = 0;
  b1 = 0;
  b2 = 0;
  dbdx0 = 0;
  dbdx1 = 0;
  dbdx2 = 0;
  dbdy0 = 0;
  dbdy1 = 0;
  dbdy2 = 0;
  /** NDC depth of the fragment (bias included). */
  z = 0;

  private scratch: Float64Array;
  private readonly dist = new Float64Array(MAX_POLY);
  // Snapped screen positions (fixed point, y down), 1/w and NDC z of the polygon's vertices.
  private readonly fx = new Float64Array(MAX_POLY);
  private readonly fy = new Float64Array(MAX_POLY);
  private readonly iw = new Float64Array(MAX_POLY);
  private readonly nz = new Float64Array(MAX_POLY);

  constructor(maxWidth = 0, maxHeight = 0) {
    this.depth = new Float32Array(0);
    this.poly = new Float64Array(0);
    this.scratch = new Float64Array(0);
    if (maxWidth > 0) this.resize(maxWidth, maxHeight);
  }

  /** Sets the target size; the depth buffer grows as needed (never per frame once large enough). */
  resize(width: number, height: number): void {
    this.width = width;
    this.height = height;
    if (this.depth.length < width * height) this.depth = new Float32Array(width * height);
  }

  clearDepth(): void {
    this.depth.fill(Infinity, 0, this.width * this.height);
  }

  /**
   * Draws `count` indices' triangles of `vertices` (layout above, `this.stride` floats each).
   * Pixel (i, j) is sampled at its centre (i + ½, j + ½), row 0 at the top.
   */
  drawTriangles(vertices: Float64Array, indices: ArrayLike<number>, count: number, shader: FragmentShader): void {
    const s = this.stride;
    if (this.poly.length < MAX_POLY * s) {
      this.poly = new Float64Array(MAX_POLY * s);
      this.scratch = new Float64Array(MAX_POLY * s);
    }
    const user = this.userClip;
    for (let t = 0; t + 2 < count; t += 3) {
      const a = indices[t] * s, b = indices[t + 1] * s, c = indices[t + 2] * s;
      // Trivial accept: every vertex inside every plane; trivial reject: all outside one.
      const inA = inside(vertices, a, user), inB = inside(vertices, b, user), inC = inside(vertices, c, user);
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
    for (let i = 1; i + 1 < n; i++) this.triangle(0, i, i + 1, shader);
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
    const py0 = Math.max(0, Math.ceil((Math.min(y0, y1, y2) - HALF) / SUB));
    const py1 = Math.min(this.height - 1, Math.floor((Math.max(y0, y1, y2) - HALF) / SUB));
    if (px0 > px1 || py0 > py1) return;
    this.scan(i, j, k, area, px0, px1, py0, py1, shader);
  }

  /**
   * The pixels of triangle (i, j, k), ordered so that its edge functions' `area` is positive,
   * whose centres lie in it (top-left rule) within the box px0..px1 × py0..py1: depth-tested,
   * their barycentrics (and derivatives) set, and shaded.
   */
  private scan(i: number, j: number, k: number, area: number, px0: number, px1: number, py0: number, py1: number, shader: FragmentShader): void {
    const { fx, fy } = this;
    const x0 = fx[i], y0 = fy[i], x1 = fx[j], y1 = fy[j], x2 = fx[k], y2 = fy[k];
    // Edge e_v is opposite vertex v: e0 = E(1→2), e1 = E(2→0), e2 = E(0→1); E(a→b)(p) =
    // (bx − ax)(py − ay) − (by − ay)(px − ax), positive inside (area > 0).
    const ax0 = x2 - x1, ay0 = y2 - y1; // edge 1→2
    const ax1 = x0 - x2, ay1 = y0 - y2; // edge 2→0
    const ax2 = x1 - x0, ay2 = y1 - y0; // edge 0→1
    // Top-left rule (y down, interior on the right of each edge as walked): a top edge runs
    // exactly horizontally rightwards, a left edge upwards. Pixels on other edges are left out.
    const bias0 = (ay0 === 0 && ax0 > 0) || ay0 < 0 ? 0 : -1;
    const bias1 = (ay1 === 0 && ax1 > 0) || ay1 < 0 ? 0 : -1;
    const bias2 = (ay2 === 0 && ax2 > 0) || ay2 < 0 ? 0 : -1;
    const cx = px0 * SUB + HALF, cy = py0 * SUB + HALF;
    let row0 = ax0 * (cy - y1) - ay0 * (cx - x1);
    let row1 = ax1 * (cy - y2) - ay1 * (cx - x2);
    let row2 = ax2 * (cy - y0) - ay2 * (cx - x0);
    // Steps per pixel (exact integers).
    const stepX0 = -ay0 * SUB, stepX1 = -ay1 * SUB, stepX2 = -ay2 * SUB;
    const stepY0 = ax0 * SUB, stepY1 = ax1 * SUB, stepY2 = ax2 * SUB;

    const inv = 1 / area;
    const z0 = this.nz[i], z1 = this.nz[j], z2 = this.nz[k];
    const w0 = this.iw[i], w1 = this.iw[j], w2 = this.iw[k];
    // d(screen barycentric)/dx and /dy per pixel, times 1/w: the derivatives of λ_v/w_v.
    const ax = stepX0 * inv * w0, bx = stepX1 * inv * w1, cxw = stepX2 * inv * w2;
    const ay = stepY0 * inv * w0, by = stepY1 * inv * w1, cyw = stepY2 * inv * w2;
    const sumX = ax + bx + cxw, sumY = ay + by + cyw;
    const s = this.stride;
    this.o0 = i * s + VARYINGS;
    this.o1 = j * s + VARYINGS;
    this.o2 = k * s + VARYINGS;
    const { depth, mask, depthTest, depthWrite, depthBias, derivatives } = this;
    const width = this.width;

    const span = px1 - px0;
    for (let y = py0; y <= py1; y++, row0 += stepY0, row1 += stepY1, row2 += stepY2) {
      // The row's covered run [k0, k1] (pixels from px0), solved per edge from e + bias + k·step ≥ 0
      // and widened by one: the exact integer test below still decides every pixel.
      let k0 = 0, k1 = span;
      k0 = Math.max(k0, runStart(row0 + bias0, stepX0)); k1 = Math.min(k1, runEnd(row0 + bias0, stepX0, span));
      k0 = Math.max(k0, runStart(row1 + bias1, stepX1)); k1 = Math.min(k1, runEnd(row1 + bias1, stepX1, span));
      k0 = Math.max(k0, runStart(row2 + bias2, stepX2)); k1 = Math.min(k1, runEnd(row2 + bias2, stepX2, span));
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
              if (depthWrite) depth[pixel] = z;
              const a0 = l0 * w0, a1 = l1 * w1, a2 = l2 * w2;
              const q = 1 / (a0 + a1 + a2);
              const b0 = a0 * q, b1 = a1 * q, b2 = a2 * q;
              this.b0 = b0; this.b1 = b1; this.b2 = b2;
              this.z = z;
              if (derivatives) {
                this.dbdx0 = (ax - b0 * sumX) * q; this.dbdx1 = (bx - b1 * sumX) * q; this.dbdx2 = (cxw - b2 * sumX) * q;
                this.dbdy0 = (ay - b0 * sumY) * q; this.dbdy1 = (by - b1 * sumY) * q; this.dbdy2 = (cyw - b2 * sumY) * q;
              }
              shader.fragment(pixel, this);
            }
          }
        }
        e0 += stepX0; e1 += stepX1; e2 += stepX2;
      }
    }
  }
}

// Clip planes, as distances that are ≥ 0 inside: near z + w, far w − z, the guard band
// G·w ± x and G·w ± y, and the user clip distance.
const PLANES = 7;
const USER = 6;
const ALL_FRUSTUM = (1 << USER) - 1;
const ALL = (1 << PLANES) - 1;

function planeDistance(v: Float64Array, o: number, plane: number): number {
  const w = v[o + CLIP_W];
  switch (plane) {
    case 0: return v[o + 2] + w;
    case 1: return w - v[o + 2];
    case 2: return GUARD * w + v[o];
    case 3: return GUARD * w - v[o];
    case 4: return GUARD * w + v[o + 1];
    case 5: return GUARD * w - v[o + 1];
    default: return v[o + CLIP_DISTANCE];
  }
}

/** Bit p set: the vertex is inside plane p (the user bit is set when `user` is off). */
function inside(v: Float64Array, o: number, user: boolean): number {
  let bits = user ? (v[o + CLIP_DISTANCE] >= 0 ? 1 << USER : 0) : 1 << USER;
  const x = v[o], y = v[o + 1], z = v[o + 2], w = v[o + CLIP_W], g = GUARD * w;
  if (z + w >= 0) bits |= 1;
  if (w - z >= 0) bits |= 2;
  if (g + x >= 0) bits |= 4;
  if (g - x >= 0) bits |= 8;
  if (g + y >= 0) bits |= 16;
  if (g - y >= 0) bits |= 32;
  return bits & (ALL_FRUSTUM | (1 << USER));
}

/** First k ≥ 0 (one early) where e + k·step ≥ 0 can hold; a value past any span when it never can. */
function runStart(e: number, step: number): number {
  if (step > 0) return e >= 0 ? 0 : Math.ceil(-e / step) - 1;
  return e >= 0 ? 0 : 1 << 30;
}

/** Last k (one late) where e + k·step ≥ 0 can hold, capped at `span`; −1 when it never can. */
function runEnd(e: number, step: number, span: number): number {
  if (step < 0) return e < 0 ? -1 : Math.min(span, Math.floor(e / -step) + 1);
  return e >= 0 || step > 0 ? span : -1;
}

function copyVertex(src: Float64Array, from: number, dst: Float64Array, to: number, n: number): void {
  for (let k = 0; k < n; k++) dst[to + k] = src[from + k];
}
