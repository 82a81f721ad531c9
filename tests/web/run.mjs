// run.mjs — the pages in a real browser (Debian's Chromium through
// playwright-core), against a server started here.  Ends with the line
// "browser: N passed, M failed"; exit code 0 only when M is 0.
// Screenshots go to test-output/screenshots/.
import assert from 'node:assert/strict';
import { mkdirSync } from 'node:fs';
import { readFile } from 'node:fs/promises';
import { nextRender, openExercise, startBrowser, startServer, stopBrowser, stopServer } from './common.mjs';

const shots = 'test-output/screenshots';
mkdirSync(shots, { recursive: true });

let server, browser;
const results = [];

async function test(name, fn) {
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
    const rendered = nextRender(page);
    await page.fill('#p-m', '-1');
    await rendered;
    await page.waitForSelector('#e-m:not([hidden])');
    const msg = await page.textContent('#e-m');
    assert.match(msg, /m must be between 0\.001 and 1000 kg/);
    assert.equal(await page.getAttribute('#p-m', 'aria-invalid'), 'true');
    assert.ok(await page.$('#figures svg path'), 'the previous answer is kept');
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
    await page.goBack();
    await page.waitForFunction(() => !location.search.includes('m=4'), null, { timeout: 10000 });
    await page.waitForFunction(() => document.querySelector('#p-m').value === '1', null, { timeout: 10000 });
    await page.goForward();
    await page.waitForFunction(() => location.search.includes('m=4'), null, { timeout: 10000 });
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
  });

  await test('the form is reachable by keyboard and every input has its label', async (page) => {
    await openExercise(page, server.origin, 'id=num-linear-system');
    const unlabelled = await page.$$eval('#fields .input', (inputs) =>
      inputs.filter((i) => !document.querySelector(`label[for="${i.id}"]`)).map((i) => i.id));
    assert.deepEqual(unlabelled, []);
    await page.focus('#p-A');
    await page.keyboard.press('Tab');
    assert.equal(await page.evaluate(() => document.activeElement.id), 'p-b', 'Tab goes from A to b');
  });

  await test('every exercise page loads and draws its answer without errors', async (page) => {
    for (const e of api) {
      await openExercise(page, server.origin, `id=${e.id}`);
      const failed = await page.$('#answer-error:not([hidden])');
      assert.equal(failed, null, `${e.id} shows an error at its defaults`);
      assert.ok(await page.$('#checks'), `${e.id} shows its checks`);
    }
  });

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
