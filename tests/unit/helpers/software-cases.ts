// The software renderer's test scenes (docs/software-renderer.md): the cases software-reference.test.ts compares
// with the float64 reference (with the figures measured there) and software-baseline.test.ts
// holds to the bit, at 160×90.
import { BACKGROUND, DEFAULT_GLASS, DEFAULT_LIGHT, defaultScene } from '../../../src/scene/default-scene';
import type { Geometry, Material, Scene, SceneObject } from '../../../src/scene/scene';
import type { FrameState } from '../../../src/frame/types';
import type { DecodedImage } from '../../../src/reference';
import { bezierPatchMesh } from '../../../src/scene/geometry/bezier';
import { defaultFrameState } from './frame-state';
import { courseBasis, type CourseCamera } from '../../../src/math/course-camera';

/** A bicubic Bézier bump (docs/software-renderer.md#bezier-surfaces) at E = 40, as the course's .byu loader makes it. */
function bezierBump() {
  const points: number[] = [];
  for (let i = 0; i <= 3; i++) for (let j = 0; j <= 3; j++) {
    const inner = i > 0 && i < 3 && j > 0 && j < 3;
    points.push(-1.2 + 0.8 * i, inner ? 1.6 : (i + j) % 2 ? 0.3 : 0, -1.2 + 0.8 * j);
  }
  return bezierPatchMesh({ degreeU: 3, degreeV: 3, points }, 40);
}

/** PSNR in dB measured per region (null: the region is empty, as the glass without a glass). */
export interface Figures {
  all: number;
  objects: number;
  glass: number | null;
  background: number;
  edges: number;
  /** Pixels whose reference is below 32/255 in every channel (the banding region, docs/colour.md#eight-bit-targets), in any class. */
  dark?: number | null;
}

export const STATE: FrameState = defaultFrameState({ width: 160, height: 90, time: 1.25, colorSpace: 'none', samples: 0 });

const MATTE: Material = {
  ambient: [0.2, 0.2, 0.2], diffuse: [0.8, 0.8, 0.8], specular: [0.5, 0.5, 0.5], shininess: 32, opacity: 1,
  texture: { kind: 'procedural' }, mapping: 'uv',
};

function object(geometry: Geometry, position: [number, number, number], material: Partial<Material> = {}, over: Partial<SceneObject> = {}): SceneObject {
  return {
    geometry, material: { ...MATTE, ...material }, bounds: { center: [0, 0, 0], radius: 1 },
    transform: { position, rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 }, ...over,
  };
}

/** An 8×8 RGBA checker of two colours with a red top-left texel (orientation shows). */
function checkerImage(): DecodedImage {
  const w = 8, h = 8, data = new Uint8Array(w * h * 4);
  for (let y = 0; y < h; y++) {
    for (let x = 0; x < w; x++) {
      const i = 4 * (y * w + x), light = ((x >> 1) + (y >> 1)) % 2 === 0;
      data.set(x === 0 && y === 0 ? [255, 0, 0, 255] : light ? [230, 200, 90, 255] : [40, 90, 160, 255], i);
    }
  }
  return { width: w, height: h, data };
}
export const IMAGES = new Map([['checker.png', checkerImage()]]);

/** A square pyramid (apex up, open base), UVs per face corner, normals per face: hand-made. */
function pyramid(): Geometry {
  const apex = [0, 1, 0];
  const base = [[-1, 0, -1], [1, 0, -1], [1, 0, 1], [-1, 0, 1]];
  const positions: number[] = [], normals: number[] = [], uvs: number[] = [], indices: number[] = [];
  for (let f = 0; f < 4; f++) {
    const a = base[f], b = base[(f + 1) % 4];
    const e1 = [b[0] - a[0], b[1] - a[1], b[2] - a[2]], e2 = [apex[0] - a[0], apex[1] - a[1], apex[2] - a[2]];
    const n = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]];
    const len = Math.hypot(n[0], n[1], n[2]);
    const k = positions.length / 3;
    for (const [p, uv] of [[a, [0, 0]], [b, [1, 0]], [apex, [0.5, 1]]] as const) {
      positions.push(...p);
      normals.push(n[0] / len, n[1] / len, n[2] / len);
      uvs.push(...uv);
    }
    indices.push(k, k + 1, k + 2);
  }
  return {
    kind: 'mesh', key: 'pyramid',
    data: { positions: new Float32Array(positions), normals: new Float32Array(normals), uvs: new Float32Array(uvs), indices: new Uint16Array(indices) },
  };
}

export interface Case {
  name: string;
  scene: Scene;
  state?: Partial<FrameState>;
  /** What `npx vitest run tests/unit/software-reference.test.ts` prints for it. */
  measured: Figures;
}

const glassScene = (objects: SceneObject[], lights = [DEFAULT_LIGHT]): Scene => ({ glass: DEFAULT_GLASS, objects, lights, background: BACKGROUND });

export const CASES: Case[] = [
  { name: 'default scene', scene: defaultScene(0.75, 0.8), measured: { all: 55.1, objects: 58.0, glass: 58.3, background: 54.2, edges: 51.5 } },
  // Orthographic (docs/interaction.md#orthographic-projection): F and the highlights from the view's direction, not from the eye
  // point (that way, as this renderer drew it before: objects 25.6 dB, glass 34.9).
  { name: 'default scene, orthographic', scene: defaultScene(0.75, 0.8), state: { projection: 'orthographic' }, measured: { all: 53.8, objects: 53.1, glass: 58.4, background: 54.2, edges: 51.5 } },
  {
    name: 'Gaussian (resolution 40)',
    measured: { all: 56.5, objects: 56.3, glass: 58.8, background: 54.2, edges: 55.3 },
    scene: glassScene([object({ kind: 'gaussian', resolution: 40 }, [0, 0.3, 1.2], { diffuse: [0.2, 0.5, 0.9] },
      { transform: { position: [0, 0.3, 1.2], rotation: [0, 20, 0], scale: [0.8, 1.2, 0.8], spin: 0 }, bounds: { center: [0, 0, 0], radius: 2.9 } })]),
  },
  {
    name: 'textured mesh (image texture)',
    measured: { all: 56.8, objects: 58.8, glass: 58.9, background: 54.2, edges: 57.0 },
    scene: glassScene([object(pyramid(), [0.5, 0.2, 1.2], { texture: { kind: 'image', url: 'checker.png' }, diffuse: [0.9, 0.9, 0.9] },
      { transform: { position: [0.5, 0.2, 1.2], rotation: [0, 30, 0], scale: [0.9, 1.4, 0.9], spin: 0 }, bounds: { center: [0, 0.5, 0], radius: 1.5 } })]),
  },
  {
    // On the line from the default eye (3.6, 2.4, 0.2) to the box: the sphere covers its middle.
    name: 'half-transparent sphere in front of an opaque box, no glass',
    measured: { all: 54.2, objects: 57.2, glass: null, background: 54.2, edges: 53.4 },
    scene: {
      glass: null, lights: [DEFAULT_LIGHT], background: BACKGROUND,
      objects: [
        object({ kind: 'box', size: 1.2 }, [-1, 0.8, -0.5], { diffuse: [0.8, 0.3, 0.3], ambient: [0.8, 0.3, 0.3] }),
        object({ kind: 'sphere', radius: 0.6 }, [1.2, 1.6, -0.1], { opacity: 0.5, diffuse: [0.3, 0.8, 0.3], ambient: [0.3, 0.8, 0.3] }),
      ],
    },
  },
  {
    // Seen from the front: one transparent sphere between the eye and the glass (blended over
    // the glass, as the reference sorts it), one straddling the glass plane.
    name: 'half-transparent spheres in front of and across the glass',
    measured: { all: 57.2, objects: 57.5, glass: 58.8, background: 54.2, edges: 56.0 },
    state: { cameraPosition: [0.5, 1.2, 4], yaw: -90, pitch: -5 },
    scene: glassScene([
      object({ kind: 'box', size: 1 }, [-1, 1, -1], { diffuse: [0.8, 0.3, 0.3], ambient: [0.8, 0.3, 0.3] }),
      object({ kind: 'sphere', radius: 0.5 }, [0.8, 0.8, 1.3], { opacity: 0.5, diffuse: [0.3, 0.3, 0.9], ambient: [0.3, 0.3, 0.9] }),
      object({ kind: 'sphere', radius: 0.4 }, [-1.6, 0.3, 0.1], { opacity: 0.4, diffuse: [0.9, 0.8, 0.2], ambient: [0.9, 0.8, 0.2] }),
    ]),
  },
  {
    name: 'a bicubic Bézier surface (E = 40) before the glass',
    measured: { all: 55.9, objects: 56.0, glass: 58.9, background: 54.2, edges: 53.4 },
    scene: glassScene([object({ kind: 'mesh', key: 'bezier-bump', data: bezierBump() }, [0.3, 0.2, 1.3], { diffuse: [0.9, 0.6, 0.3] },
      { transform: { position: [0.3, 0.2, 1.3], rotation: [0, 25, 0], scale: [0.7, 0.7, 0.7], spin: 0 }, bounds: { center: [0, 0.6, 0], radius: 1.8 } })]),
  },
  {
    name: 'triplanar, cylindrical and spherical mappings, a point light',
    measured: { all: 52.1, objects: 46.6, glass: 58.8, background: 54.2, edges: 45.8 },
    scene: glassScene([
      object({ kind: 'box', size: 0.9 }, [-1.2, 0.8, 1.2], { mapping: 'triplanar' },
        { transform: { position: [-1.2, 0.8, 1.2], rotation: [20, 35, 0], scale: [1, 1, 1], spin: 0 }, bounds: { center: [0, 0, 0], radius: 0.78 } }),
      object({ kind: 'sphere', radius: 0.5 }, [0.3, 0.7, 1.4], { mapping: 'cylindrical' }, { bounds: { center: [0, 0, 0], radius: 0.5 } }),
      object({ kind: 'sphere', radius: 0.5 }, [1.2, 1.2, -1.0], { mapping: 'spherical', texture: { kind: 'image', url: 'checker.png' } },
        { transform: { position: [1.2, 1.2, -1.0], rotation: [0, 0, 30], scale: [1, 1, 1], spin: 0 }, bounds: { center: [0, 0, 0], radius: 0.5 } }),
    ], [DEFAULT_LIGHT, { kind: 'point', vector: [1, 2.5, 2], ambient: [0, 0, 0], diffuse: [0.5, 0.4, 0.3], specular: [0.6, 0.6, 0.6] }]),
  },
];

/** The course's camera the CPU renderers' tests draw with: from (3.6, 2.4, 4) towards (0, 1, 0), a 1.2 × 1 window at d = 1. */
export function courseCamera(): CourseCamera {
  const basis = courseBasis([-3.6, -1.4, -4], [0, 1, 0]);
  if (typeof basis === 'string') throw new Error(basis);
  return { c: [3.6, 2.4, 4], ...basis, d: 1, hx: 0.6, hy: 0.5 };
}
