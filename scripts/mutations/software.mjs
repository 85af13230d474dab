// The software renderer's workers as the element runs them in a page (element/software-host.ts).
// The renderer itself (src/software/: raster, shading, glass, bands) is unit-tested: StrykerJS mutates it.
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const BANDS_E2E = 'tests/e2e/software-bands.spec.ts';
const ELEMENT = 'tests/e2e/software.spec.ts';

export default [
  {
    name: 'S58 bands: the workers never terminated (the element gone, they stay)',
    why: 'the element in a page: its software Workers terminated on removal',
    edits: [{ file: 'src/element/software-host.ts', find: '    this.worker.terminate();\n', replace: '' }],
    tests: [BANDS_E2E],
  },
  {
    name: 'S59 bands: a worker that cannot start leaves the frame waiting (no fall back to the main thread)',
    why: 'the element in a page: a Worker that fails to start',
    edits: [{ file: 'src/element/software-host.ts', find: '      e.preventDefault?.();\n      failed();\n', replace: '      e.preventDefault?.();\n' }],
    tests: [ELEMENT],
  },
  {
    name: 'S62 a frame in flight when the element goes drawn again on the main thread (a whole CPU frame thrown away)',
    why: 'the element in a page: a Worker\'s frame in flight at removal',
    edits: [{ file: 'src/element/software-host.ts', find: '.catch(() => (this.disposed ? new Uint8ClampedArray(0) : this.renderNow(scene, state, samplesPerAxis)));', replace: '.catch(() => this.renderNow(scene, state, samplesPerAxis));' }],
    tests: [BANDS_E2E],
  },
];
