// Bounding-volume hierarchy over a triangle mesh, float64: binned SAH build, nearest-hit traversal.
// Flat typed arrays only (no per-node objects), so the hot loop touches numbers, not objects.

/** Nearest hit of a ray: parameter t, triangle (index into the mesh's triangle list), barycentrics. */
export class BvhHit {
  t = Infinity;
  triangle = -1;
  /** Weights of the triangle's second and third corners (the first has 1 − b1 − b2). */
  b1 = 0;
  b2 = 0;
}

const BINS = 16;
const LEAF_SIZE = 4;
/** SAH cost of one traversal step relative to one triangle test. */
const TRAVERSAL_COST = 1;

export class Bvh {
  /** Per node: minX, minY, minZ, maxX, maxY, maxZ. */
  readonly bounds: Float64Array;
  /** Per node: [first triangle slot, count] for a leaf (count > 0), [right child, 0] for an inner node (left child = node + 1). */
  readonly nodes: Int32Array;
  /** Triangle slot → triangle index in the mesh. */
  readonly order: Int32Array;
  /** Per slot: v0, e1 = v1 − v0, e2 = v2 − v0 (9 numbers), in slot order. */
  readonly edges: Float64Array;
  readonly nodeCount: number;
  readonly depth: number;
  private readonly stack: Int32Array;

  /** `positions` xyz per vertex, `indices` three per triangle (a trailing partial triangle is ignored). */
  constructor(positions: ArrayLike<number>, indices: ArrayLike<number>) {
    const count = Math.floor(indices.length / 3);
    const box = new Float64Array(count * 6);
    const centre = new Float64Array(count * 3);
    for (let f = 0; f < count; f++) {
      for (let k = 0; k < 3; k++) {
        let lo = Infinity, hi = -Infinity;
        for (let c = 0; c < 3; c++) {
          const x = positions[indices[3 * f + c] * 3 + k];
          if (x < lo) lo = x;
          if (x > hi) hi = x;
        }
        box[f * 6 + k] = lo;
        box[f * 6 + 3 + k] = hi;
        centre[f * 3 + k] = (lo + hi) / 2;
      }
    }
    const order = new Int32Array(count);
    for (let f = 0; f < count; f++) order[f] = f;
    const maxNodes = Math.max(1, 2 * count - 1);
    const bounds = new Float64Array(maxNodes * 6);
    const nodes = new Int32Array(maxNodes * 2);
    const builder = new Builder(box, centre, order, bounds, nodes);
    builder.build(count);
    this.nodeCount = builder.nodeCount;
    this.depth = builder.depth;
    this.bounds = bounds.slice(0, this.nodeCount * 6);
    this.nodes = nodes.slice(0, this.nodeCount * 2);
    this.order = order;
    this.edges = new Float64Array(count * 9);
    for (let s = 0; s < count; s++) {
      const f = order[s];
      const a = indices[3 * f] * 3, b = indices[3 * f + 1] * 3, c = indices[3 * f + 2] * 3;
      for (let k = 0; k < 3; k++) {
        this.edges[s * 9 + k] = positions[a + k];
        this.edges[s * 9 + 3 + k] = positions[b + k] - positions[a + k];
        this.edges[s * 9 + 6 + k] = positions[c + k] - positions[a + k];
      }
    }
    this.stack = new Int32Array(this.depth + 2);
  }

  /**
   * Nearest triangle hit with tMin < t ≤ tMax along o + t·d (both faces, or with `frontOnly` those counter-clockwise as the ray
   * sees them: det = −d·(e1 × e2) > 0); Möller–Trumbore in float64, edges inclusive. Returns false, leaving `hit` as it was, on a miss.
   */
  intersect(
    ox: number, oy: number, oz: number, dx: number, dy: number, dz: number,
    tMin: number, tMax: number, hit: BvhHit, frontOnly = false,
  ): boolean {
    if (this.order.length === 0) return false;
    const { bounds, nodes, edges, stack } = this;
    const ix = 1 / dx, iy = 1 / dy, iz = 1 / dz;
    let best = tMax, found = -1, b1 = 0, b2 = 0;
    let top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const node = stack[--top];
      // Slab test against [tMin, best]; NaN (origin on a slab of a parallel axis) counts as inside.
      const o6 = node * 6;
      let t0 = tMin, t1 = best;
      // Stryker disable ConditionalExpression, EqualityOperator: the survivors widen [t0, t1] or swap equal ends: no kept hit is culled
      let a = (bounds[o6] - ox) * ix, b = (bounds[o6 + 3] - ox) * ix;
      if (a > b) { const s = a; a = b; b = s; }
      if (a > t0) t0 = a;
      if (b < t1) t1 = b;
      a = (bounds[o6 + 1] - oy) * iy; b = (bounds[o6 + 4] - oy) * iy;
      if (a > b) { const s = a; a = b; b = s; }
      if (a > t0) t0 = a;
      if (b < t1) t1 = b;
      a = (bounds[o6 + 2] - oz) * iz; b = (bounds[o6 + 5] - oz) * iz;
      if (a > b) { const s = a; a = b; b = s; }
      if (a > t0) t0 = a;
      if (b < t1) t1 = b;
      if (t0 > t1) continue;
      // Stryker restore ConditionalExpression, EqualityOperator
      const first = nodes[2 * node], n = nodes[2 * node + 1];
      if (n === 0) {
        stack[top++] = first; // right child, visited after the left
        stack[top++] = node + 1;
        continue;
      }
      for (let s = first; s < first + n; s++) {
        const e = s * 9;
        const e1x = edges[e + 3], e1y = edges[e + 4], e1z = edges[e + 5];
        const e2x = edges[e + 6], e2y = edges[e + 7], e2z = edges[e + 8];
        const px = dy * e2z - dz * e2y, py = dz * e2x - dx * e2z, pz = dx * e2y - dy * e2x;
        const det = e1x * px + e1y * py + e1z * pz;
        // Stryker disable next-line ConditionalExpression, LogicalOperator: det 0 or NaN makes u, v, t infinite or NaN: turned down below
        if (det === 0 || det !== det || (frontOnly && det < 0)) continue;
        const inv = 1 / det;
        const sx = ox - edges[e], sy = oy - edges[e + 1], sz = oz - edges[e + 2];
        const u = (sx * px + sy * py + sz * pz) * inv;
        if (u < 0 || u > 1) continue;
        const qx = sy * e1z - sz * e1y, qy = sz * e1x - sx * e1z, qz = sx * e1y - sy * e1x;
        const v = (dx * qx + dy * qy + dz * qz) * inv;
        if (v < 0 || u + v > 1) continue;
        const t = (e2x * qx + e2y * qy + e2z * qz) * inv;
        if (t > tMin && t <= best) {
          best = t; found = s; b1 = u; b2 = v;
        }
      }
    }
    if (found < 0) return false;
    hit.t = best;
    hit.triangle = this.order[found];
    hit.b1 = b1;
    hit.b2 = b2;
    return true;
  }
}

/** Top-down binned SAH build with an explicit work list; nodes in depth-first order (left child = node + 1). */
class Builder {
  nodeCount = 0;
  depth = 0;
  private readonly binBox = new Float64Array(BINS * 6);
  private readonly binCount = new Int32Array(BINS);
  private readonly rightArea = new Float64Array(BINS);
  private readonly rightCount = new Int32Array(BINS);

  constructor(
    private readonly box: Float64Array, private readonly centre: Float64Array, private readonly order: Int32Array,
    private readonly bounds: Float64Array, private readonly nodes: Int32Array,
  ) {}

  build(count: number): void {
    if (count === 0) {
      this.nodeCount = 1;
      this.bounds.set([Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity], 0);
      this.nodes[0] = 0; this.nodes[1] = 0;
      return;
    }
    // Work items: [node, first, count, depth, parent]. A left child is numbered when pushed (it is
    // popped next, so it lands at parent + 1); a right child (node −1) when popped, after the whole
    // left subtree, and its parent then learns its index.
    const work: number[] = [];
    this.nodeCount = 1;
    work.push(0, 0, count, 1, -1);
    while (work.length > 0) {
      const parent = work.pop()!;
      const depth = work.pop()!;
      const n = work.pop()!;
      const first = work.pop()!;
      let node = work.pop()!;
      if (parent >= 0) {
        node = this.nodeCount++;
        this.nodes[2 * parent] = node;
      }
      if (depth > this.depth) this.depth = depth;
      this.fitBounds(node, first, n);
      const split = n > LEAF_SIZE ? this.split(node, first, n) : -1;
      if (split < 0) {
        this.nodes[2 * node] = first;
        this.nodes[2 * node + 1] = n;
        continue;
      }
      const left = this.nodeCount++;
      work.push(-1, split, first + n - split, depth + 1, node);
      work.push(left, first, split - first, depth + 1, -1);
      this.nodes[2 * node + 1] = 0;
    }
  }

  private fitBounds(node: number, first: number, n: number): void {
    const b = this.bounds, o = node * 6;
    b[o] = b[o + 1] = b[o + 2] = Infinity;
    b[o + 3] = b[o + 4] = b[o + 5] = -Infinity;
    for (let s = first; s < first + n; s++) {
      const f = this.order[s] * 6;
      for (let k = 0; k < 3; k++) {
        if (this.box[f + k] < b[o + k]) b[o + k] = this.box[f + k];
        if (this.box[f + 3 + k] > b[o + 3 + k]) b[o + 3 + k] = this.box[f + 3 + k];
      }
    }
  }

  /** Partitions [first, first + n) by the cheapest binned SAH plane; returns the split slot, or −1 for a leaf. */
  private split(node: number, first: number, n: number): number {
    const { centre, order } = this;
    let bestCost = Infinity, bestAxis = -1, bestBin = -1;
    let cMin = 0, cScale = 0, bestMin = 0, bestScale = 0;
    for (let axis = 0; axis < 3; axis++) {
      cMin = Infinity;
      let cMax = -Infinity;
      for (let s = first; s < first + n; s++) {
        const c = centre[order[s] * 3 + axis];
        if (c < cMin) cMin = c;
        if (c > cMax) cMax = c;
      }
      // Stryker disable next-line ConditionalExpression, EqualityOperator: at cMax = cMin every bin index is NaN: no bin filled, no split
      if (!(cMax > cMin)) continue;
      cScale = BINS / (cMax - cMin);
      const cost = this.bestBinSplit(first, n, axis, cMin, cScale);
      if (cost.cost < bestCost) {
        bestCost = cost.cost; bestAxis = axis; bestBin = cost.bin; bestMin = cMin; bestScale = cScale;
      }
    }
    if (bestAxis < 0) return -1; // every centroid in one point: nothing to split
    const leafCost = n;
    const parentArea = area(this.bounds, node * 6);
    if (parentArea > 0 && TRAVERSAL_COST + bestCost / parentArea >= leafCost && n <= 4 * LEAF_SIZE) return -1;
    // Partition in place: bins ≤ bestBin go left.
    let i = first, j = first + n - 1;
    while (i <= j) {
      const bin = Math.min(BINS - 1, Math.floor((centre[order[i] * 3 + bestAxis] - bestMin) * bestScale));
      if (bin <= bestBin) i++;
      else { const t = order[i]; order[i] = order[j]; order[j] = t; j--; }
    }
    if (i === first || i === first + n) return first + (n >> 1); // cannot happen with cMax > cMin; guards the build
    return i;
  }

  /** Cheapest split between bins along `axis`: Σ area·count of the two sides (not yet divided by the parent's area). */
  private bestBinSplit(first: number, n: number, axis: number, cMin: number, cScale: number): { cost: number; bin: number } {
    const { binBox, binCount, rightArea, rightCount, box, centre, order } = this;
    binCount.fill(0);
    for (let k = 0; k < BINS; k++) {
      binBox[k * 6] = binBox[k * 6 + 1] = binBox[k * 6 + 2] = Infinity;
      binBox[k * 6 + 3] = binBox[k * 6 + 4] = binBox[k * 6 + 5] = -Infinity;
    }
    for (let s = first; s < first + n; s++) {
      const f = order[s];
      const bin = Math.min(BINS - 1, Math.floor((centre[f * 3 + axis] - cMin) * cScale));
      binCount[bin]++;
      const o = bin * 6;
      for (let k = 0; k < 3; k++) {
        if (box[f * 6 + k] < binBox[o + k]) binBox[o + k] = box[f * 6 + k];
        if (box[f * 6 + 3 + k] > binBox[o + 3 + k]) binBox[o + 3 + k] = box[f * 6 + 3 + k];
      }
    }
    // Sweep from the right: rightArea[k] = area of bins k+1.., rightCount likewise.
    const acc = new Float64Array([Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity]);
    let cnt = 0;
    for (let k = BINS - 1; k > 0; k--) {
      grow(acc, binBox, k * 6);
      cnt += binCount[k];
      rightArea[k - 1] = cnt > 0 ? area(acc, 0) : 0;
      rightCount[k - 1] = cnt;
    }
    acc.set([Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity]);
    cnt = 0;
    let best = Infinity, bestBin = -1;
    for (let k = 0; k < BINS - 1; k++) {
      grow(acc, binBox, k * 6);
      cnt += binCount[k];
      if (cnt === 0 || rightCount[k] === 0) continue;
      const cost = area(acc, 0) * cnt + rightArea[k] * rightCount[k];
      if (cost < best) { best = cost; bestBin = k; }
    }
    return { cost: best, bin: bestBin };
  }
}

function grow(acc: Float64Array, b: Float64Array, o: number): void {
  for (let k = 0; k < 3; k++) {
    if (b[o + k] < acc[k]) acc[k] = b[o + k];
    if (b[o + 3 + k] > acc[3 + k]) acc[3 + k] = b[o + 3 + k];
  }
}

/** Half the surface area of a box (the SAH needs only ratios); 0 for an empty one. */
function area(b: Float64Array, o: number): number {
  const x = b[o + 3] - b[o], y = b[o + 4] - b[o + 1], z = b[o + 5] - b[o + 2];
  if (!(x >= 0 && y >= 0 && z >= 0)) return 0;
  return x * y + y * z + z * x;
}
