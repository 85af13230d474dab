// In-browser half of bench/gltf.spec.ts: a GLB read to arrays by our reader (openGltf,
// decompressGltf, readGltf: what the element's glTF chunk runs) and by three.js's GLTFLoader.parse
// with the same decoders (meshoptimizer's MeshoptDecoder, Draco's decoder through DRACOLoader),
// timed in this page on the main thread, the file already in memory.
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { DRACOLoader } from 'three/examples/jsm/loaders/DRACOLoader.js';
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import { decompressGltf, openGltf, readGltf } from '../src/loaders/gltf';

// three.js's own copy of Draco's decoder (its wasm build: the page has WebAssembly).
const draco = new DRACOLoader().setDecoderPath('/node_modules/three/examples/jsm/libs/draco/gltf/');
const three = new GLTFLoader().setMeshoptDecoder(MeshoptDecoder).setDRACOLoader(draco);

async function ours(bytes: Uint8Array): Promise<{ ms: number; triangles: number }> {
  const t0 = performance.now();
  const open = openGltf(bytes, 'bench.glb');
  await decompressGltf(open);
  const r = readGltf(open);
  return { ms: performance.now() - t0, triangles: r.indices.length / 3 };
}

async function threeParse(bytes: Uint8Array): Promise<{ ms: number; triangles: number }> {
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
  const t0 = performance.now();
  const gltf = await new Promise<{ scene: { traverse(f: (o: { isMesh?: boolean; geometry?: { index: { count: number } | null } }) => void): void } }>(
    (resolve, reject) => three.parse(buffer, '', resolve as never, reject),
  );
  const ms = performance.now() - t0;
  let triangles = 0;
  gltf.scene.traverse((o) => { if (o.isMesh && o.geometry?.index) triangles += o.geometry.index.count / 3; });
  return { ms, triangles };
}

async function run(url: string, who: 'ours' | 'three'): Promise<{ ms: number; triangles: number }> {
  const bytes = new Uint8Array(await (await fetch(url)).arrayBuffer());
  return who === 'ours' ? ours(bytes) : threeParse(bytes);
}

(window as unknown as { __gltf: unknown }).__gltf = { run };
