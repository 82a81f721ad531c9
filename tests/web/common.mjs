// common.mjs — start the server and Debian's Chromium for the browser tests
// and the browser benchmark.  The server is $MM_SERVER (default
// build/mechmat-server) on a free port; Chromium is driven by playwright-core
// (its own browser download does not work here, so /usr/bin/chromium).
import { spawn } from 'node:child_process';
import { mkdtempSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium } from 'playwright-core';

export async function startServer(args = []) {
  const bin = process.env.MM_SERVER || 'build/mechmat-server';
  const proc = spawn(bin, ['--port', '0', '--quiet', ...args], { stdio: ['ignore', 'pipe', 'inherit'] });
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
    // animations stand still unless a test plays them: screenshots and
    // timings do not depend on when they are taken
    reducedMotion: 'reduce',
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

// Open an exercise page and wait until its first answer is drawn (or its
// error shown): the page sets <html data-rendered> after every answer.
export async function openExercise(page, origin, query) {
  await page.goto(`${origin}/exercise.html?${query}`);
  await page.waitForFunction(() => document.documentElement.dataset.rendered, null, { timeout: 15000 });
}

// Open an exercise page and wait until its theory is typeset too.
export async function openTypeset(page, origin, query) {
  await openExercise(page, origin, query);
  await page.waitForFunction(() => document.documentElement.dataset.typeset === 'done', null, { timeout: 15000 });
}

// axe-core in the page: the violations of impact critical or serious, as
// "rule: target, target" lines (empty when there are none).  context as
// for axe.run (default the whole document).
export async function axeSerious(page, context = null) {
  const has = await page.evaluate(() => typeof window.axe !== 'undefined');
  if (!has) await page.addScriptTag({ path: 'node_modules/axe-core/axe.min.js' });
  const v = await page.evaluate((ctx) => window.axe.run(ctx || document, { resultTypes: ['violations'] })
    .then((r) => r.violations.filter((x) => x.impact === 'critical' || x.impact === 'serious')
      .map((x) => `${x.id} (${x.impact}): ${x.nodes.slice(0, 3).map((n) => n.target.join(' ')).join(', ')}`)), context);
  return v;
}

// What the eye checks on a laid-out page, measured: no sideways scrolling,
// every table inside its box, every figure drawn at the width it is shown,
// the y label clear of the tick labels and the x tick labels clear of each
// other, and every box that scrolls sideways reachable by keyboard.
export async function layoutProblems(page) {
  return page.evaluate(() => {
    const out = [];
    const over = document.documentElement.scrollWidth - window.innerWidth;
    if (over > 1) out.push(`the page scrolls sideways by ${over} px`);
    for (const w of document.querySelectorAll('.answer .table-wrap')) {
      if (!w.offsetParent) continue;
      const t = w.querySelector('table');
      if (t && t.getBoundingClientRect().width > w.getBoundingClientRect().width + 1) out.push(`table ${w.dataset.table || t.className} is ${Math.round(t.getBoundingClientRect().width)} px in a ${Math.round(w.getBoundingClientRect().width)} px box`);
    }
    const hit = (a, b) => a.left < b.right - 0.5 && b.left < a.right - 0.5 && a.top < b.bottom - 0.5 && b.top < a.bottom - 0.5;
    document.querySelectorAll('svg.mm-plot').forEach((svg, i) => {
      if (!svg.getClientRects().length) return;
      const shown = svg.getBoundingClientRect().width, drawn = Number(svg.getAttribute('width'));
      const inStage = svg.closest('.stage') && document.querySelector('.workbench:has(.params:focus-within)');
      if (!inStage && Math.abs(shown - drawn) > 1) out.push(`figure ${i + 1} drawn ${drawn} px wide, shown at ${shown.toFixed(1)}`);
      const yl = svg.querySelector('.mm-ylabel');
      if (yl && yl.textContent) {
        const r = yl.getBoundingClientRect();
        for (const tk of svg.querySelectorAll('.mm-ytick')) if (hit(r, tk.getBoundingClientRect())) { out.push(`figure ${i + 1}: the y label touches the tick "${tk.textContent}"`); break; }
        if (r.left < svg.getBoundingClientRect().left - 0.5) out.push(`figure ${i + 1}: the y label is cut at the left`);
      }
      const xt = [...svg.querySelectorAll('.mm-xtick')].map((e) => e.getBoundingClientRect());
      for (let k = 1; k < xt.length; k++) if (hit(xt[k - 1], xt[k])) { out.push(`figure ${i + 1}: x tick labels overlap`); break; }
    });
    for (const e of document.querySelectorAll('#theory .katex-display, #theory pre, .curl pre, .table-wrap')) {
      const cs = getComputedStyle(e);
      if (/(auto|scroll)/.test(cs.overflowX) && e.scrollWidth > e.clientWidth + 1 && e.getAttribute('tabindex') !== '0' && !e.querySelector('[tabindex="0"], a, button, input')) {
        out.push(`${e.className || e.tagName} scrolls sideways but cannot be reached by keyboard`);
      }
    }
    return out;
  });
}

// Wait until every figure is drawn at the width of its box (after a resize).
export async function settledFigures(page) {
  await page.waitForFunction(() => [...document.querySelectorAll('svg.mm-plot')].every((s) => !s.getClientRects().length ||
    Math.abs(Number(s.getAttribute('width')) - Math.floor(s.parentElement.clientWidth)) <= 1), null, { timeout: 10000 });
}
