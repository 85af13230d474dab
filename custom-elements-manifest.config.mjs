// @custom-elements-manifest/analyzer: dist/custom-elements.json from the JSDoc of the three
// element classes (`npm run build`). The attributes are defined from tables at run time, so
// their rows are JSDoc `@attr` lines; tests/unit/manifest.test.ts holds them to the tables.
export default {
  globs: ['src/element/glass-plane-scene.ts', 'src/element/children/glass-object.ts', 'src/element/children/glass-light.ts'],
  outdir: 'dist',
  packagejson: false,
  plugins: [publicApi()],
};

/**
 * Documented public members and events only (undocumented ones are inherited typed overloads,
 * internal helpers or misreadings such as `this.message.hidden` taken for `this.hidden`), in
 * one module: the bundle users import.
 */
function publicApi() {
  return {
    name: 'glass-plane-scene-public-api',
    packageLinkPhase({ customElementsManifest: manifest }) {
      const declarations = manifest.modules.flatMap((m) => m.declarations ?? []).filter((d) => d.customElement);
      for (const d of declarations) {
        const seen = new Set();
        d.members = (d.members ?? []).filter((m) => {
          if ((m.privacy && m.privacy !== 'public') || m.static || !m.description || seen.has(m.name)) return false;
          seen.add(m.name);
          return true;
        });
        d.events = (d.events ?? []).filter((e) => e.description);
      }
      const path = 'dist/glass-plane-scene.js';
      manifest.modules = [{
        kind: 'javascript-module',
        path,
        declarations,
        exports: declarations.flatMap((d) => [
          { kind: 'js', name: d.name, declaration: { name: d.name, module: path } },
          { kind: 'custom-element-definition', name: d.tagName, declaration: { name: d.name, module: path } },
        ]),
      }];
    },
  };
}
