// Dev server for the demo (and the browser tests), and the two library builds:
//   `vite build`                    ESM, gl-matrix left as a dependency
//   `vite build --mode standalone`  one self-contained minified file for <script type="module">
import fs from 'node:fs';
import { defineConfig, searchForWorkspaceRoot, type Plugin } from 'vite';
import { demoModels } from './demo/demo-models.ts';
import { glslMinify } from './scripts/glsl-minify.ts';
import { chunkGroups } from './scripts/chunk-groups.ts';
import { dracoWasm } from './scripts/draco-wasm.ts';

/** `/` opens the demo, so `npm run demo` lands on it. */
const demoAtRoot: Plugin = {
  name: 'demo-at-root',
  configureServer(server) {
    server.middlewares.use((req, res, next) => {
      if (req.url === '/' || req.url === '/index.html') {
        res.statusCode = 302;
        res.setHeader('Location', '/demo/');
        res.end();
        return;
      }
      next();
    });
  },
};

export default defineConfig(({ mode, command }) => {
  const standalone = mode === 'standalone';
  return {
    // Built files find their workers and chunks relative to their own URL, wherever they are served.
    base: command === 'build' ? './' : '/',
    plugins: [demoAtRoot, demoModels(), glslMinify(), dracoWasm()],
    // The glTF worker imports the Draco decoder's wasm URL too (scripts/draco-wasm.ts).
    worker: { format: 'es' as const, plugins: () => [dracoWasm()] },
    appType: 'mpa',
    // The software renderer's worker is a module worker (it imports the renderer's chunk).
    // Draco's wasm is served from its package by path (/@fs/…, scripts/draco-wasm.ts): allowed where the
    // package really lies, also when node_modules is a link to another checkout's (the mutation copies).
    server: { host: '127.0.0.1', port: 5173, fs: { allow: [searchForWorkspaceRoot(process.cwd()), fs.realpathSync('node_modules/draco3d')] } },
    // The dev server's dependency scan reads every HTML file but the framework apps' (tests/frameworks/,
    // built on their own by tests/e2e/frameworks.spec.ts): the demo pre-bundles no React, Vue or Svelte.
    // The package check's app (tests/package/) imports the packed package, installed only there.
    optimizeDeps: { entries: ['**/*.html', '!tests/frameworks/**', '!tests/package/**'] },
    build: {
      outDir: 'dist',
      emptyOutDir: !standalone,
      target: 'es2022',
      minify: standalone,
      sourcemap: true,
      lib: {
        entry: 'src/index.ts',
        formats: ['es'],
        fileName: () => (standalone ? 'glass-plane-scene.standalone.js' : 'glass-plane-scene.js'),
      },
      rollupOptions: {
        external: standalone ? [] : [/^gl-matrix/],
        // gl-matrix builds a few helpers at load (vec3.forEach, vec4.forEach, quat.sqlerp: each an
        // IIFE around its module's `create()`), which kept them, and what they use, even unused;
        // create() only allocates. quat.setAxes and rotationTo, built around
        // `mat3.create()` / `vec3.create()` of another module, stay.
        treeshake: { manualPureFunctions: ['create'] },
        // Library mode keeps whitespace in ES output; the self-contained file is for <script>
        // tags and CDNs, so it is minified whole.
        // What the element needs before its first frame is one chunk (group `$initial`): split into
        // the many small chunks the automatic splitting makes where lazy chunks share a module,
        // it gzips larger (README.md#size).
        output: { ...(standalone ? { minify: true } : {}), codeSplitting: {
          groups: [
            { name: 'core', tags: ['$initial'] },
            // The chunk groups of src/frame/chunks.ts: its small parts, one file for each moment they are needed.
            ...chunkGroups(),
          ],
        } },
      },
    },
  };
});
