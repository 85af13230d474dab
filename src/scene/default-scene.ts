// The normative numbers of docs/default-scene.md, in one place: renderer, reference and tests read them here.
// Shared by the reference and both renderers, so each number is tied to docs/default-scene.md by tests that
// write it out: reference-pixels.test.ts (albedos, light, Ka/Kd/Ks, shininess, tint, darkness,
// background, positions), texture.test.ts (512), orthographic.test.ts and reference-scene.test.ts
// (near, far).
import type { Glass, Light, Material, Scene, Vec3 } from './scene';

export const GLASS = {
  /** Plane z = 0 as [nx, ny, nz, d]; the normal points to +Z. */
  plane: [0, 0, 1, 0] as const,
  xMin: -4, xMax: 4, yMin: -1, yMax: 3,
  /** D = tex ⊙ tint ⊙ darkness: the glass body's colour. */
  tint: [0.7, 0.9, 1.0] as const,
  darkness: 0.35,
} as const;

/**
 * tint ⊙ darkness: the glass body's colour before the texture (D = tex ⊙ GLASS_BODY), for all
 * three renderers; reference-pixels.test.ts writes it out by hand.
 */
export const GLASS_BODY: readonly number[] = GLASS.tint.map((c) => c * GLASS.darkness);

export const CUBE = {
  edge: 1,
  /** Centre x, y; z is `cube-distance`. */
  x: -1, y: 1,
  albedo: [0.8, 0.3, 0.3] as const,
} as const;

export const SPHERE = {
  radius: 0.75,
  centre: [1, 1, -1.5] as const,
  albedo: [0.3, 0.8, 0.3] as const,
} as const;

export const BACKGROUND = [0.1, 0.1, 0.1] as const;

const l = Math.hypot(0.4, 1.0, 0.6);
export const LIGHT = {
  /** Unit vector towards the light. */
  direction: [0.4 / l, 1.0 / l, 0.6 / l] as const,
  ambient: 0.15,
  diffuse: 0.85,
  specular: 1.0,
} as const;

export const MATERIAL = { ks: 0.5, shininess: 32 } as const;

/** Near and far (docs/default-scene.md#the-camera): defined with the camera maths, which needs them (math imports no scene). */
export { CAMERA } from '../math/camera';

export const TEXTURE_SIZE = 512;

/** The material of the default objects (docs/default-scene.md#material-and-lighting): Ka = Kd = albedo (⊙ tex), Ks = 0.5, shininess 32. */
export function defaultMaterial(albedo: Vec3): Material {
  const ks = MATERIAL.ks;
  return {
    ambient: albedo, diffuse: albedo, specular: [ks, ks, ks], shininess: MATERIAL.shininess,
    opacity: 1, texture: { kind: 'procedural' }, mapping: 'uv',
  };
}

const NO_ROTATION: Vec3 = [0, 0, 0];
const UNIT_SCALE: Vec3 = [1, 1, 1];

/** The glass of docs/default-scene.md#the-glass as a scene value. */
export const DEFAULT_GLASS: Glass = {
  center: [(GLASS.xMin + GLASS.xMax) / 2, (GLASS.yMin + GLASS.yMax) / 2, 0],
  normal: [GLASS.plane[0], GLASS.plane[1], GLASS.plane[2]],
  size: [GLASS.xMax - GLASS.xMin, GLASS.yMax - GLASS.yMin],
};

/** The light of docs/default-scene.md#the-light as a scene value. */
export const DEFAULT_LIGHT: Light = {
  kind: 'directional', vector: LIGHT.direction,
  ambient: [LIGHT.ambient, LIGHT.ambient, LIGHT.ambient],
  diffuse: [LIGHT.diffuse, LIGHT.diffuse, LIGHT.diffuse],
  specular: [LIGHT.specular, LIGHT.specular, LIGHT.specular],
};

/**
 * The default scene as one value of the scene model (docs/scene-model.md#one-scene-value): the cube at `cubeDistance` turning at
 * `spin` rad/s, the sphere behind the glass, one directional light. With no children the
 * element renders exactly this.
 */
export function defaultScene(cubeDistance: number, spin: number): Scene {
  const half = CUBE.edge / 2;
  return {
    glass: DEFAULT_GLASS,
    objects: [
      {
        geometry: { kind: 'box', size: CUBE.edge },
        transform: { position: [CUBE.x, CUBE.y, cubeDistance], rotation: NO_ROTATION, scale: UNIT_SCALE, spin },
        material: defaultMaterial(CUBE.albedo),
        bounds: { center: [0, 0, 0], radius: Math.sqrt(3) * half },
      },
      {
        geometry: { kind: 'sphere', radius: SPHERE.radius },
        transform: { position: SPHERE.centre, rotation: NO_ROTATION, scale: UNIT_SCALE, spin: 0 },
        material: defaultMaterial(SPHERE.albedo),
        bounds: { center: [0, 0, 0], radius: SPHERE.radius },
      },
    ],
    lights: [DEFAULT_LIGHT],
    background: BACKGROUND,
  };
}

/**
 * The default scene for renderers called without one (the bench, tests): the same value while the
 * cube distance and spin stay, a new one when either changes.
 */
export class DefaultSceneCache {
  private last: { cubeDistance: number; spin: number; scene: Scene } | null = null;

  get(cubeDistance: number, spin: number): Scene {
    const d = this.last;
    if (d && Object.is(d.cubeDistance, cubeDistance) && Object.is(d.spin, spin)) return d.scene;
    this.last = { cubeDistance, spin, scene: defaultScene(cubeDistance, spin) };
    return this.last.scene;
  }
}
