// How big the reader's lists will get, guessed from a few samples of the bytes, so a big file
// fills lists of about the right size instead of doubling them a dozen times (each doubling
// a copy, and a garbage collection its allocation calls for). A guess only: a list too small
// still grows, one too large wastes at most the guess's excess.

/** Samples spread over the file, and the bytes each reads. */
const SAMPLES = 16;
const SAMPLE_BYTES = 4096;
/** Below this, no guess: the lists' default sizes are as good. */
const SMALL = SAMPLES * SAMPLE_BYTES * 4;
/** A guess this much over the sampled rate: most files are a little uneven. */
const MARGIN = 1.1;

export interface Capacities {
  positions: number;
  uvs: number;
  normals: number;
  /** Face corners. */
  corners: number;
  /** Ints: 3 per triangle. */
  triangles: number;
  /** Ints of the face list: one per face, two per polygon (raw.ts). */
  faces: number;
}

/** The lists' lengths for the whole file, from the lines of SAMPLES windows; null for a small file. */
export function estimateCapacities(b: Uint8Array): Capacities | null {
  if (b.length < SMALL) return null;
  const count = { v: 0, vt: 0, vn: 0, f: 0, corners: 0, polygons: 0, polygonCorners: 0, sampled: 0 };
  const stride = Math.floor((b.length - SAMPLE_BYTES) / (SAMPLES - 1));
  // Stryker disable next-line EqualityOperator: a 17th window starts at 16·stride ≥ b.length (b.length ≥ SMALL): it counts no line
  for (let s = 0; s < SAMPLES; s++) sampleLines(b, s * stride, s * stride + SAMPLE_BYTES, count);
  if (count.sampled === 0) return null;
  const scale = (MARGIN * b.length) / count.sampled;
  const corners = Math.ceil(count.corners * scale);
  return {
    positions: 3 * Math.ceil(count.v * scale),
    uvs: 2 * Math.ceil(count.vt * scale),
    normals: 3 * Math.ceil(count.vn * scale),
    corners,
    // A polygon of n corners is n − 2 triangles; a face of 3 is none (raw.ts).
    triangles: 3 * Math.max(0, Math.ceil(count.polygonCorners * scale) - 2 * Math.ceil(count.polygons * scale)),
    faces: Math.ceil((count.f + count.polygons) * scale),
  };
}

interface Counts {
  v: number;
  vt: number;
  vn: number;
  f: number;
  corners: number;
  /** Faces of more than 3 corners, and their corners. */
  polygons: number;
  polygonCorners: number;
  /** Bytes of the lines counted. */
  sampled: number;
}

/** Counts the statements of the whole lines that start in `from` .. `to`. */
function sampleLines(b: Uint8Array, from: number, to: number, count: Counts): void {
  let p = from;
  // Stryker disable next-line EqualityOperator: p ≤ to only goes on to to + 1 in a window with no line start: no line counted
  if (p > 0) while (p < to && b[p - 1] !== 10) p++; // the first line start in the window
  const first = p;
  while (p < to) {
    let end = p;
    const last = Math.min(b.length, to + SAMPLE_BYTES);
    // Stryker disable next-line EqualityOperator: with no \n before last, end stops at last or last + 1: both break below
    while (end < last && b[end] !== 10) end++;
    if (end >= last) break; // a line running past the sample (or the file's last): not counted
    const c0 = b[p], c1 = b[p + 1];
    if (c0 === 118 /* v */ && c1 === 32) count.v++;
    else if (c0 === 118 && c1 === 116 /* t */) count.vt++;
    else if (c0 === 118 && c1 === 110 /* n */) count.vn++;
    else if (c0 === 102 /* f */ && c1 === 32) {
      count.f++;
      let n = 0;
      // Stryker disable next-line ArithmeticOperator,EqualityOperator: q = p − 1, q = end read \n (or none), f, \n too: no space
      for (let q = p + 1; q < end; q++) if (b[q] === 32 && b[q + 1] > 32) n++;
      count.corners += n;
      if (n > 3) {
        count.polygons++;
        count.polygonCorners += n;
      }
    }
    p = end + 1;
  }
  count.sampled += p - first;
}
