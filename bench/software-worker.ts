// The bench's software-renderer worker: the same SoftwareRenderer as src/software/worker.ts, but
// it reports its own render time (and, when asked, the renderer's phase split), so the bench can
// tell the worker's work from the round trip. Scenes are named, not sent: built here.
/// <reference lib="webworker" />
import { SoftwareRenderer, type SoftwareTiming } from '../src/software';
import type { FrameState } from '../src/frame/types';
import { BENCH_SCENES } from './scenes';

export interface BenchWorkerRequest {
  id: number;
  /** null: the default scene; else an index into BENCH_SCENES. */
  scene: number | null;
  state: FrameState;
  samplesPerAxis: number;
  /** Fill a SoftwareTiming (constant fragments or shaded) for this frame. */
  timing: { constantFragments: boolean } | null;
}

export interface BenchWorkerResponse {
  id: number;
  renderMs: number;
  timing: SoftwareTiming | null;
}

const renderer = new SoftwareRenderer();
const scope = self as unknown as DedicatedWorkerGlobalScope;

scope.onmessage = (e: MessageEvent<BenchWorkerRequest>) => {
  const r = e.data;
  renderer.samplesPerAxis = r.samplesPerAxis;
  const timing: SoftwareTiming | null = r.timing ? { vertex: 0, triangles: 0, glass: 0, total: 0, constantFragments: r.timing.constantFragments } : null;
  renderer.timing = timing;
  const t0 = performance.now();
  // Copied as the element's worker does, so the work is the same.
  const pixels = renderer.render(r.scene === null ? null : BENCH_SCENES[r.scene].scene, r.state).slice();
  const renderMs = performance.now() - t0;
  renderer.timing = null;
  const response: BenchWorkerResponse = { id: r.id, renderMs, timing };
  scope.postMessage(response);
  void pixels;
};
