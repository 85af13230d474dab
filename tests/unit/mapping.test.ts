// The texture mappings of src/scene/mapping.ts at hand-computed points.
import { describe, expect, it } from 'vitest';
import { cylindricalUV, sphericalUV, triplanarUV, TRIPLANAR_SHARPNESS } from '../../src/scene/mapping';
import type { Bounds } from '../../src/scene/scene';
import { expectClose } from './helpers/math';

const UNIT: Bounds = { center: [0, 0, 0], radius: 1 };
const OFF: Bounds = { center: [1, 2, 3], radius: 2 };
const uv = (): number[] => [NaN, NaN];

describe('cylindrical', () => {
  it('u = ½ + atan2(x, z)/2π about the bounds centre, v = ½ + (y − c.y)/2r', () => {
    expectClose(cylindricalUV(uv(), [0, 0, 1], UNIT), [0.5, 0.5]); // facing +Z
    expectClose(cylindricalUV(uv(), [1, 0, 0], UNIT), [0.75, 0.5]); // +X: a quarter turn on
    expectClose(cylindricalUV(uv(), [-1, 1, 0], UNIT), [0.25, 1]); // −X, top of the bounds
    expectClose(cylindricalUV(uv(), [0, -1, -1], UNIT), [1, 0]); // −Z: the seam (atan2(0, −1) = π), bottom
    expectClose(cylindricalUV(uv(), [1 + 5, 2 - 1, 3], OFF), [0.75, 0.25]); // relative to (1, 2, 3), r = 2
  });
});

describe('spherical', () => {
  it('the default sphere UV (docs/default-scene.md#texture-coordinates) on the direction from the bounds centre', () => {
    expectClose(sphericalUV(uv(), [0, -3, 0], UNIT), [0.5, 0]); // bottom pole, any distance
    expectClose(sphericalUV(uv(), [0, 0, 2], UNIT), [0.5, 0.5]);
    expectClose(sphericalUV(uv(), [1, 1, 0], UNIT), [0.75, 0.75]); // acos(−1/√2)/π = ¾
    expectClose(sphericalUV(uv(), [1, 2, 3 - 4], OFF), [1, 0.5]); // −Z from (1, 2, 3)
    expectClose(sphericalUV(uv(), [1, 2, 3], OFF), [0.5, 0.5]); // the centre itself
  });
});

describe('triplanar', () => {
  it('weights abs(n_i)^k normalised; each projection maps the bounds cube onto [0, 1]²', () => {
    const w = [0, 0, 0], uvs = [0, 0, 0, 0, 0, 0];
    triplanarUV(w, uvs, [0.5, -0.5, 1], [0, 0, 1], UNIT);
    expectClose(w, [0, 0, 1]);
    // x → ½ + 0.5/2 = 0.75, y → 0.25, z → 1
    expectClose(uvs, [1, 0.25, 0.75, 1, 0.75, 0.25]);
    const s = Math.SQRT1_2;
    triplanarUV(w, uvs, [3, 2, 3], [s, -s, 0], OFF);
    expectClose(w, [0.5, 0.5, 0]);
    expectClose(uvs, [0.5, 0.5, 1, 0.5, 1, 0.5]); // x: ½ + 2/4 = 1, y: ½, z: ½
    // k = 4, as shaders/standard.frag writes it (n·n·n·n): 0.6⁴ = 0.1296, 0.8⁴ = 0.4096, sum 0.5392.
    expect(TRIPLANAR_SHARPNESS).toBe(4);
    triplanarUV(w, uvs, [0, 0, 0], [0.6, 0.8, 0], UNIT);
    expectClose(w, [0.1296 / 0.5392, 0.4096 / 0.5392, 0]);
    triplanarUV(w, uvs, [0, 0, 0], [-0.48, 0.6, -0.64], UNIT); // signs do not matter: 0.48⁴, 0.6⁴, 0.64⁴
    expectClose(w, [0.05308416 / 0.35045632, 0.1296 / 0.35045632, 0.16777216 / 0.35045632]);
    triplanarUV(w, uvs, [0, 0, 0], [0, 0, 0], UNIT);
    expectClose(w, [1 / 3, 1 / 3, 1 / 3]);
  });
});
