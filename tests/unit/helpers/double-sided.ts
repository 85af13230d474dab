// A glTF mesh quad in the plane z = 0, counter-clockwise seen from +z (its front), its normals +z, seen head-on by the camera
// of BOX_STATE (at +z) under the head-on light of boxScene: turned about Y by 0° (front to the camera) or 180° (back), with
// its material single- or double-sided (docs/gltf.md#drawing). Shared by tests/unit/double-sided.test.ts and the GLSL's spec.
import type { Scene } from '../../../src/scene/scene';
import { boxScene, pbrMaterial } from './pbr-scenes';

const QUAD = {
  positions: new Float32Array([-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0]),
  normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1]),
  uvs: new Float32Array([0, 0, 1, 0, 1, 1, 0, 1]),
  indices: new Uint16Array([0, 1, 2, 0, 2, 3]),
};

/** The rough dielectric of base 0.5 head-on: Ia·0.5 + Id·(0.96·0.5 + 0.04/4) = 0.148 (tests/unit/helpers/pbr-scenes.ts HAND_CASES). */
export const LIT = 0.148;

/** The quad turned `turn`° about Y; `doubleSided` null: not a glTF material (an OBJ's, drawn from both sides). */
export function quadScene(turn: 0 | 180, doubleSided: boolean | null): Scene {
  const s = boxScene(pbrMaterial({ baseColor: [0.5, 0.5, 0.5, 1], metallic: 0, roughness: 1, doubleSided: doubleSided === true }));
  const o = s.objects[0];
  const material = doubleSided === null
    ? { ...o.material, pbr: undefined, ambient: [0.5, 0.5, 0.5] as const, diffuse: [0.5, 0.5, 0.5] as const }
    : o.material;
  return {
    ...s,
    objects: [{
      ...o, material, bounds: { center: [0, 0, 0], radius: Math.SQRT2 },
      geometry: { kind: 'mesh', key: 'quad', data: QUAD }, transform: { ...o.transform, rotation: [0, turn, 0] },
    }],
  };
}

/** What the centre shows: lit, or the background (0) where the back face is culled. Blinn-Phong's: Kd·(Ia + Id) = 0.5·0.3 = 0.15. */
export const QUAD_CASES: { name: string; scene: Scene; want: number }[] = [
  { name: 'single-sided, its front to the camera', scene: quadScene(0, false), want: LIT },
  { name: 'single-sided, its back to the camera: culled', scene: quadScene(180, false), want: 0 },
  { name: 'double-sided, its back to the camera: lit, its normal turned to the viewer', scene: quadScene(180, true), want: LIT },
  { name: 'not a glTF material, its back to the camera: drawn from both sides', scene: quadScene(180, null), want: 0.15 },
];
