// The software renderer's worker (docs/software-renderer.md#worker): draws each requested frame, or its band of rows when
// the frame is split across workers, off the main thread and sends the pixels back (transferred,
// not copied). Meshes and images arrive once and are kept.
/// <reference lib="webworker" />
import { SoftwareRenderer } from './software-renderer';
import { renderBand } from './bands';
import { unpackScene, type SoftwareRequest, type SoftwareResponse } from './protocol';
import type { MeshData } from '../scene/geometry/mesh-data';
import type { DecodedImage } from '../scene/decoded-image';
import type { Scene } from '../scene/scene';
import { environmentReady } from './environment-ready';

const renderer = new SoftwareRenderer();
const meshes = new Map<string, MeshData>();
const images = new Map<string, DecodedImage>();
/** The scene of the last request that carried one (a request without one draws it again). */
let scene: Scene | null = null;
const scope = self as unknown as DedicatedWorkerGlobalScope;

/**
 * While a request waits for the environment's maps (made here once, environment-ready.ts), the requests after it wait
 * behind it, in the order they came; otherwise each is drawn as it arrives.
 */
let waiting: Promise<void> | null = null;

scope.onmessage = (e: MessageEvent<SoftwareRequest>) => {
  const r = e.data;
  // The packed scene has the environment and the materials as they are (only meshes travel apart).
  const ready = r.scene ? environmentReady(r.scene) : null;
  if (ready) waiting = (waiting ?? Promise.resolve()).then(() => ready);
  if (waiting === null) {
    draw(r);
    return;
  }
  const after: Promise<void> = waiting.then(() => draw(r));
  waiting = after;
  void after.then(() => {
    if (waiting === after) waiting = null;
  });
};

function draw(r: SoftwareRequest): void {
  for (const [key, data] of r.meshes) meshes.set(key, data);
  for (const [url, image] of r.images) images.set(url, image);
  let response: SoftwareResponse;
  try {
    if (r.scene) scene = unpackScene(r.scene, meshes);
    if (!scene) throw new Error('no scene sent yet');
    renderer.samplesPerAxis = r.samplesPerAxis;
    const t0 = performance.now();
    const pixels = renderBand(renderer, scene, r.state, images, r.band);
    response = { id: r.id, pixels, width: r.state.width, height: r.state.height, ms: performance.now() - t0 };
    scope.postMessage(response, [pixels.buffer]);
  } catch (err) {
    response = { id: r.id, error: err instanceof Error ? err.message : String(err) };
    scope.postMessage(response);
  }
}
