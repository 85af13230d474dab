// The glass passes in WebGL: mirror, clip plane, Fresnel, the classic blend, a face in the glass plane.
// (The software renderer's and the reference's sides are unit-tested: StrykerJS mutates them.)
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const PASSES = 'tests/e2e/passes.spec.ts';
const TIE_E2E = 'tests/e2e/glass-tie.spec.ts';

export default [
  {
    name: '1 reflection drawn from the unmirrored camera',
    why: 'WebGL reflection pass (the mirrored camera): only a browser draws it',
    edits: [{
      file: 'src/frame/frame-setup.ts',
      find: 'this.compose(o.mirrored, o.model, o.normal, mirroredEye, this.mirroredViewProjection);',
      replace: 'this.compose(o.mirrored, o.model, o.normal, eye, this.viewProjection);',
    }],
    tests: [PASSES],
  },
  {
    name: '2 clip plane sign flipped',
    why: 'WebGL reflection pass (its clip plane): only a browser draws it',
    edits: [{
      file: 'src/frame/frame-setup.ts',
      find: 'eyeRelativePlane(this.mirroredClip, plane, mirroredEye, this.side)',
      replace: 'eyeRelativePlane(this.mirroredClip, plane, mirroredEye, -this.side)',
    }],
    tests: [PASSES],
  },
  {
    name: '3 abs() removed from cosθ',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{
      file: 'shaders/glass.frag',
      find: 'float c = clamp(abs(dot(normalize(vNormal), v)), 0.0, 1.0);',
      replace: 'float c = clamp(dot(normalize(vNormal), v), 0.0, 1.0);',
    }],
    tests: [PASSES],
  },
  {
    name: '5a discard fallback removed',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: 'shaders/standard.frag', find: '  if (vClipDistance < 0.0) discard;\n', replace: '' }],
    tests: [PASSES],
  },
  {
    name: '5b discard fallback inverted',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: 'shaders/standard.frag', find: 'if (vClipDistance < 0.0) discard;', replace: 'if (vClipDistance > 0.0) discard;' }],
    tests: [PASSES],
  },
  {
    name: '6a classic alpha without (1 − T)',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{
      file: 'shaders/glass.frag',
      find: 'float a = (1.0 - uTransparency) * (0.2 + 0.8 * f);',
      replace: 'float a = 0.2 + 0.8 * f;',
    }],
    tests: [PASSES],
  },
  {
    name: '6b classic colour not premultiplied',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: 'shaders/glass.frag', find: 'outColor = vec4(mix(d, r, f) * a, a);', replace: 'outColor = vec4(mix(d, r, f), a);' }],
    tests: [PASSES],
  },
  {
    name: '7a far-side clip removed (clip distance and discard)',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [
      { file: 'shaders/standard.vert', find: 'gl_ClipDistance[0] = clipDistance;', replace: 'gl_ClipDistance[0] = 1.0;' },
      { file: 'shaders/standard.frag', find: '  if (vClipDistance < 0.0) discard;\n', replace: '' },
    ],
    tests: [PASSES],
  },
  {
    name: '7b far-side clip removed (uClipPlane zeroed)',
    why: 'WebGL clip plane uniform: only a browser draws it',
    edits: [{
      file: 'src/render/passes/draw-objects.ts',
      find: "gl.uniform4fv(program.location('uClipPlane'), setup.clipPlane);",
      replace: "gl.uniform4fv(program.location('uClipPlane'), [0, 0, 0, 0]);",
    }],
    tests: [PASSES],
  },
  {
    name: '8 F forced to 0',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: 'shaders/glass.frag', find: 'float f = fresnel(c);', replace: 'float f = 0.0;' }],
    tests: [PASSES],
  },
  // A face in the glass plane: the glass covers what lies on it or beyond it.
  {
    name: 'G1 WebGL: objects on the glass or beyond it not pushed back (a face in its plane wins the depth test)',
    why: 'WebGL polygon offset (depth test): only a browser draws it',
    edits: [{ file: 'src/render/passes/draw-objects.ts', find: 'gl.polygonOffset(0, 2);', replace: 'gl.polygonOffset(0, 0);' }],
    tests: [TIE_E2E],
  },
];
