// glTF data read exactly (src/loaders/gltf, docs/gltf.md#accessors, #materials): quantized,
// interleaved, sparse and unaligned accessors, and every field of a metallic-roughness material
// with its extensions (emissive strength, unlit, texture transform), samplers and images.
import { KHRMaterialsEmissiveStrength, KHRMaterialsUnlit, KHRMeshQuantization, KHRTextureTransform } from '@gltf-transform/extensions';
import { PNG } from 'pngjs';
import { describe, expect, it } from 'vitest';
import { accessor, glbBin, glbJson, glbOf, makeGlb, newDocument, parse, primitive } from './helpers/gltf';
import { io } from './helpers/gltf';
import { VertexLayout } from '@gltf-transform/core';
import { transformAsObj } from '../../src/loaders/gltf/as-obj';

const TRI = [0, 0, 0, 1, 0, 0, 0, 1, 0];
const round = (a: ArrayLike<number>, digits = 6) => Array.from(a, (x) => Number(x.toFixed(digits)) + 0);

/** A 1×1 PNG of one colour. */
function png(r: number, g: number, b: number): Uint8Array {
  const image = new PNG({ width: 1, height: 1 });
  image.data.set([r, g, b, 255]);
  return new Uint8Array(PNG.sync.write(image));
}

describe('accessors', () => {
  it('reads KHR_mesh_quantization: SHORT positions normalized, BYTE normals, placed by their node', async () => {
    const { doc, root } = newDocument();
    doc.createExtension(KHRMeshQuantization).setRequired(true);
    const position = accessor(doc, 'VEC3', new Int16Array([0, 0, 0, 32767, 0, 0, 0, -32768, 0]), true);
    const normal = accessor(doc, 'VEC3', new Int8Array([0, 0, 127, 0, 0, 127, 0, 0, 127]), true);
    const p = doc.createPrimitive().setAttribute('POSITION', position).setAttribute('NORMAL', normal);
    root.setMesh(doc.createMesh().addPrimitive(p)).setScale([4, 4, 4]);
    const r = parse(await glbOf(doc));
    // −32768 reads as −1 (glTF clamps the one value below −32767).
    expect(round(r.positions)).toEqual([0, 0, 0, 4, 0, 0, 0, -4, 0]);
    expect(round(r.normals)).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1]);
  });

  it('reads interleaved attributes (one buffer view with a stride) as separate ones do', async () => {
    const make = async (layout: VertexLayout) => {
      const { doc, root } = newDocument();
      const uv = accessor(doc, 'VEC2', new Float32Array([0, 0, 1, 0, 0, 1]));
      const normal = accessor(doc, 'VEC3', new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1]));
      root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null, { NORMAL: normal, TEXCOORD_0: uv })));
      const bytes = await io().setVertexLayout(layout).writeBinary(doc);
      return { json: glbJson(bytes), r: parse(bytes) };
    };
    const interleaved = await make(VertexLayout.INTERLEAVED);
    const separate = await make(VertexLayout.SEPARATE);
    expect(interleaved.json.bufferViews).toEqual([expect.objectContaining({ byteStride: 32 })]);
    expect(separate.json.bufferViews.length).toBe(3);
    expect(interleaved.r).toEqual(separate.r);
    expect(round(interleaved.r.uv0!)).toEqual([0, 0, 1, 0, 0, 1]);
  });

  it('applies sparse substitutions, over a buffer view and over zeros', async () => {
    const { doc, root } = newDocument();
    const positions = accessor(doc, 'VEC3', new Float32Array([0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0])).setSparse(true);
    root.setMesh(doc.createMesh().addPrimitive(doc.createPrimitive().setAttribute('POSITION', positions)
      .setIndices(accessor(doc, 'SCALAR', new Uint16Array([0, 2, 3])))));
    const glb = await io().writeBinary(doc);
    const json = glbJson(glb);
    expect(json.accessors[0].sparse.count).toBe(1);
    expect(json.accessors[0].bufferView).toBeUndefined();
    // Two sparse values: one over the zeros written by glTF-Transform, and a hand-made one with a base view.
    const r = parse(glb);
    expect(round(r.positions)).toEqual([0, 0, 0, 0, 1, 0, 0, 0, 0]);
    // Now the same sparse part over a base view of all 2s: vertex 2 becomes (0, 1, 0), others stay 2.
    const bin = glbBin(glb);
    const base = new Uint8Array(new Float32Array(12).fill(2).buffer);
    const data = new Uint8Array(bin.length + base.length);
    data.set(bin);
    data.set(base, bin.length);
    json.buffers[0].byteLength = data.length;
    json.bufferViews.push({ buffer: 0, byteOffset: bin.length, byteLength: base.length });
    json.accessors[0].bufferView = json.bufferViews.length - 1;
    expect(round(parse(makeGlb(json, data)).positions)).toEqual([2, 2, 2, 0, 1, 0, 2, 2, 2]);
  });

  it('reads a buffer view at an odd offset (a hand-made file) the same as an aligned one', async () => {
    const { doc, root } = newDocument();
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null)));
    const glb = await glbOf(doc);
    const json = glbJson(glb);
    const bin = glbBin(glb);
    const shifted = new Uint8Array(bin.length + 4);
    shifted.set(bin, 1);
    json.buffers[0].byteLength = shifted.length;
    json.bufferViews[0].byteOffset = 1;
    expect(round(parse(makeGlb(json, shifted)).positions)).toEqual(TRI);
  });
});

describe('materials', () => {
  it('reads every field of a metallic-roughness material and its textures', async () => {
    const { doc, root } = newDocument();
    const texture = (name: string, c: number) => doc.createTexture(name).setImage(png(c, c, c)).setMimeType('image/png');
    const base = texture('base', 200), mr = texture('mr', 100), normal = texture('normal', 128), ao = texture('ao', 255), glow = texture('glow', 50);
    const m = doc.createMaterial('every field')
      .setBaseColorFactor([0.5, 0.25, 1, 0.75]).setBaseColorTexture(base)
      .setMetallicFactor(0.3).setRoughnessFactor(0.6).setMetallicRoughnessTexture(mr)
      .setNormalTexture(normal).setNormalScale(0.8).setOcclusionTexture(ao).setOcclusionStrength(0.4)
      .setEmissiveFactor([1, 0.5, 0]).setEmissiveTexture(glow).setAlphaMode('MASK').setAlphaCutoff(0.3).setDoubleSided(true);
    m.getBaseColorTextureInfo()!.setWrapS(33071).setWrapT(33648).setMagFilter(9728).setMinFilter(9987);
    m.getOcclusionTextureInfo()!.setTexCoord(1);
    m.setExtension('KHR_materials_emissive_strength', doc.createExtension(KHRMaterialsEmissiveStrength).createEmissiveStrength().setEmissiveStrength(4));
    const uv = accessor(doc, 'VEC2', new Float32Array(6));
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null, { TEXCOORD_0: uv, TEXCOORD_1: uv }, m)));
    const r = parse(await glbOf(doc));
    const image = (name: string) => r.images.findIndex((i) => i.name.includes(name));
    const ref = (name: string, texCoord = 0) => ({ source: { image: image(name) }, texCoord, transform: null, sampler: { magFilter: undefined, minFilter: undefined, wrapS: 10497, wrapT: 10497 } });
    expect(r.materials).toEqual([{
      name: 'every field', baseColor: [0.5, 0.25, 1, 0.75],
      baseColorTexture: { ...ref('base'), sampler: { magFilter: 9728, minFilter: 9987, wrapS: 33071, wrapT: 33648 } },
      metallic: 0.3, roughness: 0.6, metallicRoughnessTexture: ref('mr'), normalTexture: ref('normal'), normalScale: 0.8,
      occlusionTexture: ref('ao', 1), occlusionStrength: 0.4, emissive: [1, 0.5, 0], emissiveTexture: ref('glow'), emissiveStrength: 4,
      alphaMode: 'mask', alphaCutoff: 0.3, doubleSided: true, unlit: false,
    }]);
    expect(r.images.map((i) => i.kind)).toEqual(['bytes', 'bytes', 'bytes', 'bytes', 'bytes']);
    const first = r.images[image('base')];
    expect(first.kind === 'bytes' && [first.mimeType, [...first.bytes.subarray(0, 4)]]).toEqual(['image/png', [0x89, 0x50, 0x4e, 0x47]]);
  });

  it('gives a primitive without a material none (null), and reads the defaults of an empty material', async () => {
    const { doc, root } = newDocument();
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null, {}, doc.createMaterial())).addPrimitive(primitive(doc, TRI, null)));
    const r = parse(await glbOf(doc));
    expect(r.groups.map((g) => g.material)).toEqual([0, null]);
    expect(r.materials[0]).toMatchObject({
      baseColor: [1, 1, 1, 1], metallic: 1, roughness: 1, emissive: [0, 0, 0], emissiveStrength: 1, alphaMode: 'opaque', alphaCutoff: 0.5,
      doubleSided: false, unlit: false, normalScale: 1, occlusionStrength: 1, baseColorTexture: null,
    });
  });

  it('reads KHR_materials_unlit and KHR_texture_transform (offset, rotation, scale, texCoord) as a UV matrix', async () => {
    const { doc, root } = newDocument();
    const t = doc.createTexture('t').setImage(png(9, 9, 9)).setMimeType('image/png');
    const m = doc.createMaterial('flat').setBaseColorTexture(t);
    m.setExtension('KHR_materials_unlit', doc.createExtension(KHRMaterialsUnlit).createUnlit());
    const transform = doc.createExtension(KHRTextureTransform).createTransform().setOffset([0, 1]).setRotation(Math.PI / 2).setScale([0.5, 0.5]).setTexCoord(1);
    m.getBaseColorTextureInfo()!.setExtension('KHR_texture_transform', transform);
    const uv = accessor(doc, 'VEC2', new Float32Array(6));
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null, { TEXCOORD_0: uv, TEXCOORD_1: uv }, m)));
    const r = parse(await glbOf(doc));
    expect(r.materials[0].unlit).toBe(true);
    const ref = r.materials[0].baseColorTexture!;
    expect(ref.texCoord).toBe(1);
    // The extension's own example: offset (0, 1), a quarter turn, half scale: the image's lower-left
    // quadrant, turned. (u, v) = (0, 0) → (0, 1); (1, 0) → (0, 0.5); (0, 1) → (0.5, 1).
    const [a, b, c, d, e, f] = ref.transform!;
    const apply = (u: number, v: number) => round([a * u + b * v + c, d * u + e * v + f], 9);
    expect([apply(0, 0), apply(1, 0), apply(0, 1)]).toEqual([[0, 1], [0, 0.5], [0.5, 1]]);
  });

  it('draws a KTX2-only texture and a TEXCOORD_2 one with the factor alone, one warning each', async () => {
    const { doc, root } = newDocument();
    const t = doc.createTexture('t').setImage(png(9, 9, 9)).setMimeType('image/png');
    const m = doc.createMaterial('m').setBaseColorTexture(t).setEmissiveTexture(t);
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null, {}, m)));
    const glb = await io().writeBinary(doc);
    const json = glbJson(glb);
    json.textures.push({ extensions: { KHR_texture_basisu: { source: 0 } } });
    json.materials[0].pbrMetallicRoughness.baseColorTexture = { index: 1 };
    json.materials[0].emissiveTexture = { index: 0, texCoord: 2 };
    const r = parse(makeGlb(json, glbBin(glb)));
    expect([r.materials[0].baseColorTexture, r.materials[0].emissiveTexture]).toEqual([null, null]);
    expect(r.warnings.map((w) => w.path)).toEqual(['textures[1].extensions.KHR_texture_basisu', 'materials[0].emissiveTexture.texCoord']);
  });
});

describe('what is not drawn', () => {
  it('leaves out points and lines with one warning, and draws the triangles beside them', async () => {
    const { doc, root } = newDocument();
    const mesh = doc.createMesh().addPrimitive(primitive(doc, TRI, null).setMode(0)).addPrimitive(primitive(doc, TRI, null).setMode(1))
      .addPrimitive(primitive(doc, TRI, null));
    root.setMesh(mesh);
    const r = parse(await glbOf(doc));
    expect(r.indices.length).toBe(3);
    expect(r.warnings).toEqual([{ path: 'meshes[0].primitives[0].mode', message: 'points and lines are not drawn (the first named; any others too)' }]);
  });

  it('draws every root node of a file without scenes, saying so', async () => {
    const { doc, root } = newDocument();
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null)));
    const glb = await glbOf(doc);
    const json = glbJson(glb);
    delete json.scenes;
    delete json.scene;
    const r = parse(makeGlb(json, glbBin(glb)));
    expect(r.indices.length).toBe(3);
    expect(r.warnings.map((w) => w.path)).toEqual(['scenes']);
  });
});

describe('transformAsObj', () => {
  it('maps the same point of the surface: a glTF UV (u, v) through T lands where the OBJ-way-up UV (u, 1 − v) through it does', () => {
    // T: rotation 0.4, scale (1.7, 0.8), offset (0.15, −0.2), as loaders/gltf/materials.ts writes it.
    const c = Math.cos(0.4), s = Math.sin(0.4);
    const t = [c * 1.7, s * 0.8, 0.15, -s * 1.7, c * 0.8, -0.2];
    const m = transformAsObj(t);
    for (const [u, v] of [[0, 0], [1, 0], [0.3, 0.8], [-2, 5]]) {
      const gu = t[0] * u + t[1] * v + t[2], gv = t[3] * u + t[4] * v + t[5];
      const o = [m[0] * u + m[1] * (1 - v) + m[2], m[3] * u + m[4] * (1 - v) + m[5]];
      expect(o[0]).toBeCloseTo(gu, 12);
      expect(o[1]).toBeCloseTo(1 - gv, 12);
    }
    // By hand: an offset alone (0.25, 0.5) moves v the other way, and the identity stays the identity.
    expect(transformAsObj([1, 0, 0.25, 0, 1, 0.5])).toEqual([1, -0, 0.25, -0, 1, -0.5]);
    expect(transformAsObj([1, 0, 0, 0, 1, 0])).toEqual([1, -0, 0, -0, 1, 0]);
  });
});
