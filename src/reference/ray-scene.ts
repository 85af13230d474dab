// A scene ready for rays: one tracer per object at the frame's time, the glass rectangle, the surface codes.
import { glassFrame, type GlassFrame } from '../scene/glass-frame';
import { gaussianMesh } from '../scene/geometry/gaussian';
import type { MeshData } from '../scene/geometry/mesh-data';
import type { Scene, SceneObject } from '../scene/scene';
import { BoxTracer, SphereTracer, type ObjectTracer } from './analytic-tracers';
import { MeshTracer } from './mesh-tracer';
import { ObjectFrame } from './object-frame';
import type { Ray } from './ray';
import { SurfaceCodes } from './surface-codes';
import type { SurfaceHit } from './surface-hit';

/** Gaussian meshes by resolution: the same N gives the same triangles, so one BVH. */
const GAUSSIANS = new Map<number, MeshData>();

function gaussianOf(resolution: number): MeshData {
  let mesh = GAUSSIANS.get(resolution);
  if (mesh === undefined) {
    mesh = gaussianMesh(resolution);
    GAUSSIANS.set(resolution, mesh);
  }
  return mesh;
}

function tracerOf(object: SceneObject, index: number, code: number, time: number): ObjectTracer {
  const frame = new ObjectFrame(object.transform, time);
  const g = object.geometry;
  switch (g.kind) {
    case 'box': return new BoxTracer(frame, g.size, index, code);
    case 'sphere': return new SphereTracer(frame, g.radius, index, code);
    case 'gaussian': return new MeshTracer(frame, gaussianOf(g.resolution), index, code);
    // A glTF material's mesh is single-sided unless it says otherwise (docs/gltf.md#drawing): its back faces are not hit.
    case 'mesh': return new MeshTracer(frame, g.data, index, code, object.material.pbr?.doubleSided === false);
  }
}

export class RayScene {
  readonly tracers: readonly ObjectTracer[];
  readonly codes: SurfaceCodes;
  /** The glass's plane and axes; null when the scene has no glass. */
  readonly glass: GlassFrame | null;
  // Stryker disable next-line ArrayDeclaration: read only when the scene has a glass, and then set from it in the constructor
  private readonly size: readonly [number, number] = [0, 0];

  /** Each object's bounds centre in the world at the frame's time (which side of the glass it is on). */
  readonly centres: readonly Float64Array[];

  constructor(readonly scene: Scene, time: number) {
    this.codes = new SurfaceCodes(scene);
    this.tracers = scene.objects.map((o, i) => tracerOf(o, i, this.codes.first[i], time));
    this.centres = scene.objects.map((o) => {
      const f = new ObjectFrame(o.transform, time), m = f.matrix, c = o.bounds.center, s = f.scale;
      const x = c[0] * s[0], y = c[1] * s[1], z = c[2] * s[2];
      return new Float64Array([m[0] * x + m[4] * y + m[8] * z + m[12], m[1] * x + m[5] * y + m[9] * z + m[13], m[2] * x + m[6] * y + m[10] * z + m[14]]);
    });
    this.glass = scene.glass === null ? null : glassFrame(scene.glass);
    if (scene.glass !== null) this.size = scene.glass.size;
  }

  /**
   * The glass rectangle (two-sided), any t: normal as the scene gives it, u along a and v along
   * b over [0, 1], from the corner c − a·w/2 − b·h/2.
   */
  hitGlass(ray: Ray, hit: SurfaceHit): boolean {
    const g = this.glass;
    if (g === null) return false;
    const [nx, ny, nz, pd] = g.plane;
    const ro = ray.origin, rd = ray.direction;
    const dn = nx * rd[0] + ny * rd[1] + nz * rd[2];
    if (dn === 0) return false;
    const t = -(nx * ro[0] + ny * ro[1] + nz * ro[2] + pd) / dn;
    const x = ro[0] + t * rd[0], y = ro[1] + t * rd[1], z = ro[2] + t * rd[2];
    const c = g.corners[0], a = g.a, b = g.b;
    const [w, h] = this.size;
    const cx = x - c[0], cy = y - c[1], cz = z - c[2];
    const s = cx * a[0] + cy * a[1] + cz * a[2];
    const r = cx * b[0] + cy * b[1] + cz * b[2];
    if (!(s >= 0 && s <= w && r >= 0 && r <= h)) return false;
    hit.surface = this.codes.glass;
    hit.object = -1;
    hit.frame = null;
    hit.t = t;
    hit.p[0] = x; hit.p[1] = y; hit.p[2] = z;
    hit.n[0] = nx; hit.n[1] = ny; hit.n[2] = nz;
    hit.ng[0] = nx; hit.ng[1] = ny; hit.ng[2] = nz;
    hit.u = s / w;
    hit.v = r / h;
    // Stryker disable next-line EqualityOperator: k = 3 writes past the end of gu and gv (Float64Array(3)): dropped
    for (let k = 0; k < 3; k++) {
      hit.gu[k] = a[k] / w;
      hit.gv[k] = b[k] / h;
    }
    return true;
  }
}
