// What the core leaves out and loads when a scene asks (docs/package.md#chunks): camera-src's two chunks (the
// element's camera-source, the renderer's course-projection), the group rotation, the debug
// views, the orthographic projection, the children's gatherer, the failure messages and image
// textures, and how frames wait for them.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const CHUNK = 'tests/e2e/course-chunk.spec.ts';
const RIG = 'src/element/camera-rig.ts';
const LOD = 'tests/e2e/reflection-lod.spec.ts';
const CHUNKS = 'tests/e2e/turn-debug-chunks.spec.ts';
const CORE = 'tests/e2e/core-chunks.spec.ts';
const LP = 'src/frame/lazy-parts.ts';
const PARTS = 'tests/unit/lazy-parts.test.ts';

export default [
  {
    name: 'Z1 camera-source\'s chunk arrives but is never connected (camera-src never loads its file)',
    edits: [{ file: 'src/element/camera-rig.ts', find: '    if (this.connected) this.source.hostConnected();\n', replace: '' }],
    tests: [CHUNK],
  },
  {
    name: 'Z2 ready fired while a lazy part (camera-src\'s reader) is still on its way',
    edits: [{ file: 'src/element/glass-plane-scene.ts', find: ' || this.rig.loading || this.parts.loading });', replace: ' || this.rig.loading });' }],
    tests: [CHUNK],
  },
  {
    name: 'Z3 the course projection loads but FrameSetup is never given it',
    edits: [{ file: 'src/render/parts.ts', find: '    h.ctx.setup.course ??= new m.CourseProjection();\n', replace: '' }],
    tests: [CHUNK],
  },
  {
    name: 'Z4 Renderer.load never asks for the course projection',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => !!h.ctx.state.courseCamera,', replace: 'needed: () => false,' }],
    tests: [CHUNK],
  },
  {
    name: 'Z5 a FrameSetup without the projection still takes its eye from the course camera',
    edits: [{ file: 'src/frame/frame-setup.ts', find: '    const course = this.course ? s.courseCamera ?? null : null;\n    const position', replace: '    const course = this.course ? s.courseCamera ?? null : null;\n    const position = s.courseCamera ? s.courseCamera.c : s.cameraPosition;\n    const _p' }],
    tests: ['tests/unit/course-view.test.ts'],
  },
  {
    name: 'Z6 camera-source takes the depth range straight from scene/ (its chunk loads without the projection\'s)',
    edits: [{ file: 'src/element/camera-source.ts', find: "import { courseSceneRange } from '../frame/course-projection';", replace: "import { courseSceneRange } from '../scene/course-depth';" }],
    tests: [CHUNK],
  },
  {
    name: 'Z7 the element\'s WebGL backend does not hand the scene to Renderer.load (reflections never clustered)',
    edits: [{ file: 'src/element/webgl-backend.ts', find: 'return this.renderer.load(scene, state) !== null;', replace: 'return this.renderer.load(null, state) !== null;' }],
    tests: [LOD],
  },
  {
    name: 'Z8 only meshes, not Gaussians, ask for the mesh extras (a Gaussian never drawn)',
    edits: [{ file: 'src/render/parts.ts', find: 'if (k === \'gaussian\' || (k === \'mesh\' && state.tessellation === \'auto\')) return true;', replace: 'if (k === \'mesh\' && state.tessellation === \'auto\') return true;' }],
    tests: [LOD],
  },
  {
    name: 'Z9 a lazy part that failed is asked for again (a warning every frame)',
    edits: [{ file: 'src/frame/lazy-parts.ts', find: '      this.status[i] = FAILED;\n', replace: '      this.status[i] = ABSENT;\n' }],
    tests: [LOD],
  },
  {
    name: 'Z10 the core\'s own quaternion product: a sign of its z term flipped',
    edits: [{ file: 'src/scene/group-rotation.ts', find: '  out[2] = az * bw + aw * bz + ax * by - ay * bx;', replace: '  out[2] = az * bw + aw * bz + ax * by + ay * bx;' }],
    tests: ['tests/unit/controls.test.ts'],
  },
  {
    name: 'Z11 the core\'s own axis quaternion: the whole angle where the half belongs',
    edits: [{ file: 'src/scene/group-rotation.ts', find: 'const h = (deg * DEG) / 2;', replace: 'const h = deg * DEG;' }],
    tests: ['tests/unit/controls.test.ts'],
  },
  {
    name: 'Z12 flat shading does not ask for the mesh extras (drawn smooth)',
    edits: [{ file: 'src/render/parts.ts', find: '  if (state.shading === \'flat\') return true;\n', replace: '' }],
    tests: [LOD],
  },
  {
    name: 'Z13 the renderer\'s checks are never loaded (frames go unchecked)',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => h.checks,', replace: 'needed: () => false,' }],
    tests: ['tests/e2e/frame-checks.spec.ts'],
  },
  {
    name: 'Z14 two parts loading at once: only the first waited for (a course frame drawn before its projection)',
    edits: [{ file: 'src/frame/lazy-parts.ts', find: 'if (p && this.specs[i].holds) held.push(p);', replace: 'if (p && this.specs[i].holds && !held.length) held.push(p);' }],
    tests: [CHUNK],
  },
  {
    name: 'Z15 the group rotation\'s own vector rotation: the last cross term added where it is subtracted',
    edits: [{ file: 'src/scene/group-rotation.ts', find: '  out[0] = vx + qw * tx + qy * tz - qz * ty;', replace: '  out[0] = vx + qw * tx + qy * tz + qz * ty;' }],
    tests: ['tests/unit/controls.test.ts'],
  },
  {
    name: 'Z16 the group rotation\'s own vector rotation summed in another order (not gl-matrix\'s bits)',
    edits: [{ file: 'src/scene/group-rotation.ts', find: '  out[1] = vy + qw * ty + qz * tx - qx * tz;', replace: '  out[1] = vy + (qw * ty + qz * tx - qx * tz);' }],
    tests: ['tests/unit/controls.test.ts'],
  },
  {
    name: 'Z17 quatToEuler\'s r21 entry with the wrong sign',
    edits: [{ file: 'src/scene/group-rotation.ts', find: 'r21 = zy + wx,', replace: 'r21 = zy - wx,' }],
    tests: ['tests/unit/controls.test.ts'],
  },
  {
    name: 'Z18 a frame with a turn is drawn without waiting for the group rotation (about the origin)',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.scenes.turnSet(), holds: true,', replace: 'needed: (h) => h.scenes.turnSet(), holds: false,' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z19 the controls\' chunk does not hand the group rotation on (`scene` unturned after a trackball turn)',
    edits: [{ file: 'src/element/parts.ts', find: '    h.provideRotation(chunk.groupRotation);\n', replace: '' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z20 the centre of a value built after the group rotation came is never found (the turn about the old centre)',
    edits: [{ file: 'src/element/scene-value.ts', find: '      this.centered = false;\n      this.builds++;', replace: '      this.centered = true;\n      this.builds++;' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z21 `scene` never turned once the group rotation is in',
    edits: [{ file: 'src/element/scene-value.ts', find: '    if (!code) return this.current;\n', replace: '    if (code) return this.current;\n' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z22 a lazy part that fails is not warned about',
    edits: [{ file: 'src/frame/lazy-parts.ts', find: 'this.listener.warn(loadFailed(', replace: 'void (loadFailed(' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z23 Renderer.load never asks for the debug views (the final image in their place)',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => h.ctx.state.view !== \'final\' && h.ctx.state.view !== \'scene\',', replace: 'needed: () => false,' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z24 the debug views\' chunk asked for in the final view too (fetched by every page)',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => h.ctx.state.view !== \'final\' && h.ctx.state.view !== \'scene\',', replace: 'needed: (h) => h.ctx.state.view !== \'scene\',' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z25 the passes view\'s reflection tile drawn over the fresnel tile\'s place',
    edits: [{ file: 'src/render/debug-views.ts', find: 'n += blit(f, framebuffer, setTile(0, bottom, left, top));', replace: 'n += blit(f, framebuffer, setTile(0, 0, left, top));' }],
    tests: ['tests/e2e/goldens.spec.ts'],
  },
  {
    name: 'Z26 FrameSetup draws in perspective though it has the orthographic projection',
    edits: [{ file: 'src/frame/frame-setup.ts', find: "const projection = course || !this.ortho ? 'perspective'", replace: "const projection = course || this.ortho ? 'perspective'" }],
    tests: ['tests/unit/orthographic.test.ts'],
  },
  {
    name: 'Z27 Renderer.load never asks for the orthographic projection (drawn in perspective)',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => h.ctx.state.projection === \'orthographic\',', replace: 'needed: () => false,' }],
    tests: [CORE],
  },
  {
    name: 'Z28 the orthographic projection\'s depth row with the wrong sign (near and far swapped)',
    edits: [{ file: 'src/math/orthographic.ts', find: '  out[10] = 2 * depth;', replace: '  out[10] = -2 * depth;' }],
    tests: ['tests/unit/orthographic.test.ts'],
  },
  {
    name: 'Z29 a child found but what gathers the parts never fetched (the default scene for ever)',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.source.hasChild(),', replace: 'needed: () => false,' }],
    tests: ['tests/e2e/children.spec.ts'],
  },
  {
    name: 'Z30 the gatherer\'s arrival not waited for (the default scene shown first)',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.source.hasChild(), holds: true,', replace: 'needed: (h) => h.source.hasChild(), holds: false,' }],
    tests: ['tests/e2e/children-chunk.spec.ts'],
  },
  {
    name: 'Z31 a failure\'s message part left empty',
    edits: [{ file: 'src/element/failure.ts', find: 'this.message.textContent = m?.FAILURE_MESSAGES[type] ?? message;', replace: 'this.message.textContent = m ? \'\' : message;' }],
    tests: [CORE, 'tests/e2e/no-webgl2.spec.ts'],
  },
  {
    name: 'Z32 no message at all when the messages\' chunk cannot load',
    edits: [{ file: 'src/element/failure.ts', find: 'm?.FAILURE_MESSAGES[type] ?? message', replace: 'm?.FAILURE_MESSAGES[type] ?? \'\'' }],
    tests: [CORE],
  },
  {
    name: 'Z33 image textures never asked for (the procedural texture for ever)',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.namesImages(),', replace: 'needed: () => false,' }],
    tests: [CORE, 'tests/e2e/texture-images.spec.ts'],
  },
  {
    name: 'Z34 only the first scene value is looked through for images (a texture added later is never fetched)',
    edits: [{ file: 'src/element/scene-value.ts', find: '      this.images = this.value.objects.some(', replace: '      this.images = this.builds === 0 && this.value.objects.some(' }],
    tests: [CORE],
  },
  // The mechanism itself (src/frame/lazy-parts.ts) and the chunk groups made from the table.
  {
    name: 'P1 a module provided while its own fetch is under way is replaced by the fetched one when that lands',
    edits: [{ file: LP, find: '      if (this.status[i] !== LOADING) return; // provided meanwhile\n', replace: '' }],
    tests: [PARTS],
  },
  {
    name: 'P2 a part not marked as loading is fetched again by the next frame',
    edits: [{ file: LP, find: "    this.status[i] = LOADING;\n", replace: '' }],
    tests: [PARTS],
  },
  {
    name: 'P3 a new promise every frame while a part loads (allocation per frame)',
    edits: [{ file: LP, find: 'if (started || !this.waiting) this.waiting = this.allHeld();', replace: 'this.waiting = this.allHeld();' }],
    tests: [PARTS],
  },
  {
    name: 'P4 a provided module is not handed to its owner',
    edits: [{ file: LP, find: "    this.values[i] = value;\n    spec.arrived?.(this.host, value);\n  }\n\n  /** A part is on its way", replace: "    this.values[i] = value;\n  }\n\n  /** A part is on its way" }],
    tests: [PARTS],
  },
  {
    name: 'P5 a part that does not hold the frame holds it',
    edits: [{ file: LP, find: '      if (specs[i].holds) holds = true;', replace: '      holds = true;' }],
    tests: [PARTS],
  },
  {
    name: 'P6 an owner that throws on arrival: the part counts as in',
    edits: [{ file: LP, find: "      this.status[i] = FAILED;\n      this.values[i] = null;\n", replace: "      if (this.status[i] !== IN) this.status[i] = FAILED;\n" }],
    tests: [PARTS],
  },
  {
    name: 'P7 fetch() of a part no frame asked for never starts it (a failure shows no text)',
    edits: [{ file: LP, find: '    if (this.status[i] === ABSENT) this.start(i);\n    return (this.loads[i]', replace: '    return (this.loads[i]' }],
    tests: [PARTS],
  },
  {
    name: 'P8 a chunk group matches any file ending in one of its names (a neighbour joins it)',
    edits: [{ file: 'scripts/chunk-groups.ts', find: "new RegExp(`(^|[\\\\\\\\/])(${paths.join('|')})$`)", replace: "new RegExp(`(${paths.join('|')})$`)" }],
    tests: [PARTS],
  },
  {
    name: 'P9 the chunk groups leave out the table\'s order (a shared file goes to a later group)',
    edits: [{ file: 'scripts/chunk-groups.ts', find: 'return Object.entries(table).flatMap(', replace: 'return Object.entries(table).reverse().flatMap(' }],
    tests: [PARTS],
  },
];
