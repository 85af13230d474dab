// Loaders: OBJ indices of every kind, MTL, the course's .byu, camera .cfg and iluminacao.txt.
// Each: { name, edits: [{ file, find, replace }], tests: Playwright specs (*.spec.ts) or vitest files (*.test.ts) }.
const OBJ = 'tests/unit/obj.test.ts';
const MTL = 'tests/unit/mtl.test.ts';
const BYU = 'tests/unit/course-byu-mesh.test.ts';
const BEZIER = 'tests/unit/course-byu-bezier.test.ts';
const CAMERA = 'tests/unit/course-camera.test.ts';
const LIGHTING = 'tests/unit/course-lighting.test.ts';
const READER = 'src/loaders/obj/reader.ts';
const CORNERS = 'src/loaders/obj/corners.ts';

export default [
  {
    name: 'L1 a negative vn index read as positive',
    edits: [{ file: CORNERS, find: 'ni = nn === 0 ? -1 : resolve(nn, nCount);', replace: 'ni = nn === 0 ? -1 : resolve(Math.abs(nn), nCount);' }],
    tests: [OBJ],
  },
  {
    name: 'L2 positive OBJ indices read as 0-based (off by one)',
    edits: [{ file: CORNERS, find: 'const i = index > 0 ? index - 1 : count + index;', replace: 'const i = index > 0 ? index : count + index;' }],
    tests: [OBJ],
  },
  {
    name: 'L3 a negative vt index counted back from the vertices',
    edits: [{ file: CORNERS, find: 'ti = t === 0 ? -1 : resolve(t, tCount), ni', replace: 'ti = t === 0 ? -1 : resolve(t, vCount), ni' }],
    tests: [OBJ],
  },
  {
    name: 'L4 vt v flipped (v = 0 read as the top row)',
    edits: [{ file: READER, find: 'uvs.push(n > 1 ? values[1] : 0);', replace: 'uvs.push(n > 1 ? 1 - values[1] : 1);' }],
    tests: [OBJ],
  },
  {
    name: 'L5 MTL Tr read as d (not inverted)',
    edits: [{ file: 'src/loaders/mtl.ts', find: 'm.opacity = 1 - clamped(s, v[0], 0, 1, \'Tr\');', replace: 'm.opacity = clamped(s, v[0], 0, 1, \'Tr\');' }],
    tests: [MTL],
  },
  {
    name: 'L6 MTL map_Kd -clamp taken as a flag (its on/off read as the path)',
    edits: [{ file: 'src/loaders/mtl-map.ts', find: '\'-clamp\': 1,', replace: '\'-clamp\': 0,' }],
    tests: [MTL],
  },
  {
    name: 'L7 .byu face indices read as 0-based',
    edits: [{ file: 'src/loaders/course/byu-mesh.ts', find: 'kept.push(a - 1, b - 1, c - 1);', replace: 'kept.push(a, b, c);' }],
    tests: [BYU],
  },
  {
    name: 'L8 .byu drops the faces on its last vertex (range check off by one)',
    edits: [{ file: 'src/loaders/course/byu-mesh.ts', find: 'i < 1 || i > nv);', replace: 'i < 1 || i >= nv);' }],
    tests: [BYU],
  },
  {
    name: 'L9 Bézier .byu index order chosen by the longer net',
    edits: [{ file: 'src/loaders/course/byu-bezier.ts', find: 'const firstFastest = columnWise < rowWise * (1 - 1e-9);', replace: 'const firstFastest = columnWise > rowWise * (1 + 1e-9);' }],
    tests: [BEZIER],
  },
  {
    name: 'L10 camera.cfg hx and hy swapped',
    edits: [{ file: 'src/loaders/course/camera-cfg.ts', find: 'const [d, hx, hy] = window.xyz;', replace: 'const [d, hy, hx] = window.xyz;' }],
    tests: [CAMERA],
  },
  {
    name: 'L11 camera U = V × N (the right vector flipped)',
    edits: [{ file: 'src/math/course-camera.ts', find: 'u: clean(cross(n, v))', replace: 'u: clean(cross(v, n))' }],
    tests: [CAMERA],
  },
  {
    name: 'L12 iluminacao.txt Ia and Il swapped',
    edits: [{ file: 'src/loaders/course/lighting-txt.ts', find: 'const [pl, [ka], ia, [kd], od, [ks], il, [n]] = values;', replace: 'const [pl, [ka], il, [kd], od, [ks], ia, [n]] = values;' }],
    tests: [LIGHTING],
  },
  {
    name: 'L13 iluminacao.txt kd and ks swapped',
    edits: [{ file: 'src/loaders/course/lighting-txt.ts', find: 'const [pl, [ka], ia, [kd], od, [ks], il, [n]] = values;', replace: 'const [pl, [ka], ia, [ks], od, [kd], il, [n]] = values;' }],
    tests: [LIGHTING],
  },
];
