// run.mjs — the pages in a real browser (Debian's Chromium through
// playwright-core), against a server started here.  Ends with the line
// "browser: N passed, M failed"; exit code 0 only when M is 0.
// Screenshots go to test-output/screenshots/ (after-*.png: the states the
// defects of issue 11 were seen in, to set beside the before-*.png that
// tests/web/dev_before.mjs takes of the pages as they were before).
//
// Deterministic: every wait is for a state of the page (an answer drawn,
// a frame shown), never for a time; animations stand still (reduced
// motion) unless a test plays one.
import assert from 'node:assert/strict';
import { mkdirSync, mkdtempSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { readFile } from 'node:fs/promises';
import {
  axeSerious, layoutProblems, nextRender, openExercise, openTypeset, settledFigures,
  startBrowser, startServer, stopBrowser, stopServer,
} from './common.mjs';
import { staTrussTests } from './sta-truss.mjs';
import { assignmentTests } from './assignment.mjs';

const shots = 'test-output/screenshots';
mkdirSync(shots, { recursive: true });

let server, browser;
const results = [];
const t00 = Date.now();

// MM_WEB_ONLY=text runs only the tests whose name holds text (to repeat one).
async function test(name, fn) {
  if (process.env.MM_WEB_ONLY && !name.includes(process.env.MM_WEB_ONLY)) return;
  const page = await browser.newPage();
  const outside = [];
  page.on('request', (r) => { if (!r.url().startsWith(server.origin) && !r.url().startsWith('data:') && !r.url().startsWith('blob:')) outside.push(r.url()); });
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  const t0 = Date.now();
  try {
    await fn(page);
    assert.deepEqual(outside, [], 'every request goes to our own server (no CDN)');
    assert.deepEqual(errors, [], 'no script errors on the page');
    results.push({ name, ok: true });
    console.log(`ok   ${name} (${Date.now() - t0} ms)`);
  } catch (e) {
    results.push({ name, ok: false });
    console.log(`FAIL ${name}: ${e.message.split('\n').slice(0, 8).join('\n     ')}`);
  } finally {
    await page.close();
  }
}

const scalar = (page, name) => page.$eval(`[data-scalar="${name}"] .val`, (e) => Number(e.dataset.value));
const firstPath = (page) => page.$eval('svg.mm-plot', (svg) => [...svg.querySelectorAll('path.mm-series')].map((p) => p.getAttribute('d')).join('|'));
const solveJson = async (query) => (await fetch(`${server.origin}/api/exercises/${query}`)).json();
/** Answer every solve of the page with the server's answer changed by f. */
const rewriteSolve = (page, f) => page.route('**/api/exercises/*/solve*', async (route) => {
  const response = await route.fetch();
  const json = await response.json();
  await route.fulfill({ response, json: f(json) || json });
});

try {
  server = await startServer();
  browser = await startBrowser();
  const api = await (await fetch(`${server.origin}/api/exercises`)).json();

  // ---- the catalog -------------------------------------------------------------------

  await test('the catalog lists every exercise of the registry, in book order', async (page) => {
    await page.goto(`${server.origin}/`);
    await page.waitForSelector('li.exercise');
    const ids = await page.$$eval('li.exercise', (lis) => lis.map((li) => li.dataset.id));
    assert.deepEqual(ids, api.map((e) => e.id));
    const titles = await page.$$eval('li.exercise a', (as) => as.map((a) => a.textContent));
    for (const e of api) assert.ok(titles.some((t) => t.includes(e.title)), `title of ${e.id} shown`);
  });

  await test('the search box filters the catalog as you type', async (page) => {
    await page.goto(`${server.origin}/`);
    await page.waitForSelector('li.exercise');
    await page.fill('#q', 'coulomb');
    await page.waitForFunction(() => [...document.querySelectorAll('li.exercise')].filter((li) => !li.hidden).length === 1);
    const shown = await page.$$eval('li.exercise', (lis) => lis.filter((li) => !li.hidden).map((li) => li.dataset.id));
    assert.deepEqual(shown, ['vib-coulomb']);
  });

  // ---- the exercise page ------------------------------------------------------------------

  await test('an exercise page shows typeset math and a plot with labelled axes', async (page) => {
    await openTypeset(page, server.origin, 'id=vib-sdof-forced');
    assert.ok(await page.$('.katex'), 'a KaTeX element');
    assert.ok(await page.$('math'), 'MathML for screen readers');
    assert.ok(await page.$('svg.mm-plot path.mm-series'), 'a plotted path');
    assert.equal(await page.$eval('svg.mm-plot .mm-xlabel', (e) => e.textContent), 't [s]', 'x axis labelled with its unit');
    assert.equal(await page.$eval('svg.mm-plot .mm-ylabel', (e) => e.textContent), `${(await solveJson('vib-sdof-forced')).outputs.find((o) => o.name === 'x').label} [m]`, 'y axis: the declared label and unit');
    assert.equal(await scalar(page, 'omega_n'), 10);
  });

  await test('typing a new stiffness changes the natural frequency and the plot', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const before = await firstPath(page);
    const rendered = nextRender(page);
    await page.fill('#p-k', '400');
    await rendered;
    assert.equal(await scalar(page, 'omega_n'), 20);
    assert.notEqual(await firstPath(page), before, 'the curve was redrawn');
  });

  await test('a negative mass shows the API message beside the mass field', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const api400 = await solveJson('vib-sdof-forced/solve?m=-1');
    let rendered = nextRender(page);
    await page.fill('#p-m', '-1');
    await rendered;
    await page.waitForSelector('#e-m:not([hidden])');
    assert.equal((await page.textContent('#e-m')).trim(), api400.error.message, 'the API message, word for word');
    assert.equal(await page.getAttribute('#p-m', 'aria-invalid'), 'true');
    assert.ok((await page.getAttribute('#p-m', 'aria-describedby')).split(' ').includes('e-m'), 'the message describes the field');
    assert.ok(await page.$('svg.mm-plot path.mm-series'), 'the previous answer is kept');
    assert.ok(await page.$('#answer.stale'), 'and dimmed');
    assert.equal(await scalar(page, 'omega_n'), 10, 'the kept answer is the last good one');
    rendered = nextRender(page);
    await page.fill('#p-m', '4');
    await rendered;
    assert.equal(await page.$('#e-m:not([hidden])'), null, 'the message goes with a good value');
    assert.equal(await page.getAttribute('#p-m', 'aria-invalid'), null);
    assert.equal(await page.$('#answer.stale'), null, 'no longer dimmed');
    assert.equal(await scalar(page, 'omega_n'), 5);
  });

  await test('a failed check is shown, not hidden', async (page) => {
    await rewriteSolve(page, (json) => { if (json.checks && json.checks.length) json.checks[0].passed = false; });
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const row = await page.waitForSelector('#checks tr.fail');
    assert.ok(await row.isVisible(), 'the failed row is visible');
    assert.match(await row.textContent(), /failed/);
    assert.match(await page.textContent('#checks .summary'), /1 of \d+ checks failed/);
  });

  await test('the URL reproduces the state after a reload, and back and forward work', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    let rendered = nextRender(page);
    await page.fill('#p-k', '400');
    await rendered;
    await page.waitForFunction(() => location.search.includes('k=400'));
    rendered = nextRender(page);
    await page.fill('#p-m', '4');
    await rendered;
    await page.waitForFunction(() => location.search.includes('m=4'));
    const url = page.url();
    await openExercise(page, server.origin, url.split('?')[1]);
    assert.equal(await page.inputValue('#p-k'), '400');
    assert.equal(await page.inputValue('#p-m'), '4');
    assert.equal(await scalar(page, 'omega_n'), 10);          // sqrt(400/4)
    rendered = nextRender(page);
    await page.goBack();
    await rendered;
    assert.equal(new URL(page.url()).search, '?id=vib-sdof-forced&k=400');
    assert.equal(await page.inputValue('#p-m'), '1');
    assert.equal(await scalar(page, 'omega_n'), 20, 'back redraws the earlier answer');
    rendered = nextRender(page);
    await page.goForward();
    await rendered;
    assert.equal(new URL(page.url()).search, '?id=vib-sdof-forced&m=4&k=400');
    assert.equal(await page.inputValue('#p-m'), '4');
    assert.equal(await scalar(page, 'omega_n'), 10);
    rendered = nextRender(page);
    await page.click('#reset');
    await rendered;
    assert.equal(new URL(page.url()).search, '?id=vib-sdof-forced');
    assert.equal(await page.inputValue('#p-k'), '100');
  });

  await test('an invalid value stays out of the URL and the history', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced&k=400');
    const before = await page.evaluate(() => [location.search, history.length]);
    let rendered = nextRender(page);
    await page.fill('#p-m', 'abc');
    assert.equal((await rendered).ok, false);
    assert.deepEqual(await page.evaluate(() => [location.search, history.length]), before, 'm=abc is not pushed');
    rendered = nextRender(page);
    await page.fill('#p-m', '-3');
    assert.equal((await rendered).ok, false);
    assert.deepEqual(await page.evaluate(() => [location.search, history.length]), before, 'm=-3 neither');
    rendered = nextRender(page);
    await page.fill('#p-m', '4');
    assert.equal((await rendered).ok, true);
    assert.equal(await page.evaluate(() => location.search), '?id=vib-sdof-forced&m=4&k=400', 'a good value is');
  });

  await test('ArrowUp and ArrowDown are inverses, also at a decade', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const press = async (key, want) => {
      const rendered = nextRender(page);
      await page.press('#p-k', key);
      await rendered;
      assert.equal(await page.inputValue('#p-k'), want, `${key} gives ${want}`);
    };
    await page.focus('#p-k');
    await press('ArrowDown', '99');          // below a power of ten the step is the lower decade's
    await press('ArrowUp', '100');
    await press('ArrowUp', '110');
    await press('ArrowDown', '100');
    await press('Shift+ArrowDown', '90');
    await press('Shift+ArrowUp', '100');
    assert.equal(await scalar(page, 'omega_n'), 10);
  });

  await test('the CSV download holds the series of the JSON answer', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced&points=21');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#dl-csv')]);
    const csv = await readFile(await download.path(), 'utf8');
    const answer = await solveJson('vib-sdof-forced/solve?points=21');
    const rows = csv.trim().split('\n');
    assert.match(rows[0], /^t \[s\],x \[m\]$/);
    assert.equal(rows.length, 1 + answer.series[0].x.length);
    rows.slice(1).forEach((row, i) => {
      const [t, x] = row.split(',').map(Number);
      assert.equal(t, answer.series[0].x[i]);
      assert.equal(x, answer.series[0].y[i]);
    });
    await openExercise(page, server.origin, 'id=vib-dft');
    const [dl2] = await Promise.all([page.waitForEvent('download'), page.click('#dl-csv')]);
    const long = (await readFile(await dl2.path(), 'utf8')).trim().split('\n');
    const dft = await solveJson('vib-dft/solve');
    assert.equal(long[0], 'series,x,x_unit,y,y_unit');
    const points = dft.series.flatMap((s) => s.x.map((x, i) => [s.name, x, s.y[i]]));
    assert.equal(long.length - 1, points.length);
    points.forEach(([name, x, y], i) => {
      const cells = long[i + 1].split(',');
      assert.deepEqual([cells[0], Number(cells[1]), Number(cells[3])], [name, x, y]);
    });
  });

  await test('the form is reachable by keyboard and every input has its label', async (page) => {
    await openExercise(page, server.origin, 'id=num-linear-system');
    const unlabelled = await page.$$eval('#fields .input', (inputs) =>
      inputs.filter((i) => !document.querySelector(`label[for="${i.id}"]`)).map((i) => i.id));
    assert.deepEqual(unlabelled, []);
    await page.focus('#p-A');
    await page.keyboard.press('Tab');
    assert.equal(await page.evaluate(() => document.activeElement.id), 'p-b', 'Tab goes from A to b');
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const meta = await solveJson('vib-sdof-forced');
    const want = meta.params.map((p) => `p-${p.name}`);
    const seen = [];
    for (let i = 0; i < 60 && seen.length < want.length; i++) {
      await page.keyboard.press('Tab');
      const id = await page.evaluate(() => document.activeElement.id);
      if (want.includes(id) && !seen.includes(id)) seen.push(id);
    }
    assert.deepEqual(seen, want);
  });

  await test('help texts keep their first letter; a word stands for its number', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-free');
    const meta = await solveJson('vib-sdof-free');
    const x0 = meta.params.find((p) => p.name === 'x0');
    assert.ok((await page.textContent('#h-x0')).startsWith(x0.help), `"${x0.help}" as written`);
    assert.equal((await page.textContent('[data-scalar="regime"] dd')).trim(), 'underdamped', 'the word, without a bare 0');
  });

  await test('numbers carry the digits their accuracy supports', async (page) => {
    await rewriteSolve(page, (json) => {
      json.scalars.push(
        { name: 'zz_err', label: 'with an error', unit: 'm', value: 1.23456789, error: 3e-4, error_kind: 'bound' },
        { name: 'zz_est', label: 'with an estimate', unit: '', value: 0.017967921145630915, error: 6.1e-10, error_kind: 'estimate' },
        { name: 'zz_none', label: 'neither', unit: '', value: 2.5383654128340476 });
    });
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const digits = (n) => page.$eval(`[data-scalar="${n}"] .val`, (e) => e.dataset.digits);
    assert.equal(await digits('X'), '0.02538365412834048', 'exact: every digit of the shortest form');
    assert.equal(await digits('magnification'), '2.5383654128340476');
    assert.equal(await digits('zz_err'), '1.2346', 'no digit beyond a 3e-4 bound');
    assert.equal(await page.textContent('[data-scalar="zz_err"] .acc'), '± 0.0003 (error bound)');
    assert.equal(await digits('zz_est'), '0.0179679211', 'to the 1e-10 of the estimate');
    assert.equal(await digits('zz_none'), '2.53837', 'neither: six significant digits');
  });

  await test('a new answer is announced in a live region', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    assert.equal(await page.getAttribute('#announce', 'aria-live'), 'polite');
    const rendered = nextRender(page);
    await page.fill('#p-k', '400');
    await rendered;
    const text = await page.textContent('#announce');
    assert.match(text, /natural frequency 20 rad\/s/, text);
  });

  // ---- figures --------------------------------------------------------------------------

  await test('figures use the figure hints: grouping, marks, reference under the result, log scales, equal aspect', async (page) => {
    await rewriteSolve(page, (json) => {
      const x = json.series[0];
      json.series = [
        { ...x, name: 'x_ref', label: 'displacement, exact', role: 'reference', figure: 'a' },
        { ...x, figure: 'a' },
        { ...x, name: 'x_steps', label: 'displacement, steps', mark: 'step', figure: 'a', y: x.y.map((v) => v * 0.5) },
        { name: 'err', label: 'error', unit: 'm', x_label: 'h', x_unit: 's', x: [1e-3, 1e-2, 1e-1, 1], y: [1e-9, 1e-7, 1e-5, 1e-3], mark: 'dots', x_scale: 'log', y_scale: 'log', figure: 'b' },
        { name: 'orbit', label: 'orbit', unit: 'm', x_label: 'x', x_unit: 'm', x: [0, 4, 0, -4, 0], y: [1, 0, -1, 0, 1], aspect: 'equal', figure: 'c' },
        { name: 'bars', label: 'amplitude', unit: '', x_label: 'k', x_unit: '', x: [1, 2, 3], y: [3, 1, 2], mark: 'bars', figure: 'd' },
      ];
    });
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const figs = await page.$$eval('svg.mm-plot', (svgs) => svgs.map((svg) => ({
      scales: svg.dataset.scales, aspect: svg.dataset.aspect || '',
      series: [...svg.querySelectorAll('.mm-plotarea > .mm-series')].map((e) => ({ name: e.dataset.series, cls: e.getAttribute('class'), tag: e.tagName, dash: e.getAttribute('stroke-dasharray') || '', d: e.getAttribute('d') || '' })),
    })));
    assert.equal(figs.length, 4, 'four figure hints, four figures');
    assert.deepEqual(figs[0].series.map((s) => s.name), ['x_ref', 'x', 'x_steps'], 'the reference is drawn first, under the result');
    assert.match(figs[0].series[0].cls, /mm-reference/);
    assert.notEqual(figs[0].series[0].dash, '', 'the reference is dashed');
    assert.equal(figs[0].series[1].dash, '', 'the result is solid');
    assert.match(figs[0].series[2].d, /H[\d.]+V/, 'a step mark is drawn as steps');
    assert.equal(figs[1].scales, 'log,log');
    assert.equal(figs[1].series[0].tag, 'g', 'dots');
    const [ux, uy] = figs[2].aspect.split(':').map(Number);
    assert.ok(Math.abs(ux - uy) <= 0.02 * ux, `equal aspect: the same metres per pixel both ways (${figs[2].aspect})`);
    assert.equal(await page.$$eval('svg.mm-plot', (s) => s[3].querySelectorAll('.mm-series rect').length), 3, 'bars');
  });

  await test('labels come from the declared outputs, colours and dashes keep overlaid series apart', async (page) => {
    await openExercise(page, server.origin, 'id=num-newmark');
    // the response figure (the energy residual may come first)
    const fig = await page.$eval('figure.plot:has(svg.mm-plot path.mm-series[stroke-dasharray]) svg.mm-plot', (svg) => ({
      text: svg.textContent,
      ylabel: svg.querySelector('.mm-ylabel').textContent,
      series: [...svg.querySelectorAll('.mm-plotarea path.mm-series')].map((p) => `${p.getAttribute('stroke')}|${p.getAttribute('stroke-dasharray') || ''}|${p.getAttribute('stroke-width')}`),
      legend: [...svg.querySelectorAll('.mm-legend line')].map((l) => `${l.getAttribute('stroke')}|${l.getAttribute('stroke-dasharray') || ''}`),
    }));
    assert.equal(fig.ylabel, 'displacement [m]');
    assert.doesNotMatch(fig.text, /q1_reference|q2_reference/, 'no internal names');
    assert.equal(new Set(fig.series).size, fig.series.length, `every curve drawn its own way: ${fig.series.join(', ')}`);
    const drawn = new Set(fig.series.map((s) => s.split('|').slice(0, 2).join('|')));
    for (const l of fig.legend) assert.ok(drawn.has(l), `the legend's ${l} is a drawn curve`);
    // one colour per method across the figures of a page
    await openExercise(page, server.origin, 'id=vib-integrators');
    const colours = await page.$$eval('svg.mm-plot', (svgs) => svgs.map((svg) => Object.fromEntries(
      [...svg.querySelectorAll('.mm-plotarea .mm-series')].map((e) => [e.dataset.series, e.getAttribute('stroke') || e.getAttribute('fill')]))));
    // a method is the family member's key (x_rk4, work_rk4, step_rk4 → rk4)
    const byKey = new Map();
    for (const f of colours) for (const [n, c2] of Object.entries(f)) {
      const key = n.replace(/^[a-z]+_/, '');
      if (!byKey.has(key)) byKey.set(key, []);
      byKey.get(key).push(c2);
    }
    let shared = 0;
    for (const [key, c] of byKey) {
      if (c.length < 2) continue;
      shared++;
      assert.equal(new Set(c).size, 1, `${key} has one colour in every figure: ${c}`);
    }
    assert.ok(shared >= 3, `methods drawn in two figures or more: ${shared}`);
    assert.equal(colours[0].x_exact, '#4a525b', 'the reference of all the methods is none of their colours');
  });

  await test('whole-number axes have no decimals; a zoom, a different scale or unit gets its own figure', async (page) => {
    await openExercise(page, server.origin, 'id=num-linear-system');
    const ticks = await page.$$eval('svg.mm-plot', (svgs) => svgs.map((s) => [...s.querySelectorAll('.mm-xtick')].map((t) => t.textContent)));
    assert.equal(ticks.length, 2, 'x near 2000 and the singular values do not share an axis');
    for (const t of ticks) assert.deepEqual(t, ['1', '2', '3']);
    await openExercise(page, server.origin, 'id=vib-fourier-series');
    assert.equal((await page.$$('svg.mm-plot')).length, 2, 'the zoom near the jump is a figure of its own');
  });

  await test('a figure reads its values by pointer and by keyboard, and has a data table', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-free');
    await (await page.$('svg.mm-plot')).scrollIntoViewIfNeeded();   // below the animation
    const box = await (await page.$('svg.mm-plot')).boundingBox();
    await page.mouse.move(box.x + box.width * 0.55, box.y + box.height * 0.5);
    const tip = await page.waitForSelector('svg.mm-plot .mm-tip');
    assert.match(await tip.textContent(), /t = [\d.\u2009]+ s.*displacement( \(closed form\))? = −?[\d.\u2009 ]+( × 10[⁻\d]+)? m/);
    await page.focus('.plot-svg');
    assert.equal(await page.getAttribute('.plot-svg', 'role'), 'slider');
    const v0 = Number(await page.getAttribute('.plot-svg', 'aria-valuenow'));
    await page.keyboard.press('ArrowRight');
    assert.equal(Number(await page.getAttribute('.plot-svg', 'aria-valuenow')), v0 + 1);
    await page.keyboard.press('Home');
    assert.match(await page.getAttribute('.plot-svg', 'aria-valuetext'), /^t = 0 s; displacement( \(closed form\))? = 0[.,]01 m$/);
    await page.click('.fig-data summary');
    // the table is built when the details open: wait for its rows (a busy machine)
    await page.waitForSelector('.fig-data table tbody tr');
    const rows = await page.$$eval('.fig-data table tbody tr', (r) => r.length);
    const answer = await solveJson('vib-sdof-free/solve');
    assert.ok(rows >= 20 && rows <= 62, `a table of ${rows} rows`);
    assert.equal(await page.$eval('.fig-data table tbody tr td .num', (e) => Number(e.dataset.value)), answer.series[0].x[0]);
  });

  await test('every figure downloads as SVG, each alone and all in one file', async (page) => {
    await openExercise(page, server.origin, 'id=vib-base-excitation');
    const n = (await page.$$('svg.mm-plot')).length;
    assert.ok(n >= 2);
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#dl-svg')]);
    const svg = await readFile(await download.path(), 'utf8');
    assert.match(svg, /^<\?xml[^>]*>\s*<svg[^>]+xmlns="http:\/\/www\.w3\.org\/2000\/svg"/);
    const anims = (await page.$$('figure.anim .anim-svg svg')).length ? 1 : 0;
    assert.equal((svg.match(/<svg/g) || []).length, n + anims + 1, 'every figure (and the animation\'s frame) in the file');
    for (const label of await page.$$eval('svg.mm-plot .mm-xlabel', (e) => e.map((x) => x.textContent))) assert.ok(svg.includes(label), label);
    const [d2] = await Promise.all([page.waitForEvent('download'), page.click('#figures figure.plot .dl-svg')]);
    assert.match(d2.suggestedFilename(), /^vib-base-excitation.*fig2\.svg$/);
    await page.setContent((await readFile(await d2.path(), 'utf8')).replace(/^<\?xml[^>]*>\s*/, ''));
    assert.ok(await page.$('svg path'), 'it draws on its own');
  });

  await test('the curl line is the exact request of the answer shown', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced&c=1&omega=10');
    const line = (await page.textContent('#curl')).trim();
    const m = line.match(/^curl '([^']+)'$/);
    assert.ok(m, `a curl line: ${line}`);
    assert.equal(m[1], `${server.origin}/api/exercises/vib-sdof-forced/solve?c=1&omega=10`);
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#dl-json')]);
    const shown = JSON.parse(await readFile(await download.path(), 'utf8'));
    const fetched = await (await fetch(m[1])).json();
    delete shown.elapsed_us;
    delete fetched.elapsed_us;
    assert.deepEqual(fetched, shown);
  });

  await test('keep a run and compare: both curves, both sets of numbers', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    await page.click('#keep');
    assert.equal(await page.getAttribute('#keep', 'aria-pressed'), 'true');
    const rendered = nextRender(page);
    await page.fill('#p-k', '400');
    await rendered;
    const fig = await page.$eval('svg.mm-plot', (svg) => ({
      kept: [...svg.querySelectorAll('.mm-kept')].map((e) => e.dataset.series),
      now: [...svg.querySelectorAll('.mm-plotarea > .mm-series:not(.mm-kept)')].map((e) => e.dataset.series),
      legend: svg.querySelector('.mm-legend').textContent,
    }));
    assert.deepEqual(fig.kept, ['x']);
    assert.deepEqual(fig.now, ['x']);
    assert.match(fig.legend, /kept run \(k = 100\)/);
    assert.equal(await scalar(page, 'omega_n'), 20);
    assert.equal(await page.$eval('[data-scalar="omega_n"] .kept-val', (e) => Number(e.dataset.kept)), 10);
    assert.match(await page.textContent('#keep-note'), /k = 100/);
    await page.click('#keep');
    assert.equal(await page.$('.mm-kept'), null, 'forgotten');
  });

  // ---- the animation ------------------------------------------------------------------------

  await test('the animation player: scrubber, speed, loop, play, a marker on the time plot, scrubbing the plot, touch', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const answer = await solveJson('vib-sdof-forced/solve');
    const ts = answer.animation.t;
    assert.equal(await page.getAttribute('figure.anim', 'data-frame'), '0', 'reduced motion: it does not start by itself');
    assert.ok(await page.$('figure.anim .anim-play'));
    // the scrubber moves the drawing and the marker on the time plot
    const F = Math.floor(0.6 * (ts.length - 1));      // a frame past the middle
    await page.$eval('.anim-scrub', (s, f) => { s.value = String(f); s.dispatchEvent(new Event('input')); }, F);
    assert.equal(await page.getAttribute('figure.anim', 'data-frame'), String(F));
    assert.equal(Number(await page.$eval('svg.mm-plot .mm-marker', (g) => g.dataset.t)), ts[F]);
    assert.match(await page.getAttribute('.anim-scrub', 'aria-valuetext'), /^t = [\d.]+ s$/);
    const massX = () => page.$eval('figure.anim [data-name="mass"] polygon', (p) => p.getAttribute('points'));
    const at120 = await massX();
    // a press on the time plot moves the animation to that time
    const plot = await page.$('figure.plot.linked svg.mm-plot');
    const geo = await plot.evaluate((svg) => { const r = svg.getBoundingClientRect(); const a = svg.querySelector('.mm-axis line'); return { x: r.x, y: r.y, x1: Number(a.getAttribute('x1')), x2: Number(a.getAttribute('x2')), w: Number(svg.getAttribute('width')), rw: r.width }; });
    const px = geo.x + (geo.x1 + 0.25 * (geo.x2 - geo.x1)) * geo.rw / geo.w;
    await page.mouse.move(px, geo.y + 60);
    await page.mouse.down();
    await page.mouse.up();
    const f = Number(await page.getAttribute('figure.anim', 'data-frame'));
    const want = ts.reduce((b, t, i) => (Math.abs(t - 2.5) < Math.abs(ts[b] - 2.5) ? i : b), 0);
    assert.ok(Math.abs(f - want) <= 1, `a press at t = 2.5 s shows frame ${want} (got ${f})`);
    assert.notEqual(await massX(), at120, 'the mass moved');
    // a touch drag across the drawing scrubs too (from the first frame: the
    // press above may have landed on the last one)
    await page.$eval('.anim-scrub', (s) => { s.value = '0'; s.dispatchEvent(new Event('input')); });
    const f0 = Number(await page.getAttribute('figure.anim', 'data-frame'));
    const anim = await (await page.$('figure.anim svg')).boundingBox();
    await page.$eval('figure.anim svg', (svg, b) => {
      const ev = (type, x) => svg.dispatchEvent(new PointerEvent(type, { pointerId: 7, pointerType: 'touch', clientX: x, clientY: b.y + b.height / 2, bubbles: true }));
      ev('pointerdown', b.x + 10); ev('pointermove', b.x + 30); ev('pointermove', b.x + b.width * 0.6); ev('pointerup', b.x + b.width * 0.6);
    }, anim);
    assert.notEqual(Number(await page.getAttribute('figure.anim', 'data-frame')), f0, 'a touch drag moved the animation');
    // play: frames advance (motion allowed for this test)
    await page.emulateMedia({ reducedMotion: 'no-preference' });
    await page.$eval('.anim-scrub', (s) => { s.value = '0'; s.dispatchEvent(new Event('input')); });
    await page.click('.anim-play');
    await page.waitForFunction(() => Number(document.querySelector('figure.anim').dataset.frame) >= 3);
    assert.equal(await page.getAttribute('.anim-play', 'aria-label'), 'Pause');
    await page.click('.anim-play');
    assert.equal(await page.getAttribute('.anim-play', 'aria-label'), 'Play');
    // speed: the note says how it relates to real time
    assert.equal(await page.textContent('.anim-rate'), 'real time');
    await page.selectOption('.anim-speed', '0.5');
    assert.equal(await page.textContent('.anim-rate'), '2× slower than real time');
    // without loop it stops at the last frame
    await page.selectOption('.anim-speed', '4');
    await page.uncheck('.anim-loop');
    await page.$eval('.anim-scrub', (s) => { s.value = String(Number(s.max) - 6); s.dispatchEvent(new Event('input')); });
    await page.click('.anim-play');
    await page.waitForFunction(() => document.querySelector('.anim-play').getAttribute('aria-label') === 'Play');
    assert.equal(Number(await page.getAttribute('figure.anim', 'data-frame')), ts.length - 1);
  });

  await test('every kind and style of shape is drawn; one frame is a static diagram', async (page) => {
    await rewriteSolve(page, (json) => {
      json.animation = {
        t: [0], t_label: 't', t_unit: 's', bounds: [-1, -1, 3, 2],
        shapes: [
          { name: 'ground', kind: 'polygon', x: [[-1, 3, 3, -1]], y: [[-1, -1, -0.8, -0.8]], style: 'ground' },
          { name: 'wall', kind: 'line', x: [[0, 0]], y: [[-0.8, 2]], style: 'ground' },
          { name: 'AB', kind: 'line', x: [[0, 2]], y: [[0, 0]], value: [1500], style: 'tension' },
          { name: 'BC', kind: 'line', x: [[2, 1]], y: [[0, 1.5]], value: [-900], style: 'compression' },
          { name: 'pin', kind: 'circle', x: [[2]], y: [[0]], r: 0.08 },
          { name: 'F', kind: 'arrow', x: [[1, 1]], y: [[1.5, 0.5]], value: [1000], unit: 'N', scale: 0.001 },
          { name: 'path', kind: 'path', x: [[0, 1, 2]], y: [[1, 1.8, 1]] },
          { name: 'A', kind: 'label', x: [[0]], y: [[0.2]], text: 'A' },
          { name: 'hl', kind: 'line', x: [[0, 1]], y: [[0, 1.5]], style: 'highlight' },
        ],
      };
    });
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    assert.ok(await page.$('figure.anim.still'), 'a still');
    assert.equal(await page.isVisible('figure.anim .anim-controls'), false, 'no player controls');
    const d = await page.$eval('figure.anim svg', (svg) => {
      const g = (n) => svg.querySelector(`[data-name="${n}"]`);
      return {
        hatch: !!g('ground').querySelector('polygon[fill^="url(#"]') && !!svg.querySelector('pattern'),
        wallHatch: !!g('wall').querySelector('path'),
        tension: g('AB').querySelector('polyline').getAttribute('stroke'),
        compression: g('BC').querySelector('polyline').getAttribute('stroke'),
        circle: !!g('pin').querySelector('circle'),
        arrow: g('F').textContent,
        path: !!g('path').querySelector('polyline'),
        label: g('A').textContent,
        values: svg.closest('figure').querySelector('.anim-values').textContent,
      };
    });
    assert.ok(d.hatch && d.wallHatch, 'ground is hatched');
    assert.notEqual(d.tension, d.compression, 'tension and compression by colour');
    assert.ok(d.circle && d.path);
    assert.equal(d.arrow, 'F = 1000 N', 'an arrow with its value and unit');
    assert.equal(d.label, 'A');
    assert.match(d.values, /AB = 1500.*BC = −900/, 'each value shown');
  });

  await test('an answer with neither series nor animation shows its numbers alone', async (page) => {
    await rewriteSolve(page, (json) => { json.series = []; delete json.animation; });
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    assert.equal(await page.isVisible('#stage'), false);
    assert.equal(await page.isVisible('#figures'), false);
    assert.equal(await scalar(page, 'omega_n'), 10);
    const rendered = nextRender(page);
    await page.fill('#p-k', '400');
    await rendered;
    assert.equal(await scalar(page, 'omega_n'), 20);
  });

  // ---- phone, print, languages, schemes, embed, extensions ----------------------------------------

  await test('on a phone the figure and the animation stay in sight while a value is edited', async (page) => {
    await page.setViewportSize({ width: 390, height: 844 });
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    for (const field of ['#p-k', '#p-t_end']) {
      await page.focus(field);
      await page.$eval(field, (e) => e.scrollIntoView({ block: 'nearest' }));
      const rendered = nextRender(page);
      await page.fill(field, field === '#p-k' ? '400' : '8');
      await rendered;
      const r = await page.evaluate((sel) => {
        const box = (e) => { const b = e.getBoundingClientRect(); return { top: b.top, bottom: b.bottom }; };
        return { anim: box(document.querySelector('.stage figure.anim svg')), fig: box(document.querySelector('.stage svg.mm-plot')), input: box(document.querySelector(sel)), h: innerHeight };
      }, field);
      for (const [k, b] of Object.entries({ anim: r.anim, fig: r.fig, input: r.input })) assert.ok(b.top >= -1 && b.bottom <= r.h + 1, `${k} in sight (${Math.round(b.top)}..${Math.round(b.bottom)} of ${r.h}) while ${field} is edited`);
      assert.ok(r.input.top >= r.fig.bottom - 1, `${field} is not under the figure`);
    }
    await page.focus('#p-k');
    await page.$eval('#p-k', (e) => e.scrollIntoView({ block: 'nearest' }));
    await page.screenshot({ path: `${shots}/after-phone-field-focused.png` });
  });

  await test('print: a worked solution on A4', async (page) => {
    // A page learns of print media by its media-query listener, which runs
    // at the next frame, not when emulateMedia returns (CI once read the
    // printed copy before that redraw and the screen's frame after it).  The
    // listener is slowed by 400 ms here, so the test must wait for the page
    // to say it has drawn for print (data-medium) before it reads anything.
    await page.addInitScript(() => {
      const add = MediaQueryList.prototype.addEventListener;
      MediaQueryList.prototype.addEventListener = function (type, fn, o) {
        const slow = this.media === 'print' && type === 'change' ? (e) => setTimeout(() => fn(e), 400) : fn;
        return add.call(this, type, slow, o);
      };
    });
    await openTypeset(page, server.origin, 'id=vib-sdof-forced');
    assert.equal(await page.getAttribute('html', 'data-medium'), 'screen');
    const frame0 = await page.$eval('figure.anim .anim-svg [data-name="mass"] polygon', (p) => p.getAttribute('points'));
    await page.$eval('.anim-scrub', (s) => { s.value = '50'; s.dispatchEvent(new Event('input')); });
    assert.notEqual(await page.$eval('figure.anim .anim-svg [data-name="mass"] polygon', (p) => p.getAttribute('points')), frame0);
    await page.emulateMedia({ media: 'print' });
    await page.waitForFunction(() => document.documentElement.dataset.medium === 'print');
    const vis = await page.evaluate(() => Object.fromEntries(Object.entries({
      form: '#params', theory: '#theory', given: '#print-params table', results: '#scalars', checks: '#checks', figure: 'svg.mm-plot', animation: 'figure.anim .anim-print svg', live: 'figure.anim .anim-svg', controls: '.anim-controls', header: 'header.site', takeaway: '#takeaway',
    }).map(([k, s]) => { const e = document.querySelector(s); return [k, !!e && getComputedStyle(e).display !== 'none' && e.getClientRects().length > 0]; })));
    assert.deepEqual(vis, { form: false, theory: true, given: true, results: true, checks: true, figure: true, animation: true, live: false, controls: false, header: false, takeaway: false });
    // the printed drawing is the first frame, whatever frame the screen shows
    const printed = await page.$eval('figure.anim .anim-print [data-name="mass"] polygon', (p) => p.getAttribute('points'));
    assert.equal(await page.getAttribute('figure.anim', 'data-frame'), '50', 'the screen keeps its frame');
    await page.$eval('.anim-scrub', (s) => { s.value = '0'; s.dispatchEvent(new Event('input')); });
    assert.equal(printed, await page.$eval('figure.anim .anim-svg [data-name="mass"] polygon', (p) => p.getAttribute('points')));
    assert.match(await page.textContent('#print-params'), /stiffness\s*k\s*100\s*N\/m/);
    const pdf = 'test-output/print-vib-sdof-forced.pdf';
    await page.pdf({ path: pdf, format: 'A4', printBackground: true });
    assert.ok(statSync(pdf).size > 20000, 'a PDF was printed');
  });

  await test('languages: Czech and German by address or browser, English where nothing is translated', async (page) => {
    await page.goto(`${server.origin}/?lang=cs`);
    await page.waitForSelector('li.exercise');
    assert.equal(await page.getAttribute('html', 'lang'), 'cs');
    assert.equal(await page.textContent('h1'), 'Obsah');
    assert.equal(await page.textContent('[data-id="vib-sdof-forced"] .extitle'), 'Vynucené kmitání tlumeného oscilátoru');
    assert.match(await page.getAttribute('[data-id="vib-sdof-forced"] a', 'href'), /lang=cs/, 'links keep the language');
    await openExercise(page, server.origin, 'id=vib-sdof-free&lang=cs');
    assert.equal(await page.textContent('#params-h'), 'Parametry');
    assert.equal((await page.textContent('[data-scalar="zeta"] .val')).trim(), '0,1', 'a decimal comma in the page');
    assert.match(await page.textContent('#curl'), /solve'$/, 'the API is untouched');
    assert.equal(await page.getAttribute('#theory', 'lang'), 'en', 'the theory is English, and says so');
    // …until a translated theory file is listed for the exercise
    const p3 = await browser.newPage();
    await p3.route('**/i18n/cs.js*', async (route) => {
      const body = (await (await route.fetch()).text()).replace('theory: [],', "theory: ['vib-sdof-free'],");
      await route.fulfill({ contentType: 'text/javascript', body });
    });
    await p3.route('**/i18n/theory/cs/vib-sdof-free.html', (route) => route.fulfill({
      contentType: 'text/html', body: '<h1>Volné kmitání</h1><h2>Model</h2><p>Hmota <span class="math math-inline">m</span> na pružině.</p>',
    }));
    await openExercise(p3, server.origin, 'id=vib-sdof-free&lang=cs');
    await p3.waitForFunction(() => document.querySelector('#theory h3') && document.querySelector('#theory h3').textContent === 'Model');
    assert.equal(await p3.getAttribute('#theory', 'lang'), null, 'a Czech theory in a Czech page');
    await p3.waitForSelector('#theory .katex');
    await p3.close();
    // every interface string exists in every language
    const missing = await page.evaluate(async () => {
      const { EN } = await import('/js/i18n.js');
      const out = [];
      for (const l of ['cs', 'de']) { const d = (await import(`/i18n/${l}.js`)).default; for (const k of Object.keys(EN)) if (!(k in d.ui)) out.push(`${l}:${k}`); }
      return out;
    });
    assert.deepEqual(missing, []);
    // the browser's language, and an exercise nobody translated
    const p2 = await browser.newPage();
    await p2.addInitScript(() => Object.defineProperty(navigator, 'languages', { get: () => ['de-DE', 'de', 'en'] }));
    await p2.route('**/api/exercises', async (route) => {
      const response = await route.fetch();
      const json = await response.json();
      json.push({ ...json[0], id: 'zz-new', title: 'A new exercise', summary: 'Nobody has translated it yet.' });
      await route.fulfill({ response, json });
    });
    try {
      await p2.goto(`${server.origin}/`);
      await p2.waitForSelector('li.exercise');
      assert.equal(await p2.getAttribute('html', 'lang'), 'de');
      assert.equal(await p2.textContent('h1'), 'Inhalt');
      assert.equal(await p2.textContent('[data-id="zz-new"] .extitle'), 'A new exercise');
      assert.equal(await p2.getAttribute('[data-id="zz-new"] .extitle', 'lang'), 'en');
      await p2.selectOption('#pref-lang', 'cs');
      await p2.waitForFunction(() => document.documentElement.lang === 'cs' && document.querySelector('li.exercise'));
      assert.match(p2.url(), /lang=cs/, 'the switch is kept in the address');
    } finally {
      await p2.close();
    }
  });

  await test('dark and projector schemes, kept in the address', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced&scheme=dark');
    const bg = await page.evaluate(() => getComputedStyle(document.body).backgroundColor);
    assert.equal(bg, 'rgb(21, 25, 30)');
    assert.equal(await page.$eval('svg.mm-plot path.mm-series', (p) => p.getAttribute('stroke')), '#7fb2f0', 'the figure in the dark palette');
    assert.deepEqual(await axeSerious(page), [], 'dark passes axe');
    await page.selectOption('#pref-scheme', 'projector');
    await page.waitForFunction(() => document.querySelector('svg.mm-plot').getAttribute('font-size') === '16');
    assert.match(page.url(), /scheme=projector/);
    assert.equal(await page.evaluate(() => getComputedStyle(document.body).fontSize), '20px');
    assert.deepEqual(await axeSerious(page), [], 'projector passes axe');
  });

  await test('embed: one exercise, no chrome, parameters fixed by the address', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced&k=400&embed=1');
    const vis = await page.evaluate(() => ['header.site', 'footer.site', '#theory', '#params', '#takeaway', '#pager'].map((s) => { const e = document.querySelector(s); return e && e.getClientRects().length > 0; }));
    assert.deepEqual(vis, [false, false, false, false, false, false]);
    assert.equal(await scalar(page, 'omega_n'), 20);
    assert.ok(await page.isVisible('svg.mm-plot'));
    assert.match(await page.getAttribute('#embed-open', 'href'), /k=400/);
    await openExercise(page, server.origin, 'id=vib-sdof-forced&embed=omega');
    assert.deepEqual(await page.$$eval('#fields .field', (f) => f.filter((x) => !x.hidden).map((x) => x.dataset.param)), ['omega']);
    const h = await page.evaluate(() => history.length);
    const rendered = nextRender(page);
    await page.fill('#p-omega', '10');
    await rendered;
    assert.equal(await page.evaluate(() => history.length), h, "the course page's history is left alone");
  });

  await test('exercise extensions: mount(host, api) with getParams, setParams, onAnswer, lang', async (page) => {
    await page.route('**/js/ex/registry.js*', (route) => route.fulfill({
      contentType: 'text/javascript',
      body: "export const extensions = { 'vib-sdof-forced': () => import('/js/ex/zz-test.js') };",
    }));
    await page.route('**/js/ex/zz-test.js', (route) => route.fulfill({
      contentType: 'text/javascript',
      body: `export function mount(host, api) {
        window.zz = { answers: [], lang: api.lang, params: api.getParams(), host: host.className, parent: host.parentElement.id };
        host.textContent = 'extension here';
        api.onAnswer((a) => window.zz.answers.push(a.scalars.find((s) => s.name === 'omega_n').value));
        window.zzSet = () => api.setParams({ k: '400' });
        return () => {};
      }`,
    }));
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    await page.waitForFunction(() => window.zz && window.zz.answers.length === 1);
    const zz = await page.evaluate(() => window.zz);
    assert.deepEqual({ lang: zz.lang, host: zz.host, parent: zz.parent, k: zz.params.k, m: zz.params.m }, { lang: 'en', host: 'extension', parent: 'answer', k: '100', m: '1' });
    const rendered = nextRender(page);
    await page.evaluate(() => window.zzSet());
    await rendered;
    assert.deepEqual(await page.evaluate(() => window.zz.answers), [10, 20], 'called now and after every answer');
    assert.match(page.url(), /k=400/, 'as if typed');
  });

  await staTrussTests(test, server.origin);

  // ---- every page, at desktop and phone widths -------------------------------------------------

  await test('every exercise: no error at its defaults, laid out at 1280 and 390 px', async (page) => {
    const problems = [];
    for (const [w, h, tag] of [[1280, 800, 'desktop'], [390, 844, 'phone']]) {
      await page.setViewportSize({ width: w, height: h });
      await page.goto(`${server.origin}/`);
      await page.waitForFunction(() => document.documentElement.dataset.ready === 'true');
      for (const p of await layoutProblems(page)) problems.push(`catalog ${tag}: ${p}`);
    }
    for (const e of api) {
      const meta = await solveJson(e.id);
      for (const p of meta.params) if (['id', 'lang', 'scheme', 'embed'].includes(p.name)) problems.push(`${e.id}: a parameter named ${p.name}, a name of the page's own`);
      let step = 'opened and typeset';
      try {
        await page.setViewportSize({ width: 1280, height: 800 });
        await openTypeset(page, server.origin, `id=${e.id}`);
        if (await page.$('#answer-error:not([hidden])')) problems.push(`${e.id}: an error at its defaults: ${await page.textContent('#answer-error')}`);
        for (const f of await page.$$eval('#theory .katex-error', (es) => es.map((x) => x.textContent.slice(0, 60)))) problems.push(`${e.id}: a formula of the theory does not parse: ${f}`);
        for (const p of await layoutProblems(page)) problems.push(`${e.id} desktop: ${p}`);
        step = 'figures redrawn at 390 px';
        await page.setViewportSize({ width: 390, height: 844 });
        await settledFigures(page);
        for (const p of await layoutProblems(page)) problems.push(`${e.id} phone: ${p}`);
      } catch (err) {
        problems.push(`${e.id}: not ${step}: ${err.message.split('\n')[0]}`);
      }
    }
    assert.deepEqual(problems, []);
  });

  // axe-core on the pages that hold every kind of part (the rules look at
  // kinds of element, not at which exercise they came from): the catalog,
  // an animation with time plots and checks (vib-sdof-forced), matrices and
  // tables (num-linear-system), code in the theory (num-polyfit), an
  // extension (sta-truss), a pendulum pair (dyn-double-pendulum), the
  // complex plane at equal aspect (num-complex), in light at 1280 px; the
  // dark scheme at 390 px on the catalog, the tables and the extension
  // (vib-sdof-forced is checked dark and projector in the schemes' test).  The typeset formulas' inner
  // boxes are left out (their colours are the theory's text, checked with
  // it; they are half of axe's time), their scrolling boxes are not.  The
  // assignment sheet has its own (assignment.mjs).
  // "typeset" is done only when the theory is laid out in its own fonts:
  // KaTeX_Size2 (a tall bracket) is asked for only when a display is first
  // laid out, and a display that overflows once it arrives must be reachable
  // by keyboard when the page says done (axe found one that was not, the
  // font arriving between the page's measurement and axe's).  The fonts are
  // slowed here so that they are always still on their way when the page
  // first measures; before the page waited for them this failed every time.
  await test('typeset is done only once the theory\'s fonts are in, and every box that then overflows is reachable by keyboard (fonts slowed 700 ms)', async (page) => {
    await page.route('**/katex/dist/fonts/*', async (route) => {
      await new Promise((resolve) => setTimeout(resolve, 700));
      await route.continue();
    });
    await openTypeset(page, server.origin, 'id=dyn-double-pendulum');
    const s = await page.evaluate(() => ({
      loading: [...document.fonts].filter((f) => f.status === 'loading').map((f) => `${f.family} ${f.style} ${f.weight}`),
      unreachable: [...document.querySelectorAll('#theory .katex-display, #theory pre')]
        .filter((e) => e.scrollWidth > e.clientWidth + 1 && e.getAttribute('tabindex') !== '0').length,
      reachable: document.querySelectorAll('#theory [tabindex="0"]').length,
    }));
    assert.deepEqual(s.loading, [], 'no font still loading when typeset is done');
    assert.equal(s.unreachable, 0, 'every overflowing box has tabindex 0');
    assert.ok(s.reachable >= 1, 'the wide display is reachable (the check has something to check)');
  });

  await test('axe: the catalog and representative exercises, light at 1280 px and dark at 390 px: zero critical or serious violations', async (page) => {
    const problems = [];
    const known = (id) => !id || api.some((e) => e.id === id);
    const runs = [
      [1280, 800, 'light', ['', 'vib-sdof-forced', 'num-linear-system', 'num-polyfit', 'sta-truss', 'dyn-double-pendulum', 'num-complex']],
      [390, 844, 'dark', ['', 'num-linear-system', 'sta-truss']],
    ];
    for (const [w, h, scheme, ids] of runs) {
      await page.setViewportSize({ width: w, height: h });
      for (const id of ids.filter(known)) {
        if (!id) {
          await page.goto(`${server.origin}/?scheme=${scheme}`);
          await page.waitForFunction(() => document.documentElement.dataset.ready === 'true');
        } else {
          await openTypeset(page, server.origin, `id=${id}&scheme=${scheme}`);
          if (id === 'sta-truss') await page.waitForSelector('.extension .truss-ed');
        }
        for (const v of await axeSerious(page, { exclude: [['#theory .katex-html']] })) problems.push(`${id || 'catalog'} ${scheme} ${w} px: ${v}`);
      }
    }
    assert.deepEqual(problems, []);
  });

  await test('under a base path (course base_path "/mech/"): the pages ask only under it and work', async () => {
    const dir = mkdtempSync(join(tmpdir(), 'mm-course-'));
    writeFileSync(join(dir, 'course.json'), JSON.stringify({ base_path: '/mech/' }));
    const sub = await startServer(['--course', join(dir, 'course.json')]);
    const page = await browser.newPage();
    const asked = [];
    page.on('request', (r) => asked.push(new URL(r.url())));
    const errors = [];
    page.on('pageerror', (e) => errors.push(String(e)));
    try {
      await page.goto(`${sub.origin}/mech/?lang=cs`);
      await page.waitForSelector('li.exercise');
      await page.click('li.exercise[data-id="vib-sdof-forced"] a');
      await page.waitForFunction(() => document.documentElement.dataset.rendered && document.documentElement.dataset.typeset === 'done', null, { timeout: 15000 });
      assert.equal(new URL(page.url()).pathname, '/mech/exercise.html');
      assert.ok(await page.$('svg.mm-plot path.mm-series'), 'a figure drawn');
      assert.ok(await page.$('#theory .katex'), 'the theory typeset');
      assert.match(await page.textContent('#curl'), new RegExp(`^curl '${sub.origin}/mech/api/exercises/vib-sdof-forced/solve'$`));
      await page.click('#crumb-home');
      await page.waitForSelector('li.exercise');
      assert.equal(new URL(page.url()).pathname, '/mech/');
      const outside = asked.filter((u) => u.origin === sub.origin && !u.pathname.startsWith('/mech/')).map((u) => u.pathname);
      assert.deepEqual(outside, [], 'every request under /mech/');
      const css = asked.find((u) => u.pathname === '/mech/css/style.css');
      assert.ok(css && css.searchParams.get('v') && css.searchParams.get('v') !== '__MM_ASSET_VERSION__', 'assets under a versioned URL');
      const unversioned = asked.filter((u) => /\.(js|mjs|css)$/.test(u.pathname) && u.searchParams.get('v') !== css.searchParams.get('v')).map((u) => u.pathname);
      assert.deepEqual(unversioned, [], 'every script and style sheet versioned (one module instance each, cached for a year)');
      assert.deepEqual(errors, []);
    } finally {
      await page.close();
      await stopServer(sub);
      rmSync(dir, { recursive: true, force: true });
    }
  });

  await assignmentTests(test, server.origin);

  await test('screenshots: the states the defects were seen in, after', async (page) => {
    await page.setViewportSize({ width: 390, height: 844 });
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    await page.$eval('#checks', (e) => e.scrollIntoView());
    await page.screenshot({ path: `${shots}/after-phone-checks-table.png` });
    await openTypeset(page, server.origin, 'id=num-polyfit');
    await page.screenshot({ path: `${shots}/after-phone-polyfit.png`, fullPage: true });
    await page.setViewportSize({ width: 1280, height: 800 });
    for (const [id, fig, name] of [['num-newmark', 1, 'newmark-response'], ['vib-base-excitation', 1, 'base-excitation-fig2'], ['vib-integrators', 0, 'integrators-fig1'], ['vib-integrators', 1, 'integrators-fig2'], ['num-complex', 0, 'complex-argand'], ['vib-harmonics', 1, 'harmonics-lissajous'], ['num-linear-system', 0, 'linear-system-fig1'], ['num-eigen', 0, 'eigen-fig1']]) {
      await openExercise(page, server.origin, `id=${id}`);
      const figs = await page.$$('figure.plot');
      await figs[fig].screenshot({ path: `${shots}/after-${name}.png` });
      // a caption names its series once ("a, the result against Re", not "…: a, the result")
      for (const c of await page.$$eval('figure.plot .figtext', (es) => es.map((e) => e.textContent))) {
        const m = c.match(/^(.*) against [^:]*: (.*)$/);
        assert.ok(!m || m[1] !== m[2], `${id}: caption "${c}" says its series twice`);
      }
    }
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    await (await page.$('#checks')).screenshot({ path: `${shots}/after-desktop-checks-table.png` });
    await page.screenshot({ path: `${shots}/after-desktop-sdof-forced.png` });
    await openExercise(page, server.origin, 'id=vib-sdof-free');
    await (await page.$('#scalars')).screenshot({ path: `${shots}/after-sdof-free-results.png` });
    await page.screenshot({ path: `${shots}/after-desktop-sdof-free.png` });
    await openExercise(page, server.origin, 'id=vib-sdof-forced&lang=de&scheme=dark');
    await page.screenshot({ path: `${shots}/after-desktop-sdof-forced-de-dark.png` });
    await openExercise(page, server.origin, 'id=vib-sdof-forced&lang=cs&scheme=projector');
    await page.screenshot({ path: `${shots}/after-desktop-sdof-forced-cs-projector.png` });
  });
} catch (e) {
  console.log(`FAIL setup: ${e.message}`);
  results.push({ name: 'setup', ok: false });
} finally {
  await stopBrowser(browser);
  await stopServer(server);
}

const failed = results.filter((r) => !r.ok).length;
console.log(`browser: ${results.length - failed} passed, ${failed} failed (${((Date.now() - t00) / 1000).toFixed(0)} s)`);
process.exit(failed ? 1 : 0);
