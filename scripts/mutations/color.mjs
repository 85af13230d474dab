// Linear light on the GPU (docs/colour.md#srgb): decoding colour data, the one encode at the end,
// the targets that hold linear colour, and the anisotropic reads that come with it.
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const COLOR = 'tests/e2e/color-space.spec.ts';
const GOLDENS = 'tests/e2e/goldens.spec.ts';
const REFERENCE = 'tests/e2e/scene-reference.spec.ts';

export default [
  {
    name: 'K1 the final encode missing: the frame in linear light goes to the canvas as it is',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: 'shaders/encode.frag', find: 'outColor = vec4(encode(c), 1.0);', replace: 'outColor = vec4(clamp(c, 0.0, 1.0), 1.0);' }],
    tests: [COLOR],
  },
  {
    name: 'K2 the encode applied twice',
    why: 'GLSL: Stryker does not mutate shader source (shaders/)',
    edits: [{ file: 'shaders/encode.frag', find: 'outColor = vec4(encode(c), 1.0);', replace: 'outColor = vec4(encode(encode(c)), 1.0);' }],
    tests: [COLOR],
  },
  {
    name: 'K3 image and procedural textures uploaded as RGBA8 in srgb: colour data not decoded',
    why: 'WebGL texture format (sRGB decode on upload): only a browser draws it',
    edits: [{ file: 'src/render/gl/texture.ts', find: 'const format = o.srgb ? gl.SRGB8_ALPHA8 : gl.RGBA8;', replace: 'const format = gl.RGBA8;' }],
    tests: [COLOR],
  },
  {
    name: 'K4 the procedural texture not decoded (uploaded as stored in srgb)',
    why: 'WebGL procedural texture upload: only a browser draws it',
    edits: [{ file: 'src/render/gl/shared-resources.ts', find: 'data: proceduralTexture(), mipmap: true, repeat: true, srgb, anisotropic: srgb,', replace: 'data: proceduralTexture(), mipmap: true, repeat: true, srgb: false, anisotropic: srgb,' }],
    tests: [GOLDENS],
  },
  {
    name: 'K5 the background (a CSS colour) not decoded',
    why: 'WebGL clear colour: only a browser draws it',
    edits: [{ file: 'src/render/renderer.ts', find: 'this.background[k] = srgb ? srgbToLinear(scene.background[k]) : scene.background[k];', replace: 'this.background[k] = scene.background[k];' }],
    tests: [GOLDENS],
  },
  {
    name: 'K6 the frame in linear light held in an 8-bit linear target (RGBA8): the darks band',
    why: 'WebGL render target format: only a browser draws it',
    edits: [{ file: 'src/render/linear-frame.ts', find: "const format = hdr ? 'rgba16f' : 'srgb8';", replace: "const format = hdr ? 'rgba16f' : 'rgba8';" }],
    tests: [COLOR],
  },
  {
    name: 'K7 the 8-bit reflection holds linear light as RGBA8',
    why: 'WebGL reflection target format: only a browser draws it',
    edits: [{ file: 'src/render/renderer.ts', find: "? 'rgba16f' : srgb ? 'srgb8' : 'rgba8';", replace: "? 'rgba16f' : 'rgba8';" }],
    tests: [COLOR],
  },
  {
    name: 'K8 the fresnel view encoded like a picture',
    why: 'WebGL frame\'s final encode (fresnel view, goldens): only a browser draws it',
    edits: [{ file: 'src/frame/linear-light.ts', find: "export const encodesAtEnd = (state: Pick<FrameState, 'colorSpace' | 'view'>): boolean =>\n  state.colorSpace === 'srgb' && state.view !== 'fresnel';", replace: "export const encodesAtEnd = (state: Pick<FrameState, 'colorSpace' | 'view'>): boolean =>\n  state.colorSpace === 'srgb';" }],
    tests: [GOLDENS],
  },
  {
    name: 'K9 textures read isotropically in linear light',
    why: 'WebGL anisotropic texture reads: only a browser draws it',
    edits: [{ file: 'src/render/gl/shared-resources.ts', find: 'data: proceduralTexture(), mipmap: true, repeat: true, srgb, anisotropic: srgb,', replace: 'data: proceduralTexture(), mipmap: true, repeat: true, srgb, anisotropic: false,' }],
    tests: [REFERENCE],
  },
  {
    name: 'K10 images keep the space they were uploaded in when color-space changes',
    why: 'WebGL texture cache re-upload: only a browser draws it',
    edits: [{ file: 'src/render/texture-cache.ts', find: '    if (srgb === this.srgb) return;\n    this.srgb = srgb;\n    for (const e of this.images.values()) {', replace: '    if (srgb === this.srgb) return;\n    this.srgb = srgb;\n    for (const e of [] as ImageEntry[]) {' }],
    tests: [COLOR],
  },
];
