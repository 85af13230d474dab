// The reflection's level of detail, culling and skips.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const LEAKS = 'tests/e2e/gl-leaks.spec.ts';

export default [
  {
    name: '12 a dense mesh\'s clustered reflection copies never released',
    edits: [{ file: 'src/render/object-meshes.ts', find: '    for (const entry of slot.reflection.values()) if (entry) this.shared.releaseMesh(entry.key);\n', replace: '' }],
    tests: [LEAKS],
  },
];
