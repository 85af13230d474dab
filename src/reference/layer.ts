// The sample tracer's per-level buffers: each transparency layer of a path keeps its own hits and colours.
import { SurfaceHit } from './surface-hit';

/** Per transparency layer, for one path (direct or mirrored): its hits and colour buffers. */
export class Layer {
  readonly a = new SurfaceHit();
  readonly b = new SurfaceHit();
  readonly glass = new SurfaceHit();
  /** The colour of this layer's ray segment (written by the layer above). */
  readonly colour = new Float64Array(3);
  readonly behind = new Float64Array(3);
  readonly reflection = new Float64Array(3);
  readonly tex = new Float64Array(3);
}
