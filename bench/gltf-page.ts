// In-browser half of bench/gltf.spec.ts: a GLB read to arrays by our reader (openGltf,
// decompressGltf, readGltf: what the element's glTF chunk runs) and by three.js's GLTFLoader.parse
// with the same decoders (meshoptimizer's MeshoptDecoder, Draco's decoder through DRACOLoader),
// timed in this page on the main thread, the file already in memory.
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { DRACOLoader } from 'three/examples/jsm/loaders/DRACOLoader.js';
import { MeshoptDecoder } from 'meshoptimizer/decoder';
import * as THREE from 'three';
import { decompressGltf, openGltf, readGltf } from '../src/loaders/gltf';
import '../src/index';

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

/**
 * Load to first frame at 640×360: our element from `src` to `ready` (its fetch, its reader, the
 * glass, reflection and scene drawn); three.js from `load` to a frame of the model rendered (fetch,
 * GLTFLoader, a WebGLRenderer frame with a light, finished by a pixel read). A fresh URL each run:
 * neither page cache serves it.
 */
async function firstFrame(url: string, who: 'ours' | 'three'): Promise<number> {
  const t0 = performance.now();
  if (who === 'ours') {
    const el = document.createElement('glass-plane-scene');
    el.setAttribute('style', 'display:block;width:640px;height:360px');
    el.setAttribute('pixel-ratio', '1');
    el.innerHTML = `<glass-object src="${url}" normalize position="0 1 1"></glass-object>`;
    const ready = new Promise((r) => el.addEventListener('ready', r, { once: true }));
    document.body.append(el);
    await ready;
    const ms = performance.now() - t0;
    el.remove();
    return ms;
  }
  const canvas = document.createElement('canvas');
  document.body.append(canvas);
  const renderer = new THREE.WebGLRenderer({ canvas, antialias: true });
  renderer.setPixelRatio(1);
  renderer.setSize(640, 360, false);
  const gltf = await new Promise<{ scene: THREE.Object3D }>((resolve, reject) => three.load(url, resolve as never, undefined, reject));
  const scene = new THREE.Scene();
  scene.add(gltf.scene, new THREE.HemisphereLight(0xffffff, 0x222222, 1), new THREE.DirectionalLight(0xffffff, 2));
  const box = new THREE.Box3().setFromObject(gltf.scene);
  const camera = new THREE.PerspectiveCamera(60, 640 / 360, 0.01, 1000);
  const centre = box.getCenter(new THREE.Vector3()), size = box.getSize(new THREE.Vector3()).length();
  camera.position.copy(centre).add(new THREE.Vector3(0, size * 0.3, size));
  camera.lookAt(centre);
  renderer.render(scene, camera);
  renderer.getContext().readPixels(0, 0, 1, 1, WebGL2RenderingContext.RGBA, WebGL2RenderingContext.UNSIGNED_BYTE, new Uint8Array(4));
  const ms = performance.now() - t0;
  renderer.dispose();
  canvas.remove();
  return ms;
}

(window as unknown as { __gltf: unknown }).__gltf = { run, firstFrame };
