// The orthographic projection (docs/interaction.md#orthographic-projection) for FrameSetup: a part of its own (docs/package.md#chunks), loaded
// only by a renderer whose frames ask for `projection="orthographic"` (the software renderer's
// chunk has it always). Without it FrameSetup draws in perspective; the element holds such a
// frame until it is in (Renderer.load).
import type { ReadonlyVec3 } from 'gl-matrix';
import { reflectDirection, type Plane } from '../math/mirror';
import { CAMERA } from '../math/camera';
import { orthoHalfHeight, orthographicMatrix, type OrthoView } from '../math/orthographic';

/** What orthographicView writes: FrameSetup's fields of the same names. */
export interface OrthographicTarget {
  halfHeight: number;
  readonly projection: Float64Array;
  readonly viewVectorMain: Float32Array;
  readonly viewVectorMirrored: Float32Array;
}

const towardsViewer = new Float64Array(3);

/**
 * The orthographic half-height and projection of `s` (sized at its target, else at
 * `glassCenter`), and each eye's constant view vector: (−forward, 0), mirrored in `plane` for
 * the mirrored camera.
 */
export function orthographicView(
  out: OrthographicTarget, s: OrthoView, glassCenter: ReadonlyVec3 | null, forward: ReadonlyVec3, plane: Plane, aspect: number,
): void {
  out.halfHeight = orthoHalfHeight(s, glassCenter);
  orthographicMatrix(out.projection, out.halfHeight, aspect, CAMERA.near, CAMERA.far);
  const vm = out.viewVectorMain, vr = out.viewVectorMirrored, t = towardsViewer;
  vm[0] = t[0] = -forward[0];
  vm[1] = t[1] = -forward[1];
  vm[2] = t[2] = -forward[2];
  vm[3] = 0;
  reflectDirection(t, t, plane);
  vr[0] = t[0]; vr[1] = t[1]; vr[2] = t[2]; vr[3] = 0;
}

export type OrthographicView = typeof orthographicView;
