// The alpha mask's scene (docs/gltf.md#alpha), shared by tests/unit/alpha-mask.test.ts and tests/e2e/alpha-mask.spec.ts: a box
// head-on to BOX_STATE's camera whose glTF material is alphaMode `mask` (cutoff ½), in front of an unlit green plate drawn after it.
import type { PbrMaterial } from '../../../src/scene/pbr-material';
import type { Scene, SceneObject } from '../../../src/scene/scene';
import type { DecodedImage } from '../../../src/scene/decoded-image';
import { boxScene, pbrMaterial, withPbr } from './pbr-scenes';
import { map } from './pbr-map-cases';

export const BASE = 'https://example.com/leaf base.png';
export const PLATE = [0.2, 0.8, 0.4];

/** 2×2 white texels, alpha by column as the image is stored: left column `left`, right column `right`. */
export const columns = (left: number, right: number): DecodedImage => ({
  width: 2, height: 2, data: new Uint8ClampedArray([255, 255, 255, left, 255, 255, 255, right, 255, 255, 255, left, 255, 255, 255, right]),
});

export function maskScene(over: Partial<PbrMaterial>, textured = false): Scene {
  const pbr = pbrMaterial({ baseColor: [0.5, 0.5, 0.5, 1], metallic: 1, roughness: 1, alphaMode: 'mask', alphaCutoff: 0.5, ...(textured ? { baseColorTexture: map(BASE) } : {}), ...over });
  const s = boxScene(pbr);
  const front = s.objects[0];
  const material = textured ? withPbr(pbr, { kind: 'image', url: BASE, fallback: 'none' }) : front.material;
  const plate: SceneObject = {
    ...front, material: withPbr(pbrMaterial({ baseColor: [...PLATE, 1] as [number, number, number, number], unlit: true })),
    transform: { ...front.transform, position: [0, 0, -3], scale: [8, 8, 0.1] }, bounds: { center: [0, 0, 0], radius: 0.9 },
  };
  return { ...s, objects: [{ ...front, material }, plate] };
}


/** 2×2 texels by row as the image is stored: the top row red and opaque, the bottom row blue and clear (alpha 0). */
export const redOverClear = (): DecodedImage => ({
  width: 2, height: 2, data: new Uint8ClampedArray([255, 0, 0, 255, 255, 0, 0, 255, 0, 0, 255, 0, 0, 0, 255, 0]),
});
