// Tone mapping in the frame (docs/pbr.md#tone-mapping): light above 1 kept until the frame's end, then exposed, tone mapped
// and encoded, in the float64 reference and the software renderer. A box face head-on to a light of 3
// (Kd (1, ½, ¼): the colour (3, 1.5, 0.75), worked out by hand for PBR Neutral below); ACES and
// exposure through math/tone-map.ts (tied to hand values in tone-map.test.ts); a frame with neither
// is today's, byte for byte; a glass reflecting a light above 1 shows it, where 8-bit targets clip.
import { describe, expect, it } from 'vitest';
import { compareImages, renderScene } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import { linearToSrgb } from '../../src/math/srgb';
import { toneMap } from '../../src/math/tone-map';
import type { FrameState } from '../../src/frame/types';
import { colourCeiling } from '../../src/reference/reference-state';
import { toneMapped } from '../../src/frame/linear-light';
import { resolveFrame } from '../../src/software/encode';
import { BOX, BOX_STATE as STATE, CENTRE, FLOOR, FLOOR_STATE, NEUTRAL } from './helpers/tone-scenes';

describe('a box face of light (3, 1.5, 0.75), tone mapped', () => {
  it('PBR Neutral by hand: 0.9764 and the rest', () => {
    expect(NEUTRAL[0]).toBeCloseTo(0.97639, 5);
    const cases: [Partial<FrameState>, number[]][] = [
      [{ toneMapping: 'neutral' }, NEUTRAL],
      [{ toneMapping: 'aces' }, [...toneMap('aces', [0, 0, 0], 3, 1.5, 0.75)]],
      // Exposure ½ and no curve: (1.5, 0.75, 0.375), clipped to 1 by the encode.
      [{ toneMapping: 'none', exposure: 0.5 }, [1, 0.75, 0.375]],
      [{ toneMapping: 'neutral', exposure: 0.25 }, [...toneMap('neutral', [0, 0, 0], 0.75, 0.375, 0.1875)]],
    ];
    for (const [over, linear] of cases) {
      const state = { ...STATE, ...over };
      const ref = renderScene(BOX, state, null, { samplesPerAxis: 1 }).rgb;
      const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(BOX, state);
      linear.forEach((l, k) => {
        const want = linearToSrgb(l);
        expect(ref[3 * CENTRE + k], `${JSON.stringify(over)} reference channel ${k}`).toBeCloseTo(want, 12);
        expect(soft[4 * CENTRE + k], `${JSON.stringify(over)} software channel ${k}`).toBe(Math.round(want * 255));
      });
    }
  });

  it('without tone mapping the light clips at 1 (the 8-bit targets), and `none` with exposure 1 is that frame byte for byte', () => {
    const plain = new SoftwareRenderer({ samplesPerAxis: 2 }).render(BOX, STATE);
    expect([...plain.subarray(4 * CENTRE, 4 * CENTRE + 3)]).toEqual([255, 255, Math.round(linearToSrgb(0.75) * 255)]);
    const none = new SoftwareRenderer({ samplesPerAxis: 2 }).render(BOX, { ...STATE, toneMapping: 'none', exposure: 1 });
    expect(Buffer.from(none).equals(Buffer.from(plain))).toBe(true);
    const ref = renderScene(BOX, STATE, null, { samplesPerAxis: 2 }).rgba;
    expect(Buffer.from(renderScene(BOX, { ...STATE, toneMapping: 'none', exposure: 1 }, null, { samplesPerAxis: 2 }).rgba).equals(Buffer.from(ref))).toBe(true);
  });
});

describe('a glass reflecting light above 1', () => {
  it('the software renderer against the reference, tone mapped: every region within 2 dB of its figure, and brighter glass than clipped', () => {
    const state = { ...FLOOR_STATE, toneMapping: 'neutral' as const, exposure: 0.5 };
    const ref = renderScene(FLOOR, state, null, { samplesPerAxis: 2 });
    const soft = new SoftwareRenderer({ samplesPerAxis: 2 }).render(FLOOR, state);
    const cmp = compareImages(ref, soft);
    const p = cmp.psnr;
    console.log(`tone-mapped glass floor, software against the reference: all ${p.all.toFixed(1)}, objects ${p.objects.toFixed(1)}, glass ${p.glass.toFixed(1)} dB`);
    const measured = { all: 59.6, objects: 63.1, glass: 57.7 };
    for (const [r, figure] of Object.entries(measured) as [keyof typeof measured, number][]) expect(p[r], r).toBeGreaterThanOrEqual(figure - 2);
    // The same frame with the reflection clipped at 1 (8-bit targets) and the same curve applied after would be darker on the glass:
    // its glass pixels against the tone-mapped reference lose more than 2 dB.
    const clipped = new SoftwareRenderer({ samplesPerAxis: 2 }).render(FLOOR, { ...FLOOR_STATE });
    expect(compareImages(ref, clipped).psnr.glass).toBeLessThan(p.glass - 10);
  });
});

describe('frames that are not tone mapped, whatever they ask', () => {
  it('colour space none or the fresnel view: the curve and exposure ignored, in both CPU renderers; an exposure alone is none\'s', () => {
    for (const base of [{ colorSpace: 'none' as const }, { view: 'fresnel' as const }]) {
      const plain = { ...STATE, ...base };
      const asked = { ...plain, toneMapping: 'neutral' as const, exposure: 2 };
      expect(Buffer.from(renderScene(BOX, asked, null, { samplesPerAxis: 1 }).rgba).equals(Buffer.from(renderScene(BOX, plain, null, { samplesPerAxis: 1 }).rgba)), JSON.stringify(base)).toBe(true);
      expect(Buffer.from(new SoftwareRenderer({ samplesPerAxis: 1 }).render(BOX, asked)).equals(Buffer.from(new SoftwareRenderer({ samplesPerAxis: 1 }).render(BOX, plain))), JSON.stringify(base)).toBe(true);
    }
    const alone = renderScene(BOX, { ...STATE, toneMapping: undefined, exposure: 0.5 }, null, { samplesPerAxis: 1 }).rgba;
    const none = renderScene(BOX, { ...STATE, toneMapping: 'none', exposure: 0.5 }, null, { samplesPerAxis: 1 }).rgba;
    expect(Buffer.from(alone).equals(Buffer.from(none))).toBe(true);
    expect(alone[4 * CENTRE]).toBe(255);
  });
});

describe('which frames are tone mapped (frame/linear-light.ts, and the reference\'s own reading)', () => {
  it('encoded at the end, with a curve other than none or an exposure other than 1', () => {
    const rows: [Partial<FrameState>, boolean][] = [
      [{}, false],
      [{ toneMapping: 'none' }, false],
      [{ toneMapping: 'none', exposure: 1 }, false],
      [{ toneMapping: 'neutral' }, true],
      [{ toneMapping: 'aces' }, true],
      [{ exposure: 0.5 }, true],
      [{ toneMapping: 'none', exposure: 2 }, true],
      // Not encoded at the end: values as stored, or F shown as a number.
      [{ toneMapping: 'neutral', colorSpace: 'none' }, false],
      [{ exposure: 2, colorSpace: 'none' }, false],
      [{ toneMapping: 'neutral', view: 'fresnel' }, false],
      [{ toneMapping: 'neutral', view: 'reflection' }, true],
      [{ toneMapping: 'neutral', view: 'scene' }, true],
    ];
    for (const [over, want] of rows) {
      const state = { ...STATE, toneMapping: undefined, exposure: undefined, ...over };
      expect(toneMapped(state), JSON.stringify(over)).toBe(want);
      expect(colourCeiling(state), JSON.stringify(over)).toBe(want ? Infinity : 1);
    }
  });

  it('the software resolve: an exposure without a curve is none\'s (clipped at 1), by pixel and sample', () => {
    // Two pixels of 2×2 samples: (0.5, 1, 3) and (0.2, 0.4, 0.8) light, each sample alike.
    const source = new Float32Array(2 * 4 * 3);
    for (let y = 0; y < 2; y++) for (let x = 0; x < 4; x++) source.set(x < 2 ? [0.5, 1, 3] : [0.2, 0.4, 0.8], 3 * (y * 4 + x));
    const out = new Uint8ClampedArray(8);
    resolveFrame(out, source, 2, 1, 2, { ...STATE, toneMapping: undefined, exposure: 0.5 });
    const byte = (l: number) => Math.round(linearToSrgb(l) * 255);
    expect([...out]).toEqual([byte(0.25), byte(0.5), 255, 255, byte(0.1), byte(0.2), byte(0.4), 255]);
  });
});
