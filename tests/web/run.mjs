// run.mjs — the pages in a real browser (Debian's Chromium through
// playwright-core), against a server started here.  Ends with the line
// "browser: N passed, M failed"; exit code 0 only when M is 0.
// Screenshots go to test-output/screenshots/.
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { nextRender, openExercise, startBrowser, startServer, stopBrowser, stopServer } from './common.mjs';
import { staTrussTests } from './sta-truss.mjs';

const shots = 'test-output/screenshots';
mkdirSync(shots, { recursive: true });

let server, browser;
const results = [];

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
    console.log(`FAIL ${name}: ${e.message.split('\n').slice(0, 6).join('\n     ')}`);
  } finally {
    await page.close();
  }
}

const scalar = (page, name) => page.$eval(`[data-scalar="${name}"] .val`, (e) => Number(e.dataset.value));
// every path of the first figure, joined: the curve is one of them
const firstPath = (page) => page.$eval('#figures svg', (svg) =>
  [...svg.querySelectorAll('path[d]')].map((p) => p.getAttribute('d')).join('|'));

try {
  server = await startServer();
  browser = await startBrowser();
  const api = await (await fetch(`${server.origin}/api/exercises`)).json();

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

  await test('an exercise page shows typeset math and a plot with labelled axes', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    await page.waitForFunction(() => document.documentElement.dataset.typeset === 'done', null, { timeout: 15000 });
    assert.ok(await page.$('.katex'), 'a KaTeX element');
    assert.ok(await page.$('math'), 'MathML for screen readers');
    assert.ok(await page.$('#figures svg path'), 'a plotted path');
    const text = await page.$eval('#figures svg', (s) => s.textContent);
    assert.match(text, /t \[s\]/, 'x axis labelled with its unit');
    assert.match(text, /displacement \[m\]|x \[m\]/, 'y axis labelled with its unit');
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
    const api400 = await (await fetch(`${server.origin}/api/exercises/vib-sdof-forced/solve?m=-1`)).json();
    let rendered = nextRender(page);
    await page.fill('#p-m', '-1');
    await rendered;
    await page.waitForSelector('#e-m:not([hidden])');
    assert.equal((await page.textContent('#e-m')).trim(), api400.error.message, 'the API message, word for word');
    assert.equal(await page.getAttribute('#p-m', 'aria-invalid'), 'true');
    assert.ok((await page.getAttribute('#p-m', 'aria-describedby')).split(' ').includes('e-m'), 'the message describes the field');
    assert.ok(await page.$('#figures svg path'), 'the previous answer is kept');
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
    await page.route('**/solve*', async (route) => {
      const response = await route.fetch();
      const json = await response.json();
      if (json.checks && json.checks.length) json.checks[0].passed = false;
      await route.fulfill({ response, json });
    });
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
    // back: to the state before m = 4
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
    // reset: only the id is left in the URL
    rendered = nextRender(page);
    await page.click('#reset');
    await rendered;
    assert.equal(new URL(page.url()).search, '?id=vib-sdof-forced');
    assert.equal(await page.inputValue('#p-k'), '100');
  });

  await test('the CSV download holds the series of the JSON answer', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced&points=21');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#dl-csv')]);
    const csv = await readFile(await download.path(), 'utf8');
    const answer = await (await fetch(`${server.origin}/api/exercises/vib-sdof-forced/solve?points=21`)).json();
    const rows = csv.trim().split('\n');
    assert.match(rows[0], /^t \[s\],x \[m\]$/);
    assert.equal(rows.length, 1 + answer.series[0].x.length);
    rows.slice(1).forEach((row, i) => {
      const [t, x] = row.split(',').map(Number);
      assert.equal(t, answer.series[0].x[i]);
      assert.equal(x, answer.series[0].y[i]);
    });
    // series over different x: long form, one row per point
    await openExercise(page, server.origin, 'id=vib-dft');
    const [dl2] = await Promise.all([page.waitForEvent('download'), page.click('#dl-csv')]);
    const long = (await readFile(await dl2.path(), 'utf8')).trim().split('\n');
    const dft = await (await fetch(`${server.origin}/api/exercises/vib-dft/solve`)).json();
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
    // from the top of a page, Tab alone reaches every field, in table order
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const meta = await (await fetch(`${server.origin}/api/exercises/vib-sdof-forced`)).json();
    const want = meta.params.map((p) => `p-${p.name}`);
    const seen = [];
    for (let i = 0; i < 60 && seen.length < want.length; i++) {
      await page.keyboard.press('Tab');
      const id = await page.evaluate(() => document.activeElement.id);
      if (want.includes(id) && !seen.includes(id)) seen.push(id);
    }
    assert.deepEqual(seen, want);
    // the arrow keys step a number and re-solve
    await page.focus('#p-k');
    const rendered = nextRender(page);
    await page.keyboard.press('ArrowUp');
    await rendered;
    assert.equal(await page.inputValue('#p-k'), '110');
    assert.equal(await scalar(page, 'omega_n'), Math.sqrt(110));
  });

  await test('hovering the plot reads out the values', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const box = await (await page.$('#figures svg')).boundingBox();
    await page.mouse.move(box.x + box.width * 0.55, box.y + box.height * 0.5);
    const tip = await page.waitForSelector('#figures svg [aria-label="tip"] text', { timeout: 5000 });
    assert.match(await tip.textContent(), /t = [\d.]+ s.*displacement = −?-?[\d.e-]+ m/);
  });

  await test('the figure downloads as a standalone SVG', async (page) => {
    await openExercise(page, server.origin, 'id=vib-sdof-forced');
    const [download] = await Promise.all([page.waitForEvent('download'), page.click('#dl-svg')]);
    assert.match(download.suggestedFilename(), /^vib-sdof-forced.*\.svg$/);
    const svg = await readFile(await download.path(), 'utf8');
    assert.match(svg, /^<\?xml[^>]*>\s*<svg[^>]+xmlns="http:\/\/www\.w3\.org\/2000\/svg"/);
    assert.match(svg, /<path[^>]+d="M/, 'the curve');
    assert.match(svg, /t \[s\]/, 'the axis label');
    await page.setContent(svg.replace(/^<\?xml[^>]*>\s*/, ''));
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

  await test('every exercise page loads and draws its answer without errors', async (page) => {
    for (const e of api) {
      await openExercise(page, server.origin, `id=${e.id}`);
      const failed = await page.$('#answer-error:not([hidden])');
      assert.equal(failed, null, `${e.id} shows an error at its defaults`);
      assert.ok(await page.$('#checks'), `${e.id} shows its checks`);
    }
  });

  await staTrussTests(test, server.origin);

  await test('screenshots of the catalog and an exercise at desktop and phone widths', async (page) => {
    for (const [w, h, tag] of [[1280, 800, 'desktop'], [375, 740, 'phone']]) {
      await page.setViewportSize({ width: w, height: h });
      await page.goto(`${server.origin}/`);
      await page.waitForSelector('li.exercise');
      await page.screenshot({ path: `${shots}/catalog-${tag}.png`, fullPage: false });
      await openExercise(page, server.origin, 'id=vib-sdof-forced');
      await page.waitForFunction(() => document.documentElement.dataset.typeset === 'done', null, { timeout: 15000 });
      await page.screenshot({ path: `${shots}/vib-sdof-forced-${tag}.png`, fullPage: false });
      const overflow = await page.evaluate(() => document.documentElement.scrollWidth - window.innerWidth);
      assert.ok(overflow <= 1, `no sideways scrolling at ${w} px (overflow ${overflow} px)`);
    }
  });
} catch (e) {
  console.log(`FAIL setup: ${e.message}`);
  results.push({ name: 'setup', ok: false });
} finally {
  await stopBrowser(browser);
  await stopServer(server);
}

const failed = results.filter((r) => !r.ok).length;
console.log(`browser: ${results.length - failed} passed, ${failed} failed`);
process.exit(failed ? 1 : 0);
