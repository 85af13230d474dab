// The element's own scene value, frame state and images, brought out of the page for the float64 reference: what a test of
// "drawn as the reference draws the element's scene value" compares the element's picture with.
import type { Page } from '@playwright/test';
import { PNG } from 'pngjs';
import type { DecodedImage } from '../../../src/reference';
import { materialImages, type Scene, type SceneObject } from '../../../src/scene/scene';
import type { FrameState } from '../../../src/frame/types';
import { defaultFrameState } from '../../unit/helpers/frame-state';

interface JsonMesh { kind: 'mesh'; key: string; data: Record<string, number[]> }

/**
 * The scene value of the page's `glass-plane-scene` (meshes as typed arrays again), its camera as a frame state of
 * width × height (`over` on top), and every image its materials name, decoded in Node (PNG).
 */
export async function elementScene(page: Page, width: number, height: number, over: Partial<FrameState> = {}): Promise<{ scene: Scene; state: FrameState; images: Map<string, DecodedImage> }> {
  const { scene, view } = await page.evaluate(() => {
    const el = document.querySelector('glass-plane-scene') as unknown as {
      scene: Scene; cameraPosition: number[]; cameraRotation: number[]; fov: number; transparency: number; ior: number;
    };
    const s = el.scene;
    const objects = s.objects.map((o) => {
      if (o.geometry.kind !== 'mesh') return o;
      const d = o.geometry.data;
      return { ...o, geometry: { ...o.geometry, data: { positions: [...d.positions], normals: [...d.normals], uvs: [...d.uvs], indices: [...d.indices], tangents: d.tangents ? [...d.tangents] : undefined } } };
    });
    // An environment image's texels as a plain array (made a Float32Array again below).
    const environment = s.environment?.kind === 'image' ? { ...s.environment, image: { ...s.environment.image, rgb: [...s.environment.image.rgb] } } : s.environment;
    return { scene: { ...s, objects, ...(environment ? { environment } : {}) } as unknown as Scene, view: { position: el.cameraPosition, rotation: el.cameraRotation, fov: el.fov, transparency: el.transparency, ior: el.ior } };
  });
  const objects = scene.objects.map((o): SceneObject => {
    if (o.geometry.kind !== 'mesh') return o;
    const g = o.geometry as unknown as JsonMesh;
    const data = {
      positions: new Float32Array(g.data.positions), normals: new Float32Array(g.data.normals), uvs: new Float32Array(g.data.uvs), indices: new Uint32Array(g.data.indices),
      ...(g.data.tangents ? { tangents: new Float32Array(g.data.tangents) } : {}),
    };
    return { ...o, geometry: { kind: 'mesh', key: g.key, data } };
  });
  const images = new Map<string, DecodedImage>();
  for (const url of new Set(objects.flatMap((o) => materialImages(o.material)))) {
    const png = PNG.sync.read(Buffer.from(await page.evaluate((u) => fetch(u).then((r) => r.arrayBuffer()).then((b) => [...new Uint8Array(b)]), url)));
    images.set(url, { width: png.width, height: png.height, data: new Uint8ClampedArray(png.data) });
  }
  const state = defaultFrameState({
    width, height, spin: 0, transparency: view.transparency, ior: view.ior, fov: view.fov,
    cameraPosition: view.position as [number, number, number], yaw: view.rotation[0], pitch: view.rotation[1], ...over,
  });
  const env = scene.environment;
  const environment = env?.kind === 'image' ? { ...env, image: { ...env.image, rgb: new Float32Array(env.image.rgb) } } : env;
  return { scene: { ...scene, objects, ...(environment ? { environment } : {}) }, state, images };
}
