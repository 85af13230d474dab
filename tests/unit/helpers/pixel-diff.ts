// Counting what differs between two frames (RGBA8, 4 bytes a pixel), for unit and browser tests alike.

/** Bytes of `a` that differ from `b` at the same index (every index of `a` is compared). */
export function differingBytes(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let n = 0;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) n++;
  return n;
}

/** Pixels of `a` (4 bytes each) whose red, green or blue differs from `b`'s; alpha is not compared. */
export function differingPixels(a: ArrayLike<number>, b: ArrayLike<number>): number {
  let n = 0;
  for (let i = 0; i < a.length; i += 4) if (a[i] !== b[i] || a[i + 1] !== b[i + 1] || a[i + 2] !== b[i + 2]) n++;
  return n;
}
