// What the core leaves out and loads when a scene asks (docs/package.md#chunks): camera-src's two chunks (the
// element's camera-source, the renderer's course-projection), the group rotation, the debug
// views, the orthographic projection, the children's gatherer, the failure messages and image
// textures, and how frames wait for them: in a page, as the element loads them.
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const CHUNK = 'tests/e2e/course-chunk.spec.ts';
const LOD = 'tests/e2e/reflection-lod.spec.ts';
const CHUNKS = 'tests/e2e/turn-debug-chunks.spec.ts';
const CORE = 'tests/e2e/core-chunks.spec.ts';
const PARTS = 'tests/unit/lazy-parts.test.ts';
const GLTF = 'tests/e2e/gltf.spec.ts';

export default [
  {
    name: 'Z1 camera-source\'s chunk arrives but is never connected (camera-src never loads its file)',
    why: 'lazy chunks in a page: camera-src\'s chunk connected to the element',
    edits: [{ file: 'src/element/camera-rig.ts', find: '    if (this.connected) this.source.hostConnected();\n', replace: '' }],
    tests: [CHUNK],
  },
  {
    name: 'Z2 ready fired while a lazy part (camera-src\'s reader) is still on its way',
    why: 'lazy chunks in a page: the element\'s ready event waits for them',
    edits: [{ file: 'src/element/glass-plane-scene.ts', find: ' || this.rig.loading || this.parts.loading, atRest:', replace: ' || this.rig.loading, atRest:' }],
    tests: [CHUNK],
  },
  {
    name: 'Z3 the course projection loads but FrameSetup is never given it',
    why: 'lazy chunks in a page: the course projection handed to the WebGL renderer',
    edits: [{ file: 'src/render/parts.ts', find: '    h.ctx.setup.course ??= new m.CourseProjection();\n', replace: '' }],
    tests: [CHUNK],
  },
  {
    name: 'Z4 Renderer.load never asks for the course projection',
    why: 'lazy chunks in a page: the WebGL renderer asks for the course projection',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => !!h.ctx.state.courseCamera,', replace: 'needed: () => false,' }],
    tests: [CHUNK],
  },
  {
    name: 'Z6 camera-source takes the depth range straight from scene/ (its chunk loads without the projection\'s)',
    why: 'lazy chunks in a page: which chunk camera-src\'s code lands in (the build)',
    edits: [{ file: 'src/element/camera-source.ts', find: "import { courseSceneRange } from '../frame/course-projection';", replace: "import { courseSceneRange } from '../scene/course-depth';" }],
    tests: [CHUNK],
  },
  {
    name: 'Z7 the element\'s WebGL backend does not hand the scene to Renderer.load (reflections never clustered)',
    why: 'lazy chunks in a page: the WebGL backend hands the scene to Renderer.load',
    edits: [{ file: 'src/element/webgl-backend.ts', find: 'return this.renderer.load(scene, state) !== null;', replace: 'return this.renderer.load(null, state) !== null;' }],
    tests: [LOD],
  },
  {
    name: 'Z8 only meshes, not Gaussians, ask for the mesh extras (a Gaussian never drawn)',
    why: 'lazy chunks in a page: the WebGL renderer\'s mesh extras for Gaussians',
    edits: [{ file: 'src/render/parts.ts', find: 'if (k === \'gaussian\' || (k === \'mesh\' && state.tessellation === \'auto\')) return true;', replace: 'if (k === \'mesh\' && state.tessellation === \'auto\') return true;' }],
    tests: [LOD],
  },
  {
    name: 'Z9 a lazy part that failed is asked for again (a warning every frame)',
    why: 'lazy chunks in a page: a failed part\'s warnings from a running element',
    edits: [{ file: 'src/frame/lazy-parts.ts', find: '      this.status[i] = FAILED;\n', replace: '      this.status[i] = ABSENT;\n' }],
    tests: [LOD],
  },
  {
    name: 'Z12 flat shading does not ask for the mesh extras (drawn smooth)',
    why: 'lazy chunks in a page: the WebGL renderer\'s mesh extras for flat shading',
    edits: [{ file: 'src/render/parts.ts', find: '  if (state.shading === \'flat\') return true;\n', replace: '' }],
    tests: [LOD],
  },
  {
    name: 'Z13 the renderer\'s checks are never loaded (frames go unchecked)',
    why: 'lazy chunks in a page: the WebGL renderer\'s frame checks',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => h.checks,', replace: 'needed: () => false,' }],
    tests: ['tests/e2e/frame-checks.spec.ts'],
  },
  {
    name: 'Z14 two parts loading at once: only the first waited for (a course frame drawn before its projection)',
    why: 'lazy chunks in a page: a course frame in WebGL waits for both parts',
    edits: [{ file: 'src/frame/lazy-parts.ts', find: 'if (p && this.specs[i].holds) held.push(p);', replace: 'if (p && this.specs[i].holds && !held.length) held.push(p);' }],
    tests: [CHUNK],
  },
  {
    name: 'Z18 a frame with a turn is drawn without waiting for the group rotation (about the origin)',
    why: 'lazy chunks in a page: a turned frame waits for the group rotation',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.scenes.turnSet(), holds: true,', replace: 'needed: (h) => h.scenes.turnSet(), holds: false,' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z19 the controls\' chunk does not hand the group rotation on (`scene` unturned after a trackball turn)',
    why: 'lazy chunks in a page: the controls\' chunk hands the group rotation to the element',
    edits: [{ file: 'src/element/parts.ts', find: '    h.provideRotation(chunk.groupRotation);\n', replace: '' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z20 the centre of a value built after the group rotation came is never found (the turn about the old centre)',
    why: 'lazy chunks in a page: the element\'s scene value turned about its centre',
    edits: [{ file: 'src/element/scene-value.ts', find: '      this.centered = false;\n      this.builds++;', replace: '      this.centered = true;\n      this.builds++;' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z21 `scene` never turned once the group rotation is in',
    why: 'lazy chunks in a page: the element\'s scene value turned once the rotation is in',
    edits: [{ file: 'src/element/scene-value.ts', find: '    if (!code) return this.current;\n', replace: '    if (code) return this.current;\n' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z22 a lazy part that fails is not warned about',
    why: 'lazy chunks in a page: a failed chunk\'s warning from a running element',
    edits: [{ file: 'src/frame/lazy-parts.ts', find: 'this.listener.warn(loadFailed(', replace: 'void (loadFailed(' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z23 Renderer.load never asks for the debug views (the final image in their place)',
    why: 'lazy chunks in a page: the WebGL renderer asks for the debug views',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => h.ctx.state.view !== \'final\' && h.ctx.state.view !== \'scene\',', replace: 'needed: () => false,' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z24 the debug views\' chunk asked for in the final view too (fetched by every page)',
    why: 'lazy chunks in a page: the debug views\' chunk not fetched by every page',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => h.ctx.state.view !== \'final\' && h.ctx.state.view !== \'scene\',', replace: 'needed: (h) => h.ctx.state.view !== \'scene\',' }],
    tests: [CHUNKS],
  },
  {
    name: 'Z25 the passes view\'s reflection tile drawn over the fresnel tile\'s place',
    why: 'WebGL debug view tiles (goldens): only a browser draws it',
    edits: [{ file: 'src/render/debug-views.ts', find: 'n += blit(f, framebuffer, setTile(0, bottom, left, top));', replace: 'n += blit(f, framebuffer, setTile(0, 0, left, top));' }],
    tests: ['tests/e2e/goldens.spec.ts'],
  },
  {
    name: 'Z27 Renderer.load never asks for the orthographic projection (drawn in perspective)',
    why: 'lazy chunks in a page: the WebGL renderer asks for the orthographic projection',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => h.ctx.state.projection === \'orthographic\',', replace: 'needed: () => false,' }],
    tests: [CORE],
  },
  {
    name: 'Z29 a child found but what gathers the parts never fetched (the default scene for ever)',
    why: 'lazy chunks in a page: the children\'s gatherer fetched by the element',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.source.hasChild(),', replace: 'needed: () => false,' }],
    tests: ['tests/e2e/children.spec.ts'],
  },
  {
    name: 'Z30 the gatherer\'s arrival not waited for (the default scene shown first)',
    why: 'lazy chunks in a page: the element waits for the children\'s gatherer',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.source.hasChild(), holds: true,', replace: 'needed: (h) => h.source.hasChild(), holds: false,' }],
    tests: ['tests/e2e/children-chunk.spec.ts'],
  },
  {
    name: 'Z31 a failure\'s message part left empty',
    why: 'the element in a page: its failure message in the shadow DOM (messages\' chunk)',
    edits: [{ file: 'src/element/failure.ts', find: 'this.message.textContent = m?.FAILURE_MESSAGES[type] ?? message;', replace: 'this.message.textContent = m ? \'\' : message;' }],
    tests: [CORE, 'tests/e2e/no-webgl2.spec.ts'],
  },
  {
    name: 'Z32 no message at all when the messages\' chunk cannot load',
    why: 'the element in a page: its failure message when the messages\' chunk fails',
    edits: [{ file: 'src/element/failure.ts', find: 'm?.FAILURE_MESSAGES[type] ?? message', replace: 'm?.FAILURE_MESSAGES[type] ?? \'\'' }],
    tests: [CORE],
  },
  {
    name: 'Z33 image textures never asked for (the procedural texture for ever)',
    why: 'lazy chunks in a page: image textures fetched by the element',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.namesImages(),', replace: 'needed: () => false,' }],
    tests: [CORE, 'tests/e2e/texture-images.spec.ts'],
  },
  {
    name: 'Z34 only the first scene value is looked through for images (a texture added later is never fetched)',
    why: 'lazy chunks in a page: image textures fetched for a later scene value',
    edits: [{ file: 'src/element/scene-value.ts', find: '      this.images = this.value.objects.some(', replace: '      this.images = this.builds === 0 && this.value.objects.some(' }],
    tests: [CORE],
  },
  // The chunk groups made from the table (scripts/chunk-groups.ts, outside Stryker's src/); the
  // mechanism itself (src/frame/lazy-parts.ts) is unit-tested: StrykerJS mutates it.
  {
    name: 'P8 a chunk group matches any file ending in one of its names (a neighbour joins it)',
    why: 'scripts/: Stryker mutates src/ only (the chunk groups of the build)',
    edits: [{ file: 'scripts/chunk-groups.ts', find: "new RegExp(`(^|[\\\\\\\\/])(${paths.join('|')})$`)", replace: "new RegExp(`(${paths.join('|')})$`)" }],
    tests: [PARTS],
  },
  {
    name: 'P9 the chunk groups leave out the table\'s order (a shared file goes to a later group)',
    why: 'scripts/: Stryker mutates src/ only (the chunk groups of the build)',
    edits: [{ file: 'scripts/chunk-groups.ts', find: 'return Object.entries(table).flatMap(', replace: 'return Object.entries(table).reverse().flatMap(' }],
    tests: [PARTS],
  },
  {
    name: 'Z40 the meshopt decoder\'s chunk handed on as the module, not its MeshoptDecoder (no meshopt file decodes)',
    why: 'lazy chunks in a page: the decoders are imported only in a page or its worker (a unit test injects its own)',
    edits: [{ file: 'src/loaders/gltf/decoders.ts', find: ".then((m) => m.MeshoptDecoder)", replace: ".then((m) => m as unknown as MeshoptDecoderLike)" }],
    tests: [GLTF],
    build: true,
  },
  {
    name: 'Z41 a Draco wasm that failed to load is remembered (every later Draco model fails too)',
    why: 'lazy chunks in a page: the Draco decoder is loaded only in a page or its worker (a unit test injects its own)',
    edits: [{ file: 'src/loaders/gltf/decoders.ts', find: '    draco = null;\n', replace: '' }],
    tests: [GLTF],
    build: true,
  },
  {
    name: 'Z42 the Draco wasm\'s HTTP status not checked (an error page handed to WebAssembly)',
    why: 'lazy chunks in a page: the Draco decoder is loaded only in a page or its worker (a unit test injects its own)',
    edits: [{ file: 'src/loaders/gltf/decoders.ts', find: '  if (!response.ok) throw new Error(`${wasmUrl}: HTTP ${response.status}`);\n', replace: '' }],
    tests: [GLTF],
    build: true,
  },
];
