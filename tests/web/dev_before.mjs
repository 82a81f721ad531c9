// dev_before.mjs — the "before" screenshots of issue 11: the pages as they
// were before its work (web/ of commit fbde60f, the last before the rewrite,
// on Observable Plot and d3), served by today's server (the API only ever
// adds), in the same states and under the same names as the "after" ones of
// run.mjs's screenshot test:  test-output/screenshots/before-*.png.
//
//   node tests/web/dev_before.mjs [commit]
//
// The old pages load d3 and @observablehq/plot from /vendor/, which today's
// package.json no longer installs: MM_BEFORE_VENDOR names a node_modules that
// has them (default ./node_modules).  A developer's tool, not a test.
import { execSync } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, rmSync, symlinkSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { startBrowser, startServer, stopBrowser, stopServer } from './common.mjs';

const commit = process.argv[2] || 'fbde60f';
const vendor = resolve(process.env.MM_BEFORE_VENDOR || 'node_modules');
if (!existsSync(join(vendor, 'd3')) || !existsSync(join(vendor, '@observablehq/plot'))) {
  console.error(`${vendor} has no d3 and @observablehq/plot: set MM_BEFORE_VENDOR`);
  process.exit(2);
}
const shots = 'test-output/screenshots';
mkdirSync(shots, { recursive: true });

// a root with the old web/, today's exercises (theory texts) and the vendor tree
const root = mkdtempSync(join(tmpdir(), 'mm-before-'));
execSync(`git archive ${commit} web | tar -x -C ${root}`);
symlinkSync(resolve('exercises'), join(root, 'exercises'));
symlinkSync(vendor, join(root, 'node_modules'));

// the old page has no data-rendered: wait for a figure or an answer, and the theory
const open = async (page, origin, query) => {
  await page.goto(`${origin}/exercise.html?${query}`);
  await page.waitForFunction(() => (document.querySelector('#figures svg') || !document.querySelector('#scalars').hidden)
    && document.documentElement.dataset.typeset === 'done', null, { timeout: 20000 });
};

let server, browser;
try {
  server = await startServer(['--root', root]);
  browser = await startBrowser();
  const page = await browser.newPage();
  await page.setViewportSize({ width: 390, height: 844 });
  await open(page, server.origin, 'id=vib-sdof-forced');
  await page.$eval('#checks', (e) => e.scrollIntoView());
  await page.screenshot({ path: `${shots}/before-phone-checks-table.png` });
  await open(page, server.origin, 'id=num-polyfit');
  await page.screenshot({ path: `${shots}/before-phone-polyfit.png`, fullPage: true });
  await page.setViewportSize({ width: 1280, height: 800 });
  for (const [id, fig, name] of [['num-newmark', 1, 'newmark-response'], ['vib-base-excitation', 1, 'base-excitation-fig2'], ['vib-integrators', 0, 'integrators-fig1'], ['vib-integrators', 1, 'integrators-fig2'], ['num-complex', 0, 'complex-argand'], ['vib-harmonics', 1, 'harmonics-lissajous'], ['num-linear-system', 0, 'linear-system-fig1'], ['num-eigen', 0, 'eigen-fig1']]) {
    await open(page, server.origin, `id=${id}`);
    const figs = await page.$$('figure.plot');
    if (figs[fig]) await figs[fig].screenshot({ path: `${shots}/before-${name}.png` });
    else console.log(`${id}: no figure ${fig + 1} before`);
  }
  await open(page, server.origin, 'id=vib-sdof-forced');
  await (await page.$('#checks')).screenshot({ path: `${shots}/before-desktop-checks-table.png` });
  await page.screenshot({ path: `${shots}/before-desktop-sdof-forced.png` });
  await open(page, server.origin, 'id=vib-sdof-free');
  await (await page.$('#scalars')).screenshot({ path: `${shots}/before-sdof-free-results.png` });
  await page.screenshot({ path: `${shots}/before-desktop-sdof-free.png` });
  await page.setViewportSize({ width: 390, height: 844 });
  await open(page, server.origin, 'id=vib-sdof-forced');
  await page.focus('#p-k');
  await page.$eval('#p-k', (e) => e.scrollIntoView({ block: 'nearest' }));
  await page.screenshot({ path: `${shots}/before-phone-field-focused.png` });
  console.log(`before: screenshots of ${commit}'s pages in ${shots}/before-*.png`);
} finally {
  await stopBrowser(browser);
  await stopServer(server);
  rmSync(root, { recursive: true, force: true });
}
