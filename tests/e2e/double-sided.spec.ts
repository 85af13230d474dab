// glTF's doubleSided in the GLSL path (docs/gltf.md#drawing): the quad of tests/unit/helpers/double-sided.ts seen from its front
// and its back, single- and double-sided, and as an OBJ's mesh, drawn by the WebGL renderer to one 8-bit level of the hand value.
import { test, expect } from './fixtures';
import { drawScene, openRendererPage } from './helpers/scene-json';
import { BOX_STATE } from '../unit/helpers/pbr-scenes';
import { QUAD_CASES } from '../unit/helpers/double-sided';

const CENTRE = 4 * (16 * 33 + 16);

test('WebGL: a glTF mesh is single-sided unless its material is double-sided', async ({ page }) => {
  await openRendererPage(page);
  for (const c of QUAD_CASES) {
    const got = [...(await drawScene(page, BOX_STATE, c.scene)).data.subarray(CENTRE, CENTRE + 3)];
    got.forEach((g, k) => expect(Math.abs(g - c.want * 255), `${c.name}, channel ${k}: ${got} against ${c.want * 255}`).toBeLessThanOrEqual(1));
  }
});
