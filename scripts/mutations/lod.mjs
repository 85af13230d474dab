// The reflection's level of detail, culling and skips.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const LEAKS = 'tests/e2e/gl-leaks.spec.ts';
const ON_DEMAND = 'tests/e2e/on-demand.spec.ts';
const LOD = 'tests/e2e/reflection-lod.spec.ts';
const SCISSOR = 'tests/unit/reflection-scissor.test.ts';
const PASSES = 'tests/e2e/passes.spec.ts';

export default [
  {
    name: '12 a dense mesh\'s clustered reflection copies never released',
    edits: [{ file: 'src/render/object-meshes.ts', find: '    for (const entry of slot.reflection.values()) if (entry) this.shared.releaseMesh(entry.key);\n', replace: '' }],
    tests: [LEAKS],
  },
  {
    name: 'D1 the reflection pass runs with the glass off screen or edge-on (the optimize test inverted)',
    edits: [{ file: 'src/frame/pass-reports.ts', find: ': !optimize ? undefined', replace: ': optimize ? undefined' }],
    tests: [ON_DEMAND],
  },
  {
    name: 'D2 reflection culling ignores the camera\'s side: from behind the glass the wrong objects are culled',
    edits: [{
      file: 'src/frame/frame-setup.ts',
      find: 'out.viewerDistance = this.side * signedDistance(this.glass.plane, out.center);',
      replace: 'out.viewerDistance = signedDistance(this.glass.plane, out.center);',
    }],
    tests: [ON_DEMAND],
  },
  {
    name: 'D3 the reflection scissor loses its texel of margin on the low side (off by one)',
    edits: [{ file: 'src/frame/reflection-scissor.ts', find: 'Math.max(0, Math.floor(rect.x0 * sx) - 1)', replace: 'Math.max(0, Math.floor(rect.x0 * sx))' }],
    tests: [SCISSOR],
  },
  {
    name: 'D4 the reflection scissor scales y by the width ratio (wrong once the target is clamped)',
    edits: [{ file: 'src/frame/reflection-scissor.ts', find: 'const sy = targetHeight / height;', replace: 'const sy = targetWidth / width;' }],
    tests: [SCISSOR],
  },
  {
    name: 'D5 the reflection LOD\'s pixel size from tan(fov) instead of tan(fov / 2)',
    edits: [{
      file: 'src/render/passes/draw-objects.ts',
      find: 'const focal = focalPixels(targetHeight, ctx.state.fov);',
      replace: 'const focal = focalPixels(targetHeight, 2 * ctx.state.fov);',
    }],
    tests: [LOD],
  },
  {
    name: 'D6 the clustered copy chosen by the real eye\'s distance, not the mirrored eye\'s',
    edits: [{ file: 'src/render/passes/draw-objects.ts', find: 'const eye = setup.mirroredEye;', replace: 'const eye = setup.eye;' }],
    tests: [LOD],
  },
  {
    name: 'D7 the sphere\'s auto tessellation sizes it with tan(fov) instead of tan(fov / 2)',
    edits: [{ file: 'src/frame/sphere-screen.ts', find: 'focalPixels(state.height, state.fov)', replace: 'focalPixels(state.height, 2 * state.fov)' }],
    tests: ['tests/unit/quality-knobs.test.ts'],
  },
  {
    name: 'D8 the reflection scissored to the glass rectangle with x and y swapped',
    edits: [{
      file: 'src/render/passes/reflection-pass.ts',
      find: 'gl.scissor(scissor.x, scissor.y, scissor.width, scissor.height);',
      replace: 'gl.scissor(scissor.y, scissor.x, scissor.width, scissor.height);',
    }],
    tests: [PASSES],
  },
  {
    name: 'D9 culling by the wrong sign of the radius: an object straddling the glass is dropped from the reflection',
    edits: [{ file: 'src/render/passes/draw-objects.ts', find: '<= -m.radius) continue;', replace: '<= m.radius) continue;' }],
    tests: [PASSES],
  },
  {
    name: 'D10 tan(fov / 2), written once, becomes tan(fov): the orthographic size (and every size on screen) off',
    edits: [{ file: 'src/math/camera.ts', find: 'return Math.tan((fovDeg * DEG) / 2);', replace: 'return Math.tan(fovDeg * DEG);' }],
    tests: ['tests/unit/orthographic.test.ts'],
  },
];
