// Scenes for the renderer page: a Scene value made JSON-safe (mesh typed arrays as plain arrays),
// and the page's pixels back as an RgbaImage.
import type { Page } from '@playwright/test';
import type { Scene } from '../../../src/scene/scene';
import type { FrameState } from '../../../src/frame/types';
import type { RgbaImage } from './golden';

export function sceneToJson(scene: Scene): Scene {
  return {
    ...scene,
    objects: scene.objects.map((o) => {
      if (o.geometry.kind !== 'mesh') return o;
      const d = o.geometry.data;
      const data = { positions: [...d.positions], normals: [...d.normals], uvs: [...d.uvs], indices: [...d.indices], ...(d.tangents ? { tangents: [...d.tangents] } : {}), ...(d.colors ? { colors: [...d.colors] } : {}) };
      return { ...o, geometry: { ...o.geometry, data: data as unknown as typeof d } };
    }),
    ...(scene.environment?.kind === 'image'
      ? { environment: { ...scene.environment, image: { ...scene.environment.image, rgb: [...scene.environment.image.rgb] as unknown as Float32Array } } }
      : {}),
  };
}

export async function openRendererPage(page: Page): Promise<void> {
  await page.goto('/tests/e2e/pages/renderer.html');
  await page.waitForFunction(() => '__renderer' in window, undefined, { timeout: 30_000 });
}

export type Images = Record<string, { width: number; height: number; rgba: number[] }>;

/** `state.view` of `scene` drawn by the Renderer in the page. */
export async function drawScene(page: Page, state: FrameState, scene: Scene, images: Images = {}): Promise<RgbaImage> {
  const b64 = await page.evaluate(
    ({ state, scene, images }) => (window as unknown as { __renderer: { draw(s: unknown, sc: unknown, i: unknown): Promise<string> } }).__renderer.draw(state, scene, images),
    { state, scene: sceneToJson(scene), images },
  );
  const buf = Buffer.from(b64, 'base64');
  return { width: state.width, height: state.height, data: new Uint8Array(buf.buffer, buf.byteOffset, buf.length) };
}

/** The picture a still view of `frames` refinement frames of `scene` ends with, drawn by the Renderer in the page. */
export async function refineScene(page: Page, state: FrameState, scene: Scene, frames: number): Promise<RgbaImage> {
  const b64 = await page.evaluate(
    ({ state, scene, frames }) => (window as unknown as { __renderer: { refine(s: unknown, sc: unknown, n: number): Promise<string> } }).__renderer.refine(state, scene, frames),
    { state, scene: sceneToJson(scene), frames },
  );
  const buf = Buffer.from(b64, 'base64');
  return { width: state.width, height: state.height, data: new Uint8Array(buf.buffer, buf.byteOffset, buf.length) };
}
