// exercise.js — one page for every exercise, driven by its metadata.
//
//   /exercise.html?id=vib-sdof-forced&k=400
//
// The state lives in the URL: the id and every parameter whose value is not
// the default.  The page talks only to the public API:
//   GET /api/exercises/{id}          metadata (theory, params, outputs)
//   GET /api/exercises/{id}/solve?…  the answer
// After every redraw it dispatches `mm:rendered` on window (detail: {seq,
// ok}), which the browser tests and the benchmark wait for.

import { fmtNumber, inputText, unitHtml, unitText, escapeHtml, encodeValue, el } from './format.js';
import { groupSeries, drawFigure, standaloneSvg, figureNames } from './plot.js';

const DEBOUNCE_MS = 150;
const $ = (s, root = document) => root.querySelector(s);

const state = {
  id: new URLSearchParams(location.search).get('id') || '',
  meta: null,
  answer: null,        // the last good answer (parsed)
  answerText: '',      // …and as the server sent it
  answerQuery: '',
  error: null,         // the error of the last solve, if it failed
  seq: 0,
  requested: null,     // query of the last solve started
  inflight: null,
  timer: 0,
  lastEdit: { name: null, t: 0 },
  figures: [],         // [{group, svg}]
  figWidth: 0,
};

const apiBase = () => `/api/exercises/${encodeURIComponent(state.id)}`;

// ---- the query ---------------------------------------------------------------

/** Parameters from the page's URL, as an encoded query (without id). */
function queryFromUrl() {
  const parts = [];
  for (const [k, v] of new URLSearchParams(location.search)) {
    if (k !== 'id') parts.push(`${encodeValue(k)}=${encodeValue(v)}`);
  }
  return parts.join('&');
}

function valuesFromUrl() {
  const m = new Map();
  for (const [k, v] of new URLSearchParams(location.search)) if (k !== 'id') m.set(k, v);
  return m;
}

function defaultText(p) {
  return p.kind === 'real' || p.kind === 'integer' ? inputText(p.default) : String(p.default ?? '');
}

function isDefault(p, text) {
  const t = text.trim();
  const d = defaultText(p);
  if (t === d) return true;
  if (p.kind === 'real' || p.kind === 'integer') return t !== '' && Number(t) === p.default;
  if (p.kind === 'vector' || p.kind === 'matrix') return t.replace(/\s+/g, '') === d.replace(/\s+/g, '');
  return false;
}

/** The query the form stands for: the non-default values, in table order. */
function queryFromForm() {
  const parts = [];
  for (const p of state.meta.params) {
    const input = document.getElementById(`p-${p.name}`);
    if (!input) continue;
    const v = input.value.trim();
    if (!isDefault(p, v)) parts.push(`${encodeValue(p.name)}=${encodeValue(v)}`);
  }
  return parts.join('&');
}

function pageUrl(query) {
  return `${location.pathname}?id=${encodeValue(state.id)}${query ? '&' + query : ''}`;
}

function solveUrl(query) {
  return `${apiBase()}/solve${query ? '?' + query : ''}`;
}

// ---- solving ------------------------------------------------------------------

async function solve(query) {
  const seq = ++state.seq;
  state.requested = query;
  if (state.inflight) state.inflight.abort();
  const ac = new AbortController();
  state.inflight = ac;
  $('#answer').setAttribute('aria-busy', 'true');
  let res, text, body;
  try {
    res = await fetch(solveUrl(query), { signal: ac.signal });
    text = await res.text();
  } catch (e) {
    if (e.name === 'AbortError') return;
    body = { error: { code: 'network', param: '', message: `the server did not answer (${e.message})` } };
  }
  if (seq !== state.seq) return;             // a newer request has been made
  state.inflight = null;
  if (!body) {
    try {
      body = JSON.parse(text);
    } catch {
      body = { error: { code: 'bad_answer', param: '', message: `the server sent something that is not JSON (HTTP ${res.status})` } };
    }
  }
  $('#answer').removeAttribute('aria-busy');
  if (!res || !res.ok || body.error) {
    state.error = body.error || { code: 'http', param: '', message: `HTTP ${res.status}` };
    showError();
  } else {
    state.error = null;
    state.answer = body;
    state.answerText = text;
    state.answerQuery = query;
    showError();
    renderAnswer();
  }
  window.dispatchEvent(new CustomEvent('mm:rendered', { detail: { seq, ok: !state.error } }));
}

/** After an edit: solve now (change, select) or when typing pauses (input). */
function schedule(name, now) {
  clearTimeout(state.timer);
  const go = () => {
    const q = queryFromForm();
    if (q === state.requested) return;
    recordHistory(q, name);
    solve(q);
  };
  if (now) go();
  else state.timer = setTimeout(go, DEBOUNCE_MS);
}

/** One history entry per field edited; typing on in the same field replaces it. */
function recordHistory(query, name) {
  const url = pageUrl(query);
  if (url === location.pathname + location.search) return;
  const t = performance.now();
  const same = name && state.lastEdit.name === name && t - state.lastEdit.t < 2000;
  if (same) history.replaceState({ q: query }, '', url);
  else history.pushState({ q: query }, '', url);
  state.lastEdit = { name, t };
  updateCurl();
}

window.addEventListener('popstate', () => {
  clearTimeout(state.timer);
  state.lastEdit = { name: null, t: 0 };
  if (state.meta) fillForm(valuesFromUrl());
  updateCurl();
  solve(queryFromUrl());
});

// ---- errors -------------------------------------------------------------------

function showError() {
  const err = state.error;
  const box = $('#answer-error');
  for (const f of document.querySelectorAll('.field')) {
    f.classList.remove('invalid');
    const input = $('.input', f);
    input.removeAttribute('aria-invalid');
    const msg = $('.field-error', f);
    msg.textContent = '';
    msg.hidden = true;
  }
  box.hidden = true;
  box.textContent = '';
  $('#answer').classList.toggle('stale', !!err && !!state.answer);
  if (!err) return;
  const field = err.param && state.meta ? document.getElementById(`f-${err.param}`) : null;
  if (field) {
    field.classList.add('invalid');
    $('.input', field).setAttribute('aria-invalid', 'true');
    const msg = $('.field-error', field);
    msg.textContent = err.message;
    msg.hidden = false;
  }
  box.hidden = false;
  box.append(
    el('strong', { text: field ? 'Not solved: ' : `Not solved (${err.code}): ` }),
    field ? `check ${err.param} (${paramLabel(err.param)}).` : err.message,
    state.answer ? el('span', { class: 'muted', text: ' The answer below is for the last values that worked.' }) : '',
  );
}

function paramLabel(name) {
  const p = state.meta && state.meta.params.find((q) => q.name === name);
  return p ? p.label : name;
}

// ---- the form -----------------------------------------------------------------

function rangeText(p) {
  const u = p.unit ? ` ${unitText(p.unit)}` : '';
  const lo = fmtNumber(p.min).text, hi = fmtNumber(p.max).text;
  switch (p.kind) {
    case 'real': return `Range ${lo} to ${hi}${u}.`;
    case 'integer': return `A whole number, ${lo} to ${hi}.`;
    case 'vector': return `Numbers separated by commas${p.max_length ? `, at most ${p.max_length}` : ''}; each ${lo} to ${hi}${u}.`;
    case 'matrix': return `MATLAB form: commas between numbers, ; between rows${p.max_rows ? ` (at most ${p.max_rows}×${p.max_cols})` : ''}.`;
    case 'expression': return `An expression of ${(p.variables || []).join(', ') || 'the variables'}, with + − * / ^ and sin, exp, sqrt, pi ….`;
    default: return '';
  }
}

function buildForm(values) {
  const form = $('#params');
  const list = $('#fields');
  list.textContent = '';
  for (const p of state.meta.params) {
    const fid = `p-${p.name}`;
    const helpId = `h-${p.name}`, errId = `e-${p.name}`;
    const label = el('label', { for: fid },
      el('span', { class: 'plabel', text: p.label || p.name }), ' ',
      el('code', { class: 'pname', text: p.name }),
      p.unit ? el('span', { class: 'punit', html: ` [${unitHtml(p.unit)}]` }) : '');
    let input;
    if (p.kind === 'choice') {
      input = el('select', { id: fid, name: p.name, class: 'input', 'aria-describedby': `${helpId} ${errId}` },
        (p.choices || []).map((c) => el('option', { value: c, text: c })));
    } else {
      const wide = p.kind === 'vector' || p.kind === 'matrix' || p.kind === 'expression';
      input = el('input', {
        id: fid, name: p.name, type: 'text', class: `input${wide ? ' mono' : ''}`,
        autocomplete: 'off', spellcheck: 'false', autocapitalize: 'off',
        inputmode: p.kind === 'integer' && p.min >= 0 ? 'numeric' : null,
        'aria-describedby': `${helpId} ${errId}`,
      });
    }
    const help = el('p', { class: 'help', id: helpId },
      p.help ? `${p.help[0].toUpperCase()}${p.help.slice(1)}${/[.!?]$/.test(p.help) ? '' : '.'} ` : '', el('span', { class: 'range', text: rangeText(p) }));
    const err = el('p', { class: 'field-error', id: errId, hidden: true });
    const field = el('div', { class: `field kind-${p.kind}`, id: `f-${p.name}`, 'data-param': p.name }, label, input, help, err);
    list.append(field);
    input.addEventListener('input', () => schedule(p.name, p.kind === 'choice'));
    input.addEventListener('change', () => schedule(p.name, true));
    if (p.kind === 'integer' || p.kind === 'real') input.addEventListener('keydown', (e) => stepKey(e, p, input));
  }
  fillForm(values);
  form.addEventListener('submit', (e) => { e.preventDefault(); schedule(null, true); });
  $('#reset').addEventListener('click', () => {
    for (const p of state.meta.params) document.getElementById(`p-${p.name}`).value = defaultText(p);
    schedule('(reset)', true);
  });
}

/** Up/down arrows step a number: by 1 for integers, by a tenth of a decade for reals. */
function stepKey(e, p, input) {
  if (e.key !== 'ArrowUp' && e.key !== 'ArrowDown') return;
  const v = Number(input.value.trim());
  if (!Number.isFinite(v)) return;
  e.preventDefault();
  const dir = e.key === 'ArrowUp' ? 1 : -1;
  let next;
  if (p.kind === 'integer') next = v + dir;
  else {
    const mag = v === 0 ? 1 : 10 ** Math.floor(Math.log10(Math.abs(v)) - (e.shiftKey ? 0 : 1));
    next = Number((v + dir * mag).toPrecision(12));
  }
  if (Number.isFinite(p.min)) next = Math.max(p.min, next);
  if (Number.isFinite(p.max)) next = Math.min(p.max, next);
  input.value = inputText(next);
  schedule(p.name, false);
}

function fillForm(values) {
  for (const p of state.meta.params) {
    const input = document.getElementById(`p-${p.name}`);
    input.value = values.has(p.name) ? values.get(p.name) : defaultText(p);
  }
}

// ---- the answer ----------------------------------------------------------------

function num(v, sig) {
  const f = fmtNumber(v, sig);
  return el('span', { class: 'num', html: f.html, 'data-value': typeof v === 'number' ? String(v) : null, title: typeof v === 'number' ? String(v) : null });
}

function renderAnswer() {
  const a = state.answer;
  renderFigures();
  renderScalars(a.scalars || []);
  renderWarnings(a.warnings || []);
  renderTables(a.tables || []);
  renderChecks(a.checks || []);
  renderMethod(a.method || {}, a.elapsed_us);
  updateCurl();
  $('#takeaway').hidden = false;
}

function renderScalars(scalars) {
  const box = $('#scalars');
  box.textContent = '';
  box.hidden = scalars.length === 0;
  if (!scalars.length) return;
  const dl = el('dl', { class: 'results' });
  for (const s of scalars) {
    dl.append(el('div', { class: 'result', 'data-scalar': s.name },
      el('dt', {}, el('span', { text: s.label || s.name }), ' ', el('code', { text: s.name })),
      el('dd', {},
        el('span', { class: 'val', html: fmtNumber(s.value).html, title: String(s.value), 'data-value': String(s.value) }),
        s.unit ? el('span', { class: 'unit', html: ` ${unitHtml(s.unit)}` }) : '',
        s.text ? el('span', { class: 'vtext', text: s.text }) : '')));
  }
  box.append(el('h2', { text: 'Results' }), dl);
}

function renderWarnings(warnings) {
  const box = $('#warnings');
  box.textContent = '';
  box.hidden = warnings.length === 0;
  if (warnings.length) box.append(el('ul', {}, warnings.map((w) => el('li', { text: w }))));
}

function renderTables(tables) {
  const box = $('#tables');
  box.textContent = '';
  box.hidden = tables.length === 0;
  for (const t of tables) {
    const head = el('tr', {}, t.columns.map((c, j) =>
      el('th', { scope: 'col', html: `${escapeHtml(c)}${t.units && t.units[j] ? ` [${unitHtml(t.units[j])}]` : ''}` })));
    const body = t.rows.map((r) => el('tr', {}, r.map((v) =>
      el('td', { class: typeof v === 'number' ? 'n' : 't' }, typeof v === 'number' ? num(v) : String(v)))));
    box.append(el('div', { class: 'table-wrap', 'data-table': t.name },
      el('table', {}, el('caption', { text: `Table: ${t.name}` }), el('thead', {}, head), el('tbody', {}, body))));
  }
}

function renderChecks(checks) {
  const box = $('#checks');
  box.textContent = '';
  box.hidden = checks.length === 0;
  if (!checks.length) return;
  const failed = checks.filter((c) => !c.passed).length;
  const rows = checks.map((c) => el('tr', { class: c.passed ? 'pass' : 'fail', 'data-check': c.name },
    el('td', { class: 'verdict' }, c.passed
      ? el('span', { class: 'ok', html: '<span aria-hidden="true">✓</span> passed' })
      : el('span', { class: 'bad', html: '<span aria-hidden="true">✗</span> failed' })),
    el('th', { scope: 'row', text: c.name }),
    el('td', { class: 'n' }, num(c.value, 10)),
    el('td', { class: 'n' }, num(c.reference, 10)),
    el('td', { class: 'n' }, num(c.abs_error, 3),
      typeof c.rel_error === 'number' ? [el('br'), el('span', { class: 'muted' }, num(c.rel_error, 3), ' rel.')] : ''),
    el('td', { class: 'n' }, num(c.tolerance, 3), el('br'), el('span', { class: 'muted', text: c.tolerance_kind || '' }))));
  box.append(
    el('h2', { text: 'Checks' }),
    el('p', { class: failed ? 'summary bad' : 'summary' },
      failed ? `${failed} of ${checks.length} checks failed: the numbers disagree with an independent reference.`
        : `All ${checks.length} checks passed: the numbers agree with an independent reference.`),
    el('div', { class: 'table-wrap' }, el('table', { class: 'checks' },
      el('thead', {}, el('tr', {}, ['', 'check', 'value', 'reference', 'error', 'tolerance'].map((h) => el('th', { scope: 'col', text: h })))),
      el('tbody', {}, rows))));
}

const METHOD_LABELS = {
  step: 'step', steps: 'steps', rejected: 'rejected steps', evaluations: 'function evaluations',
  error_estimate: 'error estimate', rtol: 'relative tolerance', atol: 'absolute tolerance',
  max_error: 'largest error', iterations: 'iterations',
};

function renderMethod(m, elapsed) {
  const box = $('#method');
  box.textContent = '';
  const dl = el('dl', { class: 'method' });
  const add = (k, v) => dl.append(el('div', {}, el('dt', { text: k }), el('dd', {}, v)));
  if (m.name) add('method', m.name);
  for (const [k, v] of Object.entries(m)) {
    if (k === 'name' || (k === 'step' && v === 0)) continue;
    add(METHOD_LABELS[k] || k.replace(/_/g, ' '), typeof v === 'number' ? num(v) : String(v));
  }
  if (typeof elapsed === 'number') add('solved in', el('span', {}, num(elapsed), ' µs'));
  box.append(el('h2', { text: 'Method' }), dl);
}

// ---- figures --------------------------------------------------------------------

function figuresWidth() {
  return Math.max(260, Math.floor($('#figures').clientWidth));
}

function renderFigures() {
  const box = $('#figures');
  const groups = groupSeries(state.answer.series);
  const width = figuresWidth();
  state.figWidth = width;
  if (box.children.length !== groups.length) {
    box.textContent = '';
    groups.forEach((g, i) => {
      const fig = el('figure', { class: 'plot', 'data-figure': i },
        el('div', { class: 'plot-svg' }),
        el('figcaption', {},
          el('span', { class: 'fignum', text: `Fig. ${i + 1}` }), ' ',
          el('span', { class: 'figtext' }), ' ',
          el('button', { type: 'button', class: 'link dl-svg', 'data-figure': i, text: 'SVG' })));
      $('.dl-svg', fig).addEventListener('click', () => downloadSvg(i));
      box.append(fig);
    });
  }
  state.figures = groups.map((g, i) => {
    const fig = box.children[i];
    const { quantity, legend } = figureNames(g);
    const list = legend.join(', ');
    const caption = `${quantity} against ${g.x_label || 'x'}${g.series.length < 2 ? '' : list.length <= 90 ? `: ${list}` : ` (${g.series.length} series)`}`;
    $('.figtext', fig).textContent = caption;
    const svg = drawFigure(g, width, { title: caption });
    const holder = $('.plot-svg', fig);
    if (holder.firstChild) holder.firstChild.replaceWith(svg);
    else holder.append(svg);
    return { group: g, svg, caption };
  });
  box.hidden = groups.length === 0;
}

let resizeFrame = 0;
// The observer's frame may run after the figures box has left the document
// (the page being replaced or torn down): then there is nothing to redraw.
new ResizeObserver(() => {
  if (!state.answer) return;
  cancelAnimationFrame(resizeFrame);
  resizeFrame = requestAnimationFrame(() => {
    const box = document.getElementById('figures');
    if (!box || !box.isConnected) return;
    if (figuresWidth() !== state.figWidth) renderFigures();
  });
}).observe(document.getElementById('figures'));

// ---- take it away -------------------------------------------------------------------

function download(name, type, text) {
  const url = URL.createObjectURL(new Blob([text], { type }));
  const a = el('a', { href: url, download: name });
  document.body.append(a);
  a.click();
  a.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10000);
}

function csvCell(s) {
  s = String(s);
  return /[",\n]/.test(s) ? `"${s.replace(/"/g, '""')}"` : s;
}

/** The series as CSV: one x column and a y column per series when they share
 *  their x values, else long form (series, x, y).  Numbers as in the JSON. */
export function seriesCsv(a) {
  const series = a.series || [];
  if (!series.length) return '';
  const head = (q, u) => csvCell(u ? `${q} [${u}]` : q);
  const s0 = series[0];
  const sameX = series.every((s) => s.x_label === s0.x_label && s.x_unit === s0.x_unit &&
    s.x.length === s0.x.length && s.x.every((v, i) => v === s0.x[i]));
  const lines = [];
  if (sameX) {
    lines.push([head(s0.x_label || 'x', s0.x_unit), ...series.map((s) => head(s.name, s.unit))].join(','));
    for (let i = 0; i < s0.x.length; i++) lines.push([s0.x[i], ...series.map((s) => s.y[i])].join(','));
  } else {
    lines.push('series,x,x_unit,y,y_unit');
    for (const s of series) {
      for (let i = 0; i < s.x.length; i++) lines.push([csvCell(s.name), s.x[i], csvCell(s.x_unit), s.y[i], csvCell(s.unit)].join(','));
    }
  }
  return lines.join('\n') + '\n';
}

function stem() {
  return state.answerQuery ? `${state.id}-${state.answerQuery.replace(/[^A-Za-z0-9.=_-]+/g, '_')}`.slice(0, 120) : state.id;
}

function downloadSvg(i) {
  const f = state.figures[i];
  if (f) download(`${stem()}-fig${i + 1}.svg`, 'image/svg+xml', standaloneSvg(f.svg, `${state.meta ? state.meta.title + ': ' : ''}${f.caption}`));
}

function curlLine() {
  const q = state.meta ? queryFromForm() : queryFromUrl();
  return `curl '${location.origin}${solveUrl(q)}'`;
}

function updateCurl() {
  const code = $('#curl');
  if (code) code.textContent = curlLine();
}

async function copyText(text, button) {
  try {
    await navigator.clipboard.writeText(text);
  } catch {
    const ta = el('textarea', { class: 'offscreen' });
    ta.value = text;
    document.body.append(ta);
    ta.select();
    document.execCommand('copy');
    ta.remove();
  }
  const old = button.textContent;
  button.textContent = 'copied';
  setTimeout(() => { button.textContent = old; }, 1200);
}

function wireTakeaway() {
  $('#dl-csv').addEventListener('click', () => state.answer && download(`${stem()}.csv`, 'text/csv', seriesCsv(state.answer)));
  $('#dl-json').addEventListener('click', () => state.answer && download(`${stem()}.json`, 'application/json', state.answerText));
  $('#dl-svg').addEventListener('click', () => downloadSvg(0));
  $('#copy-curl').addEventListener('click', (e) => copyText(curlLine(), e.currentTarget));
}

// ---- metadata, theory --------------------------------------------------------------

function renderMeta(meta) {
  document.title = `${meta.title} — mechmat`;
  $('#crumb-chapter').textContent = `${meta.chapter} ${meta.chapter_title || ''}`.trim();
  $('#crumb-chapter').href = `/#ch-${meta.chapter}`;
  $('#crumb-section').textContent = meta.section;
  $('#title').textContent = meta.title;
  $('#summary').textContent = meta.summary;
  $('#tags').textContent = '';
  for (const t of meta.tags || []) $('#tags').append(el('li', { text: t }));
  const theory = $('#theory');
  theory.innerHTML = meta.theory_html || '';
  const h1 = $('h1', theory);
  if (h1 && h1.textContent.trim() === meta.title.trim()) h1.remove();
  // the page has h1 (title) and h2 (its parts): the theory's headings go one level down
  for (const h of theory.querySelectorAll('h1, h2, h3, h4, h5')) {
    const level = Math.max(3, Math.min(6, Number(h.tagName[1]) + 1));   // h1, h2 → h3; h3 → h4 …
    const n = document.createElement(`h${level}`);
    n.innerHTML = h.innerHTML;
    h.replaceWith(n);
  }
  theory.prepend(el('h2', { class: 'eyebrow', text: 'Theory' }));
  const refs = $('#references');
  refs.textContent = '';
  if (meta.references && meta.references.length) {
    refs.append(el('h2', { text: 'References' }), el('ol', {}, meta.references.map((r) => el('li', { text: r }))));
  }
  refs.hidden = !(meta.references && meta.references.length);
}

async function typeset() {
  const nodes = document.querySelectorAll('#theory .math');
  if (!nodes.length) return;
  const { default: katex } = await import('/vendor/katex/dist/katex.mjs');
  for (const n of nodes) {
    const display = n.classList.contains('math-display');
    try {
      katex.render(n.textContent, n, { displayMode: display, throwOnError: false, output: 'htmlAndMathml' });
    } catch (e) {
      n.classList.add('math-error');
      n.title = e.message;
    }
  }
  document.documentElement.dataset.typeset = 'done';
}

async function neighbours() {
  try {
    const list = await (await fetch('/api/exercises')).json();
    const i = list.findIndex((e) => e.id === state.id);
    const nav = $('#pager');
    nav.textContent = '';
    const link = (e, rel, arrow) => el('a', { href: `/exercise.html?id=${encodeValue(e.id)}`, rel, class: rel },
      el('span', { class: 'muted', text: `${arrow} ${e.section}` }), ' ', e.title);
    if (i > 0) nav.append(link(list[i - 1], 'prev', '←'));
    if (i >= 0 && i < list.length - 1) nav.append(link(list[i + 1], 'next', '→'));
  } catch { /* the pager is a nicety */ }
}

function fatal(message) {
  $('#title').textContent = 'Exercise not found';
  $('#summary').textContent = message;
  $('#workbench').hidden = true;
  document.documentElement.dataset.failed = 'true';
}

async function main() {
  wireTakeaway();
  if (!state.id) return fatal('No exercise was named in the address (?id=…). Choose one from the contents.');
  const metaP = fetch(apiBase()).then(async (r) => ({ ok: r.ok, body: await r.json() }));
  const first = solve(queryFromUrl());       // in parallel with the metadata
  let meta;
  try {
    meta = await metaP;
  } catch (e) {
    return fatal(`The server did not answer (${e.message}).`);
  }
  if (!meta.ok) return fatal(meta.body.error ? meta.body.error.message : 'The server could not describe this exercise.');
  state.meta = meta.body;
  renderMeta(state.meta);
  buildForm(valuesFromUrl());
  state.requested = queryFromUrl();
  if (state.error) showError();
  updateCurl();
  await first;
  requestAnimationFrame(() => setTimeout(() => { typeset(); neighbours(); }, 0));
}

main();
