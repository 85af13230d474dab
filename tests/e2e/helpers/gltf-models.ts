// glTF models the browser specs serve (docs/gltf.md#test-models): made here with glTF-Transform,
// the same way the unit tests make theirs (tests/unit/helpers/gltf.ts), and validated there.
import { Document, NodeIO, type Material } from '@gltf-transform/core';
import { PNG } from 'pngjs';
import { bunnyMesh } from '../../data/make-obj';

/** A box of half-size `h` around the origin: 24 vertices with their face normals and UVs. */
export function boxArrays(h: number): { positions: Float32Array<ArrayBuffer>; normals: Float32Array<ArrayBuffer>; uvs: Float32Array<ArrayBuffer>; indices: Uint16Array<ArrayBuffer> } {
  const faces: [number[], number[], number[]][] = [
    [[1, 0, 0], [0, 0, -1], [0, 1, 0]], [[-1, 0, 0], [0, 0, 1], [0, 1, 0]], [[0, 1, 0], [1, 0, 0], [0, 0, -1]],
    [[0, -1, 0], [1, 0, 0], [0, 0, 1]], [[0, 0, 1], [1, 0, 0], [0, 1, 0]], [[0, 0, -1], [-1, 0, 0], [0, 1, 0]],
  ];
  const positions: number[] = [], normals: number[] = [], uvs: number[] = [], indices: number[] = [];
  faces.forEach(([n, u, v], f) => {
    for (const [a, b] of [[-1, -1], [1, -1], [1, 1], [-1, 1]]) {
      positions.push(...[0, 1, 2].map((k) => h * (n[k] + a * u[k] + b * v[k])));
      normals.push(...n);
      uvs.push((a + 1) / 2, (1 - b) / 2);
    }
    indices.push(4 * f, 4 * f + 1, 4 * f + 2, 4 * f, 4 * f + 2, 4 * f + 3);
  });
  return { positions: new Float32Array(positions), normals: new Float32Array(normals), uvs: new Float32Array(uvs), indices: new Uint16Array(indices) };
}

/** A 4×4 PNG checker of two colours. */
export function checkerPng(a: [number, number, number], b: [number, number, number]): Uint8Array {
  const png = new PNG({ width: 4, height: 4 });
  for (let i = 0; i < 16; i++) png.data.set([...((((i % 4) + (i >> 2)) % 2) ? a : b), 255], 4 * i);
  return new Uint8Array(PNG.sync.write(png));
}

/** A maker of box meshes of half-size `h` (boxArrays) in `doc`, with positions, normals and UVs in one buffer, and `material`. */
function boxMeshes(doc: Document): (h: number, material: Material) => ReturnType<Document['createMesh']> {
  const buffer = doc.createBuffer();
  return (h, material) => {
    const b = boxArrays(h);
    const acc = (type: 'VEC3' | 'VEC2' | 'SCALAR', a: Float32Array<ArrayBuffer> | Uint16Array<ArrayBuffer>) => doc.createAccessor().setType(type).setArray(a).setBuffer(buffer);
    return doc.createMesh().addPrimitive(doc.createPrimitive().setAttribute('POSITION', acc('VEC3', b.positions))
      .setAttribute('NORMAL', acc('VEC3', b.normals)).setAttribute('TEXCOORD_0', acc('VEC2', b.uvs)).setIndices(acc('SCALAR', b.indices)).setMaterial(material));
  };
}

/**
 * A "product": a box on a plinth — the box textured (an embedded PNG), the plinth a plain red
 * material — in a node hierarchy (a parent scaled and turned, the box moved up inside it).
 */
export async function productGlb(): Promise<Uint8Array> {
  const doc = new Document();
  const mesh = boxMeshes(doc);
  const texture = doc.createTexture('checker').setImage(checkerPng([230, 200, 40], [30, 60, 200])).setMimeType('image/png');
  const boxMaterial = doc.createMaterial('box').setBaseColorTexture(texture).setMetallicFactor(0).setRoughnessFactor(0.5);
  const red = doc.createMaterial('plinth').setBaseColorFactor([0.8, 0.1, 0.1, 1]).setMetallicFactor(0).setRoughnessFactor(0.8);
  const parent = doc.createNode('product').setScale([1.2, 1.2, 1.2]).setRotation([0, Math.sin(Math.PI / 12), 0, Math.cos(Math.PI / 12)]);
  parent.addChild(doc.createNode('plinth').setMesh(mesh(0.5, red)).setScale([1, 0.2, 1]));
  parent.addChild(doc.createNode('box').setMesh(mesh(0.3, boxMaterial)).setTranslation([0, 0.45, 0]));
  doc.createScene('scene').addChild(parent);
  return new NodeIO().writeBinary(doc);
}

/** Area-weighted vertex normals of a triangle mesh (xyz per vertex, faces as index triples), unit. */
export function smoothNormals(positions: ArrayLike<number>, faces: readonly number[][]): Float32Array<ArrayBuffer> {
  const normals = new Float32Array(positions.length);
  for (const [a, b, c] of faces) {
    const u = [0, 1, 2].map((k) => positions[3 * b + k] - positions[3 * a + k]), v = [0, 1, 2].map((k) => positions[3 * c + k] - positions[3 * a + k]);
    const n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    for (const i of [a, b, c]) for (let k = 0; k < 3; k++) normals[3 * i + k] += n[k];
  }
  for (let i = 0; i < normals.length; i += 3) {
    const l = Math.hypot(normals[i], normals[i + 1], normals[i + 2]) || 1;
    for (let k = 0; k < 3; k++) normals[i + k] /= l;
  }
  return normals;
}

/**
 * The Stanford bunny (the `bunny` package) as a GLB "product": smooth normals computed here (area
 * weighted), a gold base colour, a node scaling it to 1.2 units tall and turning it 30° about +Y,
 * standing on y = 0.
 */
export async function bunnyGlb(): Promise<Uint8Array> {
  const { positions, faces: cells } = bunnyMesh();
  const p = Array.from({ length: positions.length / 3 }, (_, i) => [positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]]);
  const normals = smoothNormals(positions, cells);
  const doc = new Document();
  const buffer = doc.createBuffer();
  const acc = (type: 'VEC3' | 'SCALAR', a: Float32Array<ArrayBuffer> | Uint16Array<ArrayBuffer>) => doc.createAccessor().setType(type).setArray(a).setBuffer(buffer);
  const gold = doc.createMaterial('gold').setBaseColorFactor([0.95, 0.64, 0.22, 1]).setMetallicFactor(1).setRoughnessFactor(0.35);
  const prim = doc.createPrimitive().setAttribute('POSITION', acc('VEC3', new Float32Array(p.flat())))
    .setAttribute('NORMAL', acc('VEC3', normals)).setIndices(acc('SCALAR', new Uint16Array(cells.flat()))).setMaterial(gold);
  const s = 1.2 / 9.66;
  const node = doc.createNode('bunny').setMesh(doc.createMesh('bunny').addPrimitive(prim)).setScale([s, s, s])
    .setRotation([0, Math.sin(Math.PI / 12), 0, Math.cos(Math.PI / 12)]).setTranslation([0, 0.003149 * s, 0]);
  doc.createScene('scene').addChild(node);
  return new NodeIO().writeBinary(doc);
}

/**
 * The product's box with a glTF material's other maps (docs/gltf.md#drawing), each a 4×4 PNG checker: metallic-roughness
 * (polished metal against rough dielectric), occlusion (none against 0.35, at strength 0.8), emissive (two colours, on an
 * emissive factor) and normal (tilted either way along u); the base colour a factor. On a plain plinth, turned as the product is.
 */
export async function mapsGlb(): Promise<Uint8Array> {
  const doc = new Document();
  const mesh = boxMeshes(doc);
  const png = (name: string, a: [number, number, number], b: [number, number, number]) => doc.createTexture(name).setImage(checkerPng(a, b)).setMimeType('image/png');
  const box = doc.createMaterial('mapped').setBaseColorFactor([0.9, 0.6, 0.3, 1]).setMetallicFactor(1).setRoughnessFactor(1)
    .setMetallicRoughnessTexture(png('metal rough', [0, 50, 255], [0, 230, 0]))
    .setOcclusionTexture(png('occlusion', [255, 255, 255], [90, 90, 90])).setOcclusionStrength(0.8)
    .setEmissiveTexture(png('emissive', [255, 40, 0], [0, 0, 0])).setEmissiveFactor([0.6, 0.6, 0.6])
    // Tilted half a radian one way and the other along u (the reader computes the tangents: the file has none).
    .setNormalTexture(png('normal', [189, 128, 239], [67, 128, 239]));
  const grey = doc.createMaterial('plinth').setBaseColorFactor([0.5, 0.5, 0.55, 1]).setMetallicFactor(0).setRoughnessFactor(0.6);
  const parent = doc.createNode('product').setScale([1.2, 1.2, 1.2]).setRotation([0, Math.sin(Math.PI / 12), 0, Math.cos(Math.PI / 12)]);
  parent.addChild(doc.createNode('plinth').setMesh(mesh(0.5, grey)).setScale([1, 0.2, 1]));
  parent.addChild(doc.createNode('box').setMesh(mesh(0.3, box)).setTranslation([0, 0.45, 0]));
  doc.createScene('scene').addChild(parent);
  return new NodeIO().writeBinary(doc);
}
