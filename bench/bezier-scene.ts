// The Bézier row of bench/software.spec.ts: one bicubic patch (a bump with its corners twisted
// into a saddle) under a point light close enough for tight Blinn-Phong highlights, drawn as an
// E×E grid mesh. White 1×1 image texture, so the error measured is the geometry's, not texture
// filtering's. Built the same way in Node (reference, software renderer) and in the page (WebGL).
import { bezierPatchMesh, type BezierPatch } from '../src/scene/geometry/bezier';
import type { DecodedImage } from '../src/scene/decoded-image';
import type { Scene } from '../src/scene/scene';
import type { BenchView } from './views';

const X = [-1.5, -0.5, 0.5, 1.5];
/** Heights of the 4×4 control net: a bump in the middle, opposite corners up and down. */
const Y = [
  [-1.0, 0.0, 0.0, 1.0],
  [0.0, 1.4, 1.4, 0.0],
  [0.0, 1.4, 1.4, 0.0],
  [1.0, 0.0, 0.0, -1.0],
];

export const BEZIER_PATCH: BezierPatch = {
  degreeU: 3,
  degreeV: 3,
  points: Float64Array.from(X.flatMap((x, i) => X.map((z, j) => [x, Y[i][j], z]).flat())),
};

export const WHITE_URL = 'bench:white';
export const WHITE: DecodedImage = { width: 1, height: 1, data: new Uint8ClampedArray([255, 255, 255, 255]) };

export function bezierScene(resolution: number): Scene {
  return {
    glass: null,
    objects: [{
      geometry: { kind: 'mesh', key: `bezier ${resolution}`, data: bezierPatchMesh(BEZIER_PATCH, resolution) },
      transform: { position: [0, 0, 0], rotation: [0, 0, 0], scale: [1, 1, 1], spin: 0 },
      material: {
        ambient: [0.06, 0.06, 0.08], diffuse: [0.75, 0.45, 0.2], specular: [0.9, 0.9, 0.9], shininess: 60, opacity: 1,
        texture: { kind: 'image', url: WHITE_URL }, mapping: 'uv',
      },
      bounds: { center: [0, 0.5, 0], radius: 2.3 },
    }],
    lights: [{ kind: 'point', vector: [0.4, 4, 2.2], ambient: [1, 1, 1], diffuse: [1, 1, 1], specular: [1, 1, 1] }],
    background: [0.1, 0.1, 0.1],
  };
}

const DEG = 180 / Math.PI;
const FROM = [2.7, 2.9, 3.7], TO = [0, 0.1, 0];
const D = [TO[0] - FROM[0], TO[1] - FROM[1], TO[2] - FROM[2]];

export const BEZIER_VIEW: BenchView = {
  name: 'bezier', cameraPosition: [FROM[0], FROM[1], FROM[2]],
  yaw: Math.atan2(D[2], D[0]) * DEG, pitch: Math.asin(D[1] / Math.hypot(D[0], D[1], D[2])) * DEG,
};
