// A row's covered run from the edge functions of raster.ts: where e + k·step ≥ 0 can hold along
// the row, widened by one either side (the exact integer test per pixel still decides).

/** First k ≥ 0 (one early) where e + k·step ≥ 0 can hold; a value past any span when it never can. */
export function runStart(e: number, step: number): number {
  if (step > 0) return e >= 0 ? 0 : Math.ceil(-e / step) - 1;
  return e >= 0 ? 0 : 1 << 30;
}

/** Last k (one late) where e + k·step ≥ 0 can hold, capped at `span`; −1 when it never can. */
export function runEnd(e: number, step: number, span: number): number {
  if (step < 0) return e < 0 ? -1 : Math.min(span, Math.floor(e / -step) + 1);
  return e >= 0 || step > 0 ? span : -1;
}
