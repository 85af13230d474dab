// glTF 2.0 read into plain data (src/loaders/gltf, docs/gltf.md): GLB and .gltf containers,
// buffers from the BIN chunk, data: URIs and external files, the node hierarchy flattened,
// several primitives and materials, strips and fans, flat normals where the file has none.
// Every model is made here with glTF-Transform and passes the Khronos validator first.
import { describe, expect, it } from 'vitest';
import { accessor, glbOf, gltfOf, newDocument, parse, primitive } from './helpers/gltf';

/** One triangle in the z = 0 plane, counter-clockwise seen from +z. */
const TRI = [0, 0, 0, 1, 0, 0, 0, 1, 0];

const round = (a: ArrayLike<number>, digits = 6) => Array.from(a, (x) => Number(x.toFixed(digits)) + 0);

describe('containers and buffers', () => {
  it('reads a GLB: its positions, its indices, flat normals where the file has none', async () => {
    const { doc, root } = newDocument();
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, [0, 1, 2])));
    const r = parse(await glbOf(doc));
    expect(round(r.positions)).toEqual(TRI);
    expect([...r.indices]).toEqual([0, 1, 2]);
    expect(round(r.normals)).toEqual([0, 0, 1, 0, 0, 1, 0, 0, 1]);
    expect(r.groups).toEqual([{ material: null, start: 0, count: 3 }]);
    expect([r.uv0, r.uv1, r.colors, r.warnings]).toEqual([null, null, null, []]);
  });

  it('reads a .gltf whose buffer is an external file, and one whose buffer is a data: URI', async () => {
    const { doc, root } = newDocument();
    // Percent-encoded in the file, as a URI must be: "my modèle (1).bin".
    doc.getRoot().listBuffers()[0].setURI('my%20mod%C3%A8le%20(1).bin');
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null)));
    const { json, resources } = await gltfOf(doc);
    expect(Object.keys(resources)).toEqual(['my%20mod%C3%A8le%20(1).bin']);
    expect(round(parse(json, 'model.gltf', resources).positions)).toEqual(TRI);
    const text = JSON.parse(new TextDecoder().decode(json));
    const bin = resources['my%20mod%C3%A8le%20(1).bin'];
    text.buffers[0].uri = `data:application/octet-stream;base64,${Buffer.from(bin).toString('base64')}`;
    const inline = new TextEncoder().encode(`\uFEFF${JSON.stringify(text, null, 2).replace(/\n/g, '\r\n')}`);
    expect(round(parse(inline, 'inline.gltf').positions)).toEqual(TRI);
  });
});

describe('nodes', () => {
  it('places each mesh by its node and its parents: translation, rotation (x, y, z, w), scale, matrix', async () => {
    const { doc, root } = newDocument();
    const mesh = doc.createMesh().addPrimitive(primitive(doc, TRI, null, { NORMAL: accessor(doc, 'VEC3', new Float32Array([0, 0, 1, 0, 0, 1, 0, 0, 1])) }));
    root.setTranslation([10, 0, 0]).setScale([2, 2, 2]);
    // A quarter turn about +y (x → −z), then moved up 1: under root, scaled 2 and moved +10 in x.
    const s = Math.SQRT1_2;
    root.addChild(doc.createNode('turned').setRotation([0, s, 0, s]).setTranslation([0, 1, 0]).setMesh(mesh));
    // A matrix node beside it: columns (x, y, z, translation), mirrored in x (its winding flips).
    root.addChild(doc.createNode('matrix').setMatrix([-1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 5, 1]).setMesh(mesh));
    const r = parse(await glbOf(doc));
    expect(round(r.positions, 5)).toEqual([10, 2, 0, 10, 2, -2, 10, 4, 0, 10, 0, 10, 8, 0, 10, 10, 2, 10]);
    // Normals through the inverse transpose: +z turned to +x; mirrored in x, +z stays +z.
    expect(round(r.normals, 5)).toEqual([1, 0, 0, 1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1, 0, 0, 1]);
    // The mirrored copy's triangle is wound the other way, so that it still faces its normal.
    expect([...r.indices]).toEqual([0, 1, 2, 3, 5, 4]);
  });
});

describe('primitives', () => {
  it('lists the triangles of strips and fans as glTF orders them', async () => {
    const { doc, root } = newDocument();
    const quad = [0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0];
    const strip = primitive(doc, quad, null).setMode(5);
    const fan = primitive(doc, [0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0], [0, 1, 2, 3]).setMode(6);
    root.setMesh(doc.createMesh().addPrimitive(strip).addPrimitive(fan));
    const r = parse(await glbOf(doc));
    // Flat normals give every triangle its own vertices: compare the positions each triangle reads.
    const tri = (t: number) => round(Array.from(r.indices.subarray(3 * t, 3 * t + 3), (i) => [...r.positions.subarray(3 * i, 3 * i + 3)]).flat());
    expect([0, 1, 2, 3].map(tri)).toEqual([
      [0, 0, 0, 1, 0, 0, 0, 1, 0], [1, 0, 0, 1, 1, 0, 0, 1, 0], // strip: (0 1 2), (1 3 2)
      [1, 0, 0, 1, 1, 0, 0, 0, 0], [1, 1, 0, 0, 1, 0, 0, 0, 0], // fan: (1 2 0), (2 3 0)
    ]);
    expect(round(r.normals)).toEqual(Array(12).fill([0, 0, 1]).flat());
  });

  it('groups triangles by material in order of first use, across primitives and meshes', async () => {
    const { doc, root } = newDocument();
    const red = doc.createMaterial('red').setBaseColorFactor([1, 0, 0, 1]);
    const blue = doc.createMaterial('blue').setBaseColorFactor([0, 0, 1, 0.5]).setAlphaMode('BLEND');
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null, {}, blue)).addPrimitive(primitive(doc, TRI, null, {}, red)));
    root.addChild(doc.createNode('second').setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, null, {}, blue))));
    const r = parse(await glbOf(doc));
    // materials[0] is red (made first), but blue is drawn first.
    expect(r.groups).toEqual([{ material: 1, start: 0, count: 6 }, { material: 0, start: 6, count: 3 }]);
    expect([...r.indices]).toEqual([0, 1, 2, 6, 7, 8, 3, 4, 5]);
    expect(r.materials.map((m) => [m.name, m.baseColor, m.alphaMode])).toEqual([['red', [1, 0, 0, 1], 'opaque'], ['blue', [0, 0, 1, 0.5], 'blend']]);
  });

  it('reads TEXCOORD_0, TEXCOORD_1 and COLOR_0 (RGB given alpha 1), normalized integers mapped to [0, 1]', async () => {
    const { doc, root } = newDocument();
    const uv = accessor(doc, 'VEC2', new Uint8Array([0, 0, 255, 0, 0, 51]), true);
    const uv1 = accessor(doc, 'VEC2', new Float32Array([0.25, 0.5, 1, 1, 0, 0]));
    const color = accessor(doc, 'VEC3', new Uint16Array([65535, 0, 0, 0, 65535, 0, 0, 0, 13107]), true);
    root.setMesh(doc.createMesh().addPrimitive(primitive(doc, TRI, [0, 1, 2], { TEXCOORD_0: uv, TEXCOORD_1: uv1, COLOR_0: color })));
    const r = parse(await glbOf(doc));
    // Flat normals: three vertices per triangle, in index order.
    expect(round(r.uv0!)).toEqual([0, 0, 1, 0, 0, 0.2]);
    expect(round(r.uv1!)).toEqual([0.25, 0.5, 1, 1, 0, 0]);
    expect(round(r.colors!)).toEqual([1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 0.2, 1]);
  });
});
