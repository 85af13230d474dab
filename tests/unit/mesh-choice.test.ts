// Which mesh each object draws with: one chooser for both renderers, so the WebGL and the
// software renderer draw the same sphere in every view (orthographic 'auto' included).
import { describe, expect, it, vi } from 'vitest';
import { fakeGl } from './helpers/fake-gl';
import { Renderer } from '../../src/render/renderer';
import { SoftwareRenderer } from '../../src/software';
import { ObjectShader } from '../../src/software/object-shader';
import { segmentsForScreenRadius, sphereMesh } from '../../src/scene/geometry/sphere';
import { buildMesh, isTwoSided, meshKey, sphereSegments } from '../../src/frame/mesh-choice';
import { AUTO_SILHOUETTE_ERROR_PX, sphereScreenRadius } from '../../src/frame/sphere-screen';
import { BACKGROUND, DEFAULT_GLASS, DEFAULT_LIGHT } from '../../src/scene/default-scene';
import type { Scene } from '../../src/scene/scene';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from './helpers/frame-state';

const STATE: FrameState = defaultFrameState({
  width: 320, height: 180, spin: 0, cameraPosition: [0, 1, 6], yaw: -90, pitch: 0, colorSpace: 'none', view: 'scene', samples: 0,
});

/** One sphere of radius 1 before the glass, at the origin of its own frame. */
const SCENE: Scene = {
  glass: DEFAULT_GLASS, lights: [DEFAULT_LIGHT], background: BACKGROUND,
  objects: [{
    geometry: { kind: 'sphere', radius: 1 },
    material: { ambient: [0.2, 0.2, 0.2], diffuse: [0.8, 0.8, 0.8], specular: [0.5, 0.5, 0.5], shininess: 32, opacity: 1, texture: { kind: 'none' }, mapping: 'uv' },
    transform: { position: [0, 1, 1], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
    bounds: { center: [0, 0, 0], radius: 1 },
  }],
};

/** The WebGL renderer's sphere segments for `state` (its stats), on a stand-in context, with the parts it loads for it. */
async function webglSegments(state: FrameState): Promise<number> {
  const r = new Renderer(fakeGl().gl);
  await r.load(SCENE, state);
  r.render(SCENE, state);
  const n = r.stats.sphereSegments;
  r.dispose();
  return n;
}

/** Index count of the sphere mesh the software renderer drew `state` with. */
function softwareIndices(state: FrameState): number {
  const seen: number[] = [];
  const spy = vi.spyOn(ObjectShader.prototype, 'render').mockImplementation(function (d) { seen.push(d.mesh.indices.length); });
  try {
    new SoftwareRenderer().render(SCENE, state);
  } finally {
    spy.mockRestore();
  }
  expect(new Set(seen).size, 'one sphere mesh per frame').toBe(1);
  return seen[0];
}

describe('the sphere\'s tessellation, WebGL and software alike', () => {
  it('here the orthographic view needs fewer segments than the perspective one (24, 28): the half-height counts', async () => {
    expect(await webglSegments({ ...STATE, projection: 'perspective' })).toBe(28);
    expect(await webglSegments({ ...STATE, projection: 'orthographic' })).toBe(24);
  });

  for (const projection of ['perspective', 'orthographic'] as const) {
    it(`${projection}, tessellation auto: the software renderer draws the sphere WebGL draws`, async () => {
      const state = { ...STATE, projection };
      const segments = await webglSegments(state);
      expect(softwareIndices(state), `${segments} segments`).toBe(sphereMesh(1, segments).indices.length);
    });
  }
});

describe('sphereSegments', () => {
  const centre = [0, 1, 1], r = 1;
  const wanted = segmentsForScreenRadius(sphereScreenRadius(STATE, centre, r), AUTO_SILHOUETTE_ERROR_PX);

  it('a number asked for is taken as it is, whatever the mesh in hand', () => {
    expect(sphereSegments({ ...STATE, tessellation: 12 }, centre, r, 0, 1, 64)).toBe(12);
  });

  it('auto: the segments the size on screen needs; a mesh in hand is kept up to twice that', () => {
    expect(wanted).toBe(28);
    expect(sphereSegments(STATE, centre, r, 0)).toBe(wanted);
    expect(sphereSegments(STATE, centre, r, 0, 1, 2 * wanted)).toBe(2 * wanted);
    expect(sphereSegments(STATE, centre, r, 0, 1, 2 * wanted + 4)).toBe(wanted);
    expect(sphereSegments(STATE, centre, r, 0, 1, wanted - 4)).toBe(wanted);
  });

  it('on a grid of 2 samples per pixel, the segments of a sphere twice the size', () => {
    const big = segmentsForScreenRadius(2 * sphereScreenRadius(STATE, centre, r), AUTO_SILHOUETTE_ERROR_PX);
    expect(big).toBeGreaterThan(wanted);
    expect(sphereSegments(STATE, centre, r, 0, 2)).toBe(big);
  });
});

describe('meshKey and buildMesh', () => {
  it('name the content: equal geometry, equal key; a sphere\'s segments are part of it', () => {
    expect(meshKey({ kind: 'box', size: 1 })).toBe(meshKey({ kind: 'box', size: 1 }));
    expect(meshKey({ kind: 'box', size: 1 })).not.toBe(meshKey({ kind: 'box', size: 2 }));
    expect(meshKey({ kind: 'sphere', radius: 1 }, 16)).not.toBe(meshKey({ kind: 'sphere', radius: 1 }, 20));
    expect(meshKey({ kind: 'gaussian', resolution: 40 })).not.toBe(meshKey({ kind: 'box', size: 40 }));
  });

  it('build a sphere at its segments, and hand a loaded mesh back as it is', () => {
    expect(buildMesh({ kind: 'sphere', radius: 1 }, 16).indices.length).toBe(sphereMesh(1, 16).indices.length);
    const data = sphereMesh(1, 8);
    expect(buildMesh({ kind: 'mesh', key: 'k', data })).toBe(data);
  });

  it('only meshes from files and the Gaussian are two-sided', () => {
    expect([isTwoSided({ kind: 'box', size: 1 }), isTwoSided({ kind: 'sphere', radius: 1 })]).toEqual([false, false]);
    expect([isTwoSided({ kind: 'gaussian', resolution: 4 }), isTwoSided({ kind: 'mesh', key: 'k', data: sphereMesh(1, 8) })]).toEqual([true, true]);
  });
});
