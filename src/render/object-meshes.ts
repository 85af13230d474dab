// The GL mesh each scene object draws with this frame, as frame/mesh-choice.ts chooses it:
// built-ins from their generators, spheres at the tessellation their size on screen needs, loaded
// meshes as given, per face when flat.
// Objects of the same content share one mesh, across every renderer on the context
// (SharedResources, reference-counted); nothing is built or looked up by name in a frame where
// no object changed.
import { Mesh } from './gl/mesh';
import type { ResourceCounter } from './gl/resource-counter';
import type { SharedResources } from './gl/shared-resources';
import { SphereLod } from './sphere-lod';
import { REFLECTION_MAX_FRACTION, reflectionGrid } from '../frame/reflection-lod';
import type { Geometry } from '../scene/scene';
import type { MeshData } from '../scene/geometry/mesh-data';
import type { ObjectMatrices } from '../frame/frame-setup';
import { buildMesh, meshKey } from '../frame/mesh-choice';
import type { FrameState } from '../frame/types';

const NO_TRIANGLES: MeshData = { positions: new Float32Array(0), normals: new Float32Array(0), uvs: new Float32Array(0), indices: new Uint32Array(0) };

interface Slot {
  geometry: Geometry | null;
  flat: boolean;
  key: string | null;
  mesh: Mesh | null;
  lod: SphereLod | null;
  /** The frame `lod` was last updated in: both passes of a frame draw the same tessellation. */
  lodFrame: number;
  /**
   * The reflection's clustered meshes of `key`'s content, by grid, built when first needed and
   * kept (shared) until the content changes; null where clustering saved too little.
   */
  reflection: Map<number, { key: string; mesh: Mesh } | null>;
}

type Extras = typeof import('./mesh-extras');

/** Largest side of a static geometry's own box, computed once per mesh. */
const extents = new WeakMap<object, number>();
function extentOf(g: Geometry, c: Extras): number {
  if (g.kind === 'gaussian') return 2 * c.GAUSSIAN_EXTENT;
  if (g.kind !== 'mesh') return 0;
  let e = extents.get(g.data);
  if (e === undefined) extents.set(g.data, (e = c.meshExtent(g.data.positions)));
  return e;
}

/** Largest scale of a model matrix's linear part (column lengths). */
function maxScale(m: Float64Array): number {
  return Math.sqrt(Math.max(
    m[0] * m[0] + m[1] * m[1] + m[2] * m[2], m[4] * m[4] + m[5] * m[5] + m[6] * m[6], m[8] * m[8] + m[9] * m[9] + m[10] * m[10],
  ));
}

export class ObjectMeshes {
  private readonly slots: Slot[] = [];
  private frame = 0;
  /** This frame's orthographic half-height (0: perspective), for the spheres' size on screen. */
  private orthoHalfHeight = 0;
  /**
   * Flat shading, the Gaussian and the reflection's clustering (mesh-extras.ts), a chunk: loaded
   * by load() the first time a frame needs one. Until then (or if it cannot load) meshes are drawn
   * smooth, Gaussians not at all, reflections with the full meshes.
   */
  private extras: Extras | null = null;
  /** What a Gaussian draws while its generator is not in: nothing. */
  private empty: Mesh | null = null;

  /** The mesh extras' chunk is in (render/parts.ts). */
  setExtras(extras: Extras): void {
    this.extras = extras;
  }

  /**
   * A new frame: spheres choose their tessellation again (once, not once per pass).
   * `orthoHalfHeight`: the orthographic view's half-height, 0 in perspective.
   */
  beginFrame(orthoHalfHeight = 0): void {
    this.frame++;
    this.orthoHalfHeight = orthoHalfHeight;
  }

  constructor(
    private readonly gl: WebGL2RenderingContext, private readonly counter: ResourceCounter, private readonly shared: SharedResources,
  ) {}

  /** Segments of the first sphere drawn (stats), 0 without one. */
  get sphereSegments(): number {
    for (const s of this.slots) if (s.lod) return s.lod.segments;
    return 0;
  }

  /** The mesh object `i` (geometry `g`, world bounds in `m`) draws with this frame. */
  get(i: number, g: Geometry, m: ObjectMatrices, state: FrameState): Mesh {
    const slot = (this.slots[i] ??= { geometry: null, flat: false, key: null, mesh: null, lod: null, lodFrame: -1, reflection: new Map() });
    const ex = this.extras, flat = state.shading === 'flat' && ex !== null;
    if (g.kind === 'sphere') {
      this.release(slot);
      slot.geometry = g;
      const lod = (slot.lod ??= new SphereLod(this.gl, this.counter));
      if (slot.lodFrame === this.frame && lod.mesh) return lod.mesh;
      slot.lodFrame = this.frame;
      return lod.update(state, m.center, m.radius, g.radius, this.orthoHalfHeight, ex && ex.flatMesh);
    }
    if (g.kind === 'gaussian' && !ex) return (this.empty ??= new Mesh(this.gl, this.counter, NO_TRIANGLES));
    if (slot.geometry === g && slot.flat === flat && slot.mesh) return slot.mesh;
    slot.lod?.dispose();
    slot.lod = null;
    const key = flat ? `${meshKey(g)}:flat` : meshKey(g);
    if (key !== slot.key) {
      this.release(slot);
      slot.mesh = this.shared.mesh(key, (counter) => {
        const data = buildMesh(g, 0, ex?.gaussianMesh);
        return new Mesh(this.gl, counter, flat ? ex!.flatMesh(data) : data);
      });
      slot.key = key;
    }
    slot.geometry = g;
    slot.flat = flat;
    return slot.mesh!;
  }

  /**
   * The mesh object `i` draws with in the reflection: with tessellation 'auto', a mesh or
   * Gaussian seen at `pixelsPerUnit` pixels per world unit (at its centre, from the mirrored
   * eye, in the reflection target) draws a clustered copy whose cells span a few pixels
   * (reflection-lod.ts); anything else draws what `get` gives the scene pass.
   */
  mirrored(i: number, g: Geometry, m: ObjectMatrices, state: FrameState, pixelsPerUnit: number): Mesh {
    const full = this.get(i, g, m, state), c = this.extras;
    if (!c || state.tessellation !== 'auto' || (g.kind !== 'mesh' && g.kind !== 'gaussian')) return full;
    const grid = reflectionGrid(extentOf(g, c) * maxScale(m.model), pixelsPerUnit);
    if (grid === 0) return full;
    const slot = this.slots[i];
    let entry = slot.reflection.get(grid);
    if (entry === undefined) {
      const key = `${slot.key}:cluster${grid}`;
      const flat = slot.flat;
      const mesh = this.shared.mesh(key, (counter) => {
        const data = c.clusterMesh(buildMesh(g, 0, c.gaussianMesh), grid);
        return new Mesh(this.gl, counter, flat ? c.flatMesh(data) : data);
      });
      entry = { key, mesh };
      if (mesh.count > REFLECTION_MAX_FRACTION * full.count) {
        this.shared.releaseMesh(key);
        entry = null;
      }
      slot.reflection.set(grid, entry);
    }
    return entry ? entry.mesh : full;
  }

  /** Frees what objects past `count` held (the scene lost objects). */
  trim(count: number): void {
    while (this.slots.length > count) {
      const slot = this.slots.pop()!;
      this.release(slot);
      slot.lod?.dispose();
    }
  }

  dispose(): void {
    this.trim(0);
    this.empty?.dispose();
    this.empty = null;
  }

  private release(slot: Slot): void {
    for (const entry of slot.reflection.values()) if (entry) this.shared.releaseMesh(entry.key);
    slot.reflection.clear();
    if (slot.key === null) return;
    this.shared.releaseMesh(slot.key);
    slot.key = null;
    slot.mesh = null;
  }
}
