// The package as users get it (`npm test`, after `npm run build`): `npm pack` into a temp dir,
// then arethetypeswrong and publint on the tarball, then the consumer test: the tarball
// installed into a temporary project whose files (tests/package/) must type-check under
// `strict` with moduleResolution bundler, node16 and nodenext, and whose bad file must not.
import { execFileSync, spawnSync } from 'node:child_process';
import { cpSync, existsSync, mkdirSync, mkdtempSync, readFileSync, rmSync, symlinkSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';

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

try {
  // ---- pack ----------------------------------------------------------------------------------
  const [pack] = JSON.parse(execFileSync('npm', ['pack', '--json', '--pack-destination', work], { encoding: 'utf8', stdio: ['ignore', 'pipe', 'ignore'] }));
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
  for (const dep of ['@types/react', 'csstype', 'vue', '@vue']) {
    if (!existsSync(join(app, 'node_modules', dep))) symlinkSync(join(repo, 'node_modules', dep), join(app, 'node_modules', dep), 'dir');
  }
  const fixtures = join(repo, 'tests/package');
  cpSync(fixtures, join(app, 'src'), { recursive: true });

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

  const good = ['src/main.ts', 'src/app.tsx', 'src/vue.ts', 'src/svelte.ts'];
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
} finally {
  rmSync(work, { recursive: true, force: true });
}
console.log(`package: ${passed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
