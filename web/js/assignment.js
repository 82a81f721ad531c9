// assignment.js — a student's sheet of an assignment (web/assignment.html):
// ?name=<assignment>&student=<S> → GET api/assignments/{name}/variant?student=S
// (the exercise, its parameters for this student, the quantities asked),
// one field per asked quantity, and Check → POST api/assignments/{name}/check
// with {"student", "answers": {name: "256.6 N"}}, whose results are shown
// beside each field and in a table (expected values only when the course
// shows them).  Every address is relative to the page (a course's base_path).

import { el, fmtNumber, unitHtml, unitText, decimalSep } from './format.js?v=__MM_ASSET_VERSION__';
import { initLang, t, english, translateDocument, exerciseText, paramText, siteUrl } from './i18n.js?v=__MM_ASSET_VERSION__';
import { wirePrefs } from './prefs.js?v=__MM_ASSET_VERSION__';

const $ = (s, root = document) => root.querySelector(s);
const boot = window.mmBoot || {};
const q = new URLSearchParams(location.search);
const state = { name: q.get('name') || '', student: q.get('student') || '', variant: null, meta: null };

const api = (path) => `api/assignments/${encodeURIComponent(state.name)}${path}`;

/** The text of a failed request: the API's message when it sent one. */
function failure(status, text) {
  try {
    const b = JSON.parse(text);
    if (b && b.error) return b.error.message || b.error.code || String(b.error);
    if (b && b.message) return b.message;
  } catch { /* not JSON */ }
  return `HTTP ${status}`;
}

function showError(box, msg) {
  box.textContent = msg;
  box.hidden = false;
}

/** A parameter's value as a reader writes it: a number in the page's
 *  locale, vectors with commas, matrices row by row. */
function valueText(v) {
  const n = (x) => (typeof x === 'number' ? fmtNumber(x, 12).uni : String(x));
  if (Array.isArray(v)) {
    const sep = decimalSep() === ',' ? '; ' : ', ';
    return Array.isArray(v[0]) ? v.map((r) => `[${r.map(n).join(sep)}]`).join(' ') : `[${v.map(n).join(sep)}]`;
  }
  return v == null ? '' : n(v);
}

function renderGiven() {
  const { variant, meta } = state;
  const order = meta ? meta.params.map((p) => p.name).filter((k) => k in variant.params) : [];
  for (const k of Object.keys(variant.params)) if (!order.includes(k)) order.push(k);
  const info = (k) => (meta && meta.params.find((p) => p.name === k)) || { name: k };
  const rows = order.map((k) => {
    const p = info(k);
    const label = paramText(variant.exercise, k, 'label', p.label || k);
    return el('tr', {},
      el('th', { scope: 'row' }, label === p.label ? english(el('span', { text: label })) : label),
      el('td', {}, el('code', { text: k })),
      el('td', { class: 'n', text: valueText(variant.params[k]) }),
      el('td', { html: unitHtml(p.unit || '') }));
  });
  const table = $('#given-table');
  table.textContent = '';
  table.append(
    el('thead', {}, el('tr', {}, [t('col_param'), t('col_symbol'), t('col_value1'), t('col_unit')].map((h) => el('th', { scope: 'col', text: h })))),
    el('tbody', {}, rows));
  $('#exercise-link').href = siteUrl('exercise.html', { id: variant.exercise });
}

function renderAsked() {
  const box = $('#asked');
  box.textContent = '';
  for (const a of state.variant.asked) {
    const id = `a-${a.name}`;
    const label = el('label', { for: id },
      el('span', { class: 'plabel', text: a.label || a.name }), ' ',
      el('code', { class: 'pname', text: a.name }),
      a.unit ? el('span', { class: 'punit', html: ` [${unitHtml(a.unit)}]` }) : '');
    const input = el('input', {
      id, name: a.name, type: 'text', class: 'input', autocomplete: 'off', spellcheck: 'false', autocapitalize: 'off',
      inputmode: 'text', 'aria-describedby': a.rule ? `h-${a.name} r-${a.name}` : `r-${a.name}`,
    });
    const rule = a.rule ? el('p', { class: 'help', id: `h-${a.name}`, text: a.rule }) : '';
    const saved = sessionStorage.getItem(storeKey(a.name));
    if (saved) input.value = saved;
    input.addEventListener('input', () => sessionStorage.setItem(storeKey(a.name), input.value));
    const verdict = el('p', { class: 'a-verdict', id: `r-${a.name}` });
    box.append(el('div', { class: 'field', id: `f-${a.name}`, 'data-asked': a.name }, label, input, rule, verdict));
  }
}

/** A table wider than its box becomes one card per row (style.css
 *  .table-wrap.stacked), each cell with its column's name. */
function fitTable(table) {
  const wrap = table.parentElement;
  const heads = [...table.tHead.rows[0].cells].map((c) => c.textContent);
  for (const r of table.tBodies[0].rows) [...r.cells].forEach((c, i) => c.setAttribute('data-label', heads[i]));
  const set = (on) => {
    wrap.classList.toggle('stacked', on);
    const role = (e, x) => (on ? e.setAttribute('role', x) : e.removeAttribute('role'));
    role(table, 'table');
    for (const g of table.querySelectorAll('thead, tbody')) role(g, 'rowgroup');
    for (const r of table.rows) {
      role(r, 'row');
      for (const c of r.cells) role(c, c.tagName === 'TH' ? (c.scope === 'row' ? 'rowheader' : 'columnheader') : 'cell');
    }
  };
  set(false);
  if (table.getBoundingClientRect().width > wrap.getBoundingClientRect().width + 1) set(true);
}
function fitTables() {
  for (const id of ['given-table', 'results-table']) {
    const table = document.getElementById(id);
    if (table.tHead && table.getClientRects().length) fitTable(table);
  }
}
addEventListener('resize', () => requestAnimationFrame(fitTables));

function storeKey(name) { return `mm-assign|${state.name}|${state.student}|${name}`; }

/** One result: the verdict beside its field and a row of the table. */
function resultRow(r, asked) {
  const unit = r.unit || (asked && asked.unit) || '';
  const withUnit = (x) => (x == null || x === '' ? '' : typeof x === 'number' ? `${fmtNumber(x, 6).uni}${unit ? `\u00a0${unitText(unit)}` : ''}` : String(x));
  const verdict = r.correct ? t('a_correct') : t('a_wrong');
  const field = document.getElementById(`f-${r.name}`);
  if (field) {
    const v = $('.a-verdict', field);
    v.className = `a-verdict ${r.correct ? 'ok' : 'bad'}`;
    const parts = [verdict];
    if (!r.correct && r.expected != null) parts.push(t('a_expected', { x: withUnit(r.expected) }));
    if (r.note) parts.push(r.note);
    v.textContent = parts.join(' · ');
    const input = $('input', field);
    input.setAttribute('aria-invalid', r.correct ? 'false' : 'true');
  }
  const tol = r.tolerance == null ? '' : typeof r.tolerance === 'number' ? withUnit(r.tolerance) : String(r.tolerance);
  return el('tr', { class: r.correct ? 'pass' : 'fail' },
    el('th', { scope: 'row' }, (asked && asked.label) || r.name),
    el('td', { text: r.given == null ? '' : String(r.given) }),
    el('td', { class: 'n', text: r.expected == null ? '—' : withUnit(r.expected) }),
    el('td', { class: 'n', text: tol }),
    el('td', { class: r.correct ? 'ok' : 'bad' }, el('span', { 'aria-hidden': 'true', text: r.correct ? '✓ ' : '✗ ' }), verdict),
    el('td', { text: r.note || '' }));
}

function renderResults(body) {
  const asked = new Map(state.variant.asked.map((a) => [a.name, a]));
  const rows = (body.results || []).map((r) => resultRow(r, asked.get(r.name)));
  const table = $('#results-table');
  table.textContent = '';
  table.append(
    el('thead', {}, el('tr', {}, [t('a_quantity'), t('a_given'), t('a_expected_col'), t('a_tolerance'), t('a_verdict'), t('a_note')]
      .map((h) => el('th', { scope: 'col', text: h })))),
    el('tbody', {}, rows));
  $('#results').hidden = false;
  fitTable(table);
  const right = (body.results || []).filter((r) => r.correct).length;
  $('#score').textContent = typeof body.score === 'number' && typeof body.max_score === 'number'
    ? t('a_score', { score: fmtNumber(body.score, 4).uni, max: fmtNumber(body.max_score, 4).uni, right, n: rows.length })
    : t('a_right', { right, n: rows.length });
}

async function check(e) {
  e.preventDefault();
  const button = $('#check');
  const errBox = $('#check-error');
  errBox.hidden = true;
  const answers = {};
  for (const a of state.variant.asked) answers[a.name] = document.getElementById(`a-${a.name}`).value.trim();
  button.disabled = true;
  try {
    const r = await fetch(api('/check'), {
      method: 'POST', headers: { 'Content-Type': 'application/json' },
      body: JSON.stringify({ student: state.student, answers }),
    });
    const text = await r.text();
    if (!r.ok) { showError(errBox, `${t('a_not_checked')} ${failure(r.status, text)}`); return; }
    renderResults(JSON.parse(text));
  } catch (err) {
    showError(errBox, `${t('a_not_checked')} ${err.message || err}`);
  } finally {
    button.disabled = false;
    document.documentElement.dataset.checked = String(Number(document.documentElement.dataset.checked || 0) + 1);
  }
}

function askWho() {
  const f = $('#whoami');
  f.hidden = false;
  $('#w-name').value = state.name;
  $('#w-student').value = state.student;
  $('#title').textContent = t('assignment');
  // a plain GET form to this page: name and student (and the page's own lang, scheme) in the address
  for (const k of ['lang', 'scheme']) if (q.get(k)) f.append(el('input', { type: 'hidden', name: k, value: q.get(k) }));
}

async function load() {
  await initLang(boot.dict);
  translateDocument();
  wirePrefs();
  if (!state.name || !state.student) { askWho(); return; }
  $('#who').textContent = t('a_for', { student: state.student });
  const r = boot.variant ? await boot.variant
    : await fetch(api(`/variant?student=${encodeURIComponent(state.student)}`)).then(async (x) => ({ ok: x.ok, status: x.status, text: await x.text() }));
  if (!r.ok) {
    showError($('#load-error'), r.status === 404 ? t('a_no_such', { name: state.name }) : failure(r.status, r.text));
    askWho();
    return;
  }
  state.variant = JSON.parse(r.text);
  // the exercise's metadata for its title, labels and units, and the
  // assignment's own title from the list; either may fail without harm
  const [meta, list] = await Promise.all([
    fetch(`api/exercises/${encodeURIComponent(state.variant.exercise)}`).then((x) => (x.ok ? x.json() : null)).catch(() => null),
    state.variant.title ? null : fetch('api/assignments').then((x) => (x.ok ? x.json() : null)).catch(() => null),
  ]);
  state.meta = meta;
  const mine = state.variant.title ? state.variant : Array.isArray(list) ? list.find((a) => a.name === state.name) : null;
  const exTitle = exerciseText(state.variant.exercise, 'title', meta ? meta.title : state.variant.exercise);
  $('#title').textContent = mine && mine.title ? mine.title : exTitle;
  if (mine && mine.title && mine.title !== exTitle) $('#kicker').textContent = `${t('assignment')} · ${exTitle}`;
  document.title = `${$('#title').textContent} · mechmat`;
  renderGiven();
  renderAsked();
  $('#sheet').hidden = false;
  fitTable($('#given-table'));
  $('#answers').addEventListener('submit', check);
  $('#print').addEventListener('click', () => window.print());
}

load().catch((err) => showError($('#load-error'), String(err && err.message || err)))
  .finally(() => { document.documentElement.dataset.ready = 'true'; });
