// Pareto front over (time, error), with noise bands: a row is dominated when another is no
// slower (within the timing noise), no less accurate (within the PSNR tolerance), and
// better beyond the noise in at least one of the two. Differences inside the bands are
// not told apart, so two rows that differ only by noise both stay on the front.

export interface ParetoPoint {
  /** Median ms per frame. */
  ms: number;
  /** Timing spread (e.g. the interquartile range), ms. */
  noise: number;
  /** Accuracy, dB: higher is better. */
  psnr: number;
}

/** PSNR differences smaller than this are not told apart. */
export const PSNR_TOLERANCE_DB = 0.1;

export function dominates(a: ParetoPoint, b: ParetoPoint): boolean {
  const noise = Math.max(a.noise, b.noise);
  const noSlower = a.ms <= b.ms + noise;
  const noWorse = a.psnr >= b.psnr - PSNR_TOLERANCE_DB;
  const faster = a.ms < b.ms - noise;
  const better = a.psnr > b.psnr + PSNR_TOLERANCE_DB;
  return noSlower && noWorse && (faster || better);
}

/** For each point: true when nothing dominates it. */
export function paretoFront(points: readonly ParetoPoint[]): boolean[] {
  return points.map((p) => !points.some((q) => q !== p && dominates(q, p)));
}
