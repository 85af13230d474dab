// Loads bench/formats-probe.html headless (SwiftShader Chromium from @sparticuz/chromium) and prints
// ms/frame per render-target format, samples and step. `node bench/formats-probe.mjs`; starts
// `vite --port 5192 --strictPort` itself unless PROBE_URL points at a running server.
import { spawn } from 'node:child_process';
import { chromium } from 'playwright-core';

const ARGS = [
  '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--headless=shell',
  '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic',
];
let server = null;
let base = process.env.PROBE_URL;
if (!base) {
  base = 'http://127.0.0.1:5192';
  server = spawn('npx', ['vite', '--port', '5192', '--strictPort'], { stdio: ['ignore', 'ignore', 'inherit'], detached: true });
}
let browser;
try {
  for (let end = Date.now() + 30000; ; await new Promise((r) => setTimeout(r, 200))) {
    try { if ((await fetch(`${base}/bench/formats-probe.html`)).ok) break; } catch { /* not up yet */ }
    if (Date.now() > end) throw new Error(`no server at ${base}`);
  }
  const executablePath = await (await import('@sparticuz/chromium')).default.executablePath();
  browser = await chromium.launch({ executablePath, args: ARGS });
  const page = await browser.newPage();
  page.on('pageerror', (e) => console.log('pageerror', e.message));
  await page.goto(`${base}/bench/formats-probe.html`);
  await page.waitForSelector('body[data-done="1"]', { timeout: 300000 });
  for (const [name, ms] of await page.evaluate(() => window.__probe)) console.log(ms.toFixed(2).padStart(8), name);
} finally {
  await browser?.close();
  if (server) process.kill(-server.pid, 'SIGTERM');
}
