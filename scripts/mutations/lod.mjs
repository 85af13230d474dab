// The reflection's level of detail, culling and skips in WebGL (their maths in frame/ and math/ is unit-tested: StrykerJS).
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const LEAKS = 'tests/e2e/gl-leaks.spec.ts';
const ON_DEMAND = 'tests/e2e/on-demand.spec.ts';
const LOD = 'tests/e2e/reflection-lod.spec.ts';
const PASSES = 'tests/e2e/passes.spec.ts';

export default [
  {
    name: '12 a dense mesh\'s clustered reflection copies never released',
    why: 'WebGL mesh copies released: only a browser counts them (gl-leaks)',
    edits: [{ file: 'src/render/object-meshes.ts', find: '    for (const entry of slot.reflection.values()) if (entry) this.shared.releaseMesh(entry.key);\n', replace: '' }],
    tests: [LEAKS],
  },
  {
    name: 'D1 the reflection pass runs with the glass off screen or edge-on (the optimize test inverted)',
    why: 'the element in a page: the WebGL passes it skips (frame reports)',
    edits: [{ file: 'src/frame/pass-reports.ts', find: ': !optimize ? undefined', replace: ': optimize ? undefined' }],
    tests: [ON_DEMAND],
  },
  {
    name: 'D2 reflection culling ignores the camera\'s side: from behind the glass the wrong objects are culled',
    why: 'the element in a page: the WebGL reflection\'s culling (frame reports)',
    edits: [{
      file: 'src/frame/frame-setup.ts',
      find: 'out.viewerDistance = this.side * signedDistance(this.glass.plane, out.center);',
      replace: 'out.viewerDistance = signedDistance(this.glass.plane, out.center);',
    }],
    tests: [ON_DEMAND],
  },
  {
    name: 'D5 the reflection LOD\'s pixel size from tan(fov) instead of tan(fov / 2)',
    why: 'WebGL reflection pass (its level of detail): only a browser draws it',
    edits: [{
      file: 'src/render/passes/draw-objects.ts',
      find: 'const focal = focalPixels(targetHeight, ctx.state.fov);',
      replace: 'const focal = focalPixels(targetHeight, 2 * ctx.state.fov);',
    }],
    tests: [LOD],
  },
  {
    name: 'D6 the clustered copy chosen by the real eye\'s distance, not the mirrored eye\'s',
    why: 'WebGL reflection pass (its level of detail): only a browser draws it',
    edits: [{ file: 'src/render/passes/draw-objects.ts', find: 'const eye = setup.mirroredEye;', replace: 'const eye = setup.eye;' }],
    tests: [LOD],
  },
  {
    name: 'D8 the reflection scissored to the glass rectangle with x and y swapped',
    why: 'WebGL scissor of the reflection pass: only a browser draws it',
    edits: [{
      file: 'src/render/passes/reflection-pass.ts',
      find: 'gl.scissor(scissor.x, scissor.y, scissor.width, scissor.height);',
      replace: 'gl.scissor(scissor.y, scissor.x, scissor.width, scissor.height);',
    }],
    tests: [PASSES],
  },
  {
    name: 'D9 culling by the wrong sign of the radius: an object straddling the glass is dropped from the reflection',
    why: 'WebGL reflection pass (its culling): only a browser draws it',
    edits: [{ file: 'src/render/passes/draw-objects.ts', find: '<= -m.radius) continue;', replace: '<= m.radius) continue;' }],
    tests: [PASSES],
  },
];
