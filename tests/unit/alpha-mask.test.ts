// glTF's alpha mask (docs/gltf.md#alpha) in the software renderer and the float64 reference: a box head-on whose material is
// alphaMode `mask`, in front of an unlit green plate. Where the base colour's alpha (factor × texture alpha) is below the
// cutoff the box is no surface — the plate shows through, at its own colour exactly; at or above it the box is drawn whole.
// The plate is drawn after the box: a cut-away fragment that kept its depth would hide it.
import { describe, expect, it } from 'vitest';
import { compareImages, renderScene } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import type { Scene } from '../../src/scene/scene';
import type { DecodedImage } from '../../src/scene/decoded-image';
import { BOX_STATE, withPbr } from './helpers/pbr-scenes';
import { lit, map } from './helpers/pbr-map-cases';
import { BASE, PLATE, columns, maskScene as scene, redOverClear } from './helpers/alpha-mask-scenes';

const px = (x: number, y: number) => y * 33 + x;
const CENTRE = px(16, 16);

/**
 * The reference at spp × spp samples; the software renderer at as many, or (`msaa`) at one shading a pixel over 2×2 samples
 * (`samples` 4: its multisampled raster, where one shading's cut must cut every sample of the pixel).
 */
function draw(s: Scene, images: Map<string, DecodedImage> | null = null, spp = 1, msaa = false): { ref: Float64Array; soft: Uint8ClampedArray } {
  const soft = msaa ? new SoftwareRenderer({ samplesPerAxis: 1 }).render(s, { ...BOX_STATE, samples: 4 }, images) : new SoftwareRenderer({ samplesPerAxis: spp }).render(s, BOX_STATE, images);
  return { ref: renderScene(s, BOX_STATE, images, { samplesPerAxis: spp }).rgb, soft };
}

function expectAt(got: { ref: Float64Array; soft: Uint8ClampedArray }, pixel: number, want: readonly number[], label: string): void {
  want.forEach((w, k) => {
    expect(got.ref[3 * pixel + k], `${label}: reference channel ${k}`).toBeCloseTo(w, 12);
    expect(got.soft[4 * pixel + k], `${label}: software channel ${k}`).toBe(Math.round(w * 255));
  });
}

describe('the base colour factor\'s alpha against the cutoff, by hand', () => {
  const box = [lit(0.5, 1, 1), lit(0.5, 1, 1), lit(0.5, 1, 1)];
  it('below it: the plate shows through the box, at its own colour', () => expectAt(draw(scene({ baseColor: [0.5, 0.5, 0.5, 0.4] })), CENTRE, PLATE, 'alpha 0.4'));
  it('at it: drawn whole, as opaque (glTF: alpha ≥ cutoff)', () => expectAt(draw(scene({ baseColor: [0.5, 0.5, 0.5, 0.5] })), CENTRE, box, 'alpha 0.5'));
  it('a cutoff of 0.3 keeps alpha 0.4', () => expectAt(draw(scene({ baseColor: [0.5, 0.5, 0.5, 0.4], alphaCutoff: 0.3 })), CENTRE, box, 'cutoff 0.3'));
  it('OPAQUE and BLEND never cut: alpha 0.1 is drawn opaque, or blended by the element\'s opacity', () => {
    expectAt(draw(scene({ baseColor: [0.5, 0.5, 0.5, 0.1], alphaMode: 'opaque' })), CENTRE, box, 'opaque');
    expectAt(draw(scene({ baseColor: [0.5, 0.5, 0.5, 0.1], alphaMode: 'blend' })), CENTRE, box, 'blend (opacity set by the element, 1 here)');
  });
});

describe('the base colour texture\'s alpha', () => {
  // The face spans about 8 pixels across the centre; its texture's two columns fall left and right of it, u across x.
  const left = px(14, 16), right = px(18, 16);
  const box = [lit(0.5, 1, 1), lit(0.5, 1, 1), lit(0.5, 1, 1)];

  /** The same pixel of the box drawn OPAQUE (the same texture): what a kept fragment is. */
  const opaque = (images: Map<string, DecodedImage>, pixel: number, spp = 1): number[] => {
    const s = scene({ alphaMode: 'opaque' }, true), got = draw(s, images, spp);
    return [0, 1, 2].map((k) => got.ref[3 * pixel + k]);
  };
  const expectKept = (got: ReturnType<typeof draw>, images: Map<string, DecodedImage>, pixel: number, spp: number, label: string, msaa = false) => {
    const want = opaque(images, pixel, spp), soft = draw(scene({ alphaMode: 'opaque' }, true), images, spp, msaa).soft;
    want.forEach((w, k) => {
      expect(got.ref[3 * pixel + k], `${label}: reference channel ${k}`).toBe(w);
      expect(got.soft[4 * pixel + k], `${label}: software channel ${k}`).toBe(soft[4 * pixel + k]);
    });
    // And lit: the box's colour, not the plate's.
    expect(Math.abs(got.ref[3 * pixel + 1] - lit(0.5, 1, 1)), label).toBeLessThan(0.001);
  };

  it('cuts by column: opaque left, cut right (and the other way), both renderers, one sample a pixel, 2×2, and 2×2 shaded once', () => {
    for (const [spp, msaa] of [[1, false], [2, false], [2, true]] as const) {
      const i1 = new Map([[BASE, columns(255, 0)]]), i2 = new Map([[BASE, columns(0, 255)]]), how = `${spp}×${spp}${msaa ? ' shaded once' : ''}`;
      const a = draw(scene({}, true), i1, spp, msaa);
      expectKept(a, i1, left, spp, `left kept, ${how}`, msaa);
      expectAt(a, right, PLATE, `right cut, ${how}`);
      const b = draw(scene({}, true), i2, spp, msaa);
      expectAt(b, left, PLATE, `left cut, ${how}`);
      expectKept(b, i2, right, spp, `right kept, ${how}`, msaa);
    }
  });

  it('times the factor: texture alpha 200/255 and factor 0.6 make 0.47, under the cutoff', () => {
    const images = new Map([[BASE, columns(200, 200)]]);
    expectAt(draw(scene({ baseColor: [0.5, 0.5, 0.5, 0.6] }, true), images), CENTRE, PLATE, '0.6 × 200/255');
    const kept = draw(scene({ baseColor: [0.5, 0.5, 0.5, 0.7] }, true), images);
    expect(Math.abs(kept.ref[3 * CENTRE] - lit(0.5, 1, 1)), '0.7 × 200/255 = 0.55: kept').toBeLessThan(1e-3);
    expect(kept.soft[4 * CENTRE], '0.7 × 200/255 = 0.55: kept').toBe(Math.round(lit(0.5, 1, 1) * 255));
  });

  it('is read where the colour is: of the face\'s upper and lower halves, the red one is kept and the blue one cut (red texels opaque, blue clear)', () => {
    const images = new Map([[BASE, redOverClear()]]);
    for (const spp of [1, 2]) {
      const got = draw(scene({ baseColor: [1, 1, 1, 1] }, true), images, spp);
      const halves = [px(16, 14), px(16, 18)].map((p) => ({ ref: [0, 1, 2].map((k) => got.ref[3 * p + k]), soft: [0, 1, 2].map((k) => got.soft[4 * p + k]) }));
      const plate = (h: (typeof halves)[number]) => h.soft.every((v, k) => v === Math.round(PLATE[k] * 255)) && h.ref.every((v, k) => Math.abs(v - PLATE[k]) < 1e-12);
      // Red, with a trace of the blue texels' colour the bilinear read brings in (the face is 8 pixels for 2 texels).
      const red = (h: (typeof halves)[number]) => h.soft[0] > 4 * h.soft[2] && h.ref[0] > 4 * h.ref[2] && h.soft[0] > 0;
      expect(halves.filter(plate).length, `${spp}×${spp}: one half cut`).toBe(1);
      expect(halves.filter(red).length, `${spp}×${spp}: the other red`).toBe(1);
    }
  });

  it('its image missing: the factor alone decides', () => {
    expectAt(draw(scene({}, true), new Map()), CENTRE, box, 'no image, factor 1');
  });

  it('the software renderer against the reference over the whole frame, 2×2 samples: the cut edge where they agree', () => {
    const s = scene({}, true), images = new Map([[BASE, columns(255, 0)]]);
    const ref = renderScene(s, { ...BOX_STATE, width: 65, height: 65 }, images, { samplesPerAxis: 2 });
    const soft = new SoftwareRenderer({ samplesPerAxis: 2 }).render(s, { ...BOX_STATE, width: 65, height: 65 }, images);
    const cmp = compareImages(ref, soft);
    // Without the mask (OPAQUE): what drawing the cut half would give, far below.
    const whole = compareImages(ref, new SoftwareRenderer({ samplesPerAxis: 2 }).render({ ...s, objects: s.objects.map((o, i) => (i === 0 ? { ...o, material: { ...o.material, pbr: { ...o.material.pbr!, alphaMode: 'opaque' as const } } } : o)) }, { ...BOX_STATE, width: 65, height: 65 }, images));
    // Measured: all 71.6, objects 75.6, edges 60.2 dB (drawn unmasked: all 21.5); the bounds 2 dB under.
    expect(cmp.psnr.all, `all ${cmp.psnr.all.toFixed(1)} dB`).toBeGreaterThan(69.6);
    expect(cmp.psnr.edges, `edges ${cmp.psnr.edges.toFixed(1)} dB`).toBeGreaterThan(58.2);
    expect(whole.psnr.all, `unmasked: all ${whole.psnr.all.toFixed(1)} dB`).toBeLessThan(cmp.psnr.all - 10);
  });
});

describe('a ray through a cut surface meets the same object\'s next one', () => {
  // One mesh of two quads facing the camera (BOX_STATE's, at z = 4): the front at z = 3.5 (half a unit away: a ray's t under 1,
  // where a re-hit that did not step past the cut one would find it again), the back at z = 3.2. One material, MASK, a 2×1
  // image: the left texel clear, the right opaque; the front quad's UVs all on the left texel, the back's all on the right.
  const IMG = 'https://example.com/two texels.png';
  const quad = (z: number, u: number) => ({ p: [-0.2, -0.2, z, 0.2, -0.2, z, 0.2, 0.2, z, -0.2, 0.2, z], uv: [u, 0.5, u, 0.5, u, 0.5, u, 0.5] });
  const front = quad(3.5, 0.25), back = quad(3.2, 0.75);
  const data = {
    positions: new Float32Array([...front.p, ...back.p]), normals: new Float32Array(Array.from({ length: 8 }, () => [0, 0, 1]).flat()),
    uvs: new Float32Array([...front.uv, ...back.uv]), indices: new Uint16Array([0, 1, 2, 0, 2, 3, 4, 5, 6, 4, 6, 7]),
  };
  const image: DecodedImage = { width: 2, height: 1, data: new Uint8ClampedArray([255, 255, 255, 0, 255, 255, 255, 255]) };

  it('the reference and the software renderer draw the back quad there, lit, not the plate behind', () => {
    const base = scene({});
    const masked = base.objects[0], pbr = { ...masked.material.pbr!, baseColorTexture: map(IMG), baseColor: [0.5, 0.5, 0.5, 1] as const };
    const mesh = { ...masked, geometry: { kind: 'mesh' as const, key: 'two quads', data }, material: { ...withPbr(pbr, { kind: 'image', url: IMG, fallback: 'none' }) }, bounds: { center: [0, 0, 3.35] as const, radius: 0.4 } };
    const s: Scene = { ...base, objects: [mesh, base.objects[1]] };
    const got = draw(s, new Map([[IMG, image]]));
    const lit = Math.round(lit3() * 255);
    expect(got.soft[4 * CENTRE], 'software: the back quad').toBe(lit);
    expect(got.ref[3 * CENTRE], 'reference: the back quad').toBeCloseTo(lit3(), 12);
    // Both quads clear: the plate.
    const clear: DecodedImage = { width: 2, height: 1, data: new Uint8ClampedArray([255, 255, 255, 0, 255, 255, 255, 0]) };
    expectAt(draw(s, new Map([[IMG, clear]])), CENTRE, PLATE, 'both cut');
  });
});

/** The box's face colour head-on (metallic 1, roughness 1, base ½): lit() of pbr-map-cases. */
const lit3 = () => lit(0.5, 1, 1);
