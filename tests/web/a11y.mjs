// a11y.mjs — `make a11y`: axe-core on the catalog and on EVERY exercise page
// of the catalog, at 1280 px (desktop) and 390 px (phone), in the default
// (light) scheme, each page once its answer is drawn and its theory typeset
// (and an extension mounted, for the exercises that have one).  A page
// passes when axe finds no violation of impact critical or serious; the
// whole document is checked, the typeset formulas included.
//
// Not part of `make test` (two widths × every page is minutes of axe); the
// browser suite keeps a representative set (tests/web/run.mjs, "axe: ...").
// Ends "a11y: N passed, M failed"; exit code 0 only when M is 0.
// MM_A11Y_ONLY=text sweeps only the pages whose id holds text;
// MM_A11Y_SCHEME=dark (or projector) sweeps in that scheme.
import { readFileSync } from 'node:fs';
import { axeSerious, openTypeset, startBrowser, startServer, stopBrowser, stopServer } from './common.mjs';

// the exercises with an extension (web/js/ex/registry.js): wait for it too
const extensions = [...readFileSync('web/js/ex/registry.js', 'utf8').matchAll(/^\s*'([a-z0-9-]+)':\s*\(\)\s*=>\s*import/gm)].map((m) => m[1]);

const scheme = process.env.MM_A11Y_SCHEME || '';
const sq = scheme ? `scheme=${scheme}` : '';

let server, browser;
let passed = 0, failed = 0;
const t00 = Date.now();
try {
  server = await startServer();
  browser = await startBrowser();
  const page = await browser.newPage();
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  const ids = ['', ...(await (await fetch(`${server.origin}/api/exercises`)).json()).map((e) => e.id)]
    .filter((id) => !process.env.MM_A11Y_ONLY || (id || 'catalog').includes(process.env.MM_A11Y_ONLY));
  for (const [w, h] of [[1280, 800], [390, 844]]) {
    await page.setViewportSize({ width: w, height: h });
    for (const id of ids) {
      const name = `${id || 'catalog'} ${w} px${scheme ? ` ${scheme}` : ''}`;
      const t0 = Date.now();
      errors.length = 0;
      try {
        if (!id) {
          await page.goto(`${server.origin}/${sq ? `?${sq}` : ''}`);
          await page.waitForFunction(() => document.documentElement.dataset.ready === 'true');
        } else {
          await openTypeset(page, server.origin, `id=${id}${sq ? `&${sq}` : ''}`);
          if (extensions.includes(id)) await page.waitForSelector('.extension > :not(style)');
        }
        const v = await axeSerious(page);
        for (const f of await page.$$eval('#theory .katex-error', (es) => es.map((x) => x.textContent.slice(0, 60)))) v.push(`a formula of the theory does not parse: ${f}`);
        if (errors.length) v.push(`script errors: ${errors.join('; ')}`);
        if (v.length) throw new Error(v.join('\n'));
        passed++;
        console.log(`ok   ${name} (${Date.now() - t0} ms)`);
      } catch (e) {
        failed++;
        console.log(`FAIL ${name}: ${e.message.split('\n').slice(0, 12).join('\n     ')}`);
      }
    }
  }
} catch (e) {
  failed++;
  console.log(`FAIL setup: ${e.message}`);
} finally {
  await stopBrowser(browser);
  await stopServer(server);
}
console.log(`a11y: ${passed} passed, ${failed} failed (${((Date.now() - t00) / 1000).toFixed(0)} s)`);
process.exit(failed ? 1 : 0);
