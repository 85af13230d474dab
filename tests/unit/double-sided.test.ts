// glTF's doubleSided (docs/gltf.md#drawing) in the float64 reference and the software renderer: a quad seen from its front and
// its back, single- and double-sided, and as an OBJ's mesh (always two-sided), the centre pixel by hand.
import { describe, expect, it } from 'vitest';
import { renderScene } from '../../src/reference';
import { SoftwareRenderer } from '../../src/software';
import { BOX_STATE } from './helpers/pbr-scenes';
import { QUAD_CASES } from './helpers/double-sided';

const CENTRE = 16 * 33 + 16;

describe('a glTF mesh\'s sides', () => {
  for (const c of QUAD_CASES) {
    it(c.name, () => {
      const ref = renderScene(c.scene, BOX_STATE, null, { samplesPerAxis: 1 }).rgb;
      const soft = new SoftwareRenderer({ samplesPerAxis: 1 }).render(c.scene, BOX_STATE);
      for (let k = 0; k < 3; k++) {
        expect(ref[3 * CENTRE + k], `reference channel ${k}`).toBeCloseTo(c.want, 12);
        expect(soft[4 * CENTRE + k], `software channel ${k}`).toBe(Math.round(c.want * 255));
      }
    });
  }
});
