// Counts live GL objects per owner, so tests can see them return to zero after dispose().
import type { ResourceCounts } from '../../frame/types';

export type ResourceKind = keyof ResourceCounts;

export class ResourceCounter {
  readonly counts: ResourceCounts = {
    buffers: 0, textures: 0, framebuffers: 0, renderbuffers: 0, vertexArrays: 0, programs: 0, shaders: 0,
  };

  add(kind: ResourceKind, n = 1): void {
    this.counts[kind] += n;
  }

  get total(): number {
    let t = 0;
    for (const k in this.counts) t += this.counts[k as ResourceKind];
    return t;
  }
}
