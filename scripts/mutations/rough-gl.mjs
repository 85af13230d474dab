// Rough glass in the WebGL renderer (docs/rough-glass.md#the-gather): the gather of shaders/rough-glass.glsl and the
// mip-mapped images render/rough-targets.ts draws for it, in a chunk loaded when a frame first
// asks for roughness (render/parts.ts, render/rough-glass.ts, element/webgl-backend.ts).
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const ROUGH = 'tests/e2e/rough-glass.spec.ts';
const ELEMENT = 'tests/e2e/rough-element.spec.ts';
const GATHER = 'shaders/rough-glass.glsl';

export default [
  {
    name: 'W1 the transmission left sharp when rough (B̃ never gathered)',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{
      file: GATHER,
      find: '  vec4 acc = roughGather(uTransmission, uTransmissionCodes, uTransmissionSize, J, false);\n  return acc.a > 0.0 ? acc.rgb / acc.a : sharp;',
      replace: '  return sharp;',
    }],
    tests: [ROUGH],
  },
  {
    name: 'W2 the lobe width squared twice (α = roughness⁴)',
    why: 'WebGL rough glass inputs: only a browser draws it',
    edits: [{ file: 'src/render/rough-targets.ts', find: 'this.inputs.alpha = ggxAlpha(state.roughness ?? 0);', replace: 'this.inputs.alpha = ggxAlpha(state.roughness ?? 0) ** 2;' }],
    tests: [ROUGH],
  },
  {
    name: 'W3 the background kept where its eye ray does not go beyond the glass (the horizon test dropped)',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: GATHER, find: '        else if (!roughLeaves(q + delta, size)) continue;\n', replace: '' }],
    tests: [ROUGH],
  },
  {
    name: 'W4 a neighbour behind the pixel\'s own surface kept (the occlusion test dropped)',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: GATHER, find: '        if (go < ROUGH_HIDDEN * g) continue;\n', replace: '' }],
    tests: [ROUGH],
  },
  {
    name: 'W5 every neighbour taken at the pixel\'s own distance (gq for each sample)',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: GATHER, find: '        if (layer == 0) g = roughScale(cu / cover);\n', replace: '        if (layer == 0) g = gq;\n' }],
    tests: [ROUGH],
  },
  {
    name: 'W6 the distance code measured on the viewer\'s side (h clamps to 0: everything touches the glass)',
    why: 'WebGL rough glass distance pass: only a browser draws it',
    edits: [{ file: 'src/render/rough-targets.ts', find: 'eyeRelativePlane(this.farSide64, setup.glass.plane, setup.eye, -setup.side);', replace: 'eyeRelativePlane(this.farSide64, setup.glass.plane, setup.eye, setup.side);' }],
    tests: [ROUGH],
  },
  {
    name: 'W7 the frame beyond the glass clipped to the viewer\'s side instead',
    why: 'WebGL transmission pass (its clip plane): only a browser draws it',
    edits: [{ file: 'src/render/passes/transmission-pass.ts', find: 'eyeRelativePlane(farSide64, setup.glass.plane, setup.eye, -setup.side);', replace: 'eyeRelativePlane(farSide64, setup.glass.plane, setup.eye, setup.side);' }],
    tests: [ROUGH],
  },
  {
    name: 'W8 the multisampled depth not resolved (the distance code reads a cleared depth)',
    why: 'WebGL multisampled depth resolve: only a browser draws it',
    edits: [{ file: 'src/render/rough-targets.ts', find: 'msaa.resolve(target.framebuffer, true);', replace: 'msaa.resolve(target.framebuffer);' }],
    tests: [ROUGH],
  },
  {
    name: 'W9 the image\'s rows scaled by its width (M\'s second row in the wrong texels)',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: GATHER, find: 'rM.zw * (0.5 * size.y)', replace: 'rM.zw * (0.5 * size.x)' }],
    tests: [ROUGH],
  },
  {
    name: 'W10 the codes\' mip chain not rebuilt after the distance pass (levels above 0 left empty)',
    why: 'WebGL mip chain of the distance codes: only a browser draws it',
    edits: [{ file: 'src/render/gl/mip-target.ts', find: '    gl.bindTexture(gl.TEXTURE_2D, this.codes);\n    gl.generateMipmap(gl.TEXTURE_2D);\n', replace: '' }],
    tests: [ROUGH],
  },
  {
    name: 'W11 the renderer\'s dispose forgets the rough targets',
    why: 'WebGL rough glass targets released on dispose: only a browser runs them',
    edits: [{ file: 'src/render/rough-glass.ts', find: '    this.targets?.dispose();\n', replace: '' }],
    tests: [ROUGH],
  },
  {
    name: 'W12 the surfaces\' colour not separated from the background (one layer: the sample\'s colour as is)',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: GATHER, find: 'vec3 colour = layer == 0 ? (rgb - uBackground * (1.0 - cover)) / cover : uBackground;', replace: 'vec3 colour = layer == 0 ? rgb : uBackground;' }],
    tests: [ROUGH],
  },
  {
    name: 'W13 the bench\'s fixed blur level ignored (the gather runs)',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: GATHER, find: '  if (uFixedLevel >= 0.0) {\n', replace: '  if (uFixedLevel > 1e9) {\n' }],
    tests: [ROUGH],
  },
  {
    name: 'W14 the transparent objects drawn before the rough glass (it erases those in front of it)',
    why: 'WebGL pass order (rough glass before transparent objects): only a browser draws it',
    edits: [{ file: 'src/render/renderer.ts', find: "return scenePass(ctx, false, 'opaque') + glassPass(ctx, r.reflectionColor, false, r) + scenePass(ctx, false, 'transparent');", replace: 'return scenePass(ctx) + glassPass(ctx, r.reflectionColor, false, r);' }],
    tests: [ROUGH],
  },
  {
    name: 'W15 the rough glass leaves no depth (transparent objects beyond it drawn over it)',
    why: 'WebGL depth written by the rough glass pass: only a browser draws it',
    edits: [{ file: 'src/render/passes/glass-pass.ts', find: '  gl.depthMask(rough !== null);', replace: '  gl.depthMask(false);' }],
    tests: [ROUGH],
  },
  {
    name: 'W16 the element draws its first rough frame before rough glass\'s chunk is in (polished, then rough)',
    why: 'lazy chunks in a page: the element waits for rough glass\'s chunk',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => isRough(h.ctx.state), holds: true,', replace: 'needed: (h) => isRough(h.ctx.state), holds: false,' }],
    tests: [ELEMENT],
  },
  {
    name: 'W17 no frame asked for once the chunk is in (the element waits for ever)',
    why: 'lazy chunks in a page: a frame asked for once rough glass\'s chunk is in',
    edits: [{ file: 'src/element/webgl-backend.ts', find: '          if (!this.disposed) host.requestRender();', replace: '          void this.disposed;' }],
    tests: [ELEMENT],
  },
  {
    name: 'W18 a chunk that fails to load goes unreported',
    why: 'lazy chunks in a page: a failed rough glass chunk warned about',
    edits: [{ file: 'src/element/webgl-backend.ts', find: '        warn,\n', replace: '        warn: () => {},\n' }],
    tests: [ELEMENT],
  },
  {
    name: 'W19 the renderer takes a rough frame as rough before its chunk is in',
    why: 'lazy chunks in a page: the WebGL renderer waits for rough glass\'s chunk',
    edits: [{ file: 'src/render/rough-glass.ts', find: 'return isRough(state) && this.chunk !== null;', replace: 'return isRough(state);' }],
    tests: [ROUGH],
  },
];
