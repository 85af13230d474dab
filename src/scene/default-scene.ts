// The normative numbers of SPEC §3, in one place: renderer, reference and tests read them here.

export const GLASS = {
  /** Plane z = 0 as [nx, ny, nz, d]; the normal points to +Z. */
  plane: [0, 0, 1, 0] as const,
  xMin: -4, xMax: 4, yMin: -1, yMax: 3,
  /** D = tex ⊙ tint ⊙ darkness: the glass body's colour. */
  tint: [0.7, 0.9, 1.0] as const,
  darkness: 0.35,
} as const;

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

export const CAMERA = { near: 0.1, far: 100 } as const;

export const TEXTURE_SIZE = 512;
