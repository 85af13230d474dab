// glTF materials and tone mapping on the GPU (docs/pbr.md): the BRDF's terms in shaders/pbr.glsl, the encode's tone
// mapping in shaders/tone-map.glsl and encode.frag, the half-float targets and the glass's ceiling that keep light
// above 1, and the chunk that brings them. The CPU renderers' same maths is src/ (StrykerJS).
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests }.
const PBR = 'tests/e2e/pbr.spec.ts';
const TONE = 'tests/e2e/tone-mapping.spec.ts';
const CHUNK = 'tests/e2e/pbr-chunk.spec.ts';
const ENV = 'tests/e2e/environment.spec.ts';
const MAPS = 'tests/e2e/pbr-maps.spec.ts';
const MASK = 'tests/e2e/alpha-mask.spec.ts';
const SKY = 'tests/e2e/environment-image.spec.ts';
const GLSL = 'GLSL: Stryker does not mutate shader source (shaders/)';

export default [
  {
    name: 'P1 D without its square: α²/(π·q) for α²/(π·q²)',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 'float d = nh > 0.0 ? a2 / (3.141592653589793 * q * q) : 0.0;', replace: 'float d = nh > 0.0 ? a2 / (3.141592653589793 * q) : 0.0;' }],
    tests: [PBR],
  },
  {
    name: 'P2 V halved (G/(8 n·l n·v))',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 'float vis = 0.5 / (', replace: 'float vis = 0.25 / (' }],
    tests: [PBR],
  },
  {
    name: 'P3 Schlick\'s Fresnel with (1 − v·h)³ for (1 − v·h)⁵',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 'vec3 fr = f0 + (1.0 - f0) * (k2 * k2 * k);', replace: 'vec3 fr = f0 + (1.0 - f0) * (k2 * k);' }],
    tests: [PBR],
  },
  {
    name: 'P4 F0 not mixed by metallic: 0.04 + base·metallic',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 'vec3 f0 = vec3(0.04) * (1.0 - metallic) + base * metallic;', replace: 'vec3 f0 = vec3(0.04) + base * metallic;' }],
    tests: [PBR],
  },
  {
    name: 'P5 a metal keeps its diffuse colour (c_diff = base)',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 'vec3 cdiff = base * (1.0 - metallic);', replace: 'vec3 cdiff = base;' }],
    tests: [PBR],
  },
  {
    name: 'P6 the lights\' α without its floor (roughness 0: α = 0, D = 0/0)',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 'float alpha = max(r * r, 0.002);', replace: 'float alpha = r * r;' }],
    tests: [PBR],
  },
  {
    name: 'P7 a glTF material lit per vertex under gouraud (the frame\'s shading obeyed)',
    why: 'the variant chosen for a WebGL draw: only a browser draws it',
    edits: [{ file: 'src/render/programs.ts', find: "const shading = v.pbr ? 'phong' : requested;", replace: 'const shading = requested;' }],
    tests: [PBR],
  },
  {
    name: 'P8 the exposure after the curve: toneMap(c)·exposure',
    why: GLSL,
    edits: [{ file: 'shaders/encode.frag', find: 'c = toneMap(c * uExposure);', replace: 'c = toneMap(c) * uExposure;' }],
    tests: [TONE],
  },
  {
    name: 'P9 a tone-mapped frame in an 8-bit target: light above 1 clipped before the curve',
    why: 'WebGL render target format: only a browser draws it',
    edits: [{ file: 'src/render/linear-frame.ts', find: "const format = hdr ? 'rgba16f' : 'srgb8';", replace: "const format = 'srgb8';" }],
    tests: [TONE],
  },
  {
    name: 'P10 the glass reads R clipped at 1 in a tone-mapped frame',
    why: 'a uniform of the WebGL glass pass: only a browser draws it',
    edits: [{ file: 'src/render/passes/glass-pass.ts', find: "gl.uniform1f(program.location('uCeiling'), ctx.hdr ? 65504 : 1);", replace: "gl.uniform1f(program.location('uCeiling'), 1);" }],
    tests: [TONE],
  },
  {
    name: 'P11 PBR Neutral without its desaturation toward white',
    why: GLSL,
    edits: [{ file: 'shaders/tone-map.glsl', find: 'return mix(c, vec3(newPeak), g);', replace: 'return c;' }],
    tests: [TONE],
  },
  {
    name: 'P12 a frame with a glTF material does not wait for its chunk: the stand-in drawn meanwhile',
    why: 'a lazy chunk\'s timing in a page: only a browser loads it',
    edits: [{ file: 'src/render/parts.ts', find: 'needed: (h) => hasPbrMaterial(h.ctx.scene) || toneMapped(h.ctx.state), holds: true,', replace: 'needed: (h) => hasPbrMaterial(h.ctx.scene) || toneMapped(h.ctx.state), holds: false,' }],
    tests: [CHUNK],
  },
  {
    name: 'P13 the prefilter\'s level chosen linearly in roughness (r·7) for √r·7',
    why: GLSL,
    edits: [{ file: 'shaders/environment.glsl', find: 'float p = sqrt(clamp(roughness, 0.0, 1.0)) * LAST_LEVEL;', replace: 'float p = clamp(roughness, 0.0, 1.0) * LAST_LEVEL;' }],
    tests: [ENV],
  },
  {
    name: 'P14 the lobe read toward the mirror direction, not the dominant one',
    why: GLSL,
    edits: [{ file: 'shaders/environment.glsl', find: 'vec3 dominant = normalize(n + (mirror - n) * s);', replace: 'vec3 dominant = mirror;' }],
    tests: [ENV],
  },
  {
    name: 'P15 the environment read upside down (the lookup\'s direction flipped in y)',
    why: GLSL,
    edits: [{ file: 'shaders/environment.glsl', find: 'acos(clamp(d.y, -1.0, 1.0))', replace: 'acos(clamp(-d.y, -1.0, 1.0))' }],
    tests: [ENV],
  },
  {
    name: 'P16 the diffuse lobe read at the surface\'s roughness, not the irradiance level',
    why: GLSL,
    edits: [{ file: 'shaders/environment.glsl', find: 'prefilteredAt(n, 1.0)', replace: 'prefilteredAt(n, r)' }],
    tests: [ENV],
  },
  {
    name: 'P17 the split-sum table\'s A and B swapped (F0·B + A)',
    why: GLSL,
    edits: [{ file: 'shaders/environment.glsl', find: '(f0 * ab.x + ab.y)', replace: '(f0 * ab.y + ab.x)' }],
    tests: [ENV],
  },
  {
    name: 'P18 the environment\'s intensity not applied',
    why: 'a uniform of the WebGL object pass: only a browser draws it',
    edits: [{ file: 'src/render/environment-gl.ts', find: "gl.uniform1f(program.location('uEnvironmentIntensity'), intensity);", replace: "gl.uniform1f(program.location('uEnvironmentIntensity'), 1);" }],
    tests: [ENV],
  },
  {
    name: 'P19 a frame with an environment does not wait for its chunk',
    why: 'a lazy chunk\'s timing in a page: only a browser loads it',
    edits: [{ file: 'src/render/parts.ts', find: "needed: (h) => !!h.ctx.scene.environment && hasPbrMaterial(h.ctx.scene), holds: true,", replace: "needed: (h) => !!h.ctx.scene.environment && hasPbrMaterial(h.ctx.scene), holds: false," }],
    tests: [ENV],
  },
  {
    name: 'P20 the studio\'s maps made in one task when the frame needs them (the page held a second)',
    why: 'a page\'s tasks: only a browser runs them',
    edits: [{ file: 'src/render/parts.ts', find: "load: () => import('./environment-gl').then((m) => m.studioReady().then(() => m)),", replace: "load: () => import('./environment-gl')," }],
    tests: [ENV],
  },
  {
    name: 'P21 the maps read at (u, v), not at an image\'s (u, 1 − v)',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: '  return vec2(m.x, 1.0 - m.y);', replace: '  return m;' }],
    tests: [MAPS],
  },
  {
    name: 'P22 the metallic-roughness map\'s channels swapped (G metallic, B roughness)',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 's *= vec3(mapRead(uMetalRough, mapUv(1, uv)).bg, 1.0);', replace: 's *= vec3(mapRead(uMetalRough, mapUv(1, uv)).gb, 1.0);' }],
    tests: [MAPS],
  },
  {
    name: 'P23 the occlusion map\'s strength not applied (R itself)',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 's.z = 1.0 + uOcclusionStrength * (mapRead(uOcclusion, mapUv(2, uv)).r - 1.0);', replace: 's.z = mapRead(uOcclusion, mapUv(2, uv)).r;' }],
    tests: [MAPS],
  },
  {
    name: 'P24 occlusion not applied to the environment',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 'c += s.z * environmentLight(n, v, base, s.x, s.y);', replace: 'c += environmentLight(n, v, base, s.x, s.y);' }],
    tests: [MAPS],
  },
  {
    name: 'P25 the emissive map held as stored in srgb, not as colour',
    why: 'a texture\'s format in WebGL: only a browser samples it',
    edits: [{ file: 'src/render/pbr-maps-gl.ts', find: 'mipmap: true, repeat: true, srgb, anisotropic: srgb }', replace: 'mipmap: true, repeat: true, srgb: false, anisotropic: srgb }' }],
    tests: [MAPS],
  },
  {
    name: 'P26 the occlusion map bound on the emissive map\'s unit',
    why: 'texture units of the WebGL object pass: only a browser draws them',
    edits: [{ file: 'src/render/pbr-maps-gl.ts', find: "gl.uniform1i(p.location('uOcclusion'), OCCLUSION_UNIT);", replace: "gl.uniform1i(p.location('uOcclusion'), EMISSIVE_UNIT);" }],
    tests: [MAPS],
  },
  {
    name: 'P27 a single-sided glTF mesh drawn with its back faces (culling off)',
    why: 'face culling is the GPU\'s: only a browser draws it',
    edits: [{ file: 'src/render/passes/draw-objects.ts', find: '      const twoSided = drawnTwoSided(o);', replace: '      const twoSided = true;' }],
    tests: ['tests/e2e/double-sided.spec.ts'],
  },
  {
    name: 'P28 the base colour texture read without its transform',
    why: GLSL,
    edits: [{ file: 'shaders/standard.frag', find: '  vec3 t = tex(moveUv(0, vUv));', replace: '  vec3 t = tex(vUv);' }],
    tests: [MAPS],
  },
  {
    name: 'P29 a transform\'s rows read the other way round (v\' from the first)',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 'return vec2(dot(uUvRows[2 * i], p), dot(uUvRows[2 * i + 1], p));', replace: 'return vec2(dot(uUvRows[2 * i + 1], p), dot(uUvRows[2 * i], p));' }],
    tests: [MAPS],
  },
  {
    name: 'P30 the normal map\'s bitangent on the other side (−w·(N × T))',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: 'vec3 b = (t.w < 0.0 ? -1.0 : 1.0) * cross(n, tt);', replace: 'vec3 b = (t.w < 0.0 ? 1.0 : -1.0) * cross(n, tt);' }],
    tests: [MAPS],
  },
  {
    name: 'P31 the perturbed normal not turned to the viewer on a double-sided mesh seen from behind',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: '  if (dot(n, v) < 0.0) p = -p;', replace: '' }],
    tests: [MAPS],
  },
  {
    name: 'P32 normalScale not applied',
    why: GLSL,
    edits: [{ file: 'shaders/pbr.glsl', find: '  m.xy *= uNormalScale;', replace: '' }],
    tests: [MAPS],
  },
  {
    name: 'P33 the tangent left in the model\'s space (not through the model matrix)',
    why: GLSL,
    edits: [{ file: 'shaders/standard.vert', find: 'vTangent = vec4(mat3(uModelRelative) * aTangent.xyz, aTangent.w);', replace: 'vTangent = aTangent;' }],
    tests: [MAPS],
  },
  {
    name: 'P34 a mesh\'s tangents not uploaded',
    why: 'a vertex attribute of WebGL: only a browser draws it',
    edits: [{ file: 'src/render/gl/mesh.ts', find: '    if (data.tangents) this.attribute(ATTRIB.tangent, data.tangents, 4);', replace: '' }],
    tests: [MAPS],
  },
  {
    name: 'P35 vertex colours not multiplied into the base colour',
    why: GLSL,
    edits: [{ file: 'shaders/standard.frag', find: '  t *= vColor;', replace: '' }],
    tests: [MAPS],
  },
  {
    name: 'P36 a mesh\'s vertex colours not uploaded',
    why: 'a vertex attribute of WebGL: only a browser draws it',
    edits: [{ file: 'src/render/gl/mesh.ts', find: '    if (data.colors) this.attribute(ATTRIB.color, data.colors, 3);', replace: '' }],
    tests: [MAPS],
  },
  {
    name: 'P37 the alpha mask never discards',
    why: GLSL,
    edits: [{ file: 'shaders/standard.frag', find: '  if (alpha < uAlphaMask.y) discard;', replace: '' }],
    tests: [MASK],
  },
  {
    name: 'P38 the alpha mask reads the factor alone (not the texture\'s alpha)',
    why: GLSL,
    edits: [{ file: 'shaders/standard.frag', find: '  float alpha = uAlphaMask.x * mapRead(uTexture, uImageTexture > 0.5 ? vec2(at.x, 1.0 - at.y) : at).a;', replace: '  float alpha = uAlphaMask.x;' }],
    tests: [MASK],
  },
  {
    name: 'P39 the alpha mask reads the texture upside down (at v, not 1 − v)',
    why: GLSL,
    edits: [{ file: 'shaders/standard.frag', find: 'uImageTexture > 0.5 ? vec2(at.x, 1.0 - at.y) : at).a;', replace: 'at).a;' }],
    tests: [MASK],
  },
  {
    name: 'P40 the alpha mask\'s cutoff not set (0: nothing cut)',
    why: 'a uniform of WebGL: only a browser draws it',
    edits: [{ file: 'src/render/pbr-maps-gl.ts', find: "gl.uniform2f(p.location('uAlphaMask'), m.baseColor[3], m.alphaCutoff);", replace: "gl.uniform2f(p.location('uAlphaMask'), m.baseColor[3], 0);" }],
    tests: [MASK],
  },
  {
    name: 'P41 a PNG sky\'s bytes taken as linear light (not decoded from sRGB)',
    why: 'the browser\'s image decoder: only a page decodes a PNG',
    edits: [{ file: 'src/element/environment-files.ts', find: '    rgb[3 * k] = SRGB_BYTE_TO_LINEAR[px[4 * k]];', replace: '    rgb[3 * k] = px[4 * k] / 255;' }],
    tests: [SKY],
  },
  {
    name: 'P42 an environment file that fails leaves glTF materials without the studio',
    why: 'the element in a page: a fetch that fails',
    edits: [{ file: 'src/element/environment-files.ts', find: "    this.part = 'neutral';", replace: '    this.part = null;' }],
    tests: [SKY],
  },
  {
    name: 'P43 the environment file fetched for a scene without a glTF material',
    why: 'a lazy chunk of the element: only a page fetches it',
    edits: [{ file: 'src/element/parts.ts', find: 'needed: (h) => isEnvironmentUrl(h.values.environment) && hasPbrMaterial(h.scenes.current),', replace: 'needed: (h) => isEnvironmentUrl(h.values.environment),' }],
    tests: [SKY],
  },
];
