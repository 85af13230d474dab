// The build: the shader minifier (scripts/glsl-minify.ts) and the lazy chunks the standalone
// bundle loads (rough glass, the software renderer). `build: true` builds dist/ in the copy first.
// Each: { name, why (what keeps it out of Stryker's reach), edits: [{ file, find, replace }], tests, build? }.
const MINIFY = 'scripts/glsl-minify.ts';
const UNIT = 'tests/unit/glsl-minify.test.ts';
const STANDALONE = 'tests/e2e/standalone.spec.ts';

export default [
  {
    name: 'B1 the minifier joins the lines (directives run into the code)',
    why: 'scripts/: Stryker mutates src/ only (the shader minifier, and the standalone bundle it builds)',
    edits: [{ file: MINIFY, find: "    .join('\\n');", replace: "    .join(' ');" }],
    tests: [UNIT, STANDALONE],
    build: true,
  },
  {
    name: 'B2 the minifier squeezes the spaces around + and - too (a - -b becomes a--b)',
    why: 'scripts/: Stryker mutates src/ only (the shader minifier)',
    edits: [{ file: MINIFY, find: "replace(/ ?([=(){};,?:*]) ?/g, '$1')", replace: "replace(/ ?([=(){};,?:*+-]) ?/g, '$1')" }],
    tests: [UNIT],
  },
  {
    name: 'B3 the minifier drops the rough gather\'s marker line (every rough variant fails to compile)',
    why: 'the build: minified shaders that only a browser compiles (standalone bundle)',
    edits: [{ file: MINIFY, find: "    .filter((line) => line !== '')", replace: "    .filter((line) => line !== '' && !/^[A-Z_]+$/.test(line))" }],
    tests: [STANDALONE],
    build: true,
  },
];
