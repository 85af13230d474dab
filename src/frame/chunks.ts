// The package's chunks: what the self-contained build is split into, each with its size budget
// (bytes, min+gzip; `npm run size` checks them). A lazy part (frame/lazy-parts.ts) names the chunk
// its module is built into. Where `modules` is given, vite.config.ts makes it one chunk group: the
// small parts needed at the same moments share one file instead of one request each. The other
// chunks take the name of their entry module (rough-glass-gl.ts → rough-glass-gl). A group takes
// what its modules import too, unless an earlier group has it: shared modules' groups come first.
// Plain data, no imports: vite.config.ts and scripts/size.mjs read it too.
// Stryker disable all: build data; `npm run size` and the build check it against the built files (no unit test builds)

export interface Chunk {
  /** Largest size allowed, bytes of min+gzip. */
  readonly budget: number;
  /** Source files (from the repository's root) gathered into this chunk. */
  readonly modules?: readonly string[];
  /** When it is fetched, for the size table. */
  readonly when: string;
}

export const CHUNKS = {
  // 30,300 until a WebGL frame waited for the GPU to finish the one before (+141 B: 30,394);
  // then transparent objects' depth for rough glass's codes (30,424); then properties set before
  // the definition set again in the upgrade's constructor, not at connection (+50 B: 30,476);
  // then the scene value frozen where it is handed over (+59 B: 30,535); then the host split
  // to its 300 lines (frame events, attribute parsing and routes in modules of their own: +87 B);
  // then the loading bar and `poster` (+540 B, 31,190): both must be live from the element's first
  // moment — the poster covers the canvas before any chunk arrives, and a model's first bytes can
  // come before the children's chunks; then a material's emissive (the uniform and its line: +27 B),
  // then a missing image drawn plain for a glTF or course object (+6 B); then glTF materials' variant
  // (+310 B, 31,610): which objects take it, the part that fetches its shader (pbr-gl), the three
  // uniforms, standard.frag's branch — the BRDF itself is in pbr-gl; then tone mapping (+479 B, 32,129):
  // tone-mapping and exposure, auto's choice, half-float frame and reflection, the ceiling the glass reads
  // R to, the tone-mapped encodes' variants — the curves themselves are in pbr-gl; then an environment's light on glTF
  // materials in WebGL (+267 B, 32,396): the part that fetches environment-gl, the variant, the slot for its textures and their
  // binding — the shader part, the textures and the maps' making are in environment-gl; then the part's load waiting for
  // the studio's maps (+14 B, 32,410); then `environment` and `environment-intensity` into the scene value (+79 B, 32,489); then
  // glTF materials' metallic-roughness, occlusion and emissive maps (+154 B, 32,643): the list of the images a material draws with
  // (which the element fetches and waits for), the slot for the maps' textures, their sync, binding and disposal, and
  // standard.frag's call — the textures' code and the shader's reads are in pbr-gl; then glTF's doubleSided and the base colour
  // texture read through its KHR_texture_transform in standard.frag (+49 B, 32,692); then the normal map (+197 B, 32,889): the
  // tangent attribute, the variant and its key, standard.vert's and standard.frag's lines — the perturbation is in pbr-gl; then
  // vertex colours (the attribute, the variant, the shaders' lines: +118 B, 33,007); then `environment="url"` (+265 B, 33,272):
  // the attribute's URL form, the part that fetches environment-files when it names one and the scene has a glTF material, the
  // scene source's asking for the image and `ready` waiting for it, the scene value's image environment and the key its maps are
  // kept by — the reading, decoding and reduction of the image are in environment-files; then glTF's alpha mask (+126 B over
  // 33,300: the variant, its key and define, standard.frag's discard — its uniform is set in pbr-gl); then refinement at rest
  // (+1,305 B, 34,755: the `refine` attribute, the frame loop's still view and the `refined` event, the strata sequence and the
  // clip-space shift, the preview, sum and blend of LinearFrame, the copy shader, the textures' level-of-detail bias). In the
  // core and not a lazy part: every still view of every element refines once `refine` has its default from the bench
  // (docs/refinement.md#the-attribute), and its first strata frame must not wait for a fetch. Then rough glass's samples at
  // each frame's strata (gatherJitter, +107 B with the shaders' mapRead, 34,907); then textures and the glass's body read
  // over the stratum by scaled derivatives (textureGrad, uFootprint: +61 B, 34,968); then whenRefined() (+203 B, 35,171: the
  // method, its waiters, the frame on its way, the loop's rest, the rejection on a failure).
  core: { budget: 35185, when: 'with the element' },
  // Checks, debug views and the texts of failures: for developers, or when something went wrong.
  diagnostics: {
    budget: 1400, when: 'debug-view, frame checks, or a failure',
    modules: ['src/render/frame-checks.ts', 'src/render/debug-views.ts', 'src/element/failure-messages.ts'],
  },
  // The children's parts, their files (loaded once per page) and image textures. 1,750 until a
  // load error could name a glTF file's JSON path (+24 B); +3 B with refinement at rest (the minifier's names, 1,803).
  'scene-extras': {
    budget: 1825, when: 'a child element, a file or an image',
    modules: [
      'src/element/children/gather-parts.ts', 'src/element/texture-images.ts', 'src/element/absolute-url.ts',
      'src/element/children/model-cache.ts', 'src/loaders/load-error.ts',
    ],
  },
  // Flat shading, the Gaussian, the reflection's clustering and the GGX maths: shared by the
  // software renderer, WebGL's rough glass and its mesh extras.
  'render-extras': {
    budget: 2400, when: 'shading="flat", a Gaussian, a dense mesh, roughness, or the CPU renderer',
    modules: [
      'src/render/mesh-extras.ts', 'src/scene/geometry/flat.ts', 'src/scene/geometry/gaussian.ts',
      'src/scene/geometry/cluster.ts', 'src/math/ggx.ts', 'src/math/invert.ts', 'src/frame/rough-glass.ts',
    ],
  },
  // What turns the scene value (the trackball's, or objectRotation's, first turn).
  'group-rotation': { budget: 1300, when: 'a turn', modules: ['src/scene/group-rotation.ts'] },
  // camera-src (the element's reader, the renderer's projection) and projection="orthographic".
  'camera-extras': {
    budget: 2900, when: 'camera-src, or projection="orthographic"',
    modules: [
      'src/element/camera-source.ts', 'src/frame/course-projection.ts', 'src/scene/course-depth.ts',
      'src/math/course-camera.ts', 'src/frame/orthographic-view.ts',
    ],
  },
  controls: { budget: 5800, when: 'controls' },
  'rough-glass-gl': { budget: 5200, when: 'roughness > 0 (WebGL)' },
  // glTF materials' shader part (docs/pbr.md#the-scenes-lights), 900 until the tone-mapping curves (+172 B, 1,072), then
  // the environment's term in the lights' sum (+35 B, 1,107), then the metallic-roughness, occlusion and emissive maps (their
  // textures, PbrMapsGl, and their reads in the shader: +772 B, 1,879), then each texture's KHR_texture_transform (+165 B, 2,044),
  // then the normal map (its texture and mappedNormal: +241 B, 2,285).
  // Then the alpha mask's uniform (+24 B over 2,300).
  'pbr-gl': { budget: 2350, when: 'a glTF material or tone mapping (WebGL)' },
  // An environment's light in WebGL (docs/pbr.md#the-environment): its shader part and textures, and the code that makes its maps.
  // The shader part and the textures (1,407): the making of the maps is environment-light, which the CPU renderer loads too.
  'environment-gl': { budget: 1425, when: 'a glTF material under an environment (WebGL)' },
  // The making of an environment's maps and the split-sum table, a row at a time (frame/environment-light.ts, math/prefilter.ts,
  // the studio), once a page: by environment-gl, or by the CPU renderer on the main thread (2,582); the same in its workers (2,528).
  // Then an environment image (docs/pbr.md#an-image): its lookup, the light the maps are made from (math/environment-image.ts,
  // which environment-files reads too: one chunk, not a third), and the makings and maps kept by each environment's key
  // (+509 B, 3,109 here; +233 B, 2,783 in the workers).
  'environment-light': {
    budget: 3125, when: 'a glTF material under an environment',
    modules: ['src/frame/environment-light.ts', 'src/math/environment-image.ts'],
  },
  'assets/environment-light': { budget: 2800, when: 'the same, in the CPU renderer\'s workers' },

  // 4,700 until a glTF model was drawn plain without a texture (+1 B), then reflect="false" (+87 B), then a glTF mesh's tangents
  // and vertex colours into its MeshData (+15 B, 4,865).
  'child-elements': { budget: 4875, when: 'a child element' },
  'model-loader': { budget: 14800, when: 'a model file' },
  'model-fetch': { budget: 2400, when: 'a model file' },
  'assets/obj-worker': { budget: 13800, when: 'a model file' },
  // glTF's reader (docs/gltf.md#loading): on the page for small files, in its worker for big ones.
  // 11,200 and 10,500 until the reader skipped copies under identity matrices (+61 B, +108 B),
  // then tangents for normal maps (+573 B, +581 B), then 11,900 and 11,250 until top-level fields'
  // paths without a leading dot and Draco names checked as own properties (+16 B, +13 B), then each texture's transform turned the
  // OBJ way up with the UVs (+7 B, 11,957).
  'gltf-model': { budget: 11975, when: 'a glTF model' },
  'assets/gltf-worker': { budget: 11300, when: 'a glTF model of 256 kB or more' },
  // meshoptimizer's decoder (its wasm inlined as text), on the page or in the glTF worker.
  meshopt_decoder: { budget: 7300, when: 'a glTF model with EXT_meshopt_compression' },
  'assets/meshopt_decoder': { budget: 7300, when: 'the same, read in the glTF worker' },
  // draco3d's decoder (its emscripten glue; the wasm, 82.6 kB gzipped, is a file beside it).
  'draco-decoder': {
    budget: 12800, when: 'a glTF model with KHR_draco_mesh_compression',
    modules: ['node_modules/draco3d/draco_decoder_nodejs.js', 'virtual/draco-wasm-url.js'],
  },
  // The worker's build takes no chunk groups: the glue and the wasm URL are two chunks there.
  'assets/draco_decoder_nodejs': { budget: 12800, when: 'the same, read in the glTF worker' },
  'assets/draco-wasm-url': { budget: 150, when: 'the same, read in the glTF worker' },
  'course-files': { budget: 1200, when: 'a course file' },
  // 2,150 until the main thread waited for the environment's maps before a frame (+11 B, 2,161: the wait's code loaded then).
  'software-start': { budget: 2175, when: 'the CPU renderer' },
  // 15,400 until emissive and reflect="false" (+7 B), then glTF materials under the scene's lights
  // (the BRDF of math/pbr.ts and pbrLights: +631 B, 16,081), then tone mapping (the curves, the resolve: +614 B, 16,695), then
  // the hook for an environment's light (the split sum's code comes with the maps, frame/environment-light.ts) and the table of
  // prepared environments (frame/environment-cache.ts), which goes with it: the CPU renderer reads it, and what else reads it
  // (software/environment-ready.ts) is loaded by the CPU renderer's host after it (+259 B, 16,954). Shared with the maps' chunk
  // instead, it was a chunk of its own, one request more before the CPU renderer's first frame (first-frame.spec.ts missed its
  // 2 s once in 50 so); then the metallic-roughness, occlusion and emissive maps (their textures, software/image-textures.ts, and
  // software/pbr-fragment.ts; +374 B, 17,328), then KHR_texture_transform and glTF's doubleSided (+139 B, 17,467), then the
  // normal map (the tangent's varyings, the perturbation, the draw's key in a module of its own: +407 B, 17,874), then vertex
  // colours (+109 B, 17,983), then glTF's alpha mask (the base colour image's alpha as a texture, the cut, the raster's depth
  // taken back: +80 B, 18,063), then refinement at rest (its running mean, the strata sequence, the derivatives' scale: +318 B,
  // 18,393; rough glass's samples at each frame's strata, +39 B, 18,464).
  'software-renderer': {
    budget: 18475, when: 'the CPU renderer',
    modules: ['src/software/software-renderer.ts', 'src/frame/environment-cache.ts'],
  },
  // The CPU renderer's main thread waiting for an environment's maps (software/environment-ready.ts): a scene with a glTF
  // material under an environment, without workers.
  // environment="url" (docs/pbr.md#an-image): the Radiance reader, the browser's decode taken as sRGB, the reduction, the load.
  'environment-files': { budget: 3000, when: 'environment="url" with a glTF material' },
  'environment-ready': { budget: 300, when: 'the CPU renderer on the main thread, a glTF material under an environment' },
  // 23,850 until rough glass's gather read its centre on the fragment's footprint (23,864).
  // then emissive and reflect="false" (+13 B), then glTF materials (+658 B, 24,608), then tone mapping (+616 B, 25,224), then
  // the hook for an environment's light (+149 B, 25,399), then requests queued behind the environment's maps (+236 B, 25,635),
  // then glTF materials' maps (+400 B, 26,035), then KHR_texture_transform and glTF's doubleSided (+164 B, 26,199), then the
  // normal map (+439 B, 26,638), then vertex colours (+99 B, 26,737).
  // +13 B (26,763): the prepared environments' table keyed by environmentKey (an image's URL); then glTF's alpha mask (+224 B,
  // 26,987: its copy of the CPU renderer's cut and alpha texture); then refinement at rest (+717 B, 27,717: its copy of the
  // software renderer's running mean, the strata sequence, FrameSetup's shift and the spheres' finer cut; rough glass's
  // samples at each frame's strata, +110 B, 27,860).
  'assets/worker': { budget: 27875, when: 'the CPU renderer' },
  // The bundler's glue for lazy chunks that share modules: written by rolldown, not by us.
  // 200 until glTF's chunks shared modules with the others (+229 B).
  'rolldown-runtime': { budget: 450, when: 'with the first lazy chunk' },
} as const satisfies Record<string, Chunk>;

export type ChunkName = keyof typeof CHUNKS;
