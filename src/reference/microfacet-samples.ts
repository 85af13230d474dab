// The Monte Carlo over microfacet normals (docs/rough-glass.md#reference-monte-carlo): per pixel, M pairs (ξ1, ξ2) stratified in each
// dimension (N-rooks: one sample in each of M strata of ξ1 and of ξ2, paired by a shuffle and
// jittered inside its stratum), from a hash of the pixel, so every frame is the same frame.

export class MicrofacetSamples {
  readonly xi1: Float64Array;
  readonly xi2: Float64Array;
  private readonly order: Int32Array;
  private readonly slot: Int32Array;

  constructor(readonly count: number) {
    this.xi1 = new Float64Array(count);
    this.xi2 = new Float64Array(count);
    this.order = new Int32Array(count);
    this.slot = new Int32Array(count);
  }

  /** Fills the pairs for pixel `pixel` (any integer): deterministic, different per pixel. */
  fill(pixel: number): void {
    const m = this.count, order = this.order, slot = this.slot;
    const seed = hash(pixel >>> 0);
    let counter = 0;
    // Counter-based: the k-th number of a pixel is hash(seed + k), uniform in [0, 1).
    const next = () => hash((seed + counter++) >>> 0) / 4294967296;
    // Stryker disable next-line EqualityOperator: order[m] is past the end of an Int32Array of length m: the write is dropped
    for (let i = 0; i < m; i++) order[i] = i;
    // Fisher–Yates: which ξ2 stratum goes with the i-th ξ1 stratum.
    for (let i = m - 1; i > 0; i--) {
      const j = Math.floor(next() * (i + 1));
      const t = order[i]; order[i] = order[j]; order[j] = t;
    }
    // A second shuffle decides which primary sample takes which pair.
    // Stryker disable next-line EqualityOperator: slot[m] is past the end of an Int32Array of length m: the write is dropped
    for (let i = 0; i < m; i++) slot[i] = i;
    for (let i = m - 1; i > 0; i--) {
      const j = Math.floor(next() * (i + 1));
      const t = slot[i]; slot[i] = slot[j]; slot[j] = t;
    }
    // Stryker disable next-line EqualityOperator: at i = m, slot[m] is undefined: no element of xi1 or xi2 is written
    for (let i = 0; i < m; i++) {
      this.xi1[slot[i]] = (i + next()) / m;
      this.xi2[slot[i]] = (order[i] + next()) / m;
    }
  }
}

/** A 32-bit integer hash (lowbias32, Wellons), as an unsigned number. */
export function hash(x: number): number {
  x = (x ^ (x >>> 16)) >>> 0;
  x = Math.imul(x, 0x7feb352d) >>> 0;
  x = (x ^ (x >>> 15)) >>> 0;
  x = Math.imul(x, 0x846ca68b) >>> 0;
  return (x ^ (x >>> 16)) >>> 0;
}

/** A counter-based stream of numbers in [0, 1): the k-th after `restart(key)` is hash(hash(key) + k), so every frame is the same frame. */
export class HashStream {
  private seed = 0;
  private counter = 0;

  restart(key: number): void {
    this.seed = hash(key >>> 0);
    this.counter = 0;
  }

  readonly next = (): number => hash((this.seed + this.counter++) >>> 0) / 4294967296;
}
