// The timing harness: SoftwareRenderer.render() in plain Node (no worker, no copy), the
// default scene at 640×360 with the clock moving so the cube turns, samples 0 and 4 × srgb and
// none, and with the camera turning too (nothing as in the frame before: no glass cache), as
// bench/software.spec.ts's Node rows (same state, same medians), without Playwright, so
// `node --cpu-prof` can profile it. Not a test: nothing is asserted. Beside the wall-clock median
// it gives the process's CPU time per frame (all threads), which a shared machine's load
// disturbs less: on 2 cores under a load of 2 a frame waits for a core as well; and the fastest
// frame, the least disturbed. Bundle and run:
//   npx rolldown bench/software-node.ts --platform node --format esm --file /tmp/sw-node.mjs \
//     && node /tmp/sw-node.mjs [reps] [frames]
// `ROW=0 node --cpu-prof --cpu-prof-dir=/tmp/prof /tmp/sw-node.mjs 3 20` profiles samples 0, srgb alone. With
// `hash` as the first argument it prints a digest of each row's pixels at fixed times instead.
import { createHash } from 'node:crypto';
import { loadavg } from 'node:os';
import { DEFAULT_CAMERA_ROTATION, DEFAULT_CUBE_DISTANCE } from '../src/element/attributes';
import type { ColorSpace, FrameState } from '../src/frame/types';
import { defaultFrameState } from '../tests/unit/helpers/frame-state';
import { defaultScene } from '../src/scene/default-scene';
import { SoftwareRenderer } from '../src/software';
import { shuffled, summary } from './stats';

const SIZE = { width: 640, height: 360 };
const START = 1.25;
const WARMUP = 4;

/** `turning`: the camera's yaw moves 0.05° a frame as well, so nothing is as in the frame before. */
function state(time: number, colorSpace: ColorSpace, samples: FrameState['samples'], turning = false): FrameState {
  return defaultFrameState({
    width: SIZE.width, height: SIZE.height, time, yaw: DEFAULT_CAMERA_ROTATION[0] + (turning ? 3 * time : 0), colorSpace, samples,
  });
}

type Row = [FrameState['samples'], ColorSpace, boolean?];
const ALL_ROWS: Row[] = [[0, 'srgb'], [4, 'srgb'], [0, 'none'], [4, 'none'], [0, 'srgb', true], [4, 'srgb', true]];
const key = ([samples, cs, turning]: Row) => `samples ${samples}, ${cs}${turning ? ', camera turning' : ''}`;
/** ROW=0 (…3) keeps one row of ALL_ROWS, for a profile of that row alone. */
const ROWS = process.env.ROW === undefined ? ALL_ROWS : [ALL_ROWS[Number(process.env.ROW)]];

function timing(reps: number, frames: number): void {
  const scene = defaultScene(DEFAULT_CUBE_DISTANCE, 0.8);
  const r = new SoftwareRenderer();
  const times = new Map<string, number[]>(), cpu = new Map<string, number[]>();
  let frame = 0;
  const before = loadavg()[0];
  for (let rep = 0; rep < reps; rep++) {
    for (const row of shuffled(ROWS, 71 + rep)) {
      const next = () => r.render(scene, state(START + frame++ / 60, row[1], row[0], row[2]));
      for (let i = 0; i < WARMUP; i++) next();
      const xs = times.get(key(row)) ?? [], cs = cpu.get(key(row)) ?? [];
      for (let i = 0; i < frames; i++) {
        const c0 = process.cpuUsage(), t0 = performance.now();
        next();
        xs.push(performance.now() - t0);
        const c = process.cpuUsage(c0);
        cs.push((c.user + c.system) / 1000);
      }
      times.set(key(row), xs);
      cpu.set(key(row), cs);
    }
  }
  console.log(`Node ${process.version}, ${SIZE.width}×${SIZE.height}, ${reps} reps × ${frames} frames; load ${before.toFixed(2)} → ${loadavg()[0].toFixed(2)}`);
  for (const row of ROWS) {
    const s = summary(times.get(key(row))!), c = summary(cpu.get(key(row))!);
    const min = Math.min(...times.get(key(row))!);
    console.log(`${key(row).padEnd(34)} ${s.median.toFixed(2)} ms [IQR ${s.iqr.toFixed(2)}], min ${min.toFixed(2)}   CPU ${c.median.toFixed(2)} ms [IQR ${c.iqr.toFixed(2)}]`);
  }
}

/** A digest of each row's pixels at a few times (the cube turned), to compare builds bit for bit. */
function hashes(): void {
  const scene = defaultScene(DEFAULT_CUBE_DISTANCE, 0.8);
  const r = new SoftwareRenderer();
  for (const row of ROWS) {
    const h = createHash('sha256');
    for (const t of [0, 0.4, 1.25, 2.9]) h.update(r.render(scene, state(t, row[1], row[0], row[2])));
    console.log(`${key(row).padEnd(34)} ${h.digest('hex').slice(0, 16)}`);
  }
}

const args = process.argv.slice(2);
if (args[0] === 'hash') hashes();
else timing(Number(args[0] ?? 5), Number(args[1] ?? 10));
