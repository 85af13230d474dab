// Refinement at rest (docs/refinement.md): what only a page shows — the frame loop's restart and stop, the element's
// events, the WebGL average and its footprints. The sequence, the weights and the software renderer's mean are src/
// maths that StrykerJS mutates against tests/unit/refinement*.test.ts.
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests }.
const SPEC = 'tests/e2e/refinement.spec.ts';
const PAGE = 'the element in a page: requestAnimationFrame, observers and events (StrykerJS runs the unit tests in Node)';
const GL = 'WebGL: a pass on the GPU, or GLSL (shaders/), which StrykerJS does not run';

export default [
  {
    name: 'R1 the still view never restarts: a change goes on from the last frame drawn',
    why: PAGE,
    edits: [{ file: 'src/element/frame-loop.ts', find: 'this.host.animating() ? 0 : this.dirty ? 1 : Math.min(', replace: 'this.host.animating() ? 0 : Math.min(' }],
    tests: [SPEC],
  },
  {
    name: 'R2 no refinement frame after the preview (the stop taken at once)',
    why: PAGE,
    edits: [{ file: 'src/element/frame-loop.ts', find: 'if (drawn && this.refining()) this.schedule();', replace: '' }],
    tests: [SPEC],
  },
  {
    name: 'R3 the stop never comes: frames go on past refine',
    why: PAGE,
    edits: [{ file: 'src/element/frame-loop.ts', find: 'return this.refined > 0 && this.refined < this.host.refineFrames();', replace: 'return this.refined > 0;' }],
    tests: [SPEC],
  },
  {
    name: 'R4 refined fired after every frame of the still view',
    why: PAGE,
    edits: [{ file: 'src/element/frame-events.ts', find: 'if (refinement > 0 && refinement >= (state.refinementFrames ?? 1))', replace: 'if (refinement > 0)' }],
    tests: [SPEC],
  },
  {
    name: 'R5 refinement frames not counted apart in stats',
    why: PAGE,
    edits: [{ file: 'src/element/frame-events.ts', find: 'if (refinement > 0) this.refinementFrames++;', replace: '' }],
    tests: [SPEC],
  },
  {
    name: 'R6 a still view refines with color-space="none" (nothing linear to average)',
    why: PAGE,
    edits: [{ file: 'src/element/frame-state.ts', find: "v.colorSpace === 'srgb' && v.debugView === 'none' ? v.refine : 0", replace: "v.debugView === 'none' ? v.refine : 0" }],
    tests: [SPEC],
  },
  {
    name: 'R7 WebGL shows the preview alone (the mean never let in)',
    why: GL,
    edits: [{ file: 'src/render/linear-frame.ts', find: 'this.blend(shown, sum, share / (summing ? k - 1 : 1), 1 - share);', replace: '' }],
    tests: [SPEC],
  },
  {
    name: 'R8 WebGL sums without dividing by the frames (the mean too bright)',
    why: GL,
    edits: [{ file: 'src/render/linear-frame.ts', find: 'share / (summing ? k - 1 : 1)', replace: 'share' }],
    tests: [SPEC],
  },
  {
    name: 'R9 WebGL strata frames replace the sum instead of adding to it',
    why: GL,
    edits: [{ file: 'src/render/linear-frame.ts', find: 'k < 3 ? 0 : summing ? -1 :', replace: 'k < 3 ? 0 : summing ? 0 :' }],
    tests: [SPEC],
  },
  {
    name: 'R10 WebGL textures (materials and the glass body) read over the pixel in strata frames (derivatives unscaled)',
    why: GL,
    edits: [{ file: 'shaders/footprint.glsl', find: 'dFdx(uv) * uFootprint, dFdy(uv) * uFootprint', replace: 'dFdx(uv), dFdy(uv)' }],
    tests: [SPEC],
  },
  {
    name: 'R11 the software renderer\'s workers move their bands during a still view',
    why: PAGE,
    edits: [{ file: 'src/element/software-host.ts', find: 'if (!still && b.bottom > b.top && p.ms > 0)', replace: 'if (b.bottom > b.top && p.ms > 0)' }],
    tests: [SPEC],
  },
  {
    name: 'R12 WebGL rough glass gathers where it gathers alone in every strata frame',
    why: GL,
    edits: [{ file: 'src/render/rough-targets.ts', find: "gl.uniform3fv(p.location('uGatherJitter'), this.jitter);", replace: "gl.uniform3f(p.location('uGatherJitter'), 0.5, 0.5, 0);" }],
    tests: [SPEC],
  },
  {
    name: 'R13 WebGL glass reads its body texture over the pixel in strata frames (texture(), not mapRead)',
    why: GL,
    edits: [{ file: 'shaders/glass.frag', find: 'mapRead(uTexture, vUv)', replace: 'texture(uTexture, vUv)' }],
    tests: [SPEC],
  },
  {
    name: 'R14 WebGL glass biases its body texture\'s level by log2 uFootprint in strata frames instead of scaling its derivatives',
    why: GL,
    edits: [{ file: 'shaders/glass.frag', find: 'mapRead(uTexture, vUv)', replace: 'texture(uTexture, vUv, log2(uFootprint))' }],
    tests: [SPEC],
  },
  {
    name: 'R15 WebGL textures (materials and the glass body) biased by log2 uFootprint in strata frames instead of their derivatives scaled',
    why: GL,
    edits: [{ file: 'shaders/footprint.glsl', find: 'return textureGrad(map, uv, dFdx(uv) * uFootprint, dFdy(uv) * uFootprint);', replace: 'return texture(map, uv, log2(uFootprint));' }],
    tests: [SPEC],
  },
  {
    name: 'R16 the loop at rest while its still view still refines (whenRefined() settles on the preview)',
    why: PAGE,
    edits: [{ file: 'src/element/frame-loop.ts', find: 'return !this.dirty && !this.host.animating() && !this.refining();', replace: 'return !this.dirty && !this.host.animating();' }],
    tests: [SPEC],
  },
  {
    name: 'R17 the element\'s frame not counted as on its way (whenRefined() may settle before a CPU frame lands)',
    why: PAGE,
    edits: [{ file: 'src/element/glass-plane-scene.ts', find: '    this.events.started();\n', replace: '' }],
    tests: [SPEC],
  },
];
