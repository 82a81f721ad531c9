// exercise.js — one page for every exercise, driven by its metadata.
//
//   /exercise.html?id=vib-sdof-forced&k=400[&lang=cs][&scheme=dark][&embed=1]
//
// The state lives in the URL: the id, every parameter whose value is not
// the default (only values the server accepted: an invalid one never enters
// the address or the history), and the page-wide choices (lang, scheme,
// embed).  The page talks only to the public API:
//   GET /api/exercises/{id}          metadata (theory, params, outputs)
//   GET /api/exercises/{id}/solve?…  the answer
// boot.js has started both requests before this module runs.  After every
// answer the page dispatches `mm:rendered` on window (detail: {seq, ok}) and
// sets <html data-rendered=seq>, which the browser tests and the benchmark
// wait for.

import {
  fmtNumber, fmtScalar, inputText, unitHtml, unitText, escapeHtml, encodeValue, el,
} from './format.js?v=__MM_ASSET_VERSION__';
import { planFigures, drawFigure, figureTables, pageTheme, LIGHT, standaloneSvg, svgDocument } from './plot.js?v=__MM_ASSET_VERSION__';
import { createPlayer, animFrameSvg } from './anim.js?v=__MM_ASSET_VERSION__';
import {
  initLang, t, english, translateDocument, currentLang, exerciseText, isTranslated, paramText,
  outputLabel, chapterTitle, sectionTitle, hasTheory, siteUrl,
} from './i18n.js?v=__MM_ASSET_VERSION__';
import { wirePrefs } from './prefs.js?v=__MM_ASSET_VERSION__';
import { extensions } from './ex/registry.js?v=__MM_ASSET_VERSION__';

const DEBOUNCE_MS = 150;
const RESERVED = new Set(['id', 'lang', 'scheme', 'embed']);
const $ = (s, root = document) => root.querySelector(s);
const boot = window.mmBoot || {};
const narrowMq = matchMedia('(max-width: 860px)');
const reducedMq = matchMedia('(prefers-reduced-motion: reduce)');

const urlParams = new URLSearchParams(location.search);
const state = {
  id: urlParams.get('id') || '',
  embed: urlParams.get('embed'),           // null, "1", or the names a learner may change
  meta: null,
  outputs: new Map(),
  answer: null,        // the last good answer (parsed)
  answerText: '',      // …and as the server sent it
  answerQuery: '',
  error: null,         // the error of the last solve, if it failed
  seq: 0,
  requested: null,     // query of the last solve started
  inflight: null,
  timer: 0,
  lastEdit: { name: null, t: 0 },
  colours: new Map(),  // quantity → palette index, kept from answer to answer
  figs: [],            // the planned figures of the answer shown
  views: [],           // [{fig, view, node, holder}]
  player: null,
  pinned: null,        // the kept run: {answer, query}
  theme: null,
  extension: { listeners: [], undo: null, started: false },
};

const apiBase = () => `api/exercises/${encodeURIComponent(state.id)}`;

// ---- the query ---------------------------------------------------------------

/** Parameters from the page's URL, as an encoded query (without id). */
function queryFromUrl() {
  const parts = [];
  for (const [k, v] of new URLSearchParams(location.search)) {
    if (!RESERVED.has(k)) parts.push(`${encodeValue(k)}=${encodeValue(v)}`);
  }
  return parts.join('&');
}

function valuesFromUrl() {
  const m = new Map();
  for (const [k, v] of new URLSearchParams(location.search)) if (!RESERVED.has(k)) m.set(k, v);
  return m;
}

function defaultText(p) {
  return p.kind === 'real' || p.kind === 'integer' ? inputText(p.default) : String(p.default ?? '');
}

/** What the server is sent for a field: a decimal comma (Czech, German)
 *  becomes the API's dot in a single number. */
function sendText(p, v) {
  v = v.trim();
  if ((p.kind === 'real' || p.kind === 'integer') && /^[-+]?\d*,\d+(e[-+]?\d+)?$/i.test(v)) return v.replace(',', '.');
  return v;
}

function isDefault(p, text) {
  const tx = text.trim();
  const d = defaultText(p);
  if (tx === d) return true;
  if (p.kind === 'real' || p.kind === 'integer') return tx !== '' && Number(tx) === p.default;
  if (p.kind === 'vector' || p.kind === 'matrix') return tx.replace(/\s+/g, '') === d.replace(/\s+/g, '');
  return false;
}

/** The query the form stands for: the non-default values, in table order. */
function queryFromForm() {
  const parts = [];
  for (const p of state.meta.params) {
    const input = document.getElementById(`p-${p.name}`);
    if (!input) continue;
    const v = sendText(p, input.value);
    if (!isDefault(p, v)) parts.push(`${encodeValue(p.name)}=${encodeValue(v)}`);
  }
  return parts.join('&');
}

function pageUrl(query) {
  const keep = [];
  for (const k of ['lang', 'scheme', 'embed']) if (urlParams.get(k)) keep.push(`${k}=${encodeValue(urlParams.get(k))}`);
  return `${location.pathname}?id=${encodeValue(state.id)}${query ? '&' + query : ''}${keep.length ? '&' + keep.join('&') : ''}`;
}

function solveUrl(query) {
  return `${apiBase()}/solve${query ? '?' + query : ''}`;
}

// ---- solving ------------------------------------------------------------------

async function fetchAnswer(query, signal) {
  if (boot.solve && boot.query === query && !boot.used) {
    boot.used = true;
    return boot.solve;
  }
  const r = await fetch(solveUrl(query), { signal });
  return { ok: r.ok, status: r.status, text: await r.text() };
}

/** Solve `query`; edit: the field whose change asked for it (an entry in
 *  the history once the server accepts the values), or undefined. */
async function solve(query, edit) {
  const seq = ++state.seq;
  state.requested = query;
  if (state.inflight) state.inflight.abort();
  const ac = new AbortController();
  state.inflight = ac;
  $('#answer').setAttribute('aria-busy', 'true');
  performance.mark(`mm-solve-${seq}`);
  let res, body;
  try {
    res = await fetchAnswer(query, ac.signal);
    performance.mark(`mm-answer-${seq}`);
  } catch (e) {
    if (e.name === 'AbortError') return;
    body = { error: { code: 'network', param: '', message: t('net_error', { msg: e.message }) } };
  }
  if (seq !== state.seq) return;             // a newer request has been made
  state.inflight = null;
  if (!body) {
    try {
      body = JSON.parse(res.text);
    } catch {
      body = { error: { code: 'bad_answer', param: '', message: t('bad_answer', { status: res.status }) } };
    }
  }
  if (!state.meta) await state.metaReady;
  if (!state.meta) return;                   // the page could not be described
  $('#answer').removeAttribute('aria-busy');
  if (!res || !res.ok || body.error) {
    state.error = body.error || { code: 'http', param: '', message: `HTTP ${res.status}` };
    showError();
    announce(t('announce_error'));
    // an extension hears the refusal too (the truss editor names the mechanism)
    for (const cb of state.extension.listeners) {
      try { cb({ error: state.error }); } catch (e) { console.error(e); }
    }
  } else {
    state.error = null;
    state.answer = body;
    state.answerText = res.text;
    state.answerQuery = query;
    if (edit !== undefined) recordHistory(query, edit);
    showError();
    renderAnswer();
    if (edit !== undefined) announceAnswer();
  }
  performance.mark(`mm-drawn-${seq}`);
  // after the frame that shows it (the benchmark measures to here)
  requestAnimationFrame(() => setTimeout(() => performance.mark(`mm-painted-${seq}`), 0));
  document.documentElement.dataset.rendered = String(seq);
  window.dispatchEvent(new CustomEvent('mm:rendered', { detail: { seq, ok: !state.error } }));
}

/** After an edit: solve now (change, select) or when typing pauses (input). */
function schedule(name, now) {
  clearTimeout(state.timer);
  const go = () => {
    const q = queryFromForm();
    if (q === state.requested) return;
    solve(q, name);
  };
  if (now) go();
  else state.timer = setTimeout(go, DEBOUNCE_MS);
}

/** One history entry per field edited; typing on in the same field replaces it. */
function recordHistory(query, name) {
  if (state.embed) return;                    // in a course page's iframe: the page's history is not ours
  const url = pageUrl(query);
  if (url === location.pathname + location.search) return;
  const now = performance.now();
  const same = name && state.lastEdit.name === name && now - state.lastEdit.t < 2000;
  if (same) history.replaceState({ q: query }, '', url);
  else history.pushState({ q: query }, '', url);
  state.lastEdit = { name, t: now };
}

window.addEventListener('popstate', () => {
  clearTimeout(state.timer);
  state.lastEdit = { name: null, t: 0 };
  if (state.meta) fillForm(valuesFromUrl());
  updateCurl();
  solve(queryFromUrl());
});

// ---- announcements ------------------------------------------------------------

function announce(text) {
  const box = $('#announce');
  if (!box) return;
  // a change of text is what a live region reads; the same text twice needs a reset
  box.textContent = box.textContent === text ? `${text}\u00a0` : text;
}

function announceAnswer() {
  const a = state.answer;
  const wanted = state.meta.outputs.filter((o) => o.kind === 'scalar' && o.answer).map((o) => o.name);
  const list = (a.scalars || []).filter((s) => !wanted.length || wanted.includes(s.name)).slice(0, 4)
    .map((s) => `${scalarLabel(s)} ${s.text ? s.text : fmtScalar(s).uni + (s.unit ? ' ' + unitText(s.unit) : '')}`);
  announce(t('announce', { list: list.join('; ') }));
}

// ---- errors -------------------------------------------------------------------

function showError() {
  const err = state.error;
  const box = $('#answer-error');
  if (!err && !state.errorShown) return;      // nothing shown, nothing to show
  state.errorShown = !!err;
  for (const f of document.querySelectorAll('.field.invalid, .field:has(.field-error:not([hidden]))')) {
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
  if (field && !field.hidden) {
    field.classList.add('invalid');
    $('.input', field).setAttribute('aria-invalid', 'true');
    const msg = $('.field-error', field);
    msg.textContent = err.message;
    english(msg);
    msg.hidden = false;
  }
  box.hidden = false;
  const shown = field && !field.hidden;
  box.append(
    el('strong', { text: shown ? t('not_solved_field') : t('not_solved_code', { code: err.code }) }),
    shown ? t('not_solved_check', { param: err.param, label: paramLabel(err.param) }) : english(el('span', { text: err.message })),
    state.answer ? el('span', { class: 'muted', text: t('stale_note') }) : '',
  );
}

function paramLabel(name) {
  const p = state.meta && state.meta.params.find((q) => q.name === name);
  return p ? paramText(state.id, name, 'label', p.label) : name;
}

// ---- the form -----------------------------------------------------------------

function rangeText(p) {
  const u = p.unit ? ` ${unitText(p.unit)}` : '';
  const lo = fmtNumber(p.min).text, hi = fmtNumber(p.max).text;
  switch (p.kind) {
    case 'real': return t('range_real', { lo, hi, unit: u });
    case 'integer': return t('range_integer', { lo, hi });
    case 'vector': return t('range_vector', { most: p.max_length ? t('range_vector_most', { n: p.max_length }) : '', lo, hi, unit: u });
    case 'matrix': return t('range_matrix', { most: p.max_rows ? t('range_matrix_most', { r: p.max_rows, c: p.max_cols }) : '' });
    case 'expression': return t('range_expression', { vars: (p.variables || []).join(', ') || t('the_variables') });
    default: return '';
  }
}

/** The names a learner may change: all, or in an embed those the address lists. */
function editable(p) {
  if (!state.embed) return true;
  return state.embed.split(',').map((s) => s.trim()).includes(p.name);
}

function buildForm(values) {
  const form = $('#params');
  const list = $('#fields');
  list.textContent = '';
  let shown = 0;
  for (const p of state.meta.params) {
    const fid = `p-${p.name}`;
    const helpId = `h-${p.name}`, errId = `e-${p.name}`;
    const labelText = paramText(state.id, p.name, 'label', p.label || p.name);
    const plabel = el('span', { class: 'plabel', text: labelText });
    if (!isTranslated(state.id, 'params') || labelText === p.label) english(plabel);
    const label = el('label', { for: fid }, plabel, ' ',
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
    // the help as written: its first letter may be a symbol ("x at t = 0")
    const helpText = paramText(state.id, p.name, 'help', p.help || '');
    const help = el('p', { class: 'help', id: helpId },
      helpText ? english(el('span', { text: `${helpText}${/[.!?]$/.test(helpText) ? '' : '.'} ` })) : '',
      el('span', { class: 'range', text: rangeText(p) }));
    if (helpText === p.help && p.help) english($('span', help));
    const err = el('p', { class: 'field-error', id: errId, hidden: true });
    const field = el('div', { class: `field kind-${p.kind}`, id: `f-${p.name}`, 'data-param': p.name, hidden: !editable(p) }, label, input, help, err);
    if (editable(p)) shown++;
    list.append(field);
    input.addEventListener('input', () => schedule(p.name, p.kind === 'choice'));
    input.addEventListener('change', () => schedule(p.name, true));
    if (p.kind === 'integer' || p.kind === 'real') input.addEventListener('keydown', (e) => stepKey(e, p, input));
  }
  form.hidden = shown === 0;
  fillForm(values);
  form.addEventListener('submit', (e) => { e.preventDefault(); schedule(null, true); });
  $('#reset').addEventListener('click', () => {
    for (const p of state.meta.params) if (editable(p)) document.getElementById(`p-${p.name}`).value = defaultText(p);
    schedule('(reset)', true);
  });
  // on a phone the figure stays above the field being edited
  form.addEventListener('focusin', (e) => keepFieldInView(e.target));
}

/** Up/down arrows step a number: by 1 for integers, by a tenth of a decade
 *  for reals (with Shift a whole one).  Stepping down from a power of ten
 *  takes the smaller decade's step, so that ↓ then ↑ comes back: 100 ↓ 99 ↑ 100. */
export function stepValue(v, dir, kind, big) {
  if (kind === 'integer') return v + dir * (big ? 10 : 1);
  if (v === 0) return dir * (big ? 1 : 0.1);
  const a = Math.abs(v);
  let k = Math.floor(Math.log10(a) + 1e-12);
  const atPower = Math.abs(a / 10 ** k - 1) < 1e-9;
  const towardZero = Math.sign(v) !== dir;
  if (atPower && towardZero) k -= 1;
  const mag = 10 ** (k - (big ? 0 : 1));
  return Number((v + dir * mag).toPrecision(12));
}

function stepKey(e, p, input) {
  if (e.key !== 'ArrowUp' && e.key !== 'ArrowDown') return;
  const v = Number(sendText(p, input.value));
  if (!Number.isFinite(v) || input.value.trim() === '') return;
  e.preventDefault();
  let next = stepValue(v, e.key === 'ArrowUp' ? 1 : -1, p.kind, e.shiftKey);
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

function keepFieldInView(target) {
  if (!narrowMq.matches || !target || !target.closest('.field')) return;
  requestAnimationFrame(() => {
    const stage = $('#stage');
    const sh = stage && !stage.hidden ? stage.getBoundingClientRect().height : 0;
    const r = target.closest('.field').getBoundingClientRect();
    const vh = window.visualViewport ? window.visualViewport.height : innerHeight;
    if (r.top < sh + 8) window.scrollBy(0, r.top - sh - 8);
    else if (r.bottom > vh - 8) window.scrollBy(0, Math.min(r.bottom - vh + 8, r.top - sh - 8));
  });
}

// ---- the answer ----------------------------------------------------------------

function scalarLabel(s) {
  return outputLabel(state.id, s.name, s.label || s.name);
}

function num(v, sig) {
  const f = fmtNumber(v, sig);
  return el('span', { class: 'num', html: f.html, 'data-value': typeof v === 'number' ? String(v) : null, title: typeof v === 'number' ? String(v) : null });
}

function renderAnswer() {
  const a = state.answer;
  renderViews();
  renderKeep();
  renderScalars(a.scalars || []);
  renderWarnings(a.warnings || []);
  renderTables(a.tables || []);
  renderChecks(a.checks || []);
  renderMethod(a.method || {}, a.elapsed_us);
  renderPrintParams();
  $('#print-source').textContent = t('printed_from', { url: location.href });
  if (state.embed) $('#embed-open').href = pageUrl(state.answerQuery).replace(/&embed=[^&]*/, '');
  updateCurl();
  $('#takeaway').hidden = false;
  fitTables();
  for (const cb of state.extension.listeners) {
    try { cb(a); } catch (e) { console.error(e); }
  }
  startExtension();
}

function accuracyNote(f) {
  if (f.kind === 'exact') return t('exact');
  if (f.kind === 'bound' || f.kind === 'estimate') return `± ${f.err.uni} (${t(f.kind === 'bound' ? 'err_bound' : 'err_estimate')})`;
  return '';
}

function renderScalars(scalars) {
  const box = $('#scalars');
  box.textContent = '';
  box.hidden = scalars.length === 0;
  if (!scalars.length) return;
  const kept = state.pinned ? new Map((state.pinned.answer.scalars || []).map((s) => [s.name, s])) : null;
  const dl = el('dl', { class: 'results' });
  for (const s of scalars) {
    const f = fmtScalar(s);
    const note = s.text ? '' : accuracyNote(f);
    const k = kept && kept.get(s.name);
    const label = el('span', { text: scalarLabel(s) });
    if (outputLabel(state.id, s.name, null) == null) english(label);
    dl.append(el('div', { class: f.text.length > 12 && !s.text ? 'result long' : 'result', 'data-scalar': s.name },
      el('dt', {}, label, ' ', el('code', { text: s.name })),
      el('dd', {},
        s.text
          // a word stands for the number ("underdamped" for regime 0): the word, not both
          ? english(el('span', { class: 'val vtext', text: s.text, 'data-value': String(s.value) }))
          : el('span', { class: 'val', html: f.html, title: String(s.value), 'data-value': String(s.value), 'data-digits': f.text }),
        !s.text && s.unit ? el('span', { class: 'unit', html: ` ${unitHtml(s.unit)}` }) : '',
        note ? el('span', { class: `acc acc-${f.kind}`, text: note }) : '',
        k ? el('span', { class: 'kept-val', 'data-kept': String(k.value) },
          el('span', { class: 'kept-tag', text: `${t('kept')}: ` }),
          k.text ? english(el('span', { text: k.text })) : el('span', { html: fmtScalar(k).html }),
          !k.text && k.unit ? el('span', { html: ` ${unitHtml(k.unit)}` }) : '') : '')));
  }
  box.append(el('h2', { text: t('results') }), dl);
}

function renderWarnings(warnings) {
  const box = $('#warnings');
  box.textContent = '';
  box.hidden = warnings.length === 0;
  if (warnings.length) box.append(english(el('ul', {}, warnings.map((w) => el('li', { text: w })))));
}

function renderTables(tables) {
  const box = $('#tables');
  box.textContent = '';
  box.hidden = tables.length === 0;
  for (const tb of tables) {
    const decl = state.outputs.get(tb.name);
    const cap = outputLabel(state.id, tb.name, tb.label || (decl && decl.label) || tb.name);
    const heads = tb.columns.map((c, j) => `${c}${tb.units && tb.units[j] ? ` [${unitText(tb.units[j])}]` : ''}`);
    const head = el('tr', {}, tb.columns.map((c, j) =>
      el('th', { scope: 'col', html: `${escapeHtml(c)}${tb.units && tb.units[j] ? ` [${unitHtml(tb.units[j])}]` : ''}` })));
    const body = tb.rows.map((r) => el('tr', {}, r.map((v, j) =>
      el('td', { class: typeof v === 'number' ? 'n' : 't', 'data-label': heads[j] }, typeof v === 'number' ? num(v) : String(v)))));
    const caption = el('caption', { text: cap });
    if (outputLabel(state.id, tb.name, null) == null) english(caption);
    box.append(el('div', { class: 'table-wrap', 'data-table': tb.name },
      el('table', {}, caption, el('thead', {}, head), el('tbody', {}, body))));
  }
}

/** Digits that show where value and reference part: the agreeing ones and two more. */
function checkDigits(c) {
  if (!c.reference) return 4;                 // against zero, the error says it all
  const rel = typeof c.rel_error === 'number' && c.rel_error > 0 ? c.rel_error : c.abs_error > 0 ? c.abs_error / Math.abs(c.reference) : 1e-16;
  return Math.max(4, Math.min(17, Math.ceil(-Math.log10(rel)) + 2));
}

function renderChecks(checks) {
  const box = $('#checks');
  box.textContent = '';
  box.hidden = checks.length === 0;
  if (!checks.length) return;
  const failed = checks.filter((c) => !c.passed).length;
  const cols = [t('col_verdict'), t('col_check'), t('col_value'), t('col_error'), t('col_tolerance')];
  const rows = checks.map((c) => {
    const sig = checkDigits(c);
    return el('tr', { class: c.passed ? 'pass' : 'fail', 'data-check': c.name },
      el('td', { class: 'verdict', 'data-label': cols[0] }, c.passed
        ? el('span', { class: 'ok', html: `<span aria-hidden="true">✓</span> ${escapeHtml(t('passed'))}` })
        : el('span', { class: 'bad', html: `<span aria-hidden="true">✗</span> ${escapeHtml(t('failed'))}` })),
      english(el('th', { scope: 'row', text: c.name, 'data-label': cols[1] })),
      el('td', { class: 'n', 'data-label': cols[2] }, num(c.value, sig), el('br'), el('span', { class: 'muted' }, num(c.reference, sig))),
      el('td', { class: 'n', 'data-label': cols[3] }, num(c.abs_error, 3),
        typeof c.rel_error === 'number' ? [el('br'), el('span', { class: 'muted' }, num(c.rel_error, 3), ` ${t('rel')}`)] : ''),
      el('td', { class: 'n', 'data-label': cols[4] }, num(c.tolerance, 3), el('br'),
        el('span', { class: 'muted', text: c.tolerance_kind ? t(`tol_${c.tolerance_kind}`) : '' })));
  });
  box.append(
    el('h2', { text: t('checks') }),
    el('p', { class: failed ? 'summary bad' : 'summary' },
      failed ? t('checks_failed', { failed, n: checks.length }) : t('checks_passed', { n: checks.length })),
    el('div', { class: 'table-wrap' }, el('table', { class: 'checks' },
      el('thead', {}, el('tr', {}, cols.map((h, i) => el('th', { scope: 'col' }, i === 0 ? el('span', { class: 'visually-hidden', text: h }) : h)))),
      el('tbody', {}, rows))));
}

const METHOD_KEYS = ['step', 'steps', 'rejected', 'evaluations', 'error_estimate', 'rtol', 'atol', 'max_error', 'iterations'];

function renderMethod(m, elapsed) {
  const box = $('#method');
  box.textContent = '';
  const dl = el('dl', { class: 'method' });
  const add = (k, v, en) => dl.append(el('div', {}, el('dt', { text: k }), el('dd', {}, en ? english(el('span', { text: v })) : v)));
  if (m.name) add(t('m_method'), m.name, true);
  for (const [k, v] of Object.entries(m)) {
    if (k === 'name' || (k === 'step' && v === 0)) continue;
    add(METHOD_KEYS.includes(k) ? t(`m_${k}`) : k.replace(/_/g, ' '), typeof v === 'number' ? num(v) : String(v));
  }
  if (typeof elapsed === 'number') add(t('m_solved_in'), el('span', {}, num(elapsed), ' µs'));
  box.append(el('h2', { text: t('method') }), dl);
}

/** A resolved parameter value as a learner writes it: 1, 2, 3 or 1, 2; 3, 4. */
function paramValueText(v) {
  if (typeof v === 'number') return fmtNumber(v, 12).uni;
  if (Array.isArray(v)) return v.map((r) => (Array.isArray(r) ? r.map((x) => fmtNumber(x, 12).uni).join(', ') : fmtNumber(r, 12).uni)).join(Array.isArray(v[0]) ? '; ' : ', ');
  return v == null ? '' : String(v);
}

/** The parameters as a table, for the printed worked solution. */
function renderPrintParams() {
  const box = $('#print-params');
  box.textContent = '';
  const a = state.answer;
  const rows = state.meta.params.map((p) => {
    const v = a.params ? a.params[p.name] : undefined;
    const text = paramValueText(v);
    return el('tr', {}, english(el('td', { text: paramText(state.id, p.name, 'label', p.label) })),
      el('td', {}, el('code', { text: p.name })), el('td', { class: 'n', text }), el('td', { html: unitHtml(p.unit) }));
  });
  box.append(el('h2', { text: t('given') }), el('table', {},
    el('thead', {}, el('tr', {}, [t('col_param'), t('col_symbol'), t('col_value1'), t('col_unit')].map((h) => el('th', { scope: 'col', text: h })))),
    el('tbody', {}, rows)));
}

/** Tables that do not fit their box are laid out as one card per row.
 *  A table keeps the layout it had for the last answer at this width (no
 *  layout is forced while an answer is drawn); whether it still fits is
 *  measured after the frame, and changed only if it does not. */
const stackedAt = new Map();     // table key → whether stacked, at state.colWidth
function tableKey(wrap) {
  return `${state.colWidth}|${wrap.dataset.table || wrap.closest('[id]').id}|${$('table', wrap).rows[0]?.cells.length}`;
}
function fitTables(now) {
  const wraps = [...document.querySelectorAll('.answer .table-wrap')].filter((w) => $('table', w));
  for (const w of wraps) {
    const known = stackedAt.get(tableKey(w));
    if (known !== undefined) setStacked(w, known);
  }
  const measure = () => {
    for (const w of wraps) {
      if (!w.isConnected) continue;
      const table = $('table', w);
      setStacked(w, false);
      const stacked = table.scrollWidth > w.clientWidth + 1;
      setStacked(w, stacked);
      stackedAt.set(tableKey(w), stacked);
    }
  };
  if (now) measure(); else requestAnimationFrame(measure);
}
/** Stacked rows lose a table's meaning to a screen reader unless they say it. */
function setStacked(w, on) {
  if (w.classList.contains('stacked') === on) return;
  w.classList.toggle('stacked', on);
  const table = $('table', w);
  const role = (e, r) => (on ? e.setAttribute('role', r) : e.removeAttribute('role'));
  role(table, 'table');
  for (const g of table.querySelectorAll('thead, tbody')) role(g, 'rowgroup');
  for (const r of table.rows) {
    role(r, 'row');
    for (const c of r.cells) role(c, c.tagName === 'TH' ? (c.scope === 'row' ? 'rowheader' : 'columnheader') : 'cell');
  }
}

// ---- keep a run and compare ---------------------------------------------------------

function paramDiff(a, b) {
  const out = [];
  for (const p of state.meta.params) {
    const x = a.params ? a.params[p.name] : undefined, y = b.params ? b.params[p.name] : undefined;
    if (JSON.stringify(x) !== JSON.stringify(y)) out.push(`${p.name} = ${Array.isArray(x) ? `[${paramValueText(x)}]` : paramValueText(x)}`);
  }
  return out.join(', ');
}

function pinnedLabel() {
  if (!state.pinned) return '';
  const d = paramDiff(state.pinned.answer, state.answer);
  return d ? `${t('kept_run')} (${d})` : t('kept_run');
}

function renderKeep() {
  const bar = $('#keep-bar');
  const btn = $('#keep');
  btn.textContent = state.pinned ? t('forget') : t('keep');
  btn.setAttribute('aria-pressed', state.pinned ? 'true' : 'false');
  $('#keep-note').textContent = state.pinned ? t('kept_desc', { desc: paramDiff(state.pinned.answer, state.answer) || t('keep_hint') }) : t('keep_hint');
  bar.hidden = !!state.embed && $('#params').hidden;
}

function toggleKeep() {
  state.pinned = state.pinned ? null : { answer: state.answer, query: state.answerQuery };
  renderAnswer();
}

// ---- figures and the animation ---------------------------------------------------

function figureCaption(fig) {
  const list = fig.items.map((s) => s.legend).join(', ');
  const n = fig.items.length;
  if (!fig.quantity) return t('against', { y: list.length <= 90 ? list : t('n_series', { n }), x: fig.xLabel });
  const base = t('against', { y: fig.quantity, x: fig.xLabel });
  // a quantity that is the list already (a few unlike series) is not said twice
  return n < 2 || fig.quantity === list ? base : list.length <= 90 ? `${base}: ${list}` : `${base} (${t('n_series', { n })})`;
}

function stageMaxHeight() {
  return narrowMq.matches ? Math.round(innerHeight * 0.45) : 0;
}

function isLinked(fig) {
  const an = state.answer && state.answer.animation;
  return !!an && framesCount(an) > 1 && fig.xLabel === an.t_label && (fig.xUnit || '') === (an.t_unit || '');
}

function framesCount(an) {
  let n = (an.t || []).length;
  for (const s of an.shapes || []) n = Math.max(n, (s.x || []).length);
  return n;
}

function figureNode(i) {
  const holder = el('div', { class: 'plot-svg', tabindex: '0', role: 'slider', 'aria-orientation': 'horizontal' });
  const body = el('div', { class: 'fig-data-body' });
  const details = el('details', { class: 'fig-data' }, el('summary', { text: t('data_table') }), body);
  const node = el('figure', { class: 'plot' },
    holder,
    el('figcaption', {},
      el('span', { class: 'fignum' }), ' ', el('span', { class: 'figtext' }), ' ',
      el('button', { type: 'button', class: 'link dl-svg', text: t('svg') })),
    details);
  $('.dl-svg', node).addEventListener('click', () => downloadFigure(node._index));
  details.addEventListener('toggle', () => { if (details.open) fillDataTable(node); });
  wireFigure(node, holder);
  return node;
}

function fillDataTable(node) {
  const v = state.views[node._index];
  const body = $('.fig-data-body', node);
  body.textContent = '';
  if (!v) return;
  for (const tb of figureTables(v.fig)) {
    body.append(el('p', { class: 'muted', text: tb.k > 1 ? t('data_every', { k: tb.k, n: tb.n }) : t('data_all', { n: tb.n }) }),
      el('div', { class: 'data-wrap', tabindex: '0', role: 'region', 'aria-label': t('data_table') }, el('table', { class: 'data' },
        el('thead', {}, el('tr', {}, tb.head.map((h) => el('th', { scope: 'col', text: h })))),
        el('tbody', {}, tb.rows.map((r) => el('tr', {}, r.map((x) => el('td', { class: 'n' }, num(x)))))))));
  }
}

/** Pointer and keyboard on a figure: a cursor reads values; on a figure
 *  whose x is the animation's time, a drag moves the animation. */
function wireFigure(node, holder) {
  const current = () => state.views[node._index];
  const local = (e) => {
    const v = current();
    const r = v.view.svg.getBoundingClientRect();
    const k = v.view.width / (r.width || 1);
    return [(e.clientX - r.left) * k, (e.clientY - r.top) * k];
  };
  let scrubbing = null;
  holder.addEventListener('pointermove', (e) => {
    const v = current();
    if (!v) return;
    const [x, y] = local(e);
    if (scrubbing === e.pointerId && state.player) { state.player.seek(v.view.xOf(x)); return; }
    if (e.pointerType === 'touch') return;
    if (v.view.inPlot(x, y)) setCursor(v, null, x, y); else v.view.clearCursor();
  });
  holder.addEventListener('pointerleave', () => { const v = current(); if (v && document.activeElement !== holder) v.view.clearCursor(); });
  holder.addEventListener('pointerdown', (e) => {
    const v = current();
    if (!v || !v.linked || !state.player) return;
    const [x, y] = local(e);
    if (!v.view.inPlot(x, y)) return;
    scrubbing = e.pointerId;
    try { holder.setPointerCapture(e.pointerId); } catch { /* gone */ }
    state.player.seek(v.view.xOf(x));
  });
  const stop = (e) => { if (scrubbing === e.pointerId) scrubbing = null; };
  holder.addEventListener('pointerup', stop);
  holder.addEventListener('pointercancel', stop);
  holder.addEventListener('focus', () => { const v = current(); if (v) setCursor(v, v.view.index >= 0 ? v.view.index : Math.floor((v.view.master.raw.x.length - 1) / 2)); });
  holder.addEventListener('blur', () => { const v = current(); if (v) v.view.clearCursor(); });
  holder.addEventListener('keydown', (e) => {
    const v = current();
    if (!v) return;
    const n = v.view.master.raw.x.length;
    let i = v.view.index >= 0 ? v.view.index : 0;
    const big = Math.max(1, Math.round(n / 10));
    switch (e.key) {
      case 'ArrowRight': case 'ArrowUp': i += e.shiftKey ? big : 1; break;
      case 'ArrowLeft': case 'ArrowDown': i -= e.shiftKey ? big : 1; break;
      case 'PageUp': i += big; break;
      case 'PageDown': i -= big; break;
      case 'Home': i = 0; break;
      case 'End': i = n - 1; break;
      default: return;
    }
    e.preventDefault();
    setCursor(v, Math.max(0, Math.min(n - 1, i)));
    if (v.linked && state.player) state.player.seek(v.view.master.raw.x[v.view.index]);
  });
}

function setCursor(v, i, px, py) {
  const lines = i == null ? v.view.cursorAt(px, py) : v.view.cursorIndex(i);
  const h = v.holder;
  h.setAttribute('aria-valuenow', String(v.view.index));
  h.setAttribute('aria-valuetext', lines.join('; '));
}

function renderViews() {
  const a = state.answer;
  state.theme = state.theme || pageTheme();
  const label = (name, fallback) => outputLabel(state.id, name, fallback);
  const figs = planFigures(a.series || [], {
    outputs: state.outputs, colours: state.colours, label,
    pinned: state.pinned ? state.pinned.answer.series || [] : null,
  });
  state.figs = figs;
  const stage = $('#stage'), box = $('#figures');
  const anim = a.animation && (a.animation.shapes || []).length ? a.animation : null;

  // the animation: in the stage, kept from answer to answer
  if (anim) {
    if (!state.player) {
      const decl = [...state.outputs.values()].find((o) => o.kind === 'animation');
      state.player = createPlayer(anim, { label: decl ? outputLabel(state.id, 'animation', decl.label) : t('anim'), theme: animTheme(), t });
      state.player.onFrame((f, tt) => { for (const v of state.views) if (v.linked) v.view.setMarker(tt); });
      stage.prepend(state.player.el);
      state.autoplay = !reducedMq.matches;
    } else state.player.update(anim);
  } else if (state.player) {
    state.player.el.remove();
    state.player.destroy();
    state.player = null;
  }

  // the figures: the first in the stage (below the animation), the others after it
  const want = figs.length;
  let stageFig = $('figure.plot', stage);
  if (want && !stageFig) { stageFig = figureNode(0); stage.append(stageFig); }
  if (!want && stageFig) { stageFig.remove(); stageFig = null; }
  const nodes = [...box.querySelectorAll(':scope > figure.plot')];
  const boxWant = Math.max(0, want - 1);
  while (nodes.length > boxWant) nodes.pop().remove();
  while (nodes.length < boxWant) { const n = figureNode(0); box.append(n); nodes.push(n); }
  const all = [stageFig, ...nodes].filter(Boolean);
  stage.hidden = !anim && !want;
  box.hidden = boxWant === 0;

  // the width of the answer's column, measured once (a layout) and again
  // only when the page is resized; every figure is drawn at it
  if (!state.colWidth) {
    const n = all[0] || null;
    state.colWidth = Math.floor(n ? $('.plot-svg', n).clientWidth : box.clientWidth);
    lastWidth = $('#workbench').clientWidth;      // the observer need not redraw for this width
    state.animWidth = anim ? Math.floor($('.anim-svg', stage).clientWidth) : 0;
  }
  if (anim && !state.animWidth) state.animWidth = Math.floor($('.anim-svg', stage).clientWidth);
  const widths = all.map(() => state.colWidth);
  const stageWidth = anim ? state.animWidth : 0;
  state.views = figs.map((fig, i) => {
    const node = all[i];
    node._index = i;
    node.dataset.figure = String(i);
    node.dataset.key = fig.key;
    const caption = figureCaption(fig);
    $('.fignum', node).textContent = t('fig_n', { n: i + 1 });
    $('.figtext', node).textContent = caption;
    const width = Math.max(240, widths[i] || 600);
    const inStage = i === 0;
    const view = drawFigure(fig, width, {
      theme: state.theme, title: `${t('fig_n', { n: i + 1 })}: ${caption}`,
      maxHeight: inStage ? stageMaxHeight() : 0, pinnedLabel: pinnedLabel(),
    });
    const holder = $('.plot-svg', node);
    if (holder.firstChild) holder.firstChild.replaceWith(view.svg); else holder.append(view.svg);
    const linked = isLinked(fig);
    node.classList.toggle('linked', linked);
    holder.setAttribute('aria-label', t('plot_reader', { fig: t('fig_n', { n: i + 1 }) }));
    holder.setAttribute('aria-valuemin', '0');
    holder.setAttribute('aria-valuemax', String(Math.max(0, view.master.raw.x.length - 1)));
    holder.setAttribute('aria-valuenow', '0');
    holder.setAttribute('aria-valuetext', view.readout(0).join('; '));
    const details = $('.fig-data', node);
    const v = { fig, view, node, holder, linked, width };
    if (details.open) queueMicrotask(() => fillDataTable(node));
    return v;
  });
  if (state.player) {
    state.player.layout(stageWidth || widths[0] || 600, narrowMq.matches ? Math.round(innerHeight * 0.3) : 380);
    const tt = state.player.tOf(state.player.frame);
    for (const v of state.views) if (v.linked) v.view.setMarker(tt);
    if (state.autoplay) { state.autoplay = false; startWhenVisible(state.player); }
  }
  if (narrowMq.matches) {
    requestAnimationFrame(() => document.documentElement.style.setProperty('--stage-h', `${stage.hidden ? 0 : Math.ceil(stage.getBoundingClientRect().height)}px`));
  }
}

/** Play the animation once it is on screen (never with reduced motion). */
function startWhenVisible(player) {
  const io = new IntersectionObserver((entries) => {
    if (entries.some((e) => e.isIntersecting)) { io.disconnect(); if (!reducedMq.matches && player === state.player) player.play(); }
  });
  io.observe(player.el);
}

function animTheme(light) {
  const cs = getComputedStyle(document.documentElement);
  const v = (k, d) => (light ? d : (cs.getPropertyValue(k) || '').trim() || d);
  return {
    ink: v('--plot-ink', LIGHT.ink), muted: v('--plot-muted', LIGHT.muted), bg: v('--plot-bg', '#fff'),
    body: v('--anim-body', '#dfe7f1'), tension: v('--anim-tension', '#1f5fa8'), compression: v('--anim-compression', '#c0392b'),
    highlight: v('--anim-highlight', '#b36200'), arrow: v('--anim-arrow', '#2e7d32'), path: v('--plot-muted', LIGHT.muted),
    fontSize: Number(v('--plot-font-size', '12')) || 12,
  };
}

/** Redraw at a new width or in new colours, without asking the server. */
function redraw() {
  if (!state.answer) return;
  state.colWidth = 0;
  state.animWidth = 0;
  renderViews();
  fitTables(true);
}

let resizeFrame = 0;
let lastWidth = 0;
// The observer's frame may run after the page has left the document (the
// page being replaced or torn down): then there is nothing to redraw.
new ResizeObserver(() => {
  cancelAnimationFrame(resizeFrame);
  resizeFrame = requestAnimationFrame(() => {
    const wb = document.getElementById('workbench');
    if (!wb || !wb.isConnected || !state.answer) return;
    const w = wb.clientWidth;
    if (w !== lastWidth) { lastWidth = w; redraw(); }
  });
}).observe(document.getElementById('workbench'));

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

/** A figure as a file, drawn again in the light scheme at the width shown. */
function exportView(v) {
  const svg = drawFigure(v.fig, v.width, { theme: { ...LIGHT }, pinnedLabel: pinnedLabel() }).svg;
  return standaloneSvg(svg, `${state.meta ? state.meta.title + ': ' : ''}${figureCaption(v.fig)}`);
}

function downloadFigure(i) {
  const v = state.views[i];
  if (!v) return;
  download(`${stem()}-fig${i + 1}.svg`, 'image/svg+xml', svgDocument([{ svg: exportView(v) }]));
}

/** Every figure (and the animation as it stands) in one SVG file. */
function downloadAll() {
  const parts = [];
  if (state.player) parts.push({ svg: animFrameSvg(state.player), caption: `${t('anim')}: ${state.player.el.querySelector('.figtext').textContent}` });
  state.views.forEach((v, i) => parts.push({ svg: exportView(v), caption: `${t('fig_n', { n: i + 1 })} ${figureCaption(v.fig)}` }));
  if (parts.length) download(`${stem()}-figures.svg`, 'image/svg+xml', svgDocument(parts));
}

function curlLine() {
  const q = state.meta ? (state.error ? state.answerQuery : queryFromForm()) : queryFromUrl();
  return `curl '${new URL(solveUrl(q), location.href).href}'`;
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
  button.textContent = t('copied');
  setTimeout(() => { button.textContent = old; }, 1200);
}

function wireTakeaway() {
  $('#dl-csv').addEventListener('click', () => state.answer && download(`${stem()}.csv`, 'text/csv', seriesCsv(state.answer)));
  $('#dl-json').addEventListener('click', () => state.answer && download(`${stem()}.json`, 'application/json', state.answerText));
  $('#dl-svg').addEventListener('click', downloadAll);
  $('#copy-curl').addEventListener('click', (e) => copyText(curlLine(), e.currentTarget));
  $('#print').addEventListener('click', () => print());
  $('#keep').addEventListener('click', toggleKeep);
}

// paper is white: a page in the dark scheme prints its figures in the light one
const printMq = matchMedia('print');
function themeForMedia() {
  const th = printMq.matches ? { ...LIGHT, font: pageTheme().font } : pageTheme();
  state.theme = th;
  if (state.player) state.player.setTheme(printMq.matches ? animTheme(true) : animTheme());
  redraw();
  // the medium the figures were last drawn for: the listener runs at the next
  // frame after the medium changes, so a caller (a test) waits for this
  document.documentElement.dataset.medium = printMq.matches ? 'print' : 'screen';
}
document.documentElement.dataset.medium = printMq.matches ? 'print' : 'screen';
printMq.addEventListener('change', themeForMedia);

// ---- exercise extensions (web/js/ex/registry.js) ------------------------------------

async function startExtension() {
  const ext = state.extension;
  if (ext.started || !extensions[state.id]) return;
  ext.started = true;
  try {
    const mod = await extensions[state.id]();
    const host = el('div', { class: 'extension' });
    $('#answer').insertBefore(host, $('#figures'));
    const api = {
      getParams() {
        const o = {};
        for (const p of state.meta.params) o[p.name] = document.getElementById(`p-${p.name}`).value;
        return o;
      },
      setParams(obj) {
        for (const [k, v] of Object.entries(obj || {})) {
          const input = document.getElementById(`p-${k}`);
          if (input) input.value = String(v);
        }
        schedule('(extension)', true);
      },
      onAnswer(cb) {
        ext.listeners.push(cb);
        if (state.answer) cb(state.answer);
      },
      lang: currentLang(),
    };
    const undo = mod.mount(host, api);
    if (typeof undo === 'function') ext.undo = undo;
  } catch (e) {
    console.error('extension', e);
  }
}
addEventListener('pagehide', () => {
  if (state.extension.undo) { try { state.extension.undo(); } catch { /* leaving anyway */ } }
  state.extension.undo = null;
});

// ---- metadata, theory ---------------------------------------------------------------

function renderMeta(meta) {
  const title = exerciseText(meta.id, 'title', meta.title);
  const summary = exerciseText(meta.id, 'summary', meta.summary);
  document.title = `${title} — mechmat`;
  $('#crumb-chapter').textContent = `${meta.chapter} ${chapterTitle(meta.chapter, meta.chapter_title || '')}`.trim();
  $('#crumb-chapter').href = siteUrl('./') + `#ch-${meta.chapter}`;
  $('#crumb-section').textContent = `${meta.section} ${sectionTitle(meta.section, meta.section_title || '')}`.trim();
  $('#title').textContent = title;
  $('#summary').textContent = summary;
  if (title === meta.title) english($('#title'));
  if (summary === meta.summary) english($('#summary'));
  $('#tags').textContent = '';
  for (const tg of meta.tags || []) $('#tags').append(english(el('li', { text: tg })));
  setTheory(meta.theory_html || '', hasTheory(meta.id) ? null : 'en');
  if (hasTheory(meta.id)) {
    fetch(`i18n/theory/${currentLang()}/${encodeURIComponent(meta.id)}.html`)
      .then((r) => (r.ok ? r.text() : Promise.reject(new Error(r.status))))
      .then((html) => { setTheory(html, null); typeset(); })
      .catch(() => {});
  }
  const refs = $('#references');
  refs.textContent = '';
  if (meta.references && meta.references.length) {
    refs.append(el('h2', { text: t('references') }), english(el('ol', {}, meta.references.map((r) => el('li', { text: r })))));
  }
  refs.hidden = !(meta.references && meta.references.length);
  $('#embed-open').href = pageUrl(queryFromUrl()).replace(/&embed=[^&]*/, '');
}

function setTheory(html, lang) {
  const theory = $('#theory');
  theory.innerHTML = html;
  if (lang && currentLang() !== 'en') theory.setAttribute('lang', lang); else theory.removeAttribute('lang');
  const h1 = $('h1', theory);
  if (h1) h1.remove();
  // the page has h1 (title) and h2 (its parts): the theory's headings go one level down
  for (const h of theory.querySelectorAll('h1, h2, h3, h4, h5')) {
    const level = Math.max(3, Math.min(6, Number(h.tagName[1]) + 1));   // h1, h2 → h3; h3 → h4 …
    const n = document.createElement(`h${level}`);
    n.innerHTML = h.innerHTML;
    h.replaceWith(n);
  }
  const eb = el('h2', { class: 'eyebrow', text: t('theory') });
  if (lang) eb.setAttribute('lang', currentLang());
  theory.prepend(eb);
}

async function typeset() {
  const nodes = document.querySelectorAll('#theory .math');
  if (nodes.length) {
    // KaTeX's style sheet and code are loaded only now, after the first answer is drawn
    const css = new Promise((resolve) => {
      if (document.getElementById('katex-css')) return resolve();
      const link = el('link', { id: 'katex-css', rel: 'stylesheet', href: 'vendor/katex/dist/katex.min.css?v=__MM_ASSET_VERSION__' });
      link.addEventListener('load', resolve);
      link.addEventListener('error', resolve);
      document.head.append(link);
    });
    const [{ default: katex }] = await Promise.all([import('../vendor/katex/dist/katex.mjs?v=__MM_ASSET_VERSION__'), css]);
    for (const n of nodes) {
      const display = n.classList.contains('math-display');
      try {
        katex.render(n.textContent, n, { displayMode: display, throwOnError: false, output: 'htmlAndMathml' });
      } catch (e) {
        n.classList.add('math-error');
        n.title = e.message;
      }
    }
  }
  // a display's width is known only in its own fonts, and which fonts it
  // needs (KaTeX_Size2 for a tall bracket, bold italic for a vector) only
  // once it is laid out: measuring lays the theory out, which asks for them;
  // measure again when every font asked for is in, and only then say "done"
  // (a box that overflows once its font arrives must be reachable by
  // keyboard by then).  Fonts that arrive later still (a failed load being
  // retried) measure again when they do.
  try {
    await Promise.all([document.fonts.load('1em KaTeX_Main'), document.fonts.load('italic 1em KaTeX_Math')]);
  } catch { /* measured in the fallback font; loadingdone measures again */ }
  focusableScrollers();
  document.fonts.addEventListener('loadingdone', focusableScrollers);
  for (let i = 0; i < 4 && document.fonts.status === 'loading'; i++) {
    try { await document.fonts.ready; } catch { break; }
    focusableScrollers();
  }
  document.documentElement.dataset.typeset = 'done';
}

/** A box that scrolls sideways (wide display math, long code) can be reached
 *  and scrolled with the keyboard. */
function focusableScrollers() {
  for (const e of document.querySelectorAll('#theory .katex-display, #theory pre, .curl pre')) {
    if (e.scrollWidth > e.clientWidth + 1) {
      e.setAttribute('tabindex', '0');
      if (!e.hasAttribute('role')) e.setAttribute('role', 'region');
      if (!e.hasAttribute('aria-label')) e.setAttribute('aria-label', e.matches('pre') ? 'code' : 'equation');
    } else if (e.getAttribute('tabindex') === '0') {
      e.removeAttribute('tabindex');
      e.removeAttribute('role');
      e.removeAttribute('aria-label');
    }
  }
}

async function neighbours() {
  try {
    const list = await (await fetch('api/exercises')).json();
    const i = list.findIndex((e) => e.id === state.id);
    const nav = $('#pager');
    nav.textContent = '';
    const link = (e, rel, arrow) => el('a', { href: siteUrl('exercise.html', { id: e.id }), rel, class: rel },
      el('span', { class: 'muted', text: `${arrow} ${e.section}` }), ' ', exerciseText(e.id, 'title', e.title));
    if (i > 0) nav.append(link(list[i - 1], 'prev', '←'));
    if (i >= 0 && i < list.length - 1) nav.append(link(list[i + 1], 'next', '→'));
  } catch { /* the pager is a nicety */ }
}

function fatal(message) {
  $('#title').textContent = t('not_found');
  $('#summary').textContent = message;
  $('#workbench').hidden = true;
  document.documentElement.dataset.failed = 'true';
  document.documentElement.dataset.rendered = 'failed';
}

async function main() {
  performance.mark('mm-main');
  await initLang(boot.dict);
  translateDocument();
  wirePrefs(themeForMedia);
  wireTakeaway();
  for (const a of document.querySelectorAll('a.brand, #crumb-home, footer.site a')) a.href = siteUrl('./');
  if (state.embed) document.documentElement.dataset.embed = state.embed;
  if (!state.id) return fatal(t('no_id'));
  let metaResolve;
  state.metaReady = new Promise((r) => { metaResolve = r; });
  const metaP = boot.meta && boot.id === state.id ? boot.meta
    : fetch(apiBase()).then(async (r) => ({ ok: r.ok, body: await r.json() }));
  const first = solve(queryFromUrl());       // in parallel with the metadata
  let meta;
  try {
    meta = await metaP;
  } catch (e) {
    metaResolve();
    return fatal(t('no_server', { msg: e.message }));
  }
  if (!meta.ok) { metaResolve(); return fatal(meta.body.error ? meta.body.error.message : t('no_meta')); }
  state.meta = meta.body;
  for (const o of state.meta.outputs || []) state.outputs.set(o.name, o);
  renderMeta(state.meta);
  buildForm(valuesFromUrl());
  state.requested = queryFromUrl();
  metaResolve();
  if (state.error) showError();
  updateCurl();
  await first;
  requestAnimationFrame(() => setTimeout(() => { typeset(); neighbours(); }, 0));
  addEventListener('resize', () => { if (document.documentElement.dataset.typeset) focusableScrollers(); });
}

main();
