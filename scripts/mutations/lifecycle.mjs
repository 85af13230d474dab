// The element's lifecycle: dispose, context loss and restore, renderer switch, off-screen, idle.
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const LEAKS = 'tests/e2e/gl-leaks.spec.ts';
const LIFECYCLE = 'tests/e2e/lifecycle.spec.ts';
const ON_DEMAND = 'tests/e2e/on-demand.spec.ts';
const ELEMENT = 'src/element/glass-plane-scene.ts';
const LOOP = 'src/element/frame-loop.ts';
const BACKENDS = 'src/element/backend-controller.ts';
const SOFTWARE = 'src/element/software-backend.ts';
const SCENES = 'src/element/scene-value.ts';
const REBUILDS = 'tests/e2e/scene-rebuilds.spec.ts';

export default [
  {
    // The default element's procedural texture is the sRGB one (color-space srgb).
    name: '4 dispose() skips the texture',
    why: 'WebGL resources released on dispose: only a browser counts them (gl-leaks)',
    edits: [{ file: 'src/render/gl/shared-resources.ts', find: '    this.proceduralSrgb?.dispose();\n', replace: '' }],
    tests: [LEAKS],
  },
  {
    name: '14 the software renderer never given the decoded images',
    why: 'the element in a page: decoded images handed to the software renderer',
    edits: [{ file: SOFTWARE, find: '    this.software.setImage(url, image);\n', replace: '' }],
    tests: ['tests/e2e/model-reference.spec.ts'],
  },
  {
    name: 'E1 image textures lost after a context restore (a new renderer is not handed the images decoded so far)',
    why: 'the element in a page: a WebGL context loss and restore',
    edits: [{ file: 'src/element/texture-images.ts', find: '    for (const [url, image] of this.ready) sink.setImage(url, image);\n', replace: '' }],
    tests: [LIFECYCLE],
  },
  {
    name: 'E2 dispose() skips the image textures',
    why: 'WebGL resources released on dispose: only a browser counts them (gl-leaks)',
    edits: [{ file: 'src/render/renderer.ts', find: '    this.textures.dispose();\n', replace: '' }],
    tests: [LEAKS],
  },
  {
    name: 'E3 after webgl → software the canvas keeps the stale WebGL frame (generation test inverted)',
    why: 'the element in a page: its canvas after a webgl → software switch',
    edits: [{
      file: SOFTWARE,
      find: 'if (!this.disposed) (out as ImageBitmapRenderingContext).transferFromImageBitmap(b);',
      replace: 'if (this.disposed) (out as ImageBitmapRenderingContext).transferFromImageBitmap(b);',
    }],
    tests: [LEAKS],
  },
  {
    name: 'E4 switching back to webgl asks for the context, not the renderer: it stays software',
    why: 'the element in a page: a software → webgl switch',
    edits: [{ file: BACKENDS, find: "(!wantSoftware && kind === 'webgl')) return;", replace: '(!wantSoftware && this.shared)) return;' }],
    tests: [LEAKS],
  },
  {
    name: 'E5 off-screen elements keep drawing (frames scheduled whatever the IntersectionObserver said)',
    why: 'the element in a page: IntersectionObserver and its frames',
    edits: [{ file: LOOP, find: '|| !this.host.canDraw() || !this.inView || document.hidden) return;', replace: '|| !this.host.canDraw() || document.hidden) return;' }],
    tests: [ON_DEMAND],
  },
  {
    name: 'E6 idle broken: the live clock alone keeps frames coming (&& for ||)',
    why: 'the element in a page: idle frames on requestAnimationFrame',
    edits: [{ file: ELEMENT, find: '(this.values.time === null && sceneSpins(this.scenes.current))', replace: '(this.values.time === null || sceneSpins(this.scenes.current))' }],
    tests: [ON_DEMAND],
  },
  {
    name: 'E7 idle broken: spin counted for a scene of children, which has no cube to turn',
    why: 'the element in a page: idle frames on requestAnimationFrame',
    edits: [{ file: ELEMENT, find: '(this.values.time === null && sceneSpins(this.scenes.current))', replace: '(this.values.time === null && this.effectiveSpin() !== 0)' }],
    tests: [ON_DEMAND],
  },
  {
    name: 'E8 removal leaves the element a client of the shared context (rebuilt on a restore)',
    why: 'the element in a page: the shared WebGL context after removal',
    edits: [{ file: BACKENDS, find: '    this.stop();\n    this.shared?.release(this);\n', replace: '    this.stop();\n' }],
    tests: [LEAKS],
  },
  {
    name: 'E9 removal leaves the reduced-motion listener',
    why: 'the element in a page: a matchMedia listener after removal',
    edits: [{ file: LOOP, find: "    this.motionQuery?.removeEventListener('change', this.onMotionPreference);\n", replace: '' }],
    tests: [LIFECYCLE],
  },
  {
    name: 'E10 every attribute change rebuilds the scene value again, not only those that shape it',
    why: 'the element in a page: scene rebuilds on attribute changes',
    edits: [{ file: SCENES, find: '    if (SHAPING.has(property)) this.contentChanged();', replace: '    this.contentChanged();' }],
    tests: [REBUILDS],
  },
  {
    name: 'E11 a trackball turn rebuilds the scene value (every frame of its inertia)',
    why: 'the element in a page: scene rebuilds during a trackball\'s inertia',
    edits: [{ file: SCENES, find: '  turnChanged(): void {\n    this.turnedValue = null;', replace: '  turnChanged(): void {\n    this.value = this.turnedValue = null;' }],
    tests: [REBUILDS],
  },
  {
    name: 'E12 the software worker keeps drawing the first scene it was sent',
    why: 'the software worker in a page: a Worker only a browser runs',
    edits: [{ file: 'src/software/protocol.ts', find: '    if (scene === this.lastScene) return { scene: null', replace: '    if (this.lastScene) return { scene: null' }],
    tests: [REBUILDS],
  },
  {
    name: 'L15 frames not held while the children\'s chunk loads (the default scene shown first)',
    why: 'lazy chunks in a page: frames held while the children\'s chunk loads',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.source.hasUndefinedChild(), holds: true,', replace: 'needed: (h) => h.source.hasUndefinedChild(), holds: false,' }],
    tests: ['tests/e2e/children-chunk.spec.ts'],
  },
  {
    name: 'L16 the scene element never loads its children (they stay undefined)',
    why: 'lazy chunks in a page: the children\'s chunk fetched by the element',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => h.source.hasUndefinedChild(),', replace: 'needed: () => false,' }],
    tests: ['tests/e2e/children-chunk.spec.ts'],
  },
  {
    name: 'L17 a part that failed still holds the frames (nothing asks for a frame again)',
    why: 'lazy chunks in a page: a failed part stops holding the element\'s frames',
    edits: [{ file: 'src/frame/lazy-parts.ts', find: 'if (s === IN || s === FAILED || !specs[i].needed(this.host)) continue;', replace: 'if (s === IN || !specs[i].needed(this.host)) continue;' }],
    tests: ['tests/e2e/children-chunk.spec.ts'],
  },
  {
    name: 'L18 a worker\'s frame that lands waits for the next animation frame before the next is asked for (30 Hz for a 16 ms frame)',
    why: 'the element in a page: worker frames paced on requestAnimationFrame',
    edits: [{ file: LOOP, find: '    if (!offThread || !moving || !this.host.canDraw()', replace: '    if (true || !moving || !this.host.canDraw()' }],
    tests: ['tests/e2e/software.spec.ts'],
  },
  {
    name: 'L19 frames drawn on the main thread follow each other at once too (the page never runs between them)',
    why: 'the element in a page: main-thread frames paced on requestAnimationFrame',
    edits: [{ file: SOFTWARE, find: "        this.host.resume(this.software.thread === 'worker');", replace: '        this.host.resume(true);' }],
    tests: ['tests/e2e/software.spec.ts'],
  },
  {
    name: 'L20 properties set before the definition set again only at connection (an upgraded element not yet connected ignores them)',
    why: 'the element in a page: custom element upgrade of properties set before',
    edits: [{ file: ELEMENT, find: "    for (const name of upgradeProperties(this, ['alt', 'objectRotation'])) this.attributeChangedCallback(name);\n", replace: '' },
      { file: ELEMENT, find: '  connectedCallback(): void {\n', replace: "  connectedCallback(): void {\n    for (const name of upgradeProperties(this, ['alt', 'objectRotation'])) this.attributeChangedCallback(name);\n" }],
    tests: ['tests/e2e/properties.spec.ts'],
  },
  {
    name: 'L21 switched to the software renderer, the element stays a client of the shared context (its loss stops it; the canvas keeps WebGL\'s limit)',
    why: 'the element in a page: the shared WebGL context after a software switch',
    edits: [{ file: BACKENDS, find: '    if (wantSoftware) {\n      this.shared?.release(this);\n      this.shared = null;\n    }\n', replace: '' }],
    tests: [LIFECYCLE],
  },
];
