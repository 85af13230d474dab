// Controls: orbit, pan, trackball, flyby, inertia, gesture end.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const CONTROLS = 'tests/e2e/controls.spec.ts';

export default [
  {
    name: '9 inertia stepped by Euler (frame-rate dependent)',
    edits: [{ file: 'src/element/controls/inertia.ts', find: '    const f = INERTIA_TAU * (1 - k);', replace: '    const f = t;' }],
    tests: [CONTROLS],
  },
  {
    name: '10 touch-action none without controls',
    edits: [{ file: 'src/element/element-style.ts', find: 'canvas { display: block; width: 100%; height: 100%; }', replace: 'canvas { display: block; width: 100%; height: 100%; touch-action: none; }' }],
    tests: [CONTROLS],
  },
  {
    name: '11 pointer-lock entry movement turned by',
    edits: [{ file: 'src/element/flyby-input.ts', find: '    this.skipNext = true;', replace: '' }],
    tests: [CONTROLS],
  },
];
