// Orthographic projection (docs/interaction.md#orthographic-projection): its size, its matrix, the mirrored orthographic camera,
// the side it sees, and the sizes on screen the level-of-detail rules read.
// Each broken on purpose once and seen red: FrameSetup's side by the eye's position (the clip
// test), the mirrored view vector left unmirrored (the view-vector test; no e2e figure moves
// enough to see it: only the reflected highlights change), sphereScreenRadius ignoring the
// orthographic half-height (the sizes test), the target's distance taken for its depth (the
// target across the ray), the glass centre taken before the target (the target along the ray).
import { describe, expect, it } from 'vitest';
import { apply, expectClose } from './helpers/math';
import { forwardFromYawPitch, viewerSide } from '../../src/math/camera';
import { MIN_ORTHO_DEPTH, orthoHalfHeight, orthographicMatrix, type OrthoView } from '../../src/math/orthographic';
import { orthographicView } from '../../src/frame/orthographic-view';
import { MIRROR_CONTACT, reflectDirection, reflectPoint, type Plane } from '../../src/math/mirror';
import { FrameSetup } from '../../src/frame/frame-setup';
import { sphereScreenRadius } from '../../src/frame/sphere-screen';
import { orthoPixelsPerUnit } from '../../src/frame/reflection-lod';
import { defaultScene } from '../../src/scene/default-scene';
import type { FrameState } from '../../src/frame/types';
import { defaultFrameState } from './helpers/frame-state';
import type { Scene } from '../../src/scene/scene';

const TAN30 = Math.tan(Math.PI / 6);

function state(overrides: Partial<FrameState> = {}): FrameState {
  return defaultFrameState({ time: 1.25, colorSpace: 'none', samples: 0, projection: 'orthographic', ...overrides });
}

describe('orthoHalfHeight', () => {
  const looking = (overrides: Partial<OrthoView>): OrthoView =>
    ({ cameraPosition: [0, 1, 5], yaw: -90, pitch: 0, fov: 60, ...overrides });

  it('is depth·tan(fov/2) at the glass centre when there is no target', () => {
    expect(orthoHalfHeight(looking({}), [0, 1, 0])).toBeCloseTo(5 * TAN30, 12);
    // Depth is along the view direction, not the distance: a centre off to the side counts its depth only.
    expect(orthoHalfHeight(looking({}), [3, -2, 0])).toBeCloseTo(5 * TAN30, 12);
  });

  it('uses the target when one is set, the origin when there is neither', () => {
    expect(orthoHalfHeight(looking({ target: [0, 1, 2] }), [0, 1, 0])).toBeCloseTo(3 * TAN30, 12);
    expect(orthoHalfHeight(looking({ target: null }), null)).toBeCloseTo(5 * TAN30, 12);
    expect(orthoHalfHeight(looking({ cameraPosition: [0, 0, 7] }), null)).toBeCloseTo(7 * TAN30, 12);
  });

  it('follows the fov and the pitch', () => {
    expect(orthoHalfHeight(looking({ fov: 90 }), [0, 1, 0])).toBeCloseTo(5, 12);
    // Looking down 60° from (0, 1, 5) at the origin-ish point (0, 1, 0): depth 5·cos 60.
    expect(orthoHalfHeight(looking({ pitch: -60 }), [0, 1, 0])).toBeCloseTo(2.5 * TAN30, 12);
  });

  it('never reaches zero: a point at or behind the eye is taken at the near distance', () => {
    expect(orthoHalfHeight(looking({ target: [0, 1, 5] }), null)).toBeCloseTo(MIN_ORTHO_DEPTH * TAN30, 15);
    expect(orthoHalfHeight(looking({ target: [0, 1, 50] }), null)).toBeCloseTo(MIN_ORTHO_DEPTH * TAN30, 15);
    expect(MIN_ORTHO_DEPTH).toBe(0.1);
  });

  it('gives the default view the size the perspective view has at the glass centre', () => {
    const s = state();
    const f = forwardFromYawPitch(new Float64Array(3), s.yaw, s.pitch);
    const e = s.cameraPosition;
    const depth = (0 - e[0]) * f[0] + (1 - e[1]) * f[1] + (0 - e[2]) * f[2];
    expect(depth).toBeGreaterThan(3.5);
    expect(orthoHalfHeight(s, [0, 1, 0])).toBeCloseTo(depth * TAN30, 12);
  });
});

describe('orthographicMatrix', () => {
  it('maps the view box to the NDC cube, keeps w = 1 and is the same at every depth', () => {
    const m = orthographicMatrix(new Float64Array(16), 2, 1.5, 0.1, 100);
    expectClose(apply(m, [3, 2, -0.1]), [1, 1, -1, 1]);
    expectClose(apply(m, [-3, -2, -100]), [-1, -1, 1, 1]);
    // The same x, y at another depth lands on the same pixel: no perspective divide.
    const a = apply(m, [1, 0.5, -1]), b = apply(m, [1, 0.5, -60]);
    expect(a[0]).toBe(b[0]);
    expect(a[1]).toBe(b[1]);
    expect(a[3]).toBe(1);
  });
});

describe('viewerSide', () => {
  const floor: Plane = [0, 1, 0, 0];

  it('perspective: the side the eye stands on (on the plane counts as +)', () => {
    expect(viewerSide(floor, [0, 2, 0], [0, -1, 0], 'perspective')).toBe(1);
    expect(viewerSide(floor, [0, -2, 0], [0, -1, 0], 'perspective')).toBe(-1);
    expect(viewerSide(floor, [0, 0, 0], [0, 1, 0], 'perspective')).toBe(1);
  });

  it('orthographic: the side the view comes from, wherever the eye is', () => {
    const down = [0, -Math.sin(0.3), -Math.cos(0.3)];
    // Eye below the floor, looking down at it: its upper rays meet the floor from above.
    expect(viewerSide(floor, [0, -1, 0], down, 'orthographic')).toBe(1);
    expect(viewerSide(floor, [0, 5, 0], [0, 1, 0], 'orthographic')).toBe(-1);
    // Edge-on (view direction in the plane): the eye's side, as in perspective.
    expect(viewerSide(floor, [0, -1, 0], [0, 0, -1], 'orthographic')).toBe(-1);
  });
});

/** Clip coordinates of world point `p` through one eye's glass matrices (the glass model is the identity). */
function clip(setup: FrameSetup, eye: 'main' | 'mirrored', p: ArrayLike<number>): Float64Array {
  const m = eye === 'main' ? setup.glassMain : setup.glassMirrored;
  return apply(m.modelViewProjection, p);
}

describe('the mirrored orthographic camera (FrameSetup)', () => {
  const s = state();
  const scene = defaultScene(s.cubeDistance, s.spin);
  const setup = new FrameSetup(null, orthographicView);
  setup.update(s, scene);
  const plane = setup.glass.plane;

  it('is orthographic too: w = 1 for every point, either eye', () => {
    for (const p of [[-1, 1, 0.75], [1, 1, -1.5], [0, 3, 0], [2, 0, 4]]) {
      expect(clip(setup, 'main', p)[3]).toBeCloseTo(1, 6);
      expect(clip(setup, 'mirrored', p)[3]).toBeCloseTo(1, 6);
    }
    expect(setup.orthographic).toBe(true);
    expect(setup.halfHeight).toBeCloseTo(orthoHalfHeight(s, [0, 1, 0]), 12);
  });

  it('sees a point where the real camera sees its mirror image, and a glass point where the real one does', () => {
    for (const p of [[-1, 1, 0.75], [0.3, 2.2, 1.9], [2, 0.5, 0.2]]) {
      const image = reflectPoint(new Float64Array(3), p, plane);
      expectClose(clip(setup, 'mirrored', p), clip(setup, 'main', image), 1e-5);
    }
    const glassPoint = [1.5, 2, 0];
    expectClose(clip(setup, 'mirrored', glassPoint), clip(setup, 'main', glassPoint), 1e-5);
    // The glass pass looks the reflection up with the mirrored camera's glass matrix.
    expectClose(apply(setup.reflectionViewProjection, glassPoint), clip(setup, 'main', glassPoint), 1e-5);
  });

  it('has the constant view vector, mirrored: −forward for the eye, its reflection for the mirrored eye', () => {
    const f = forwardFromYawPitch(new Float64Array(3), s.yaw, s.pitch);
    expectClose(setup.viewVectorMain, [-f[0], -f[1], -f[2], 0], 1e-7);
    const r = reflectDirection(new Float64Array(3), [-f[0], -f[1], -f[2]], plane);
    expectClose(setup.viewVectorMirrored, [r[0], r[1], r[2], 0], 1e-7);
  });

  it('perspective keeps V towards the eye: uViewVector (0, 0, 0, 1) for both eyes', () => {
    const p = new FrameSetup(null, orthographicView);
    p.update(state({ projection: undefined }), scene);
    expect(p.orthographic).toBe(false);
    expect(p.halfHeight).toBe(0);
    expect([...p.viewVectorMain]).toEqual([0, 0, 0, 1]);
    expect([...p.viewVectorMirrored]).toEqual([0, 0, 0, 1]);
    // Perspective divides: w is the depth (the cube's centre lies deeper than the sphere's).
    expect(clip(p, 'main', [-1, 1, 0.75])[3]).toBeGreaterThan(clip(p, 'main', [1, 1, -1.5])[3] + 1);
  });

  it('clips exactly at the glass, keeping the side the view comes from even with the eye behind the plane', () => {
    // A glass floor; the eye 1 below it, looking down 30° at it: it sees the floor's top.
    const floorScene: Scene = { ...scene, glass: { center: [0, 0, 0], normal: [0, 1, 0], size: [8, 8] } };
    const low = new FrameSetup(null, orthographicView);
    low.update(state({ cameraPosition: [0, -1, 6], yaw: -90, pitch: -30 }), floorScene);
    expect(low.eyeDistance).toBeLessThan(0);
    expect(low.side).toBe(1);
    // uClipPlane is in mirrored-eye-relative coordinates: above the floor is kept, below is not.
    const keep = (p: number[]) => {
      const c = low.clipPlane, e = low.mirroredEye;
      return c[0] * (p[0] - e[0]) + c[1] * (p[1] - e[1]) + c[2] * (p[2] - e[2]) + c[3];
    };
    // Kept where side·d ≥ MIRROR_CONTACT: what touches the glass is not reflected.
    expect(keep([0.5, 1, 0])).toBeCloseTo(1 - MIRROR_CONTACT, 6);
    expect(keep([0.5, -1, 0])).toBeCloseTo(-1 - MIRROR_CONTACT, 6);
    expect(keep([3, 0, -2])).toBeCloseTo(-MIRROR_CONTACT, 6);
    expect(keep([3, 0, -2])).toBeLessThan(0);
    expect(keep([3, 2 * MIRROR_CONTACT, -2])).toBeGreaterThan(0);
  });
});

describe('a camera-target moving along the view ray (FrameSetup)', () => {
  // The eye at (0, 1, 5) looks down 30° along −Z: forward f = (0, −1/2, −√3/2), right (1, 0, 0),
  // up (0, √3/2, −1/2). The target starts 4 along f: depth 4, half-height 4·tan 30°.
  const eye: [number, number, number] = [0, 1, 5];
  const S3 = Math.sqrt(3);
  const along = (depth: number, right = 0, up = 0): [number, number, number] =>
    [right, 1 - depth / 2 + up * S3 / 2, 5 - depth * S3 / 2 - up / 2];
  const halfHeight = (target: [number, number, number]) => {
    const s = state({ cameraPosition: eye, yaw: -90, pitch: -30, target });
    const setup = new FrameSetup(null, orthographicView);
    setup.update(s, defaultScene(s.cubeDistance, s.spin));
    return setup.halfHeight;
  };

  it('grows by k·tan(fov/2) when the target moves k further along the ray, and shrinks as it comes nearer', () => {
    expect(halfHeight(along(4))).toBeCloseTo(4 * TAN30, 12);
    expect(halfHeight(along(6))).toBeCloseTo(6 * TAN30, 12);
    expect(halfHeight(along(1.5))).toBeCloseTo(1.5 * TAN30, 12);
  });

  it('keeps its size when the target moves across the ray (right and up), its depth unchanged', () => {
    expect(halfHeight(along(4, 3, 0))).toBeCloseTo(4 * TAN30, 12);
    expect(halfHeight(along(4, 0, 2))).toBeCloseTo(4 * TAN30, 12);
    expect(halfHeight(along(4, -3, 2))).toBeCloseTo(4 * TAN30, 12);
  });
});

describe('sizes on screen in orthographic', () => {
  it('a sphere is radius·height/(2·halfHeight) pixels wherever it is', () => {
    const s = state();
    expect(sphereScreenRadius(s, [1, 1, -1.5], 0.75, 2)).toBeCloseTo(0.75 * 360 / 4, 9);
    expect(sphereScreenRadius(s, [1, 1, -40], 0.75, 2)).toBeCloseTo(0.75 * 360 / 4, 9);
    // Without a half-height it is the perspective size, which shrinks with distance.
    expect(sphereScreenRadius(s, [1, 1, -40], 0.75)).toBeLessThan(sphereScreenRadius(s, [1, 1, -1.5], 0.75));
    expect(orthoPixelsPerUnit(360, 2)).toBe(90);
  });
});
