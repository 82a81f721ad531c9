// sta-truss.mjs — the truss editor of sta-truss's page (web/js/ex/sta-truss.js)
// in a real browser: the default truss coloured by its forces, a 15-joint
// truss drawn with the mouse (clicks for joints, drags for members), solved
// live, its URL under 600 characters and reloaded from it, and a member
// deleted to make a mechanism, which the editor reports in words.
//
// run.mjs calls staTrussTests(test, origin).  When the page does not mount
// extensions itself yet, the tests mount the module with a stand-in for the
// page's side of the contract (web/js/ex/registry.js) built on the form:
// getParams reads the fields, setParams types into them, onAnswer follows
// mm:rendered.  Either way the module under test is the same file.
import assert from 'node:assert/strict';
import { nextRender, openExercise } from './common.mjs';

const ED = '.truss-ed';

/** The editor on the page: the page's own mount, or the stand-in. */
async function editor(page, origin, query = '') {
  await openExercise(page, origin, `id=sta-truss${query ? '&' + query : ''}`);
  const own = await page.waitForSelector(`.extension ${ED}`, { timeout: 15000 }).catch(() => null);
  if (!own) {
    await page.evaluate(async () => {
      const mod = await import('/js/ex/sta-truss.js');
      const host = document.createElement('div');
      host.className = 'extension';
      (document.querySelector('#figures') || document.body).before(host);
      const field = (n) => document.getElementById(`p-${n}`);
      const names = ['nodes', 'members', 'supports', 'loads'];
      const api = {
        lang: 'en',
        getParams: () => Object.fromEntries(names.map((n) => [n, field(n).value])),
        setParams(obj) {
          for (const [k, v] of Object.entries(obj)) {
            field(k).value = v;
            field(k).dispatchEvent(new Event('input', { bubbles: true }));
          }
        },
        onAnswer(cb) {
          const h = async () => {
            const q = names.map((n) => `${n}=${encodeURIComponent(field(n).value)}`).join('&');
            cb(await (await fetch(`/api/exercises/sta-truss/solve?${q}`)).json());
          };
          window.addEventListener('mm:rendered', h);
          h();
          return () => window.removeEventListener('mm:rendered', h);
        },
      };
      window.__trussUnmount = mod.mount(host, api);
    });
  }
  await page.waitForSelector(ED);
  return !!own;
}

/** Screen coordinates of the world point (x, y) [m] in the editor. */
function screen(page, x, y) {
  return page.evaluate(([wx, wy]) => {
    const svg = document.querySelector('.truss-ed svg');
    const pt = svg.createSVGPoint();
    pt.x = wx;
    pt.y = -wy;
    const p = pt.matrixTransform(svg.getScreenCTM());
    return [p.x, p.y];
  }, [x, y]);
}

async function tool(page, mode) {
  await page.click(`${ED} button[data-mode="${mode}"]`);
}

async function clickAt(page, x, y) {
  const [sx, sy] = await screen(page, x, y);
  await page.mouse.click(sx, sy);
}

async function dragBetween(page, a, b) {
  const [ax, ay] = await screen(page, a[0], a[1]);
  const [bx, by] = await screen(page, b[0], b[1]);
  await page.mouse.move(ax, ay);
  await page.mouse.down();
  await page.mouse.move(bx, by, { steps: 4 });
  await page.mouse.up();
}

/** Wait for the editor to show an answer (or an error) for what it drew. */
async function settled(page, state) {
  await page.waitForFunction((s) => document.querySelector('.truss-ed')?.dataset.state === s, state, { timeout: 15000 });
}

/** Member forces as the editor shows them, by member number. */
function shownForces(page) {
  return page.$$eval(`${ED} line.member`, (ls) => ls.map((l) => ({
    member: Number(l.dataset.member), force: l.dataset.force === undefined ? null : Number(l.dataset.force),
    cls: l.getAttribute('class'),
  })));
}

export async function staTrussTests(test, origin) {
  await test('sta-truss: the editor colours the default truss by its member forces', async (page) => {
    const own = await editor(page, origin);
    await settled(page, 'solved');
    const answer = await (await fetch(`${origin}/api/exercises/sta-truss/solve`)).json();
    const rows = answer.tables.find((t) => t.name === 'members').rows;
    const shown = await shownForces(page);
    assert.equal(shown.length, 7, 'seven members drawn');
    for (const s of shown) {
      const F = rows[s.member - 1][1];
      assert.equal(s.force, F, `member ${s.member}: the API's force`);
      assert.ok(s.cls.includes(F > 0 ? 'tension' : F < 0 ? 'compression' : 'zero'), `member ${s.member} coloured by its sign`);
    }
    const arrows = await page.$$(`${ED} g.reaction`);
    assert.ok(arrows.length >= 2, 'the reactions are drawn');
    assert.match(await page.textContent(`${ED} .status`), /Determinate/);
    if (!own) console.log('     (mounted with the stand-in: the page does not mount extensions yet)');
  });

  await test('sta-truss: a 15-joint truss drawn with the mouse is solved live and fits a 600-character URL', async (page) => {
    await editor(page, origin);
    await settled(page, 'solved');
    await page.click(`${ED} button:has-text("Clear")`);
    await tool(page, 'draw');
    // a Warren truss: 8 joints below at x = 0, 2, ..., 14; 7 above at x = 1, 3, ..., 13, y = 2
    const bottom = Array.from({ length: 8 }, (_, i) => [2 * i, 0]);
    const top = Array.from({ length: 7 }, (_, i) => [2 * i + 1, 2]);
    // joints left to right: the drawing area grows as the truss does
    const order = [...bottom, ...top].sort((p, q) => p[0] - q[0]);
    for (const p of order) await clickAt(page, p[0], p[1]);
    assert.equal(await page.getAttribute(ED, 'data-joints'), '15');
    const bars = [];
    for (let i = 0; i < 7; i++) bars.push([bottom[i], bottom[i + 1]]);
    for (let i = 0; i < 6; i++) bars.push([top[i], top[i + 1]]);
    for (let i = 0; i < 7; i++) bars.push([bottom[i], top[i]], [top[i], bottom[i + 1]]);
    for (const [a, b] of bars) await dragBetween(page, a, b);
    assert.equal(await page.getAttribute(ED, 'data-members'), '27');
    await tool(page, 'pin');
    await clickAt(page, 0, 0);
    await tool(page, 'roller');
    await clickAt(page, 14, 0);
    await page.fill(`${ED} input[data-load="Fy"]`, '-5000');
    await tool(page, 'load');
    const rendered = nextRender(page, 15000);
    await clickAt(page, 7, 2);
    await rendered;
    await settled(page, 'solved');
    await page.waitForFunction(() => location.search.includes('members='));
    const url = page.url();
    assert.ok(url.length < 600, `the drawing's URL is ${url.length} characters`);
    console.log(`     the 15-joint truss's URL: ${url.length} characters`);
    await (await page.$(ED)).screenshot({ path: 'test-output/screenshots/sta-truss-editor.png' });
    // the forces shown are the API's for the same parameters
    const q = new URL(url).search.replace(/^\?id=sta-truss&?/, '');
    const answer = await (await fetch(`${origin}/api/exercises/sta-truss/solve?${q}`)).json();
    assert.equal(answer.scalars.find((s) => s.name === 'determinacy').value, 0);
    const rows = answer.tables.find((t) => t.name === 'members').rows;
    const shown = await shownForces(page);
    assert.equal(shown.length, 27);
    for (const s of shown) assert.equal(s.force, rows[s.member - 1][1], `member ${s.member}`);
    // by symmetry the top chord's middle members carry the most compression
    assert.ok(Math.min(...rows.map((r) => r[1])) < -5000, 'a compressed top chord');
    // reloaded from its URL, the same drawing comes back
    await editor(page, origin, q);
    await settled(page, 'solved');
    assert.equal(await page.getAttribute(ED, 'data-joints'), '15');
    assert.equal(await page.getAttribute(ED, 'data-members'), '27');
  });

  await test('sta-truss: deleting a member makes a mechanism, reported in words', async (page) => {
    await editor(page, origin);
    await settled(page, 'solved');
    await tool(page, 'delete');
    const rendered = nextRender(page, 15000);
    await clickAt(page, 3, 1.5);          // the middle of member 5, joints 4 (2,3) to 2 (4,0)
    await rendered;
    await settled(page, 'error');
    const text = await page.textContent(`${ED} .status`);
    assert.match(text, /a mechanism: m \+ r - 2j = -1/);
    assert.match(text, /without stretching any member/);
    assert.equal(await page.getAttribute(ED, 'data-members'), '6');
  });
}
