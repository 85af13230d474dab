// The glass passes (GL): mirror, clip plane, Fresnel, the classic blend.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const PASSES = 'tests/e2e/passes.spec.ts';
const TIE = 'tests/unit/glass-tie.test.ts';
const TIE_E2E = 'tests/e2e/glass-tie.spec.ts';

export default [
  {
    name: '1 reflection drawn from the unmirrored camera',
    edits: [{
      file: 'src/frame/frame-setup.ts',
      find: 'this.compose(o.mirrored, o.model, o.normal, mirroredEye, this.mirroredViewProjection);',
      replace: 'this.compose(o.mirrored, o.model, o.normal, eye, this.viewProjection);',
    }],
    tests: [PASSES],
  },
  {
    name: '2 clip plane sign flipped',
    edits: [{
      file: 'src/frame/frame-setup.ts',
      find: 'eyeRelativePlane(this.mirroredClip, plane, mirroredEye, this.side)',
      replace: 'eyeRelativePlane(this.mirroredClip, plane, mirroredEye, -this.side)',
    }],
    tests: [PASSES],
  },
  {
    name: '3 abs() removed from cosθ',
    edits: [{
      file: 'shaders/glass.frag',
      find: 'float c = clamp(abs(dot(normalize(vNormal), v)), 0.0, 1.0);',
      replace: 'float c = clamp(dot(normalize(vNormal), v), 0.0, 1.0);',
    }],
    tests: [PASSES],
  },
  {
    name: '5a discard fallback removed',
    edits: [{ file: 'shaders/standard.frag', find: '  if (vClipDistance < 0.0) discard;\n', replace: '' }],
    tests: [PASSES],
  },
  {
    name: '5b discard fallback inverted',
    edits: [{ file: 'shaders/standard.frag', find: 'if (vClipDistance < 0.0) discard;', replace: 'if (vClipDistance > 0.0) discard;' }],
    tests: [PASSES],
  },
  {
    name: '6a classic alpha without (1 − T)',
    edits: [{
      file: 'shaders/glass.frag',
      find: 'float a = (1.0 - uTransparency) * (0.2 + 0.8 * f);',
      replace: 'float a = 0.2 + 0.8 * f;',
    }],
    tests: [PASSES],
  },
  {
    name: '6b classic colour not premultiplied',
    edits: [{ file: 'shaders/glass.frag', find: 'outColor = vec4(mix(d, r, f) * a, a);', replace: 'outColor = vec4(mix(d, r, f), a);' }],
    tests: [PASSES],
  },
  {
    name: '7a far-side clip removed (clip distance and discard)',
    edits: [
      { file: 'shaders/standard.vert', find: 'gl_ClipDistance[0] = clipDistance;', replace: 'gl_ClipDistance[0] = 1.0;' },
      { file: 'shaders/standard.frag', find: '  if (vClipDistance < 0.0) discard;\n', replace: '' },
    ],
    tests: [PASSES],
  },
  {
    name: '7b far-side clip removed (uClipPlane zeroed)',
    edits: [{
      file: 'src/render/passes/draw-objects.ts',
      find: "gl.uniform4fv(program.location('uClipPlane'), setup.clipPlane);",
      replace: "gl.uniform4fv(program.location('uClipPlane'), [0, 0, 0, 0]);",
    }],
    tests: [PASSES],
  },
  {
    name: '8 F forced to 0',
    edits: [{ file: 'shaders/glass.frag', find: 'float f = fresnel(c);', replace: 'float f = 0.0;' }],
    tests: [PASSES],
  },
  // A face in the glass plane: the glass covers what lies on it or beyond it.
  {
    name: 'G1 WebGL: objects on the glass or beyond it not pushed back (a face in its plane wins the depth test)',
    edits: [{ file: 'src/render/passes/draw-objects.ts', find: 'gl.polygonOffset(0, 2);', replace: 'gl.polygonOffset(0, 0);' }],
    tests: [TIE_E2E],
  },
  // (The software glass's own push-back has no mutation here: with exact coplanar geometry its
  // strict LESS test already leaves a tie to the face drawn first; the push guards rounding only.)
  {
    name: 'G3 software: objects on the glass or beyond it not pushed back (their faces in its plane win)',
    edits: [{ file: 'src/software/software-renderer.ts', find: '<= 0 ? 2 * GLASS_TIE_BIAS : 0;', replace: '<= 0 ? 0 : 0;' }],
    tests: [TIE],
  },
  {
    name: 'G4 the reflection keeps what touches the glass (no contact margin on the clip plane)',
    edits: [{ file: 'src/frame/frame-setup.ts', find: 'this.mirroredClip[3] -= MIRROR_CONTACT;', replace: 'this.mirroredClip[3] -= 0;' }],
    tests: [TIE],
  },
  {
    name: 'G5 reference: a depth tie goes to the object whatever its side',
    edits: [{ file: 'src/reference/sample-tracer.ts', find: 'return this.side * signedDistance(this.plane!, this.scene.centres[object.object]) <= 0;', replace: 'return false;' }],
    tests: [TIE],
  },
  {
    name: 'G7 reference: an object beyond the glass, far off the plane, counted as a tie',
    edits: [{ file: 'src/reference/sample-tracer.ts', find: 'if (Math.abs(object.t - g.t) <= TIE * Math.abs(g.t))', replace: 'if (g.t - object.t <= TIE * Math.abs(g.t))' }],
    tests: [TIE],
  },
  {
    name: 'G6 reference: the reflection keeps a mesh face that touches the glass',
    edits: [{ file: 'src/reference/clip.ts', find: 'const s0 = clipSide * signedDistance(plane!, o) - MIRROR_CONTACT;', replace: 'const s0 = clipSide * signedDistance(plane!, o);' }],
    tests: [TIE],
  },
];
