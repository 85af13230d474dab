// Two pages: the README's bundler example and its React example (copied into react/ by
// scripts/check-package.mjs). Nothing else: the defaults of a fresh Vite app.
export default {
  build: { rollupOptions: { input: ['index.html', 'react/index.html'] } },
};
