// The course's iluminacao.txt and Phong equation (docs/course-files.md#course-phong), against hand-computed values.
import { describe, expect, it } from 'vitest';
import { parseLightingTxt } from '../../src/loaders/course/lighting-txt';
import { coursePhong, type CourseLight, type CourseMaterial } from '../../src/math/course-phong';
import type { Vec3 } from '../../src/math/course-camera';
import { expectLoadError, sample } from './helpers/course';

const R2 = Math.SQRT1_2;

describe('parseLightingTxt', () => {
  it('reads Pl / ka / Ia / kd / Od / ks / Il / n into a point light and a material', () => {
    const r = parseLightingTxt(sample('iluminacao.txt'), { url: 'iluminacao.txt' });
    expect(r.light).toEqual({ position: [-200, 50, 100], ambient: [100, 90, 80], intensity: [255, 255, 255] });
    expect(r.material).toEqual({ ka: 0.2, kd: 0.5, ks: 0.5, od: [0.7, 0.5, 0.8], n: 2 });
    expect(r.warnings).toEqual([]);
  });

  it('reads each line into its own field: no two of ka, kd, ks, Ia, Il alike', () => {
    // The sample file has kd = ks; here every value differs, so a field read from the wrong line shows.
    const r = parseLightingTxt('1 2 3\n0.1\n10 20 30\n0.6\n0.2 0.4 0.9\n0.3\n200 150 100\n7\n');
    expect(r.light).toEqual({ position: [1, 2, 3], ambient: [10, 20, 30], intensity: [200, 150, 100] });
    expect(r.material).toEqual({ ka: 0.1, kd: 0.6, ks: 0.3, od: [0.2, 0.4, 0.9], n: 7 });
  });

  it('reads CRLF, a BOM, tabs, blank lines, exponents and no final newline alike', () => {
    const text = '\uFEFF-2E2\t50 1.0e+2 \r\n\r\n2.0E-1\r\n100 90 80\r\n+.5\r\n7e-1 5.e-1 .8\r\n\r\n0.5\r\n255 255 255\r\n2';
    const r = parseLightingTxt(text);
    expect(r.light.position).toEqual([-200, 50, 100]);
    expect(r.material).toEqual({ ka: 0.2, kd: 0.5, ks: 0.5, od: [0.7, 0.5, 0.8], n: 2 });
  });

  it('clamps values outside their ranges with a warning naming the line', () => {
    const r = parseLightingTxt('0 0 0\n1.5\n300 0 -1\n0.5\n1 1 1\n0.5\n10 10 10\n-2\n');
    expect(r.material.ka).toBe(1);
    expect(r.light.ambient).toEqual([255, 0, 0]);
    expect(r.material.n).toBe(0);
    expect(r.warnings.map((w) => w.line)).toEqual([2, 3, 3, 8]);
  });

  it('warns about values and lines past the eight', () => {
    const r = parseLightingTxt(`${sample('iluminacao.txt')}\n0.3\n`.replace('0.2\n', '0.2 0.4\n'));
    expect(r.warnings.map((w) => w.line)).toEqual([2, 10]);
  });

  it('is a load error, with its line, for a token that is not a number or a missing line', () => {
    expectLoadError(() => parseLightingTxt(sample('iluminacao-bad-token.txt'), { url: 'il.txt' }), 'il.txt', 6, /ks: "0,5" is not a number/);
    expectLoadError(() => parseLightingTxt(sample('iluminacao-truncated.txt'), { url: 'il.txt' }), 'il.txt', 7, /ends here, no line for n/);
    expectLoadError(() => parseLightingTxt('0 0 0\n0.2\n100 90\n', { url: 'il.txt' }), 'il.txt', 3, /Ia needs 3 numbers/);
  });
});

describe('coursePhong', () => {
  const material: CourseMaterial = { ka: 0.2, kd: 0.5, ks: 0.5, od: [0.7, 0.5, 0.8], n: 2 };
  const light = (position: Vec3, intensity: Vec3 = [255, 255, 255]): CourseLight => ({ position, ambient: [100, 90, 80], intensity });
  const ambient = [20, 18, 16];
  const O: Vec3 = [0, 0, 0];
  const UP: Vec3 = [0, 0, 1];

  function close(actual: Vec3, want: number[]): void {
    actual.forEach((c, k) => expect(c, `channel ${k}`).toBeCloseTo(want[k], 9));
  }

  it('head-on: I = ka·Ia + Il ⊙ (kd·Od + ks)', () => {
    close(coursePhong(light([0, 0, 10]), material, O, UP, [0, 0, 10]),
      [0, 1, 2].map((c) => ambient[c] + 255 * (0.5 * material.od[c] + 0.5)));
  });

  it('light at 45°: N·L = R·V = 1/√2, the specular term (R·V)^n', () => {
    close(coursePhong(light([10, 0, 10]), material, O, UP, [0, 0, 10]),
      [0, 1, 2].map((c) => ambient[c] + 255 * (0.5 * material.od[c] * R2 + 0.5 * 0.5)));
    // The eye in the mirror direction: R·V = 1.
    close(coursePhong(light([10, 0, 10]), material, O, UP, [-5, 0, 5]),
      [0, 1, 2].map((c) => ambient[c] + 255 * (0.5 * material.od[c] * R2 + 0.5)));
  });

  it('turns N towards the viewer: a normal pointing away lights like one facing the eye', () => {
    const toward = coursePhong(light([10, 0, 10]), material, O, UP, [0, 0, 10]);
    expect(coursePhong(light([10, 0, 10]), material, O, [0, 0, -3], [0, 0, 10])).toEqual(toward);
  });

  it('no diffuse or specular where N·L ≤ 0, no specular where R·V ≤ 0', () => {
    close(coursePhong(light([0, 0, -10]), material, O, UP, [0, 0, 10]), ambient);
    close(coursePhong(light([10, 0, 0]), material, O, UP, [0, 0, 10]), ambient); // grazing: N·L = 0
    // Light at 45° on one side, eye low on the same side: R·V < 0.
    close(coursePhong(light([10, 0, 10]), material, O, UP, [10, 0, 1]),
      [0, 1, 2].map((c) => ambient[c] + 255 * 0.5 * material.od[c] * R2));
  });

  it('off the origin, every axis used: P = (1, 2, 3), N = (12, 15, 16)/25, L = (0, 0.6, 0.8), V = (0.36, 0.48, 0.8)', () => {
    // N·L = 0.36 + 0.512 = 0.872; R = 2·0.872·N − L = (0.83712, 0.4464, 0.31616);
    // R·V = 0.3013632 + 0.214272 + 0.252928 = 0.7685632, and ks·(R·V)² = 0.5·0.7685632².
    const P: Vec3 = [1, 2, 3];
    const lit = coursePhong(light([1, 8, 11]), material, P, [12, 15, 16], [4.6, 6.8, 11]);
    close(lit, [0, 1, 2].map((c) => ambient[c] + 255 * (0.5 * material.od[c] * 0.872 + 0.5 * 0.7685632 ** 2)));
  });

  it('an eye in the surface\'s plane leaves N as given; with n = 0, (R·V)^n at R·V = 0 adds nothing', () => {
    // L = N = (0, 0, 1), V = (1, 0, 0): N·V = 0, N·L = 1, R = N, R·V = 0.
    const flat = { ...material, n: 0 };
    close(coursePhong(light([0, 0, 10]), flat, O, UP, [10, 0, 0]), [0, 1, 2].map((c) => ambient[c] + 255 * 0.5 * material.od[c]));
  });

  it('a grazing light (N·L = 0) gives no specular, even toward the mirror direction', () => {
    // R would be −L = (−1, 0, 0); the eye low on that side has R·V > 0.
    close(coursePhong(light([10, 0, 0]), material, O, UP, [-10, 0, 1]), ambient);
  });

  it('a zero normal lights with the ambient term only', () => {
    close(coursePhong(light([0, 0, 10]), material, O, [0, 0, 0], [0, 0, 10]), ambient);
  });

  it('clamps every channel to 0..255', () => {
    const bright = coursePhong(light([0, 0, 10], [2550, 2550, 2550]), material, O, UP, [0, 0, 10]);
    expect(bright).toEqual([255, 255, 255]);
  });
});
