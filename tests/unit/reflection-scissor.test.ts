// The reflection pass's scissor in the texels of its target, also when the target is clamped.
import { describe, expect, it } from 'vitest';
import { reflectionScissor, reflectionTargetSide } from '../../src/frame/reflection-scissor';
import type { ScreenRect } from '../../src/frame/glass-bounds';

const rect = (x0: number, y0: number, x1: number, y1: number): ScreenRect => ({ x0, y0, x1, y1, area: (x1 - x0) * (y1 - y0) });
const scissor = () => ({ x: -1, y: -1, width: -1, height: -1 });

describe('reflectionTargetSide', () => {
  it('is the side × scale, rounded, within 1..max', () => {
    expect(reflectionTargetSide(640, 0.5, 4096)).toBe(320);
    expect(reflectionTargetSide(3, 0.125, 4096)).toBe(1);
    expect(reflectionTargetSide(3000, 2, 4096)).toBe(4096);
  });
});

describe('reflectionScissor', () => {
  it('scales the glass rectangle by the target size, one texel wider each side', () => {
    const s = reflectionScissor(rect(100, 40, 300, 120), 640, 360, 320, 180, scissor());
    expect(s).toEqual({ x: 49, y: 19, width: 102, height: 42 });
  });

  it('with the target clamped to the maximum size, still covers exactly the glass in its texels', () => {
    // 3000×1000 at reflection-scale 2 asks for 6000×2000; the limit makes it 4096×2000, so a screen
    // pixel is 4096/3000 texels wide, not 2.
    const width = 3000, height = 1000, max = 4096;
    const tw = reflectionTargetSide(width, 2, max);
    const th = reflectionTargetSide(height, 2, max);
    expect([tw, th]).toEqual([4096, 2000]);
    const glass = rect(1000, 200, 2000, 600);
    const s = reflectionScissor(glass, width, height, tw, th, scissor());
    const sx = tw / width;
    // The glass's texels [1000·sx, 2000·sx) × [400, 1200) are inside, with at most 2 texels to spare.
    expect(s.x).toBeLessThanOrEqual(Math.floor(1000 * sx));
    expect(s.x).toBeGreaterThanOrEqual(Math.floor(1000 * sx) - 2);
    expect(s.x + s.width).toBeGreaterThanOrEqual(Math.ceil(2000 * sx));
    expect(s.x + s.width).toBeLessThanOrEqual(Math.ceil(2000 * sx) + 2);
    expect(s).toMatchObject({ y: 399, height: 802 });
  });

  it('stays inside the target and is empty for an empty rectangle', () => {
    expect(reflectionScissor(rect(0, 0, 640, 360), 640, 360, 320, 180, scissor())).toEqual({ x: 0, y: 0, width: 320, height: 180 });
    expect(reflectionScissor(rect(0, 0, 0, 0), 640, 360, 320, 180, scissor())).toMatchObject({ width: 1, height: 1 });
  });
});
