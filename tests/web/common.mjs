// common.mjs — start the server and Debian's Chromium for the browser tests
// and the browser benchmark.  The server is $MM_SERVER (default
// build/mechmat-server) on a free port; Chromium is driven by playwright-core
// (its own browser download does not work here, so /usr/bin/chromium).
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';

export async function startServer() {
  const bin = process.env.MM_SERVER || 'build/mechmat-server';
  const proc = spawn(bin, ['--port', '0', '--quiet'], { stdio: ['ignore', 'pipe', 'inherit'] });
  const port = await new Promise((resolve, reject) => {
    let out = '';
    const timer = setTimeout(() => reject(new Error('the server did not start in 10 s')), 10000);
    proc.stdout.on('data', (d) => {
      out += d;
      const m = out.match(/127\.0\.0\.1:(\d+)/);
      if (m) { clearTimeout(timer); resolve(Number(m[1])); }
    });
    proc.on('exit', (code) => reject(new Error(`the server exited with ${code}`)));
  });
  return { proc, origin: `http://127.0.0.1:${port}` };
}

export async function stopServer(server) {
  if (!server) return;
  await new Promise((resolve) => {
    server.proc.on('exit', resolve);
    server.proc.kill('SIGTERM');
    setTimeout(resolve, 3000);
  });
}

// The flags keep Chromium off the (closed) network: without them it keeps
// trying to reach Google's hosts.
export async function startBrowser() {
  const profile = mkdtempSync(join(tmpdir(), 'mm-chromium-'));
  const browser = await chromium.launchPersistentContext(profile, {
    executablePath: process.env.MM_CHROMIUM || '/usr/bin/chromium',
    headless: true,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
      '--disable-dev-shm-usage'],
    acceptDownloads: true,
    viewport: { width: 1280, height: 800 },
    timeout: 30000,
  });
  browser.profile = profile;
  return browser;
}

export async function stopBrowser(browser) {
  if (!browser) return;
  await browser.close().catch(() => {});
  rmSync(browser.profile, { recursive: true, force: true });
}

// Resolves with the detail of the page's next `mm:rendered` event (the page
// dispatches it after every redraw).
export function nextRender(page, timeout = 10000) {
  return page.evaluate((ms) => new Promise((resolve, reject) => {
    const t = setTimeout(() => reject(new Error('no mm:rendered within ' + ms + ' ms')), ms);
    window.addEventListener('mm:rendered', (e) => { clearTimeout(t); resolve(e.detail); }, { once: true });
  }), timeout);
}

// Open an exercise page and wait until its first answer is drawn.
export async function openExercise(page, origin, query) {
  const first = page.waitForFunction(() => document.querySelector('#figures svg, #answer-error:not([hidden])'),
    null, { timeout: 15000 });
  await page.goto(`${origin}/exercise.html?${query}`);
  await first;
}
