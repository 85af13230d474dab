// Regenerates the browser-test goldens (tests/e2e/goldens/*.png): runs the golden spec with
// UPDATE_GOLDENS=1, which makes compareToGolden write each image instead of comparing it.
// Look at the new PNGs before committing them: a golden is only as right as the frame it froze.
import { spawn } from 'node:child_process';

const args = ['playwright', 'test', 'tests/e2e/goldens.spec.ts', ...process.argv.slice(2)];
const child = spawn('npx', args, {
  stdio: 'inherit',
  env: { ...process.env, UPDATE_GOLDENS: '1' },
  shell: process.platform === 'win32',
});
child.on('error', (err) => {
  console.error(`update-goldens: could not run npx playwright: ${err.message}`);
  process.exit(1);
});
child.on('exit', (code, signal) => {
  if (signal) console.error(`update-goldens: playwright ended by ${signal}`);
  process.exit(code ?? 1);
});
