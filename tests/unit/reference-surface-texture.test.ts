// The texture at a hit (src/reference/surface-texture.ts): which texture a material gets (images decoded once, the
// fallbacks), each mapping's UV, and the box filter's footprint: the ray differentials moved onto the tangent plane and
// through the mapping's gradients into texels, worked out by hand and read off the sampler's arguments.
import { describe, expect, it, vi } from 'vitest';
import { ObjectFrame } from '../../src/reference/object-frame';
import { Ray } from '../../src/reference/ray';
import { SurfaceHit } from '../../src/reference/surface-hit';
import { MAX_FOOTPRINT_TEXELS, SurfaceTexture } from '../../src/reference/surface-texture';
import { proceduralGrey } from '../../src/reference/texture-sampler';
import type { DecodedImage } from '../../src/scene/decoded-image';
import type { Bounds, Material, Mapping, TextureSource } from '../../src/scene/scene';
import { expectClose } from './helpers/math';

/** 2×2, top row first: (10, 20, 30), (50, 60, 70) / (90, 100, 110), (130, 140, 150). Texture row 0 is the bottom row. */
const IMAGE: DecodedImage = { width: 2, height: 2, data: new Uint8Array([10, 20, 30, 255, 50, 60, 70, 255, 90, 100, 110, 255, 130, 140, 150, 255]) };
const BAD: DecodedImage = { width: 3, height: 3, data: new Uint8Array(8) };

/** A map that counts its look-ups. */
class Images extends Map<string, DecodedImage> {
  gets = 0;
  override get(key: string) { this.gets++; return super.get(key); }
}
const images = () => new Images([['img.png', IMAGE], ['bad.png', BAD]]);

function material(texture: TextureSource, mapping: Mapping = 'uv'): Material {
  return { ambient: [1, 1, 1], diffuse: [1, 1, 1], specular: [0, 0, 0], shininess: 1, opacity: 1, texture, mapping };
}

const identity = () => new ObjectFrame({ position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 }, 0);

/** A hit at t with true normal ng, object point q (= nq's surface), UV and UV gradients. */
interface HitOver { t?: number; ng?: number[]; q?: number[]; nq?: number[]; u?: number; v?: number; gu?: number[]; gv?: number[] }
function hit(over: HitOver = {}): SurfaceHit {
  const h = new SurfaceHit();
  h.frame = identity();
  h.t = over.t ?? 2;
  h.ng.set(over.ng ?? [0, 0, 1]);
  h.q.set(over.q ?? [0, 0, 0]);
  h.nq.set(over.nq ?? [0, 0, 1]);
  h.u = over.u ?? 0.3;
  h.v = over.v ?? 0.6;
  h.gu.set(over.gu ?? [0.5, 0, 0]);
  h.gv.set(over.gv ?? [0, 0.25, 0]);
  return h;
}

function ray(d: number[], ddx: number[], ddy: number[], odx = [0, 0, 0], ody = [0, 0, 0]): Ray {
  const r = new Ray();
  r.direction.set(d); r.ddx.set(ddx); r.ddy.set(ddy); r.odx.set(odx); r.ody.set(ody);
  return r;
}
const down = () => ray([0, 0, -1], [0.01, 0, 0], [0, -0.02, 0]);
const BOUNDS: Bounds = { center: [0, 0, 0], radius: 1 };

describe('SurfaceTexture.textureOf', () => {
  it('the procedural texture: one 512² grey channel of the colour space, no image looked up', () => {
    for (const cs of ['none', 'srgb'] as const) {
      const decoded = images();
      const st = new SurfaceTexture('point', cs, decoded);
      const t = st.textureOf(material({ kind: 'procedural' }));
      expect(t).toBe(st.procedural);
      expect(decoded.gets).toBe(0);
      expect([t.channels.length, t.width, t.height]).toEqual([1, 512, 512]);
      const grey = proceduralGrey(cs);
      for (const [x, y] of [[0, 0], [5, 9], [300, 77]]) expect(t.channels[0].texel(x, y)).toBe(grey[y * 512 + x]);
    }
  });

  it("'none': a white texel, made once", () => {
    for (const cs of ['none', 'srgb'] as const) {
      const st = new SurfaceTexture('point', cs);
      const t = st.textureOf(material({ kind: 'none' }));
      expect([t.width, t.height]).toEqual([1, 1]);
      expect(t.channels.map((c) => c.texel(0, 0))).toEqual([1, 1, 1]);
      expect(st.textureOf(material({ kind: 'none' }))).toBe(t);
    }
  });

  it('an image: its three channels (decoded by the colour space), decoded once', () => {
    const decoded = images();
    const st = new SurfaceTexture('point', 'none', decoded);
    const t = st.textureOf(material({ kind: 'image', url: 'img.png' }));
    expect([t.width, t.height, t.channels.length]).toEqual([2, 2, 3]);
    // Texture texel (0, 0) is the image's bottom-left pixel (90, 100, 110).
    expect(t.channels.map((c) => c.texel(0, 0))).toEqual([90 / 255, 100 / 255, 110 / 255]);
    expect(t.channels.map((c) => c.texel(1, 1))).toEqual([50 / 255, 60 / 255, 70 / 255]);
    expect(st.textureOf(material({ kind: 'image', url: 'img.png' }))).toBe(t);
    expect(decoded.gets).toBe(1);
    const srgb = new SurfaceTexture('point', 'srgb', images()).textureOf(material({ kind: 'image', url: 'img.png' }));
    expect(srgb.channels[0].texel(0, 0)).toBeLessThan(90 / 255 - 0.15);
  });

  it('a missing or malformed image: the procedural texture, or white with fallback none; looked up once', () => {
    const decoded = images();
    const st = new SurfaceTexture('point', 'none', decoded);
    for (const url of ['missing.png', 'bad.png']) {
      expect(st.textureOf(material({ kind: 'image', url }))).toBe(st.procedural);
      expect(st.textureOf(material({ kind: 'image', url }))).toBe(st.procedural);
      const white = st.textureOf(material({ kind: 'image', url, fallback: 'none' }));
      expect([white.width, white.height]).toEqual([1, 1]);
      expect(white.channels.map((c) => c.texel(0, 0))).toEqual([1, 1, 1]);
    }
    expect(decoded.gets).toBe(2);
    // Without any images at all.
    const bare = new SurfaceTexture('point', 'none');
    expect(bare.textureOf(material({ kind: 'image', url: 'img.png' }))).toBe(bare.procedural);
  });
});

describe('SurfaceTexture: point samples', () => {
  it("'uv': the texture's bilinear value at the hit's (u, v), per channel", () => {
    const st = new SurfaceTexture('point', 'none', images());
    const out = new Float64Array([9, 9, 9, 9]);
    // (0.5, 0.5): the mean of the four texels.
    expect(st.objectTexture(hit({ u: 0.5, v: 0.5 }), down(), material({ kind: 'image', url: 'img.png' }), BOUNDS, out)).toBe(out);
    expectClose(out, [70 / 255, 80 / 255, 90 / 255, 9], 1e-15);
    // The texel centre (0.25, 0.75) is texture texel (0, 1): the image's top-left pixel.
    st.objectTexture(hit({ u: 0.25, v: 0.75 }), down(), material({ kind: 'image', url: 'img.png' }), BOUNDS, out);
    expectClose(out, [10 / 255, 20 / 255, 30 / 255, 9], 1e-15);
    // Grey textures fill the three channels.
    st.objectTexture(hit({ u: 0.3, v: 0.6 }), down(), material({ kind: 'procedural' }), BOUNDS, out);
    const g = st.procedural.channels[0].bilinear(0.3, 0.6);
    expect([...out]).toEqual([g, g, g, 9]);
    expect(st.singular).toBe(false);
  });

  it("'cylindrical' and 'spherical' read the object point through the mapping", () => {
    const st = new SurfaceTexture('point', 'none');
    const spy = vi.spyOn(st.procedural.channels[0], 'bilinear');
    const bounds: Bounds = { center: [1, 1, 1], radius: 2 };
    // q − c = (1, 0.5, 1): u = ½ + atan2(1, 1)/2π = 0.625, v = ½ + 0.5/(2·2) = 0.625.
    st.objectTexture(hit({ q: [2, 1.5, 2] }), down(), material({ kind: 'procedural' }, 'cylindrical'), bounds, new Float64Array(3));
    expect(spy.mock.calls.at(-1)![0]).toBeCloseTo(0.625, 15);
    expect(spy.mock.calls.at(-1)![1]).toBeCloseTo(0.625, 15);
    // q − c = (0.48, 0.6, 0.64), unit: u = ½ + atan2(0.48, 0.64)/2π, v = acos(−0.6)/π.
    st.objectTexture(hit({ q: [1.48, 1.6, 1.64] }), down(), material({ kind: 'procedural' }, 'spherical'), bounds, new Float64Array(3));
    expect(spy.mock.calls.at(-1)![0]).toBeCloseTo(0.5 + Math.atan2(0.48, 0.64) / (2 * Math.PI), 15);
    expect(spy.mock.calls.at(-1)![1]).toBeCloseTo(Math.acos(-0.6) / Math.PI, 15);
  });

  it("'triplanar': the projections with a weight, blended by |n|⁴", () => {
    // nq = (0.6, 0, 0.8): weights 0.1296 and 0.4096 over 0.5392; the projection along Y has none and is not sampled.
    // c = (1, 1, 1), r = 1 (s = ½), q − c = (0.2, −0.4, 0.6): along X (½ + 0.3, ½ − 0.2), along Z (½ + 0.1, ½ − 0.2).
    const st = new SurfaceTexture('point', 'none', images());
    const m = material({ kind: 'image', url: 'img.png' }, 'triplanar');
    const channels = st.textureOf(m).channels;
    const spies = channels.map((c) => vi.spyOn(c, 'bilinear'));
    const out = st.objectTexture(hit({ q: [1.2, 0.6, 1.6], nq: [0.6, 0, 0.8] }), down(), m, { center: [1, 1, 1], radius: 1 }, new Float64Array(4));
    expect(out[3]).toBe(0);
    expect(spies[0].mock.calls.map(([u, v]) => [u, v].map((x) => Math.round(x * 1e12) / 1e12))).toEqual([[0.8, 0.3], [0.6, 0.3]]);
    const wx = 0.1296 / 0.5392, wz = 0.4096 / 0.5392;
    for (let k = 0; k < 3; k++) {
      spies[k].mockRestore();
      expect(out[k]).toBeCloseTo(wx * channels[k].bilinear(0.8, 0.3) + wz * channels[k].bilinear(0.6, 0.3), 14);
    }
  });

  it('glassTexture: the procedural grey at the glass\'s own UV', () => {
    const st = new SurfaceTexture('point', 'srgb');
    expect(st.glassTexture(hit({ u: 0.71, v: 0.13 }), down())).toBe(st.procedural.channels[0].bilinear(0.71, 0.13));
  });
});

describe('SurfaceTexture: the box filter\'s footprint', () => {
  /** The edges (in texels) the sampler was asked to integrate over, per call. */
  function footprints(st: SurfaceTexture, channel = 0) {
    const spy = vi.spyOn(st.procedural.channels[channel], 'boxFilter');
    return () => spy.mock.calls.map((c) => [...c]);
  }

  it("'uv' seen head-on: ∂p = t·∂d, edges W·(gu·∂p), H·(gv·∂p)", () => {
    // t = 2, d = −z, n = +z: ∂p = (0.02, 0, 0) and (0, −0.04, 0); gu = (½, 0, 0), gv = (0, ¼, 0); W = H = 512:
    // edge 1 = (512·0.01, 0), edge 2 = (0, −512·0.01).
    const st = new SurfaceTexture('box', 'none');
    const calls = footprints(st);
    const out = st.objectTexture(hit(), down(), material({ kind: 'procedural' }), BOUNDS, new Float64Array(3));
    const [[u, v, e1s, e1t, e2s, e2t]] = calls();
    expect([u, v]).toEqual([0.3, 0.6]);
    expectClose([e1s, e1t, e2s, e2t], [5.12, 0, 0, -5.12], 1e-12);
    expect(out[0]).toBe(st.procedural.channels[0].boxFilter(0.3, 0.6, e1s, e1t, e2s, e2t));
    expect([out[1], out[2]]).toEqual([out[0], out[0]]);
    expect(st.singular).toBe(false);
  });

  it('an oblique ray and an origin differential: ∂p = q − (q·n)/(d·n)·d with q = ∂o + t·∂d', () => {
    // d = (0.6, 0, −0.8), n = +z (d·n = −0.8), t = 2. ∂d_x = (0, 0, 0.1): q = (0, 0, 0.2), q·n/d·n = −0.25,
    // ∂p = (0, 0, 0.2) + 0.25·d = (0.15, 0, 0): edge 1 = (512·½·0.15, 0) = (38.4, 0).
    // ∂o_y = (0.1, 0.2, 0.3), ∂d_y = 0: q·n/d·n = −0.375, ∂p = (0.1, 0.2, 0.3) + 0.375·d = (0.325, 0.2, 0):
    // edge 2 = (512·½·0.325, 512·¼·0.2) = (83.2, 25.6), longer than 64: shortened to 64 along itself.
    const st = new SurfaceTexture('box', 'none');
    const calls = footprints(st);
    st.objectTexture(hit(), ray([0.6, 0, -0.8], [0, 0, 0.1], [0, 0, 0], [0, 0, 0], [0.1, 0.2, 0.3]), material({ kind: 'procedural' }), BOUNDS,
      new Float64Array(3));
    const [[, , e1s, e1t, e2s, e2t]] = calls();
    expectClose([e1s, e1t], [38.4, 0], 1e-12);
    const len = Math.hypot(83.2, 25.6);
    expectClose([e2s, e2t], [(83.2 * 64) / len, (25.6 * 64) / len], 1e-12);
    expect(MAX_FOOTPRINT_TEXELS).toBe(64);
    expect(st.singular).toBe(true);
  });

  it('a tilted surface and a skewed ray: every component of n, ∂d and ∂o counts', () => {
    // n = (0, 0.6, 0.8), d = (0.6, −0.48, −0.64) (d·n = −0.8), t = 2; gu = (½, 0, 0), gv = (0, ¼, 0).
    // ∂d_x = (0.01, 0.02, 0.01): q = (0.02, 0.04, 0.02), q·n = 0.04, ∂p = q + 0.05·d = (0.05, 0.016, −0.012): edge 1 = (12.8, 2.048).
    // ∂o_y = (0.01, 0.03, −0.02): q·n = 0.002, ∂p = q + 0.0025·d = (0.0115, 0.0288, −0.0216): edge 2 = (2.944, 3.6864).
    const st = new SurfaceTexture('box', 'none');
    const calls = footprints(st);
    const r = ray([0.6, -0.48, -0.64], [0.01, 0.02, 0.01], [0, 0, 0], [0, 0, 0], [0.01, 0.03, -0.02]);
    st.objectTexture(hit({ ng: [0, 0.6, 0.8] }), r, material({ kind: 'procedural' }), BOUNDS, new Float64Array(3));
    expectClose(calls()[0].slice(2), [12.8, 2.048, 2.944, 3.6864], 1e-12);
    expect(st.singular).toBe(false);
  });

  it('the first edge too long: shortened, and the sample singular', () => {
    // ∂d_x = (0.1, 0, 0) head-on at t = 2: 512·½·0.2 = 51.2 … at t = 3, 76.8: shortened to 64.
    const st = new SurfaceTexture('box', 'none');
    const calls = footprints(st);
    st.objectTexture(hit({ t: 3 }), ray([0, 0, -1], [0.1, 0, 0], [0, -0.001, 0]), material({ kind: 'procedural' }), BOUNDS, new Float64Array(3));
    expectClose(calls()[0].slice(2), [64, 0, 0, -0.384], 1e-12);
    expect(st.singular).toBe(true);
  });

  it('a footprint of exactly 64 texels is kept as it is and not singular', () => {
    // ∂p = (0.25, 0, 0) (t = 1, ∂d = (0.25, 0, 0)): 512·½·0.25 = 64.
    const st = new SurfaceTexture('box', 'none');
    const calls = footprints(st);
    st.objectTexture(hit({ t: 1 }), ray([0, 0, -1], [0.25, 0, 0], [0, 0, 0]), material({ kind: 'procedural' }), BOUNDS, new Float64Array(3));
    expect(calls()[0].slice(2, 4)).toEqual([64, 0]);
    expect(st.singular).toBe(false);
  });

  it('a ray along the surface (d·n = 0): the point sample, and the sample is marked singular', () => {
    const st = new SurfaceTexture('box', 'none', images());
    const m = material({ kind: 'image', url: 'img.png' });
    const t = st.textureOf(m);
    const box = vi.spyOn(t.channels[0], 'boxFilter');
    const out = st.objectTexture(hit({ u: 0.5, v: 0.5 }), ray([1, 0, 0], [0, 0.01, 0], [0, 0, 0.01]), m, BOUNDS, new Float64Array(3));
    expect(box).not.toHaveBeenCalled();
    expectClose(out, [70 / 255, 80 / 255, 90 / 255], 1e-15);
    expect(st.singular).toBe(true);
  });

  it('an image: each channel filtered over the same footprint; the edges in its own texels (W = H = 2)', () => {
    const st = new SurfaceTexture('box', 'none', images());
    const m = material({ kind: 'image', url: 'img.png' });
    const t = st.textureOf(m);
    const spies = t.channels.map((c) => vi.spyOn(c, 'boxFilter'));
    const out = st.objectTexture(hit(), down(), m, BOUNDS, new Float64Array(3));
    for (let k = 0; k < 3; k++) {
      const [args] = spies[k].mock.calls;
      expect(args[0]).toBe(0.3);
      expectClose(args.slice(2), [0.02, 0, 0, -0.02], 1e-15);
      spies[k].mockRestore();
      expect(out[k]).toBe(t.channels[k].boxFilter(0.3, 0.6, args[2], args[3], args[4], args[5]));
    }
    expect(out[0]).not.toBe(out[1]);
  });

  it("'cylindrical': ∂u = (z, 0, −x)/(2πρ²), ∂v = (0, 1/2r, 0) about the bounds' centre", () => {
    // c = (1, 1, 1), r = 2; q − c = (1.2, 0.5, 1.6) (ρ² = 4): ∂u = (1.6, 0, −1.2)/8π = (0.2, 0, −0.15)/π, ∂v = (0, ¼, 0).
    // n = (0.6, 0, 0.8), d = −z (d·n = −0.8), t = 2. ∂d_x = (0.01, 0, 0): q = (0.02, 0, 0), q·n/d·n = −0.015,
    // ∂p = (0.02, 0, −0.015): edge 1 = 512·((0.004 + 0.00225)/π, 0). ∂d_y = (0, 0.01, 0): ∂p = (0, 0.02, 0): edge 2 = 512·(0, 0.005).
    const st = new SurfaceTexture('box', 'none');
    const calls = footprints(st);
    const h = hit({ q: [2.2, 1.5, 2.6], ng: [0.6, 0, 0.8] });
    st.objectTexture(h, ray([0, 0, -1], [0.01, 0, 0], [0, 0.01, 0]), material({ kind: 'procedural' }, 'cylindrical'),
      { center: [1, 1, 1], radius: 2 }, new Float64Array(3));
    const [[u, v, ...edges]] = calls();
    expect(u).toBeCloseTo(0.5 + Math.atan2(0.6, 0.8) / (2 * Math.PI), 15);
    expect(v).toBeCloseTo(0.625, 15);
    expectClose(edges, [(512 * 0.00625) / Math.PI, 0, 0, 2.56], 1e-12);
  });

  it("'spherical': ∂u = (z, 0, −x)/(2πρ²), ∂v = (e_y − (y/|d|²)·d)/(πρ) from the centre", () => {
    // q − c = (0.96, 1.2, 1.28) = 2·(0.48, 0.6, 0.64): ρ² = 2.56, ρ = 1.6, |d|² = 4. ∂u = (1.28, 0, −0.96)/(5.12π) =
    // (0.25, 0, −0.1875)/π; y/|d|² = 0.3: ∂v = (−0.288, 0.64, −0.384)/(1.6π) = (−0.18, 0.4, −0.24)/π. n = (0.48, 0.6, 0.64),
    // d = −n, t = 3; tangents ∂d_x = 0.01·(0.8, 0, −0.6), ∂d_y = 0.01·(−0.36, 0.8, −0.48): ∂p = 3·∂d.
    // Edge 1 = 512·(0.03·(0.2 + 0.1125)/π, 0) (∂v·(0.8, 0, −0.6) = 0), edge 2 = 512·(0, 0.03·0.5/π) (∂u ⊥ it).
    const st = new SurfaceTexture('box', 'none');
    const calls = footprints(st);
    const n = [0.48, 0.6, 0.64];
    const h = hit({ t: 3, q: [1.96, 2.2, 2.28], ng: n });
    st.objectTexture(h, ray(n.map((x) => -x), [0.008, 0, -0.006], [-0.0036, 0.008, -0.0048]), material({ kind: 'procedural' }, 'spherical'),
      { center: [1, 1, 1], radius: 1 }, new Float64Array(3));
    const [[u, v, ...edges]] = calls();
    expect(u).toBeCloseTo(0.5 + Math.atan2(0.48, 0.64) / (2 * Math.PI), 14);
    expect(v).toBeCloseTo(Math.acos(-0.6) / Math.PI, 14);
    expectClose(edges, [(512 * 0.03 * 0.3125) / Math.PI, 0, 0, (512 * 0.015) / Math.PI], 1e-10);
    // The same point on a flat face (n = +z, not along q − c: a box mapped spherically), seen head-on: ∂p = (0.03, 0, 0) and
    // (0, 0.03, 0) now have parts along q − c, which ∂v's radial part (through y/|d|²) meets:
    // edge 1 = 512·(0.03·0.25, 0.03·(−0.18))/π, edge 2 = 512·(0, 0.03·0.4)/π.
    const flat = hit({ t: 3, q: [1.96, 2.2, 2.28], ng: [0, 0, 1] });
    st.objectTexture(flat, ray([0, 0, -1], [0.01, 0, 0], [0, 0.01, 0]), material({ kind: 'procedural' }, 'spherical'),
      { center: [1, 1, 1], radius: 1 }, new Float64Array(3));
    expectClose(calls()[1].slice(2), [(512 * 0.0075) / Math.PI, (-512 * 0.0054) / Math.PI, 0, (512 * 0.012) / Math.PI], 1e-10);
  });

  it("'triplanar': each projection's constant gradients, s along its own axes, turned into the world", () => {
    // Rz(90°) frame: object (x, y, z) → world (−y, x, z). nq = (0.6, 0, 0.8): projections along X (u ← z, v ← y) and Z
    // (u ← x, v ← y); s = 1/(2·2) = ¼ (r = 2). World gradients: along X ∂u = (0, 0, ¼), ∂v = R(0, ¼, 0) = (−¼, 0, 0);
    // along Z ∂u = R(¼, 0, 0) = (0, ¼, 0), ∂v = (−¼, 0, 0). Head-on, ∂p = (0.02, 0, 0) and (0, −0.04, 0):
    // along X edges 512·(0, −0.005) and 512·(0, 0); along Z 512·(0, −0.005) and 512·(−0.01, 0).
    const st = new SurfaceTexture('box', 'none');
    const calls = footprints(st);
    const h = hit({ q: [0.2, -0.4, 0.6], nq: [0.6, 0, 0.8] });
    h.frame = new ObjectFrame({ position: [0, 0, 0], rotation: [0, 0, 90], scale: [1, 1, 1], spin: 0 }, 0);
    const out = st.objectTexture(h, down(), material({ kind: 'procedural' }, 'triplanar'), { center: [0, 0, 0], radius: 2 }, new Float64Array(3));
    const got = calls();
    expect(got.length).toBe(2);
    // Along X: (½ + 0.6/4, ½ − 0.4/4); along Z: (½ + 0.2/4, ½ − 0.4/4).
    expectClose(got[0], [0.65, 0.4, 0, -2.56, 0, 0], 1e-12);
    expectClose(got[1], [0.55, 0.4, 0, -2.56, -5.12, 0], 1e-12);
    const sampler = st.procedural.channels[0];
    vi.restoreAllMocks();
    // The first projection's footprint has no area: its bilinear value.
    const expected = (0.1296 * sampler.bilinear(0.65, 0.4) + 0.4096 * sampler.boxFilter(0.55, 0.4, 0, -2.56, -5.12, 0)) / 0.5392;
    expect(out[0]).toBeCloseTo(expected, 14);
    expect([out[1], out[2]]).toEqual([out[0], out[0]]);
  });

  it('glassTexture: the procedural texture over the glass hit\'s own footprint', () => {
    const st = new SurfaceTexture('box', 'none');
    const calls = footprints(st);
    const value = st.glassTexture(hit(), down());
    expectClose(calls()[0], [0.3, 0.6, 5.12, 0, 0, -5.12], 1e-12);
    vi.restoreAllMocks();
    expect(value).toBe(st.procedural.channels[0].boxFilter(0.3, 0.6, 5.12, 0, 0, -5.12));
  });
});
