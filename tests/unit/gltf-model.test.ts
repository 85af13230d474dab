// A read glTF model as the element keeps it (src/loaders/gltf/as-obj.ts, src/element/children/gltf-model.ts,
// docs/gltf.md#in-the-scene and #drawing): the OBJ-shaped geometry (v flipped, 16-bit indices while
// they fit, groups keyed #i, bounds), images as URLs, and each material's Blinn-Phong stand-in.
import { describe, expect, it } from 'vitest';
import { gltfAsObj, materialKey } from '../../src/loaders/gltf/as-obj';
import { DEFAULT_MATERIAL, type GltfMaterial } from '../../src/loaders/gltf/materials';
import type { GltfResult } from '../../src/loaders/gltf';
import { modelOf, standIn } from '../../src/element/children/gltf-model';
import type { PbrMaterial } from '../../src/scene/pbr-material';

function result(over: Partial<GltfResult> = {}): GltfResult {
  return {
    positions: new Float32Array([0, 0, 0, 2, -1, 0, 0, 3, 5]), normals: new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1]),
    uv0: new Float32Array([0, 0, 1, 0.25, 0.5, 1]), uv1: null, colors: new Float32Array([1, 0, 0, 0.5, 0, 1, 0, 1, 0, 0, 1, 1]), tangents: null,
    indices: new Uint32Array([0, 1, 2]), groups: [{ material: 1, start: 0, count: 3 }], materials: [], images: [],
    warnings: [{ path: 'meshes[0].primitives[1].mode', message: 'points and lines are not drawn (the first named; any others too)' }],
    ...over,
  };
}

describe('gltfAsObj', () => {
  it("turns v to the OBJ convention, RGBA to RGB, keys groups #i, bounds the positions, keeps the warnings' paths", () => {
    const obj = gltfAsObj(result());
    expect([...obj.uvs!]).toEqual([0, 1, 1, 0.75, 0.5, 0]);
    expect([...obj.colors!]).toEqual([1, 0, 0, 0, 1, 0, 0, 0, 1]);
    expect(obj.indices).toBeInstanceOf(Uint16Array);
    expect([...obj.indices]).toEqual([0, 1, 2]);
    expect(obj.groups).toEqual([{ material: '#1', start: 0, count: 3 }]);
    expect(obj.bounds).toEqual({ min: [0, -1, 0], max: [2, 3, 5] });
    expect(obj.warnings).toEqual([{ line: 0, path: 'meshes[0].primitives[1].mode', message: expect.stringContaining('points and lines') }]);
    expect(materialKey(7)).toBe('#7');
    // No OBJ's material libraries, objects or group names: the glTF model has none.
    expect([obj.mtllibs, obj.objects, obj.groupNames]).toEqual([[], [], []]);
  });

  it('keeps 32-bit indices past 65,535 vertices, and no UVs or colours where the model has none', () => {
    const n = 65536;
    const obj = gltfAsObj(result({ positions: new Float32Array(3 * n), normals: new Float32Array(3 * n), uv0: null, colors: null, groups: [{ material: null, start: 0, count: 3 }] }));
    expect(obj.indices).toBeInstanceOf(Uint32Array);
    expect([obj.uvs, obj.colors, obj.groups[0].material]).toEqual([null, null, null]);
    const small = gltfAsObj(result({ positions: new Float32Array(3 * 65535), normals: new Float32Array(3 * 65535) }));
    expect(small.indices).toBeInstanceOf(Uint16Array);
  });
});

const material = (over: Partial<PbrMaterial> = {}): PbrMaterial => ({ ...(DEFAULT_MATERIAL as unknown as PbrMaterial), ...over });

describe('the Blinn-Phong stand-in of a glTF material (docs/gltf.md#drawing)', () => {
  it('a rough dielectric: base colour as Ka and Kd, no highlight at roughness 1, exponent clamped to 1', () => {
    const m = standIn(material({ baseColor: [0.5, 0.25, 1, 0.4], metallic: 0, roughness: 1 }));
    expect(m).toMatchObject({ ambient: [0.5, 0.25, 1], diffuse: [0.5, 0.25, 1], specular: [0, 0, 0], shininess: 1, opacity: 1, texture: undefined });
  });

  it('a polished metal: the highlight in its base colour; α floored at 0.05 (exponent 798), alpha kept when blended', () => {
    const m = standIn(material({ baseColor: [0.9, 0.6, 0.2, 0.4], metallic: 1, roughness: 0, alphaMode: 'blend' }));
    expect(m.specular!.map((x) => Number(x.toFixed(6)))).toEqual([0.9, 0.6, 0.2]);
    expect(m.shininess).toBeCloseTo(798, 9);
    expect(m.opacity).toBe(0.4);
  });

  it('half metal at roughness 0.5: F0 mixed from 0.04, faded by half; exponent 2/α² − 2 with α = 0.25', () => {
    const m = standIn(material({ baseColor: [1, 0, 0.5, 1], metallic: 0.5, roughness: 0.5 }));
    expect(m.specular!.map((x) => Number(x.toFixed(6)))).toEqual([0.26, 0.01, 0.135]);
    expect(m.shininess).toBe(30);
  });

  it('gives off its emissive factor times its strength; none when the factor is black', () => {
    expect(standIn(material({ emissive: [1, 0.5, 0], emissiveStrength: 4 })).emissive).toEqual([4, 2, 0]);
    expect('emissive' in standIn(material({ emissive: [0, 0, 0], emissiveStrength: 4 }))).toBe(false);
    expect(standIn(material({ emissive: [0, 0, 0.25] })).emissive).toEqual([0, 0, 0.25]);
    // KHR_materials_unlit: the base colour alone (docs/pbr.md#the-scenes-lights).
    expect('emissive' in standIn(material({ emissive: [1, 0.5, 0], unlit: true }))).toBe(false);
  });

  it('draws the base colour texture when it reads TEXCOORD_0, not TEXCOORD_1; carries the material whole', () => {
    const tex = { source: { url: 'blob:x' }, texCoord: 0, sampler: { magFilter: undefined, minFilter: undefined, wrapS: 10497, wrapT: 10497 }, transform: null };
    const m = material({ baseColorTexture: tex, alphaMode: 'mask' });
    expect(standIn(m)).toMatchObject({ texture: 'blob:x', opacity: 1, pbr: m });
    expect(standIn(material({ baseColorTexture: { ...tex, texCoord: 1 } })).texture).toBeUndefined();
  });
});

describe('modelOf', () => {
  it('names every image by URL (relative to the model, or blob: for embedded bytes) in each material', () => {
    const base: GltfMaterial = { ...DEFAULT_MATERIAL, name: 'a' };
    const ref = (image: number) => ({ source: { image }, texCoord: 0, sampler: { magFilter: undefined, minFilter: undefined, wrapS: 10497, wrapT: 10497 }, transform: null });
    const model = modelOf(result({
      materials: [{ ...base, baseColorTexture: ref(0), emissiveTexture: ref(1) }, { ...base, name: 'b' }],
      images: [{ kind: 'uri', uri: 'tex/my%20wood.png', name: 'images[0]' }, { kind: 'bytes', bytes: new Uint8Array([1, 2]), mimeType: 'image/png', name: 'images[1]' }],
    }), 'https://example.com/models/chair.glb');
    expect(model.gltf).toBe(true);
    const first = model.materials.get('#0')!;
    expect(first.texture).toBe('https://example.com/models/tex/my%20wood.png');
    expect(first.pbr!.emissiveTexture!.source.url).toMatch(/^blob:/);
    expect(model.materials.get('#1')!.pbr!.name).toBe('b');
    expect(model.warnings).toEqual(['glass-plane-scene: https://example.com/models/chair.glb at meshes[0].primitives[1].mode: points and lines are not drawn (the first named; any others too)']);
  });

  it('turns each texture\'s transform the OBJ way up with the UVs (transformAsObj), and keeps none as none', () => {
    const base: GltfMaterial = { ...DEFAULT_MATERIAL, name: 'a' };
    const ref = (transform: number[] | null) => ({ source: { image: 0 }, texCoord: 0, sampler: { magFilter: undefined, minFilter: undefined, wrapS: 10497, wrapT: 10497 }, transform });
    const model = modelOf(result({
      materials: [{ ...base, baseColorTexture: ref([1, 0, 0.25, 0, 1, 0.5]), occlusionTexture: ref(null) }],
      images: [{ kind: 'uri', uri: 'a.png', name: 'images[0]' }],
    }), 'https://example.com/m.gltf');
    const pbr = model.materials.get('#0')!.pbr!;
    // An offset (0.25, 0.5) in glTF's UV (v down) is (0.25, −0.5) the OBJ way up.
    expect(pbr.baseColorTexture!.transform).toEqual([1, -0, 0.25, -0, 1, -0.5]);
    expect(pbr.occlusionTexture!.transform).toBeNull();
  });
});
