// Rough glass (docs/rough-glass.md#the-gather) in the software renderer: the gather of R̃ and B̃ (software/rough-gather.ts).
// Each: { name, edits: [{ file, find, replace }], tests }.
const ROUGH = 'tests/unit/software-rough.test.ts';

export default [
  {
    name: 'Q1 roughness ignored for the transmission (B̃ left sharp)',
    edits: [{ file: 'src/software/software-renderer.ts', find: 'glass.roughTransmission = transmits;', replace: 'glass.roughTransmission = false;' }],
    tests: [ROUGH],
  },
  {
    name: 'Q2 the lobe width squared twice (α = roughness⁴)',
    edits: [{ file: 'src/software/software-renderer.ts', find: 'g.alpha = ggxAlpha(state.roughness ?? 0);', replace: 'g.alpha = ggxAlpha(state.roughness ?? 0) ** 2;' }],
    tests: [ROUGH],
  },
  {
    name: 'Q3 rays turned past the glass kept (the background read beyond the horizon)',
    edits: [{ file: 'src/software/rough-gather.ts', find: '            if (!this.leaves(x, y)) continue;\n', replace: '' }],
    tests: [ROUGH],
  },
  {
    name: 'Q4 no occlusion: a far neighbour seen through the pixel\'s own surface',
    edits: [{ file: 'src/software/rough-gather.ts', find: 'if (go < HIDDEN * gs) continue;', replace: 'void go;' }],
    tests: [ROUGH],
  },
  {
    name: 'Q5 every neighbour blurred at the pixel\'s own distance (no contact hardening)',
    edits: [{ file: 'src/software/rough-gather.ts', find: 'if (layer === 0) gs = this.scaleOf(t[4] / cover, c, L);', replace: 'if (layer === 0) gs = gq;' }],
    tests: [ROUGH],
  },
  {
    name: 'Q6 the background\'s light kept in a surface\'s colour (one layer)',
    edits: [{ file: 'src/software/rough-gather.ts', find: 'r += (w * (cr - q * bg[0])) / cover; g += (w * (cg - q * bg[1])) / cover; b += (w * (cb - q * bg[2])) / cover;', replace: 'r += w * cr; g += w * cg; b += w * cb;' }],
    tests: [ROUGH],
  },
  {
    name: 'Q7 the lobe\'s image round, not stretched along the view\'s slope (J = 2·I)',
    edits: [{ file: 'src/software/rough-gather.ts', find: 'J[0] = 2; J[1] = 0; J[2] = 0; J[3] = 2 * c;', replace: 'J[0] = 2; J[1] = 0; J[2] = 0; J[3] = 2;' }],
    tests: [ROUGH],
  },
  {
    name: 'Q8 the mips read a level too coarse (lod bias dropped)',
    edits: [{ file: 'src/software/rough-gather.ts', find: 'Math.max(0, 0.5 * Math.log2(area) + lodBias)', replace: 'Math.max(0, 0.5 * Math.log2(area))' }],
    tests: [ROUGH],
  },
  {
    name: 'Q9 distance codes of the reflection measured on the far side (plane not turned to the viewer)',
    edits: [{ file: 'src/software/software-renderer.ts', find: 'for (let k = 0; k < 4; k++) codePlane[k] = s.side * plane[k];', replace: 'for (let k = 0; k < 4; k++) codePlane[k] = -s.side * plane[k];' }],
    tests: [ROUGH],
  },
  {
    name: 'Q10 the inverse view-projection with one cofactor\'s sign flipped (math/invert.ts)',
    edits: [{ file: 'src/math/invert.ts', find: 'out[9] = (-m30 * t23 + m32 * t03 - m33 * t02) * k;', replace: 'out[9] = (m30 * t23 - m32 * t03 + m33 * t02) * k;' }],
    tests: ['tests/unit/invert.test.ts', ROUGH],
  },
  {
    name: 'Q11 the inverse not divided by the determinant',
    edits: [{ file: 'src/math/invert.ts', find: 'const k = 1 / det;', replace: 'const k = 1;' }],
    tests: ['tests/unit/invert.test.ts', ROUGH],
  },
  {
    name: 'Q12 a singular matrix inverted anyway (out filled with infinities)',
    edits: [{ file: 'src/math/invert.ts', find: 'if (det === 0 || !Number.isFinite(det)) return false;', replace: '' }],
    tests: ['tests/unit/invert.test.ts'],
  },
];
