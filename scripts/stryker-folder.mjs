// StrykerJS on some folders of src/ only:
//   npm run test:mutations:folder -- math [frame …] [--tests "tests/unit/a.test.ts,…"] [stryker flags]
// Runs `stryker run --mutate "src/math/**/*.ts,src/frame/**/*.ts"`; stryker.config.mjs names the
// scope from that (reports/mutation/math+frame/: reports and the incremental file of that scope).
// --tests: only those test files (globs, comma-separated) make the suite (vitest.stryker.config.ts,
// STRYKER_TESTS): a folder's own tests, much faster than every test that imports the folder. Not
// Stryker's --testFiles, under which module-level (static) mutants are never switched on and all
// "survive" (Stryker 9.6.1). Other words starting with "-" go to Stryker as they are (--force).
import { spawnSync } from 'node:child_process';

/**
 * Each folder's own tests: the suite a folder's mutants are judged by when no --tests is given
 * (the README's scores). Every test that merely imports the folder would run too, much slower:
 * the software and reference renders take seconds each, and code run outside a test (a module's
 * constants, a describe body) makes Stryker run the whole suite for each of its mutants.
 */
const OWN_TESTS = {
  scene: [
    'compose-scene', 'course-depth', 'glass-frame', 'mapping', 'reference-scene', 'scene-turn', 'texture', 'reference-pixels',
    'orthographic', 'lights-rule', 'scaled-objects', 'child-attributes', 'controls', 'course-view', 'bezier', 'bvh',
    'course-byu-bezier', 'geometry-flat-gaussian', 'geometry', 'mesh-choice', 'reflection-lod', 'stability', 'deep-freeze',
    'cluster-by-hand', 'flat-by-hand', 'default-scene-cache', 'scene-rules',
  ],
  frame: [
    'frame-rules', 'frame-setup', 'lazy-parts', 'mesh-choice', 'orthographic', 'reflection-lod', 'reflection-scissor',
    'stability', 'quality-knobs', 'scene-turn', 'course-view', 'programs', 'glass-tie', 'glass-bounds', 'course-projection',
  ],
  'loaders/obj': [
    'obj', 'obj-bytes', 'obj-bytes-numbers', 'obj-bytes-suite', 'obj-data', 'obj-estimate', 'obj-fast', 'obj-faults', 'obj-job',
    'obj-load-errors', 'obj-mesh-growth', 'obj-polygons', 'obj-settings', 'obj-warnings', 'mesh-parts', 'sniff-once', 'obj-triangulate', 'obj-byte-scanner',
  ],
  'loaders/gltf': [
    'gltf-load', 'gltf-errors', 'gltf-data', 'gltf-real-files', 'gltf-compression', 'gltf-model', 'gltf-tangents', 'sniff',
    'gltf-container', 'gltf-fields', 'gltf-buffers', 'gltf-accessors', 'gltf-nodes', 'gltf-primitives', 'gltf-materials',
    'gltf-merge-images', 'gltf-index', 'gltf-decoders',
  ],
  // Frames of 32×18 (small-frames) judge a mutant of either CPU renderer in a fraction of a second under
  // Stryker's instrumentation, where a rough 160×90 frame takes seconds: the bigger frames of
  // software-baseline, software-reference, software-rough and reference-rough are left to npm test.
  software: [
    'small-frames', 'software-protocol', 'software-clip', 'software-raster', 'software-anisotropic', 'software-glass', 'software-pixels',
    'software-srgb', 'software-caches', 'software-bands', 'glass-tie', 'mesh-choice', 'scene-turn', 'software-lighting',
    'software-mip-texture', 'software-raster-options', 'software-glass-shader', 'software-object-shader',
  ],
  reference: [
    'small-frames', 'reference-pixels', 'reference-metrics', 'reference-texture', 'reference-srgb', 'reference-scene', 'bvh',
    'glass-tie', 'scaled-objects', 'lights-rule', 'reference-pbr-light',
    // Fast tests of single files, hand-computed (milliseconds each, where a frame takes seconds under Stryker).
    'reference-ray', 'reference-clip', 'reference-surface-codes', 'reference-microfacet-samples', 'reference-object-frame',
    'reference-image-texture', 'reference-rough-glass', 'reference-regions', 'reference-view-camera', 'reference-ray-scene',
    'reference-shade', 'reference-mesh-tracer', 'reference-analytic-tracers', 'reference-texture-sampler',
    'reference-surface-texture', 'reference-bvh', 'reference-sample-tracer', 'reference-renderer',
  ],
};
for (const [folder, names] of Object.entries(OWN_TESTS)) OWN_TESTS[folder] = names.map((n) => `tests/unit/${n}.test.ts`);
import fs from 'node:fs';

const args = process.argv.slice(2);
const firstFlag = args.findIndex((a) => a.startsWith('-'));
const folders = firstFlag < 0 ? args : args.slice(0, firstFlag);
const flags = firstFlag < 0 ? [] : args.slice(firstFlag);
const env = { ...process.env };
const t = flags.indexOf('--tests');
if (t >= 0) env.STRYKER_TESTS = flags.splice(t, 2)[1] ?? '';
else if (folders.every((f) => OWN_TESTS[f])) env.STRYKER_TESTS = [...new Set(folders.flatMap((f) => OWN_TESTS[f]))].join(',');
if (!folders.length) {
  console.error('usage: npm run test:mutations:folder -- <folder of src/> [more folders] [--tests globs] [stryker flags]');
  process.exit(2);
}
for (const f of folders) {
  if (!/^[\w-]+(\/[\w-]+)*$/.test(f) || !fs.statSync(`src/${f}`, { throwIfNoEntry: false })?.isDirectory()) {
    console.error(`no folder src/${f}`);
    process.exit(2);
  }
}
const mutate = folders.map((f) => `src/${f}/**/*.ts`).join(',');
const run = spawnSync('npx', ['stryker', 'run', '--mutate', mutate, ...flags], { stdio: 'inherit', env });
process.exit(run.status ?? 1);
