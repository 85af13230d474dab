// The element's lifecycle: dispose, context loss and restore, renderer switch, off-screen, idle.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const LEAKS = 'tests/e2e/gl-leaks.spec.ts';

export default [
  {
    name: '4 dispose() skips the texture',
    edits: [{ file: 'src/render/gl/shared-resources.ts', find: '    this.procedural?.dispose();\n', replace: '' }],
    tests: [LEAKS],
  },
  {
    name: '14 the software renderer never given the decoded images',
    edits: [{ file: 'src/element/glass-plane-scene.ts', find: '      this.images.attach(host);\n', replace: '' }],
    tests: ['tests/e2e/model-reference.spec.ts'],
  },
];
