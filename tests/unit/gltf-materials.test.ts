// glTF materials as data (src/loaders/gltf/materials.ts, docs/gltf.md#materials): the
// specification's defaults field by field, values clamped or refused where glTF bounds them, each
// refusal and warning with its JSON path, textures resolved through samplers, EXT_texture_webp and
// KHR_texture_basisu, and the texture transform's extension read where it sits.
import { describe, expect, it } from 'vitest';
import { LoadError } from '../../src/loaders/load-error';
import { GltfFile } from '../../src/loaders/gltf/fields';
import { DEFAULT_MATERIAL, readMaterials } from '../../src/loaders/gltf/materials';

type Json = Record<string, unknown>;
const REPEAT = 10497;

/** The file's materials and its warnings. */
function read(json: Json): { materials: ReturnType<typeof readMaterials>; warnings: GltfFile['warnings'] } {
  const file = new GltfFile('m.gltf', json);
  return { materials: readMaterials(file), warnings: file.warnings };
}

/** The path and message of the LoadError reading `json` throws. */
function refusal(json: Json): { path: string | undefined; message: string } {
  try {
    read(json);
  } catch (e) {
    expect(e).toBeInstanceOf(LoadError);
    return { path: (e as LoadError).path, message: (e as LoadError).detail.message };
  }
  throw new Error('read without an error');
}

/** One material whose base colour texture is `info`, over these textures, images and samplers. */
const textured = (info: Json, more: Json = {}): Json => ({
  materials: [{ pbrMetallicRoughness: { baseColorTexture: info } }], textures: [{ source: 0 }], images: [{ uri: 'a.png' }, { uri: 'b.webp' }], ...more,
});
const baseTexture = (json: Json) => read(json).materials[0].baseColorTexture;

describe('defaults and fields', () => {
  it('has the specification\'s defaults, field by field, for a material that says nothing', () => {
    expect(DEFAULT_MATERIAL).toEqual({
      name: '', baseColor: [1, 1, 1, 1], baseColorTexture: null, metallic: 1, roughness: 1, metallicRoughnessTexture: null,
      normalTexture: null, normalScale: 1, occlusionTexture: null, occlusionStrength: 1, emissive: [0, 0, 0], emissiveTexture: null,
      emissiveStrength: 1, alphaMode: 'opaque', alphaCutoff: 0.5, doubleSided: false, unlit: false,
    });
    expect(read({ materials: [{}] }).materials).toEqual([DEFAULT_MATERIAL]);
    expect(read({}).materials).toEqual([]);
  });

  it('reads every field given', () => {
    const [m] = read({
      materials: [{
        name: 'shoe', alphaMode: 'MASK', alphaCutoff: 0.25, doubleSided: true, emissiveFactor: [0.2, 0.3, 0.4],
        pbrMetallicRoughness: { baseColorFactor: [0.1, 0.2, 0.3, 0.4], metallicFactor: 0.6, roughnessFactor: 0.7 },
        normalTexture: { index: 0, scale: 0.5 }, occlusionTexture: { index: 0, strength: 0.75 },
        extensions: { KHR_materials_emissive_strength: { emissiveStrength: 3 }, KHR_materials_unlit: {} },
      }],
      textures: [{ source: 0 }], images: [{ uri: 'n.png' }],
    }).materials;
    expect(m).toMatchObject({
      name: 'shoe', alphaMode: 'mask', alphaCutoff: 0.25, doubleSided: true, emissive: [0.2, 0.3, 0.4], baseColor: [0.1, 0.2, 0.3, 0.4],
      metallic: 0.6, roughness: 0.7, normalScale: 0.5, occlusionStrength: 0.75, emissiveStrength: 3, unlit: true,
    });
    expect(m.normalTexture?.source).toEqual({ image: 0 });
    expect(read({ materials: [{ alphaMode: 'BLEND', doubleSided: 'yes' }] }).materials[0]).toMatchObject({ alphaMode: 'blend', doubleSided: false });
    // Scale and strength belong to their textures: without one, they stay 1.
    expect(read({ materials: [{ alphaMode: 'OPAQUE' }] }).materials[0]).toMatchObject({ alphaMode: 'opaque', normalScale: 1, occlusionStrength: 1 });
  });

  it('clamps the base colour into [0, 1] and the emissive factor to 0 from below', () => {
    const [m] = read({ materials: [{ pbrMetallicRoughness: { baseColorFactor: [-0.5, 1.5, 0.25, 2] }, emissiveFactor: [-1, 2, 0.5] }] }).materials;
    expect(m.baseColor).toEqual([0, 1, 0.25, 1]);
    expect(m.emissive).toEqual([0, 2, 0.5]);
  });
});

describe('refusals name the JSON path', () => {
  it('refuses an alpha mode glTF has no name for, quoting it', () => {
    expect(refusal({ materials: [{}, { alphaMode: 'Mask' }] })).toEqual({
      path: 'materials[1].alphaMode', message: 'materials[1].alphaMode is "Mask", not OPAQUE, MASK or BLEND',
    });
    // A long one is cut at 40 characters, its opening quote included.
    expect(refusal({ materials: [{ alphaMode: 'M'.repeat(50) }] }).message).toBe(`materials[0].alphaMode is "${'M'.repeat(39)}, not OPAQUE, MASK or BLEND`);
  });

  it('names the material, its pbr block, texture, extension and field', () => {
    expect(refusal({ materials: [{}, 7] })).toEqual({ path: 'materials[1]', message: 'materials[1] is not an object' });
    expect(refusal({ materials: [{ name: 3 }] })).toEqual({ path: 'materials[0].name', message: 'materials[0].name is 3, not a string' });
    expect(refusal({ materials: [{ pbrMetallicRoughness: { metallicFactor: 2 } }] })).toEqual({
      path: 'materials[0].pbrMetallicRoughness.metallicFactor', message: 'materials[0].pbrMetallicRoughness.metallicFactor is 2, outside [0, 1]',
    });
    expect(refusal({ materials: [{ normalTexture: { index: 0, scale: 'x' } }], textures: [{ source: 0 }], images: [{}] })).toEqual({
      path: 'materials[0].normalTexture.scale', message: 'materials[0].normalTexture.scale is "x", not a number',
    });
    expect(refusal({ materials: [{ occlusionTexture: { index: 0, strength: 2 } }], textures: [{ source: 0 }], images: [{}] })).toEqual({
      path: 'materials[0].occlusionTexture.strength', message: 'materials[0].occlusionTexture.strength is 2, outside [0, 1]',
    });
    expect(refusal({ materials: [{ extensions: { KHR_materials_emissive_strength: 1 } }] })).toEqual({
      path: 'materials[0].extensions.KHR_materials_emissive_strength', message: 'materials[0].extensions.KHR_materials_emissive_strength is not an object',
    });
    const strength = 'materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength';
    expect(refusal({ materials: [{ extensions: { KHR_materials_emissive_strength: { emissiveStrength: -1 } } }] })).toEqual({
      path: strength, message: `${strength} is -1, outside [0, Infinity]`,
    });
    expect(refusal({ materials: [{ alphaCutoff: -0.1 }] })).toEqual({ path: 'materials[0].alphaCutoff', message: 'materials[0].alphaCutoff is -0.1, outside [0, Infinity]' });
  });

  it('names the texture index, the sampler and the image where each is missing', () => {
    expect(refusal(textured({ index: 5 }))).toEqual({
      path: 'materials[0].pbrMetallicRoughness.baseColorTexture.index', message: 'textures[5] does not exist (textures has 1)',
    });
    expect(refusal(textured({ index: 0 }, { textures: [{ source: 0, sampler: 2 }] }))).toEqual({
      path: 'textures[0].sampler', message: 'samplers[2] does not exist (samplers has 0)',
    });
    expect(refusal(textured({ index: 0 }, { textures: [{ source: 3 }] }))).toEqual({ path: 'textures[0].source', message: 'images[3] does not exist (images has 2)' });
    expect(refusal(textured({ index: 0 }, { textures: [{ source: 0, extensions: { EXT_texture_webp: { source: 4 } } }] }))).toEqual({
      path: 'textures[0].extensions.EXT_texture_webp.source', message: 'images[4] does not exist (images has 2)',
    });
    expect(refusal(textured({ index: 0 }, { textures: [{ extensions: { EXT_texture_webp: 1 } }] }))).toEqual({
      path: 'textures[0].extensions.EXT_texture_webp', message: 'textures[0].extensions.EXT_texture_webp is not an object',
    });
  });

  it('names the texture transform extension and its fields', () => {
    const at = 'materials[0].pbrMetallicRoughness.baseColorTexture.extensions';
    expect(refusal(textured({ index: 0, extensions: { KHR_texture_transform: [] } }))).toEqual({
      path: `${at}.KHR_texture_transform`, message: `${at}.KHR_texture_transform is not an object`,
    });
    expect(refusal(textured({ index: 0, extensions: { KHR_texture_transform: { rotation: 'half' } } }))).toEqual({
      path: `${at}.KHR_texture_transform.rotation`, message: `${at}.KHR_texture_transform.rotation is "half", not a number`,
    });
  });
});

describe('textures', () => {
  it('repeats in both directions with the filters left to the renderer when the texture has no sampler', () => {
    expect(baseTexture(textured({ index: 0 }))).toEqual({
      source: { image: 0 }, texCoord: 0, transform: null, sampler: { magFilter: undefined, minFilter: undefined, wrapS: REPEAT, wrapT: REPEAT },
    });
  });

  it('keeps every wrap and filter value glTF allows, and replaces any other with its default, warning once with the path', () => {
    const sampled = (sampler: Json) => read(textured({ index: 0 }, { textures: [{ source: 0, sampler: 0 }], samplers: [sampler] }));
    for (const wrap of [33071, 33648, REPEAT]) expect(sampled({ wrapS: wrap, wrapT: wrap }).materials[0].baseColorTexture?.sampler).toMatchObject({ wrapS: wrap, wrapT: wrap });
    for (const mag of [9728, 9729]) expect(sampled({ magFilter: mag }).materials[0].baseColorTexture?.sampler.magFilter).toBe(mag);
    for (const min of [9728, 9729, 9984, 9985, 9986, 9987]) expect(sampled({ minFilter: min }).materials[0].baseColorTexture?.sampler.minFilter).toBe(min);
    const odd = sampled({ wrapS: 1234, magFilter: 9984 });
    expect(odd.materials[0].baseColorTexture?.sampler).toEqual({ magFilter: undefined, minFilter: undefined, wrapS: REPEAT, wrapT: REPEAT });
    expect(odd.warnings).toEqual([
      { path: 'samplers[0].magFilter', message: 'samplers[0].magFilter is 9984, not a value glTF allows: the default is used' },
      { path: 'samplers[0].wrapS', message: 'samplers[0].wrapS is 1234, not a value glTF allows: the default is used' },
    ]);
  });

  it('draws the EXT_texture_webp image in place of the source', () => {
    expect(baseTexture(textured({ index: 0 }, { textures: [{ source: 0, extensions: { EXT_texture_webp: { source: 1 } } }] }))?.source).toEqual({ image: 1 });
    expect(baseTexture(textured({ index: 0 }, { textures: [{ extensions: { EXT_texture_webp: { source: 1 } } }] }))?.source).toEqual({ image: 1 });
  });

  it('leaves out a KTX2-only texture with a warning naming it, and a texture without an image silently', () => {
    const ktx = read(textured({ index: 0 }, { textures: [{ extensions: { KHR_texture_basisu: { source: 0 } } }] }));
    expect(ktx.materials[0].baseColorTexture).toBeNull();
    expect(ktx.warnings).toEqual([{
      path: 'textures[0].extensions.KHR_texture_basisu', message: 'textures[0] is a KTX2 (Basis) image only: drawn with its material\'s factor instead',
    }]);
    for (const texture of [{}, { extensions: {} }]) {
      const none = read(textured({ index: 0 }, { textures: [texture] }));
      expect(none.materials[0].baseColorTexture).toBeNull();
      expect(none.warnings).toEqual([]);
    }
  });

  it('leaves out a texture reading TEXCOORD_2 or above, by its own texCoord or the transform\'s, with a warning', () => {
    const at = 'materials[0].pbrMetallicRoughness.baseColorTexture';
    const message = `${at} reads TEXCOORD_2: only TEXCOORD_0 and TEXCOORD_1 are read; drawn without it`;
    for (const info of [{ index: 0, texCoord: 2 }, { index: 0, extensions: { KHR_texture_transform: { texCoord: 2 } } }]) {
      const r = read(textured(info));
      expect(r.materials[0].baseColorTexture).toBeNull();
      expect(r.warnings).toEqual([{ path: `${at}.texCoord`, message }]);
    }
    expect(baseTexture(textured({ index: 0, texCoord: 2, extensions: { KHR_texture_transform: { texCoord: 1 } } }))?.texCoord).toBe(1);
  });
});
