// The software renderer: raster, shading, glass, transparency.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.

export default [
  {
    name: '13 software rasterizer without the top-left rule',
    edits: [{
      file: 'src/software/raster.ts',
      find: '    const bias0 = (ay0 === 0 && ax0 > 0) || ay0 < 0 ? 0 : -1;\n    const bias1 = (ay1 === 0 && ax1 > 0) || ay1 < 0 ? 0 : -1;\n    const bias2 = (ay2 === 0 && ax2 > 0) || ay2 < 0 ? 0 : -1;',
      replace: '    const bias0 = 0;\n    const bias1 = 0;\n    const bias2 = 0;',
    }],
    tests: ['tests/unit/software-raster.test.ts'],
  },
];
