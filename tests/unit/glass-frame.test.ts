// The glass rectangle's frame (src/scene/glass-frame.ts), which the reference and both renderers
// share: plane, width and height axes and corners worked out by hand for glass off the origin.
import { describe, it } from 'vitest';
import { glassFrame } from '../../src/scene/glass-frame';
import { expectClose } from './helpers/math';

describe('glassFrame', () => {
  it('the default glass (docs/default-scene.md#the-glass): the plane z = 0, a = +X, b = +Y, corners (∓4, −1 | 3, 0)', () => {
    const f = glassFrame({ center: [0, 1, 0], normal: [0, 0, 1], size: [8, 4] });
    expectClose(f.plane, [0, 0, 1, 0]);
    expectClose(f.a, [1, 0, 0]);
    expectClose(f.b, [0, 1, 0]);
    expectClose(f.corners.flat(), [-4, -1, 0, 4, -1, 0, 4, 3, 0, -4, 3, 0]);
  });

  it('an oblique glass off the origin: n = (0.6, 0, 0.8), centre (1, 2, 3), 4 × 2', () => {
    const f = glassFrame({ center: [1, 2, 3], normal: [0.6, 0, 0.8], size: [4, 2] });
    // d = −n·c = −(0.6 + 2.4) = −3.
    expectClose(f.plane, [0.6, 0, 0.8, -3]);
    // a = +Y × n = (n.z, 0, −n.x) = (0.8, 0, −0.6), already unit; b = n × a = (0, 0.64 + 0.36, 0).
    expectClose(f.a, [0.8, 0, -0.6]);
    expectClose(f.b, [0, 1, 0]);
    // c ∓ 2a ∓ 1b: 2a = (1.6, 0, −1.2).
    expectClose(f.corners.flat(), [-0.6, 1, 4.2, 2.6, 1, 1.8, 2.6, 3, 1.8, -0.6, 3, 4.2], 1e-12);
  });

  it('a floor (n = +Y) takes a = +X and b = n × a = −Z; a ceiling (n = −Y) b = +Z', () => {
    const floor = glassFrame({ center: [0, 0.5, 0], normal: [0, 1, 0], size: [8, 6] });
    expectClose(floor.plane, [0, 1, 0, -0.5]);
    expectClose(floor.a, [1, 0, 0]);
    expectClose(floor.b, [0, 0, -1]);
    // c ∓ 4a ∓ 3b: the first corner (−4, 0.5, 3), then (4, 0.5, 3), (4, 0.5, −3), (−4, 0.5, −3).
    expectClose(floor.corners.flat(), [-4, 0.5, 3, 4, 0.5, 3, 4, 0.5, -3, -4, 0.5, -3]);
    const ceiling = glassFrame({ center: [0, 2, 0], normal: [0, -1, 0], size: [2, 2] });
    expectClose(ceiling.plane, [0, -1, 0, 2]);
    expectClose(ceiling.a, [1, 0, 0]);
    expectClose(ceiling.b, [0, 0, 1]);
  });
  it('a tilted glass whose normal leans towards Y: n = (0.48, 0.6, 0.64), centre (1, 2, 3), 4 × 2', () => {
    const f = glassFrame({ center: [1, 2, 3], normal: [0.48, 0.6, 0.64], size: [4, 2] });
    // d = −n·c = −(0.48 + 1.2 + 1.92) = −3.6.
    expectClose(f.plane, [0.48, 0.6, 0.64, -3.6], 1e-12);
    // +Y × n = (0.64, 0, −0.48), of length 0.8: a = (0.8, 0, −0.6).
    expectClose(f.a, [0.8, 0, -0.6], 1e-12);
    // b = n × a = (0.6·(−0.6) − 0, 0.64·0.8 + 0.48·0.6, 0 − 0.6·0.8) = (−0.36, 0.8, −0.48).
    expectClose(f.b, [-0.36, 0.8, -0.48], 1e-12);
    // c ∓ 2a ∓ b, with 2a = (1.6, 0, −1.2).
    expectClose(f.corners.flat(), [
      -0.24, 1.2, 4.68, 2.96, 1.2, 2.28, 2.24, 2.8, 1.32, -0.96, 2.8, 3.72,
    ], 1e-12);
  });
});
