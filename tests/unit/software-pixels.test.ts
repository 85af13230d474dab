// The software renderer's pixels against values worked out here, independent of the reference:
// Blinn-Phong (docs/scene-model.md#lights) on a quad seen head-on and off-axis, with a directional and a point
// light, and a transparent quad blended as colour·(1 − kt) + framebuffer·kt (docs/software-renderer.md#transparency) at kt
// where kt and 1 − kt differ.
import { describe, expect, it } from 'vitest';
import { SoftwareRenderer } from '../../src/software';
import type { FrameState } from '../../src/frame/types';
import type { Light, Material, Scene } from '../../src/scene/scene';
import { N, STATE as QUAD_STATE, unitQuad, WHITE } from './helpers/quad-scenes';

// quad-scenes.ts's 17×17 pixels (odd: the centre pixel's centre is on the axis), vertical fov 90°,
// the eye at (0, 0, 2) looking down −Z; the 2×2 quad on z = 0 covers pixels 4.25..12.75.
const EYE = [0, 0, 2];
const STATE: FrameState = { ...QUAD_STATE, colorSpace: 'none' };

function quadScene(material: Material, lights: Light[], background: [number, number, number]): Scene {
  return { glass: null, background, lights, objects: [unitQuad(material)] };
}

/** The point of the quad seen through the centre of pixel (i, j): eye + 2·(x_ndc, y_ndc, −1). */
function pointAt(i: number, j: number): number[] {
  const x = (2 * (i + 0.5)) / N - 1, y = 1 - (2 * (j + 0.5)) / N;
  return [EYE[0] + 2 * x, EYE[1] + 2 * y, 0];
}

const unit = (v: number[]): number[] => { const l = Math.hypot(v[0], v[1], v[2]); return v.map((c) => c / l); };
const dot = (a: number[], b: number[]): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** Every channel of pixel (i, j) within half a level of 255·expected (8-bit rounding). */
function expectPixel(rgba: ArrayLike<number>, i: number, j: number, expected: number[]): void {
  const o = 4 * (j * N + i);
  for (let k = 0; k < 3; k++) {
    const want = 255 * Math.min(1, Math.max(0, expected[k]));
    expect(Math.abs(rgba[o + k] - want), `pixel (${i}, ${j}) channel ${k}: ${rgba[o + k]} vs ${want.toFixed(2)}`).toBeLessThanOrEqual(0.5 + 1e-4);
  }
}

describe('software renderer: hand-computed pixels', () => {
  it('Blinn-Phong: Ka⊙Ia + Kd⊙Id·max(N·L, 0) + Ks⊙Is·max(N·H, 0)^n, H = normalize(L + V), per light', () => {
    const material: Material = {
      ambient: [0.1, 0.2, 0.3], diffuse: [0.5, 0.4, 0.3], specular: [0.6, 0.5, 0.4], shininess: 20, opacity: 1,
      texture: { kind: 'image', url: 'white' }, mapping: 'uv',
    };
    const sun: Light = { kind: 'directional', vector: [0.3, 0.5, 1], ambient: [0.3, 0.3, 0.3], diffuse: [0.9, 0.8, 0.7], specular: [1, 1, 1] };
    const lamp: Light = { kind: 'point', vector: [1, 1, 1.5], ambient: [0.1, 0.1, 0.1], diffuse: [0.4, 0.4, 0.4], specular: [0.5, 0.5, 0.5] };
    const rgba = new SoftwareRenderer().render(quadScene(material, [sun, lamp], [0, 0, 0]), STATE, WHITE);
    const n = [0, 0, 1];
    // The centre (V = N = +Z), two off-axis pixels (V towards the eye from the point seen) and one near the lamp.
    for (const [i, j] of [[8, 8], [5, 11], [11, 6], [12, 4]]) {
      const p = pointAt(i, j);
      expect(Math.max(Math.abs(p[0]), Math.abs(p[1])), 'on the quad').toBeLessThan(1);
      const v = unit([EYE[0] - p[0], EYE[1] - p[1], EYE[2] - p[2]]);
      const colour = [0, 0, 0];
      for (const light of [sun, lamp]) {
        const l = unit(light.kind === 'point' ? [light.vector[0] - p[0], light.vector[1] - p[1], light.vector[2] - p[2]] : [...light.vector]);
        const nl = dot(n, l);
        const h = unit([l[0] + v[0], l[1] + v[1], l[2] + v[2]]);
        const spec = nl > 0 ? Math.max(dot(n, h), 0) ** material.shininess : 0;
        for (let k = 0; k < 3; k++) {
          colour[k] += material.ambient[k] * light.ambient[k] + material.diffuse[k] * light.diffuse[k] * Math.max(nl, 0)
            + material.specular[k] * light.specular[k] * spec;
        }
      }
      expectPixel(rgba, i, j, colour);
    }
  });

  it('opacity 0.3 (kt = 0.7) over the background: colour·(1 − kt) + background·kt', () => {
    // Ambient light only, white texture: the quad's own colour is Ka = (0.8, 0.5, 0.2).
    const material: Material = {
      ambient: [0.8, 0.5, 0.2], diffuse: [0, 0, 0], specular: [0, 0, 0], shininess: 1, opacity: 0.3,
      texture: { kind: 'image', url: 'white' }, mapping: 'uv',
    };
    const ambient: Light = { kind: 'directional', vector: [0, 0, 1], ambient: [1, 1, 1], diffuse: [0, 0, 0], specular: [0, 0, 0] };
    const bg: [number, number, number] = [0.2, 0.4, 0.6];
    const rgba = new SoftwareRenderer().render(quadScene(material, [ambient], bg), STATE, WHITE);
    // (0.8·0.3 + 0.2·0.7, 0.5·0.3 + 0.4·0.7, 0.2·0.3 + 0.6·0.7) = (0.38, 0.43, 0.48).
    const blended = [0.38, 0.43, 0.48];
    for (let j = 5; j <= 11; j++) for (let i = 5; i <= 11; i++) expectPixel(rgba, i, j, blended);
    expectPixel(rgba, 1, 1, bg); // outside the quad
  });
});
