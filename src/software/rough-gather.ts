// Rough glass on the CPU (docs/rough-glass.md#the-gather), as shaders/glass.frag gathers it (frame/rough-glass.ts has
// the method and its numbers): R̃ or B̃ at a glass pixel is a weighted mean of the sharp image
// (the reflection, or the frame beyond the glass) on rings around the pixel, each neighbour
// weighted by the share of the pixel's GGX lobe that reaches it at that neighbour's own distance
// from the glass — so an object touching the glass stays sharp and one far from it spreads its
// light wide — and left out where a ray to it would leave the glass's far side or pass the
// pixel's own surface first.
import { invert4 } from '../math/invert';
import { refractThin } from '../math/ggx';
import { ROUGH_FIRST_RING, roughRings, type RoughGatherSettings } from '../frame/rough-glass';
import { FloatMips } from './float-mips';

/** Rays leave the glass; below this a code is a surface, at or above it nothing (the background). */
const NOTHING = 0.9999;
/** A neighbour counts as farther than the pixel's own surface beyond this ratio of scales… */
const FARTHER = 1.05;
/** …and as hidden by it where the surface its ray passes first is nearer than this ratio. */
const HIDDEN = 0.9;

export class RoughGather {
  /**
   * The sharp reflection (pass 0) and the frame beyond the glass (pass 1), with mips: RGB, the
   * share covered by a surface, and that share times the surfaces' distance code.
   */
  readonly images = [new FloatMips(5), new FloatMips(5)] as const;
  alpha = 0;
  ior = 1.5;
  settings: RoughGatherSettings = { angles: 8, lodBias: -1 };
  /** ≥ 0: the bench's fixed-radius comparison at this mip level (in pixels' levels); −1: the gather. */
  fixedLevel = -1;
  /** Sample-grid cells per pixel along an axis (the gather works in pixels, reads the grid). */
  cells = 1;
  /**
   * Grid cells along an axis that one glass fragment stands for: 1 where every sample is shaded,
   * the pixel's 2 under 2× multisampling (one fragment per pixel, as WebGL shades). The gather
   * centres on that footprint and reads its centre there, exactly: a centre read at the pixel's
   * level from a sample off the pixel's centre mixed in the neighbouring pixel, so an object
   * touching the glass, seen through it, blurred by half a pixel and never hardened.
   */
  footprint = 1;
  /** A strata frame's place of each ring sample in its sector and its level's shift (frame/refinement.ts gatherJitter). */
  readonly jitter = new Float64Array([0.5, 0.5, 0]);
  private width = 0;
  private height = 0;
  private vp: Float64Array = new Float64Array(16);
  private orthographic = false;
  private readonly eye = new Float64Array(3);
  private readonly n = new Float64Array(3);
  /** Orthographic: the view direction. */
  private readonly forward = new Float64Array(3);
  private readonly d = new Float64Array(3);
  private readonly e1 = new Float64Array(3);
  private readonly e2 = new Float64Array(3);
  private readonly t = new Float64Array(3);
  private readonly m = new Float64Array(3);
  private readonly dir = new Float64Array(3);
  private readonly texel = new Float64Array(5);
  /** What a pass shows where no surface is (linear light in srgb). */
  readonly background = new Float64Array(3);
  private readonly at = new Float64Array(2);
  /** The lobe's 2×2 maps: J (slope → the ray's turn along e1, e2), A = M·J (slope → pixels). */
  private readonly J = new Float64Array(4);
  private readonly A = new Float64Array(4);
  /** The inverse of the eye-relative view-projection. */
  private readonly inverse = new Float64Array(16);

  /**
   * The frame's camera: eye-relative view-projection, eye, the sample grid's size, the glass
   * normal on the viewer's side, and (orthographic) the view direction.
   */
  frame(
    viewProjection: Float64Array, eye: ArrayLike<number>, width: number, height: number, normal: ArrayLike<number>,
    orthographic: boolean, forward: ArrayLike<number>,
  ): void {
    this.vp = viewProjection;
    invert4(this.inverse, viewProjection);
    this.width = width;
    this.height = height;
    this.orthographic = orthographic;
    for (let k = 0; k < 3; k++) {
      this.eye[k] = eye[k];
      this.n[k] = normal[k];
      this.forward[k] = forward[k];
    }
  }

  /**
   * R̃ (pass 0) or B̃ (pass 1) at the glass point eye + rel into out[0..2]; false where no
   * neighbour has weight (the caller keeps the sharp value).
   */
  gather(out: Float64Array, rel: ArrayLike<number>, pass: 0 | 1): boolean {
    if (this.fixedLevel >= 0) return pass === 0 && this.fixed(out, rel);
    const n = this.n, d = this.d, e1 = this.e1, e2 = this.e2, J = this.J, A = this.A;
    const L = Math.sqrt(rel[0] * rel[0] + rel[1] * rel[1] + rel[2] * rel[2]);
    if (this.orthographic) d.set(this.forward);
    else for (let k = 0; k < 3; k++) d[k] = rel[k] / L;
    const dn = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    const c = -dn > 1e-6 ? -dn : 1e-6;
    // e1 ⟂ d toward the viewer's side, e2 = d × e1 (head-on: any pair ⟂ d).
    for (let k = 0; k < 3; k++) e1[k] = n[k] - dn * d[k];
    let l1 = Math.hypot(e1[0], e1[1], e1[2]);
    if (l1 < 1e-9) {
      const ax = Math.abs(d[0]) < 0.9 ? 1 : 0, ay = 1 - ax;
      e1[0] = ay * d[2]; e1[1] = -ax * d[2]; e1[2] = ax * d[1] - ay * d[0];
      l1 = Math.hypot(e1[0], e1[1], e1[2]);
    }
    for (let k = 0; k < 3; k++) e1[k] /= l1;
    e2[0] = d[1] * e1[2] - d[2] * e1[1]; e2[1] = d[2] * e1[0] - d[0] * e1[2]; e2[2] = d[0] * e1[1] - d[1] * e1[0];
    if (!this.lobe(pass, c)) return false;
    // M: pixels per radian of the eye ray's turn along e1, e2 at P's distance L from the eye
    // (orthographic: from the camera's point; the scale below saturates for the background there
    // too, which keeps its share of the lobe — a scale s, unbounded, lost it: 29.4 dB in WebGL).
    const P0 = this.eye[0] + rel[0], P1 = this.eye[1] + rel[1], P2 = this.eye[2] + rel[2], at = this.at;
    if (!this.project(P0, P1, P2)) return false;
    const ax = at[0], ay = at[1], step = 1e-3 * L;
    if (!this.project(P0 + step * e1[0], P1 + step * e1[1], P2 + step * e1[2])) return false;
    const m00 = (at[0] - ax) / 1e-3, m10 = (at[1] - ay) / 1e-3;
    if (!this.project(P0 + step * e2[0], P1 + step * e2[1], P2 + step * e2[2])) return false;
    const m01 = (at[0] - ax) / 1e-3, m11 = (at[1] - ay) / 1e-3;
    A[0] = m00 * J[0] + m01 * J[2]; A[1] = m00 * J[1] + m01 * J[3];
    A[2] = m10 * J[0] + m11 * J[2]; A[3] = m10 * J[1] + m11 * J[3];
    const f = this.footprint;
    return this.rings(out, pass, f * (Math.floor(ax / f) + 0.5), f * (Math.floor(ay / f) + 0.5), c, L);
  }

  /** The bench's comparison: the reflection at one mip level wherever the pixel is (FrameState.fixedBlurLevel). */
  private fixed(out: Float64Array, rel: ArrayLike<number>): boolean {
    if (!this.project(this.eye[0] + rel[0], this.eye[1] + rel[1], this.eye[2] + rel[2])) return false;
    this.read(this.images[0], this.at[0], this.at[1], this.fixedLevel + Math.log2(this.cells));
    const t = this.texel;
    out[0] = t[0]; out[1] = t[1]; out[2] = t[2];
    return true;
  }

  /** J for this pass at cosθ = c: false where the glass lets no ray through (total internal reflection). */
  private lobe(pass: 0 | 1, c: number): boolean {
    const J = this.J;
    if (pass === 0) {
      // A facet tilted by slope σ along the view's slope turns the mirrored ray by 2σ toward the
      // glass; across it by 2σ·cosθ.
      J[0] = 2; J[1] = 0; J[2] = 0; J[3] = 2 * c;
      return true;
    }
    const n = this.n, d = this.d, e1 = this.e1, e2 = this.e2, t = this.t, m = this.m, dir = this.dir, eps = 1e-4;
    for (let col = 0; col < 2; col++) {
      // t: the glass's tangent that e1 (col 0) or e2 (col 1) lies over.
      const e = col === 0 ? e1 : e2, en = e[0] * n[0] + e[1] * n[1] + e[2] * n[2];
      for (let k = 0; k < 3; k++) t[k] = e[k] - en * n[k];
      const lt = Math.hypot(t[0], t[1], t[2]) || 1;
      for (let k = 0; k < 3; k++) m[k] = n[k] + (eps * t[k]) / lt;
      const lm = Math.hypot(m[0], m[1], m[2]);
      for (let k = 0; k < 3; k++) m[k] /= lm;
      if (!refractThin(dir, d, m, n, this.ior)) return false;
      J[col] = ((dir[0] - d[0]) * e1[0] + (dir[1] - d[1]) * e1[1] + (dir[2] - d[2]) * e1[2]) / eps;
      J[2 + col] = ((dir[0] - d[0]) * e2[0] + (dir[1] - d[1]) * e2[1] + (dir[2] - d[2]) * e2[2]) / eps;
    }
    return true;
  }

  /** The rings around pixel (qx, qy) (sample-grid units), weighted as frame/rough-glass.ts says. */
  private rings(out: Float64Array, pass: 0 | 1, qx: number, qy: number, c: number, L: number): boolean {
    const A = this.A, image = this.images[pass], s = this.cells, a2 = this.alpha * this.alpha;
    const det = Math.abs(A[0] * A[3] - A[1] * A[2]);
    if (!(det > 1e-12)) return false;
    // Work in pixels: A is in grid cells per slope.
    const A0 = A[0] / s, A1 = A[1] / s, A2 = A[2] / s, A3 = A[3] / s, detPx = det / (s * s);
    const sq = A0 * A0 + A1 * A1 + A2 * A2 + A3 * A3;
    const smax = Math.sqrt((sq + Math.sqrt(Math.max(0, sq * sq - 4 * detPx * detPx))) / 2);
    const lodCells = Math.log2(s), lodCentre = Math.log2(this.footprint), { angles, lodBias } = this.settings;
    const rings = roughRings(this.alpha, smax), px = qx / s, py = qy / s;
    const t = this.texel, bg = this.background;
    this.read(image, qx, qy, lodCentre);
    const gq = this.scaleOf(t[4] + 1 - t[3], c, L);
    let sum = 0, r = 0, g = 0, b = 0;
    for (let ring = -1; ring < rings; ring++) {
      const outer = ring < 0 ? ROUGH_FIRST_RING / 2 : ROUGH_FIRST_RING * 2 ** ring;
      const inner = ring < 0 ? 0 : ring === 0 ? ROUGH_FIRST_RING / 2 : ROUGH_FIRST_RING * 2 ** (ring - 1);
      const count = ring < 0 ? 1 : angles, jit = this.jitter;
      // Alone the sample lies mid-ring; a strata frame puts it at its share u of the sector's area.
      const mid = ring < 0 ? 0 : jit[2] === 0 ? (inner + outer) / 2 : Math.sqrt(inner * inner + jit[0] * (outer * outer - inner * inner));
      const area = ((Math.PI * (outer * outer - inner * inner)) / count) * (detPx / (smax * smax));
      const level = ring < 0 ? lodCentre : Math.max(0, 0.5 * Math.log2(area) + lodBias + jit[2]) + lodCells;
      const xo = outer / smax, xi = inner / smax;
      for (let i = 0; i < count; i++) {
        const phi = (2 * Math.PI * (i + 0.5 * (ring & 1) + jit[1] - 0.5)) / count;
        const vx = (Math.cos(phi) * mid) / smax, vy = (Math.sin(phi) * mid) / smax;
        const dx = A0 * vx + A1 * vy, dy = A2 * vx + A3 * vy, x = s * (px + dx), y = s * (py + dy);
        this.read(image, x, y, level);
        // Two layers: the surfaces the sample covers (their colour, coverage and mean distance
        // code), and the background where it covers none.
        const cover = t[3], cr = t[0], cg = t[1], cb = t[2];
        for (let layer = 0; layer < 2; layer++) {
          const part = layer === 0 ? cover : 1 - cover;
          if (!(part > 1e-6)) continue;
          let gs: number;
          if (layer === 0) gs = this.scaleOf(t[4] / cover, c, L);
          else {
            // A ray turned toward the background must still leave on the far side (docs/rough-glass.md#the-gather
            // drops the rest): at grazing incidence much of the lobe would go beyond the horizon
            // (a long floor at roughness 0.3: 39.2 dB with the test, 36.2 without). On the bench
            // floor it measures the other way (roughness 0.5: 40.6 with, 42.5 without), which
            // says some other part of the gather errs there; the rule follows the physics.
            if (!this.leaves(x, y)) continue;
            gs = 1;
          }
          if (ring >= 0 && gs > FARTHER * gq) {
            // Hidden where the ray passes the pixel's own surface first.
            const k = gq / gs;
            this.read(image, s * (px + k * dx), s * (py + k * dy), level);
            const go = this.scaleOf(t[4] + 1 - t[3], c, L);
            this.read(image, x, y, level);
            if (go < HIDDEN * gs) continue;
          }
          // The lobe's share of this sample's piece of the ring (P(|slope| < x) = x²/(α² + x²)).
          const o = xo / gs, ii = xi / gs;
          const w = (part * ((o * o) / (a2 + o * o) - (ii * ii) / (a2 + ii * ii))) / count;
          if (!(w > 0)) continue;
          sum += w;
          if (layer === 1) {
            r += w * bg[0]; g += w * bg[1]; b += w * bg[2];
          } else {
            // The surfaces' own colour: the sample's less the background's share of it.
            const q = 1 - cover;
            r += (w * (cr - q * bg[0])) / cover; g += (w * (cg - q * bg[1])) / cover; b += (w * (cb - q * bg[2])) / cover;
          }
        }
      }
    }
    if (!(sum > 0)) return false;
    out[0] = r / sum; out[1] = g / sum; out[2] = b / sum;
    return true;
  }

  /** The image's texel (r, g, b, coverage, coverage·code) at grid point (x, y), level `lod`, into this.texel. */
  private read(image: FloatMips, x: number, y: number, lod: number): void {
    const t = this.texel;
    t[0] = t[1] = t[2] = t[3] = t[4] = 0;
    image.addSample(t, x, y, lod, 1);
  }

  /** Whether the eye ray through grid point (x, y) goes to the glass's far side (a direction a turned ray can take). */
  private leaves(x: number, y: number): boolean {
    const inv = this.inverse, n = this.n;
    const nx = (2 * x) / this.width - 1, ny = 1 - (2 * y) / this.height;
    let dn = 0;
    for (let k = 0; k < 3; k++) {
      const a = (inv[k] * nx + inv[4 + k] * ny - inv[8 + k] + inv[12 + k]) / (inv[3] * nx + inv[7] * ny - inv[11] + inv[15]);
      const b = (inv[k] * nx + inv[4 + k] * ny + inv[8 + k] + inv[12 + k]) / (inv[3] * nx + inv[7] * ny + inv[11] + inv[15]);
      dn += (b - a) * n[k];
    }
    return dn < 0;
  }

  private scaleOf(u: number, c: number, L: number): number {
    if (u >= NOTHING) return 1;
    const s = u / (1 - u) / c, g = s / (L + s);
    return g > 1e-6 ? g : 1e-6;
  }

  /** Projects a world point to the sample grid into this.at; false behind the eye. */
  private project(x: number, y: number, z: number): boolean {
    const v = this.vp, rx = x - this.eye[0], ry = y - this.eye[1], rz = z - this.eye[2];
    const w = v[3] * rx + v[7] * ry + v[11] * rz + v[15];
    if (!(w > 1e-9)) return false;
    const cx = v[0] * rx + v[4] * ry + v[8] * rz + v[12], cy = v[1] * rx + v[5] * ry + v[9] * rz + v[13];
    this.at[0] = ((cx / w + 1) / 2) * this.width;
    this.at[1] = ((1 - cy / w) / 2) * this.height;
    return true;
  }
}

/** The buffers a rough frame fills: per sample, a pass's distance codes, and the images packed with them. */
export class RoughBuffers {
  /** The frame beyond the glass alone (RGB, the sample grid). */
  behind = new Float32Array(0);
  /** Per sample: the distance code of what the pass drew there (1: nothing). */
  codes = new Float32Array(0);
  private packed = [new Float32Array(0), new Float32Array(0)];

  resize(N: number): void {
    if (this.codes.length >= N) return;
    this.behind = new Float32Array(3 * N);
    this.codes = new Float32Array(N);
    this.packed = [new Float32Array(5 * N), new Float32Array(5 * N)];
  }

  /** Packs `rgb` with this.codes into `gather`'s image for `pass` (rgb, coverage, coverage·code), and builds its mips. */
  build(gather: RoughGather, pass: 0 | 1, rgb: Float32Array, W: number, H: number): void {
    const out = this.packed[pass], codes = this.codes;
    for (let i = 0, j = 0, k = 0; i < W * H; i++, j += 3, k += 5) {
      const u = codes[i], cover = u < NOTHING ? 1 : 0;
      out[k] = rgb[j]; out[k + 1] = rgb[j + 1]; out[k + 2] = rgb[j + 2]; out[k + 3] = cover; out[k + 4] = cover * u;
    }
    gather.images[pass].build(out, W, H);
  }
}
