// What the element sends the software renderer's worker each frame: the frame state, and the scene
// when it is a new value (the worker keeps the last one), with each mesh's arrays and each image's
// pixels sent once (the worker keeps them by key), not once per frame. Pure data, no DOM.
import type { FrameState } from '../frame/types';
import type { Scene } from '../scene/scene';
import type { MeshData } from '../scene/geometry/mesh-data';
import type { DecodedImage } from '../scene/decoded-image';
import type { Band } from './bands';

export interface SoftwareRequest {
  id: number;
  state: FrameState;
  /**
   * The scene, with `data` of meshes the worker already holds replaced by null; null when it is
   * the value sent before (a frame that only moved the camera or the trackball's turn).
   */
  scene: Scene | null;
  /** Meshes new to the worker, by geometry key. */
  meshes: [string, MeshData][];
  /** Images new to the worker, by URL. */
  images: [string, DecodedImage][];
  /** Samples per pixel along each axis. */
  samplesPerAxis: number;
  /** The rows this worker draws (one band of a frame split across workers); null: the whole frame. */
  band: Band | null;
}

export type SoftwareResponse =
  /** `pixels`: the band's rows (the whole frame's without one); `ms`: the worker's own time for them. */
  | { id: number; pixels: Uint8ClampedArray; width: number; height: number; ms: number }
  | { id: number; error: string };

/** Remembers what a worker holds, so a mesh or an image crosses once. */
export class SentResources {
  private readonly meshes = new Map<string, MeshData>();
  private readonly images = new Set<string>();
  private lastScene: Scene | null = null;

  /** The request's scene (null: the one sent before) and its new meshes and images. */
  pack(scene: Scene, images: ReadonlyMap<string, DecodedImage>): Pick<SoftwareRequest, 'scene' | 'meshes' | 'images'> {
    const newImages: [string, DecodedImage][] = [];
    for (const [url, image] of images) {
      if (this.images.has(url)) continue;
      this.images.add(url);
      newImages.push([url, image]);
    }
    if (scene === this.lastScene) return { scene: null, meshes: [], images: newImages };
    this.lastScene = scene;
    const meshes: [string, MeshData][] = [];
    let stripped = false;
    const objects = scene.objects.map((o) => {
      const g = o.geometry;
      if (g.kind !== 'mesh') return o;
      if (this.meshes.get(g.key) !== g.data) {
        this.meshes.set(g.key, g.data);
        meshes.push([g.key, g.data]);
      }
      stripped = true;
      return { ...o, geometry: { kind: 'mesh' as const, key: g.key, data: null as unknown as MeshData } };
    });
    return { scene: stripped ? { ...scene, objects } : scene, meshes, images: newImages };
  }
}

/** The worker's side: the scene with every mesh's arrays put back from `store`. */
export function unpackScene(scene: Scene, store: ReadonlyMap<string, MeshData>): Scene {
  if (!scene.objects.some((o) => o.geometry.kind === 'mesh')) return scene;
  return {
    ...scene,
    objects: scene.objects.map((o) => {
      const g = o.geometry;
      // Stryker disable next-line ConditionalExpression: without the kind test a box or sphere reads store.get(undefined), which no key is, and is returned as it came
      if (g.kind !== 'mesh' || g.data) return o;
      const data = store.get(g.key);
      return data ? { ...o, geometry: { ...g, data } } : o;
    }),
  };
}
