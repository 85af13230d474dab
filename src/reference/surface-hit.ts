// One ray–surface intersection, with what shading, texturing and the footprint need to know.
import type { ObjectFrame } from './object-frame';

/** Surface code of "nothing": the background. */
export const SURFACE_NONE = 0;

/**
 * Where (p, world), the unit shading normal facing the viewer's side for meshes (n), the normal
 * the texture footprint is projected on (ng: the true surface normal; = n for box and sphere),
 * the object-space point and normal the mapping modes read (q, nq), the geometry's own texture
 * coordinates (u, v) and their world gradients (gu, gv; only their tangent components matter).
 */
export class SurfaceHit {
  /** Surface code (SurfaceCodes): which object, and which face of a box. */
  surface = SURFACE_NONE;
  /** Index into the scene's objects; −1 for the glass. */
  object = -1;
  /** The object's frame (object ↔ world); null for the glass. */
  frame: ObjectFrame | null = null;
  t = Infinity;
  readonly p = new Float64Array(3);
  readonly n = new Float64Array(3);
  readonly ng = new Float64Array(3);
  readonly q = new Float64Array(3);
  readonly nq = new Float64Array(3);
  u = 0;
  v = 0;
  readonly gu = new Float64Array(3);
  readonly gv = new Float64Array(3);
  /** A mesh's tangent where it has them (MeshData.tangents): world, unit, and w the bitangent's side (0: none). */
  readonly tangent = new Float64Array(4);
  /** A mesh's vertex colour at the hit (MeshData.colors); white where it has none. */
  readonly color = new Float64Array([1, 1, 1]);
  /** n was turned to face the viewer (a two-sided mesh seen from its back). */
  flipped = false;
}
