// Material and attribute precedence (docs/scene-model.md#material-precedence, docs/course-files.md#lighting-file): attribute over MTL over lighting file over
// default, for <glass-object>; a <glass-light>'s attributes over its lighting file.
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const LOADING = 'tests/e2e/children-loading.spec.ts';
const COURSE = 'tests/e2e/course-files.spec.ts';
const MATERIAL = 'src/element/children/object-material.ts';

export default [
  {
    name: 'M1 the MTL\'s d wins over the opacity attribute',
    why: 'the element in a page: <glass-object> attributes over a fetched MTL',
    edits: [{ file: MATERIAL, find: 'opacity: attrs.opacity ?? mtl?.opacity ??', replace: 'opacity: mtl?.opacity ?? attrs.opacity ??' }],
    tests: [LOADING],
  },
  {
    name: 'M2 the MTL\'s Kd wins over the diffuse attribute',
    why: 'the element in a page: <glass-object> attributes over a fetched MTL',
    edits: [{ file: MATERIAL, find: 'diffuse: attrs.diffuse ?? mtl?.diffuse ??', replace: 'diffuse: mtl?.diffuse ?? attrs.diffuse ??' }],
    tests: [LOADING],
  },
  {
    name: 'M3 the default Ks wins over the MTL\'s (its term dropped)',
    why: 'the element in a page: a fetched MTL over the defaults',
    edits: [{ file: MATERIAL, find: 'specular: attrs.specular ?? mtl?.specular ?? file?.specular ??', replace: 'specular: attrs.specular ?? file?.specular ??' }],
    tests: [LOADING],
  },
  {
    name: 'M4 the lighting file wins over the MTL',
    why: 'the element in a page: a fetched MTL over a lighting file',
    edits: [{ file: MATERIAL, find: 'ambient: attrs.ambient ?? mtl?.ambient ?? file?.ambient ??', replace: 'ambient: attrs.ambient ?? file?.ambient ?? mtl?.ambient ??' }],
    tests: [COURSE],
  },
  {
    name: 'M5 the MTL\'s map_Kd wins over the texture attribute',
    why: 'the element in a page: <glass-object> texture over a fetched MTL',
    edits: [{ file: MATERIAL, find: 'const image = textureUrl ?? mtl?.texture ?? null;', replace: 'const image = mtl?.texture ?? textureUrl ?? null;' }],
    tests: [LOADING],
  },
  {
    name: 'M6 a lighting file\'s Pl wins over the light\'s position attribute',
    why: 'the element in a page: <glass-light> attributes over a lighting file',
    edits: [{ file: 'src/element/children/glass-light.ts', find: 'vector: position ?? l.vector,', replace: 'vector: l.vector ?? position,' }],
    tests: [COURSE],
  },
  {
    name: 'M7 the light\'s default intensities win over its lighting file',
    why: 'the element in a page: a lighting file over <glass-light> defaults',
    edits: [{ file: 'src/element/children/glass-light.ts', find: '(this.hasAttribute(name) ? v : fallback)', replace: '(v ?? fallback)' }],
    tests: [COURSE],
  },
  {
    name: 'M8 a material named in two MTL files is the last file\'s',
    why: 'the element in a page: two fetched MTL files',
    edits: [{ file: 'src/element/children/model-loader.ts', find: '        if (materials.has(key)) continue;\n', replace: '' }],
    tests: [LOADING],
  },
  {
    name: 'M9 the last of two lighting files gives the material',
    why: 'the element in a page: two fetched lighting files',
    edits: [{ file: 'src/element/children/gather-parts.ts', find: '    if (fileMaterial) break;\n', replace: '' }],
    tests: [COURSE],
  },
  {
    name: 'M10 a course .byu object takes the procedural texture by default',
    why: 'the element in a page: a course .byu child\'s default texture',
    edits: [{ file: MATERIAL, find: ': context.plain ? { kind: \'none\' } : { kind: \'procedural\' };', replace: ': { kind: \'procedural\' };' }],
    tests: [COURSE],
  },
];
