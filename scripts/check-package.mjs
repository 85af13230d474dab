// The package as users get it (`npm test`, after `npm run build`): `npm pack` into a temp dir,
// then arethetypeswrong and publint on the tarball, then the consumer test: the tarball
// installed into a temporary project whose files (tests/package/, and the README's React
// example from tests/frameworks/react/) must type-check under `strict` with moduleResolution
// bundler, node16 and nodenext, and whose bad file must not. Last, that project as a fresh Vite
// app (tests/package/vite-app/: the README's bundler and React examples) is built with
// `vite build` and its pages are opened in the tests' Chromium: the element draws, the README's
// listeners and handlers run. All offline: vite, Chromium and React come from this repository.
import { execFileSync, spawnSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, statSync, symlinkSync, writeFileSync } from 'node:fs';
import { createServer } from 'node:http';
import { tmpdir } from 'node:os';
import { extname, join, resolve, sep } from 'node:path';

const repo = resolve('.');
const bin = (name) => join(repo, 'node_modules/.bin', name);
const work = mkdtempSync(join(tmpdir(), 'glass-plane-scene-pack-'));
let failed = 0;
let passed = 0;

function run(cmd, args, opts = {}) {
  const r = spawnSync(cmd, args, { encoding: 'utf8', cwd: repo, ...opts });
  return { status: r.status, out: `${r.stdout ?? ''}${r.stderr ?? ''}`.replace(/^npm warn Unknown user config.*\n/gm, '') };
}

function check(name, ok, detail = '') {
  if (ok) passed++;
  else failed++;
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${name}${detail ? `\n${detail.replace(/^/gm, '     ')}` : ''}`);
}

/** The browser tests' Chromium flags (tests/e2e/fixtures.ts, CHROMIUM_ARGS): WebGL2 on SwiftShader, a closed network. */
const CHROMIUM_ARGS = ['--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--headless=shell',
  '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic'];

/** The model the README's React example loads (/models/spot.obj): a cube, 8 vertices and 6 quads. */
const CUBE_OBJ = 'v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n'
  + 'f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 4 8 7 3\nf 1 5 8 4\nf 2 3 7 6\n';

const MIME = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css', '.map': 'application/json', '.obj': 'text/plain' };

/**
 * The consumer project as a fresh Vite app: `vite build` (this repository's Vite, the app's own
 * node_modules for the package), then each page in Chromium from a static server of dist/.
 */
async function viteApp(root) {
  const t0 = performance.now();
  const built = run(bin('vite'), ['build', '--logLevel', 'warn'], { cwd: root });
  const seconds = () => ((performance.now() - t0) / 1000).toFixed(1);
  check(`vite build of a fresh Vite app with the tarball installed (2 pages) in ${seconds()} s`, built.status === 0, built.out.trim());
  if (built.status !== 0) return;
  const out = join(root, 'dist');
  mkdirSync(join(out, 'models'));
  writeFileSync(join(out, 'models/spot.obj'), CUBE_OBJ);
  const server = createServer((req, res) => {
    const file = join(out, decodeURIComponent(new URL(req.url ?? '/', 'http://x').pathname));
    const ok = file.startsWith(out + sep) && existsSync(file) && statSync(file).isFile();
    res.statusCode = ok ? 200 : 404;
    if (ok) res.setHeader('Content-Type', MIME[extname(file)] ?? 'application/octet-stream');
    res.end(ok ? readFileSync(file) : undefined);
  });
  await new Promise((done) => server.listen(0, '127.0.0.1', done));
  const origin = `http://127.0.0.1:${server.address().port}`;
  const { chromium } = await import('playwright-core');
  const executablePath = process.env.PLAYWRIGHT_CHROMIUM ?? await (await import('@sparticuz/chromium')).default.executablePath();
  const browser = await chromium.launch({ executablePath, args: CHROMIUM_ARGS });
  try {
    /** A page with the element's checks on, and every console line it printed. */
    const open = async (path) => {
      const page = await browser.newPage({ viewport: { width: 800, height: 600 }, deviceScaleFactor: 1 });
      await page.addInitScript(() => { globalThis.__GLASS_PLANE_SCENE_CHECKS__ = true; });
      const lines = [];
      page.on('console', (m) => lines.push({ type: m.type(), text: m.text() }));
      page.on('pageerror', (e) => lines.push({ type: 'pageerror', text: String(e) }));
      await page.goto(`${origin}/${path}`);
      return { page, lines, problems: () => lines.filter((l) => l.type !== 'log' && l.type !== 'debug' && l.type !== 'info') };
    };

    // The README's bundler example: the element renders the default scene, the page's property
    // write reflects to the attribute, the page's `frame` listener logs the passes.
    const plain = await open('index.html');
    const seen = await plain.page.waitForFunction(() => (document.querySelector('glass-plane-scene')?.stats?.frames ?? 0) > 0, null, { timeout: 30_000 })
      .then(() => true, () => false);
    const result = seen ? await plain.page.evaluate(() => {
      const el = document.querySelector('glass-plane-scene');
      const image = el.capture();
      // Pixels where one channel exceeds both others by more than 0.1 (tests/e2e/helpers/pixels.ts).
      const dominant = (c) => {
        let n = 0;
        for (let i = 0; i < image.data.length; i += 4) {
          const d = image.data;
          if (d[i + c] - Math.max(d[i + (c + 1) % 3], d[i + (c + 2) % 3]) > 25.5) n++;
        }
        return n;
      };
      return { size: `${image.width}×${image.height}`, red: dominant(0), green: dominant(1), transparency: el.getAttribute('transparency') };
    }) : null;
    const logged = plain.lines.filter((l) => l.type === 'log' && /reflection/.test(l.text));
    // The default scene at time 1.25, transparency 0.8, 320×180, in linear light: measured 1,703
    // red (the cube and its reflection) and 2,600 green (the sphere, clearer through the glass)
    // pixels; ±5 %. (As stored, 1,345 and 3,210: the glass body shows lighter in linear light.)
    check(`the Vite app draws the default scene: ${result ? `${result.size}, ${result.red} red, ${result.green} green pixels` : 'no frame within 30 s'}`,
      result !== null && result.size === '320×180' && result.red > 1_620 && result.red < 1_790 && result.green > 2_470 && result.green < 2_730);
    check(`the README's bundler example ran: transparency="${result?.transparency}", ${logged.length} frame(s) logged`,
      result?.transparency === '0.8' && logged.length > 0, logged.length ? '' : plain.lines.map((l) => `[${l.type}] ${l.text}`).join('\n'));
    check('the Vite app logs no error or warning', plain.problems().length === 0, plain.problems().map((l) => `[${l.type}] ${l.text}`).join('\n'));

    // The README's React example: the model's `load` reaches the component's handler.
    const react = await open('react/index.html');
    const status = await react.page.locator('p').filter({ hasText: /^loaded / }).textContent({ timeout: 30_000 }).catch(() => null);
    check(`the README's React example from the tarball: "${status ?? (await react.page.locator('p').textContent())}"`, status === `loaded ${origin}/models/spot.obj`);
    check('its page logs no error or warning', react.problems().length === 0, react.problems().map((l) => `[${l.type}] ${l.text}`).join('\n'));
  } finally {
    await browser.close();
    server.close();
  }
  console.log(`     the Vite app: built and rendered in ${seconds()} s`);
}

try {
  // ---- pack ----------------------------------------------------------------------------------
  const [pack] = JSON.parse(execFileSync('npm', ['pack', '--json', '--ignore-scripts', '--pack-destination', work], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }));
  const tarball = join(work, pack.filename);
  const files = pack.files.map((f) => f.path);
  console.log(`packed ${pack.filename}: ${files.length} files, ${(pack.size / 1024).toFixed(1)} kB (${(pack.unpackedSize / 1024).toFixed(1)} kB unpacked)`);
  const needed = ['LICENSE', 'CHANGELOG.md', 'README.md', 'dist/custom-elements.json', 'dist/types/index.d.ts', 'dist/frameworks/react.d.ts'];
  const absent = needed.filter((f) => !files.includes(f));
  const stray = files.filter((f) => !/^(dist\/|LICENSE$|CHANGELOG\.md$|README\.md$|package\.json$)/.test(f));
  check('tarball holds what users need and nothing else', absent.length === 0 && stray.length === 0,
    [absent.length ? `missing: ${absent.join(', ')}` : '', stray.length ? `stray: ${stray.join(', ')}` : ''].filter(Boolean).join('\n'));

  // ---- arethetypeswrong, publint --------------------------------------------------------------
  // ESM only by design (custom elements, browser modules): require() from CommonJS is not offered.
  const attw = run(bin('attw'), [tarball, '--profile', 'esm-only', '--no-definitely-typed', '--format', 'table', '--no-color', '--no-emoji']);
  check('attw (profile esm-only)', attw.status === 0, attw.status === 0 ? attw.out.trim().split('\n').filter((l) => /No problems|entrypoint|"glass-plane-scene/.test(l)).slice(0, 2).join('\n') : attw.out);
  const publint = run(bin('publint'), ['run', tarball, '--strict']);
  const publintClean = publint.status === 0 && /All good/.test(publint.out);
  check('publint --strict', publintClean, publint.out.trim());

  // ---- consumer projects ---------------------------------------------------------------------
  const app = join(work, 'consumer');
  mkdirSync(app);
  writeFileSync(join(app, 'package.json'), JSON.stringify({ name: 'consumer', private: true, type: 'module' }));
  // Offline from the npm cache (gl-matrix, a dependency of the tarball, came into it with the repo's install).
  let install = run('npm', ['install', '--offline', '--no-audit', '--no-fund', '--ignore-scripts', tarball], { cwd: app });
  if (install.status !== 0) install = run('npm', ['install', '--prefer-offline', '--no-audit', '--no-fund', '--ignore-scripts', tarball], { cwd: app });
  check('tarball installs into a new project', install.status === 0, install.status === 0 ? '' : install.out);
  // The frameworks' own typings come from this repository's devDependencies, as a user's project has them.
  mkdirSync(join(app, 'node_modules/@types'), { recursive: true });
  for (const dep of ['@types/react', 'csstype', 'vue', '@vue', 'react', 'react-dom', 'scheduler']) {
    if (!existsSync(join(app, 'node_modules', dep))) symlinkSync(join(repo, 'node_modules', dep), join(app, 'node_modules', dep), 'dir');
  }
  const fixtures = join(repo, 'tests/package');
  cpSync(fixtures, join(app, 'src'), { recursive: true });
  cpSync(join(repo, 'tests/frameworks/react'), join(app, 'src/vite-app/react'), { recursive: true });

  // Every attribute in the manifest appears in the React file (so it cannot fall behind).
  const manifest = JSON.parse(readFileSync(join(app, 'node_modules/glass-plane-scene/dist/custom-elements.json'), 'utf8'));
  const tsx = readFileSync(join(fixtures, 'app.tsx'), 'utf8');
  const unused = [];
  for (const d of manifest.modules.flatMap((m) => m.declarations)) {
    for (const a of d.attributes) {
      const prop = d.tagName === 'glass-object' && a.name === 'normalize' ? 'normalizeModel' : a.name;
      const tag = tsx.slice(tsx.indexOf(`<${d.tagName}\n`) >= 0 ? tsx.indexOf(`<${d.tagName}\n`) : tsx.indexOf(`<${d.tagName} `));
      if (!new RegExp(`\\s${prop}[=\\s/>]`).test(tag.slice(0, tag.indexOf('>') + 1 || undefined))) unused.push(`${d.tagName} ${a.name}`);
    }
  }
  check('app.tsx sets every attribute of the three elements', unused.length === 0, unused.join(', '));

  const good = ['src/main.ts', 'src/app.tsx', 'src/vue.ts', 'src/svelte.ts', 'src/vite-app/main.ts', 'src/vite-app/react/Viewer.tsx'];
  const tsconfig = (resolution, include) => ({
    compilerOptions: {
      target: 'ES2022', module: resolution === 'bundler' ? 'ESNext' : resolution, moduleResolution: resolution,
      lib: ['ES2022', 'DOM', 'DOM.Iterable'], jsx: 'react-jsx', strict: true, noEmit: true, skipLibCheck: false, types: [],
    },
    include,
  });
  for (const resolution of ['bundler', 'node16', 'nodenext']) {
    writeFileSync(join(app, `tsconfig.${resolution}.json`), JSON.stringify(tsconfig(resolution, good), null, 2));
    const t0 = performance.now();
    const tsc = run(bin('tsc'), ['-p', `tsconfig.${resolution}.json`], { cwd: app });
    check(`consumer type-checks (${resolution}, strict, skipLibCheck false: ${good.length} files) in ${((performance.now() - t0) / 1000).toFixed(1)} s`, tsc.status === 0, tsc.out.trim());
  }
  // The wrong keyword values must each be an error, on their own lines.
  writeFileSync(join(app, 'tsconfig.bad.json'), JSON.stringify(tsconfig('nodenext', ['src/bad.tsx']), null, 2));
  const bad = run(bin('tsc'), ['-p', 'tsconfig.bad.json'], { cwd: app });
  const badLines = readFileSync(join(fixtures, 'bad.tsx'), 'utf8').split('\n').flatMap((l, i) => (l.includes('BAD */') ? [i + 1] : []));
  const reported = new Set([...bad.out.matchAll(/src\/bad\.tsx\((\d+),\d+\): error TS2322/g)].map((m) => Number(m[1])));
  const missed = badLines.filter((l) => !reported.has(l));
  check(`bad.tsx: ${reported.size} of ${badLines.length} wrong values rejected (TS2322), nothing else`,
    bad.status !== 0 && missed.length === 0 && [...reported].every((l) => badLines.includes(l)) && !/error TS(?!2322)/.test(bad.out),
    missed.length ? `accepted on lines ${missed.join(', ')}\n${bad.out}` : '');

  await viteApp(join(app, 'src/vite-app'));
} finally {
  rmSync(work, { recursive: true, force: true });
}
console.log(`package: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
