// Loads bench/three-peer.html headless (SwiftShader Chromium from @sparticuz/chromium), prints the
// difference and timing figures and any console output, and saves a screenshot.
//   node bench/check-peer.mjs [query] [screenshot.png]
// e.g. node bench/check-peer.mjs 'samples=4&timing=0' /tmp/peer-4.png
// Starts `vite --port 5191 --strictPort` itself unless PEER_URL points at a running server.
import { spawn } from 'node:child_process';
import { chromium } from 'playwright-core';

const query = process.argv[2] ?? '';
const shot = process.argv[3] ?? '/tmp/three-peer-check.png';
const PORT = 5191;
const ARGS = [
  '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--headless=shell',
  '--disable-background-networking', '--disable-component-update', '--disable-sync', '--no-first-run', '--disable-quic',
];

async function waitForServer(url, ms = 30000) {
  const end = Date.now() + ms;
  while (Date.now() < end) {
    try { if ((await fetch(url)).ok) return; } catch { /* not up yet */ }
    await new Promise((r) => setTimeout(r, 200));
  }
  throw new Error(`no server at ${url}`);
}

let server = null;
let base = process.env.PEER_URL;
if (!base) {
  base = `http://127.0.0.1:${PORT}`;
  server = spawn('npx', ['vite', '--port', String(PORT), '--strictPort'], { stdio: ['ignore', 'pipe', 'inherit'], detached: true });
  server.stdout.on('data', () => {});
}
let browser;
try {
  await waitForServer(`${base}/bench/three-peer.html`);
  const executablePath = await (await import('@sparticuz/chromium')).default.executablePath();
  browser = await chromium.launch({ executablePath, args: ARGS });
  const page = await browser.newPage({ viewport: { width: 1320, height: 1200 } });
  const messages = [];
  page.on('console', (m) => messages.push(`[${m.type()}] ${m.text()}`));
  page.on('pageerror', (e) => messages.push(`[pageerror] ${e.message}`));
  await page.goto(`${base}/bench/three-peer.html${query ? `?${query}` : ''}`);
  await page.waitForSelector('body[data-done="1"]', { timeout: 300000 }).catch(() => {});
  const result = await page.evaluate(() => window.__peerCheck ?? null);
  await page.screenshot({ path: shot, clip: { x: 0, y: 0, width: 1320, height: 790 } });
  console.log(JSON.stringify(result, null, 1));
  console.log(messages.length ? `console:\n${messages.join('\n')}` : 'console: (nothing)');
  console.log(`screenshot: ${shot}`);
} finally {
  await browser?.close();
  if (server) process.kill(-server.pid, 'SIGTERM');
}
