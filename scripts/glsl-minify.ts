// The build's shader text (the small core, docs/package.md#size-budget): comments, indentation, blank lines and the
// spaces around = ( ) { } ; , ? : * dropped from shaders/*.{vert,frag,glsl} imported with ?raw.
// Lines stay lines (the preprocessor reads them); + - < > & | keep their spaces, so no two
// operators can fuse into another (`a - -b` must not become `a--b`). The dev server serves them
// as written, so compile errors there name the lines of the files.
import type { Plugin } from 'vite';

export function minifyGlsl(source: string): string {
  return source
    .replace(/\/\*[\s\S]*?\*\//g, '')
    .split('\n')
    .map((line) => line.replace(/\/\/.*$/, '').trim())
    .map((line) => (line.startsWith('#') ? line.replace(/\s+/g, ' ') : line.replace(/\s+/g, ' ').replace(/ ?([=(){};,?:*]) ?/g, '$1')))
    .filter((line) => line !== '')
    .join('\n');
}

export function glslMinify(): Plugin {
  return {
    name: 'glsl-minify',
    apply: 'build',
    enforce: 'post',
    transform(code, id) {
      if (!/\/shaders\/[^/]+\.(vert|frag|glsl)\?raw$/.test(id)) return null;
      // Vite's raw import is `export default "<JSON string>"`.
      const m = /^export default (".*");?\s*$/s.exec(code);
      if (!m) return null;
      return { code: `export default ${JSON.stringify(minifyGlsl(JSON.parse(m[1]) as string))};`, map: null };
    },
  };
}
