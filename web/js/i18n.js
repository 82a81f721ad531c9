// i18n.js — the page's language: English, Czech or German.
//
// Chosen by ?lang=cs in the address (kept when moving between pages), else
// by the browser's languages, else English.  Every interface string is a key
// of EN below; web/i18n/cs.js and web/i18n/de.js hold the same keys (`ui`),
// the titles of chapters and sections, and per exercise id its title and
// summary (`exercises`), optionally its parameters' and outputs' labels, and
// the ids that have a translated theory file (web/i18n/theory/<lang>/<id>.html,
// the same HTML the API's theory_html is).  An exercise without a
// translation is shown in English.  Numbers are formatted per language in
// the page only (format.js); the API and the inputs keep the dot.

import { setDecimal } from './format.js?v=__MM_ASSET_VERSION__';

export const LANGS = { en: 'English', cs: 'Čeština', de: 'Deutsch' };

export const EN = {
  skip_params: 'Skip to the parameters',
  skip_search: 'Skip to the search',
  where: 'Where this is in the book',
  contents: 'Contents',
  chapter_n: 'Chapter {n}',
  tagline: 'engineering mechanics by worked numerical examples',
  footer: 'engineering mechanics by worked numerical examples · SI units throughout',
  footer_catalog: 'SI units throughout · the answers come from',
  lede: 'Each exercise states a problem, explains the theory, and solves it numerically with the method of the chapter. Change the data and the solution, its plots and its checks against an independent reference follow at once.',
  search_label: 'Search the exercises',
  search_placeholder: 'title, topic, tag or id',
  search_title: 'Press / anywhere on the page to come here',
  count_all: '{n} exercises.',
  count_some: '{shown} of {n} exercises match “{q}”.',
  count_none: 'No exercise matches “{q}”.',
  contents_failed: 'The contents could not be loaded: {msg}',
  prefs: 'Display',
  language: 'Language',
  scheme: 'Colours',
  scheme_auto: 'automatic',
  scheme_light: 'light',
  scheme_dark: 'dark',
  scheme_projector: 'projector',
  parameters: 'Parameters',
  params_hint: 'Change a value: the answer follows as you type. Enter solves at once; ↑/↓ step a number (with Shift, ten times more).',
  reset: 'Reset to defaults',
  answer: 'Answer',
  results: 'Results',
  checks: 'Checks',
  method: 'Method',
  takeaway: 'Take it away',
  dl_csv: 'Series (CSV)',
  dl_svg: 'Figures (SVG)',
  dl_json: 'Answer (JSON)',
  copy: 'copy',
  copied: 'copied',
  copy_curl: 'Copy the curl command',
  theory: 'Theory',
  references: 'References',
  other_exercises: 'Other exercises',
  not_found: 'Exercise not found',
  no_id: 'No exercise was named in the address (?id=…). Choose one from the contents.',
  no_server: 'The server did not answer ({msg}).',
  no_meta: 'The server could not describe this exercise.',
  not_solved_field: 'Not solved: ',
  not_solved_check: 'check {param} ({label}).',
  not_solved_code: 'Not solved ({code}): ',
  stale_note: ' The answer below is for the last values that worked.',
  net_error: 'the server did not answer ({msg})',
  bad_answer: 'the server sent something that is not JSON (HTTP {status})',
  range_real: 'Range {lo} to {hi}{unit}.',
  range_integer: 'A whole number, {lo} to {hi}.',
  range_vector: 'Numbers separated by commas{most}; each {lo} to {hi}{unit}.',
  range_vector_most: ', at most {n}',
  range_matrix: 'MATLAB form: commas between numbers, ; between rows{most}.',
  range_matrix_most: ' (at most {r}×{c})',
  range_expression: 'An expression of {vars}, with + − * / ^ and sin, exp, sqrt, pi ….',
  the_variables: 'the variables',
  fig_n: 'Fig. {n}',
  against: '{y} against {x}',
  n_series: '{n} series',
  svg: 'SVG',
  data_table: 'Data table',
  data_every: 'Every {k}th of {n} points; the CSV download has them all.',
  data_all: 'All {n} points.',
  plot_reader: '{fig}: a cursor along the curves; ← → move it, Home and End go to the ends',
  kept_run: 'kept run',
  checks_failed: '{failed} of {n} checks failed: the numbers disagree with an independent reference.',
  checks_passed: 'All {n} checks passed: the numbers agree with an independent reference.',
  col_verdict: 'verdict',
  col_check: 'check',
  col_value: 'value / reference',
  col_error: 'error',
  col_tolerance: 'tolerance',
  passed: 'passed',
  failed: 'failed',
  rel: 'rel.',
  tol_relative: 'relative',
  tol_absolute: 'absolute',
  m_method: 'method',
  m_step: 'step',
  m_steps: 'steps',
  m_rejected: 'rejected steps',
  m_evaluations: 'function evaluations',
  m_error_estimate: 'error estimate',
  m_rtol: 'relative tolerance',
  m_atol: 'absolute tolerance',
  m_max_error: 'largest error',
  m_iterations: 'iterations',
  m_solved_in: 'solved in',
  exact: 'exact',
  err_bound: 'error bound',
  err_estimate: 'error estimate',
  keep: 'Keep this run',
  keep_hint: 'then change a value: both curves and both sets of numbers are shown',
  forget: 'Forget the kept run',
  kept_desc: 'Kept run: {desc}',
  kept: 'kept',
  print: 'Print the worked solution',
  announce: 'Answer: {list}.',
  announce_error: 'Not solved.',
  anim: 'Animation',
  play: 'Play',
  pause: 'Pause',
  anim_frame: 'Position in the animation',
  speed: 'Speed',
  loop: 'Loop',
  real_time: 'real time',
  slowed: '{x}× slower than real time',
  sped: '{x}× faster than real time',
  given: 'Given',
  col_param: 'parameter',
  col_symbol: 'symbol',
  col_value1: 'value',
  col_unit: 'unit',
  printed_from: 'Printed from {url}',
  open_in: 'Open in mechmat',
  skip_answers: 'Skip to the answers',
  assignment: 'Assignment',
  a_who: 'Who is solving it?',
  a_who_hint: 'Your variant of the assignment depends on the name or number your teacher gave you.',
  a_name: 'Assignment',
  a_student: 'Student',
  a_open: 'Open my variant',
  a_for: 'Variant of {student}',
  a_no_such: 'There is no assignment “{name}” in this course.',
  a_theory: 'The exercise and its theory',
  a_answers: 'Your answers',
  a_answers_hint: 'A number with its unit, e.g. 256.6 N, or in the unit given.',
  a_check: 'Check',
  a_print: 'Print the sheet',
  a_results: 'Checked',
  a_correct: 'correct',
  a_wrong: 'not correct',
  a_expected: 'expected {x}',
  a_quantity: 'quantity',
  a_given: 'your answer',
  a_expected_col: 'expected',
  a_tolerance: 'tolerance',
  a_verdict: 'verdict',
  a_note: 'note',
  a_score: 'Score {score} of {max}: {right} of {n} answers correct.',
  a_right: '{right} of {n} answers correct.',
  a_not_checked: 'Not checked:',
};

let lang = 'en';
let dict = EN;
let tr = { ui: {}, chapters: {}, sections: {}, exercises: {}, theory: [] };

/** The language the address or the browser asks for. */
export function chooseLang(search = location.search, langs = navigator.languages || [navigator.language || 'en']) {
  const asked = new URLSearchParams(search).get('lang');
  if (asked && LANGS[asked]) return asked;
  for (const l of langs) {
    const base = String(l).toLowerCase().split('-')[0];
    if (LANGS[base]) return base;
  }
  return 'en';
}

/** Load the chosen language's file (boot.js may have started it already). */
export async function initLang(preloaded) {
  lang = chooseLang();
  if (lang !== 'en') {
    try {
      const m = await (preloaded || import(`../i18n/${lang}.js?v=__MM_ASSET_VERSION__`));
      tr = { ui: {}, chapters: {}, sections: {}, exercises: {}, theory: [], ...m.default };
      dict = { ...EN, ...tr.ui };
    } catch {
      lang = 'en';
    }
  }
  document.documentElement.lang = lang;
  setDecimal(lang === 'en' ? '.' : ',');
  return lang;
}

export function currentLang() { return lang; }

/** An interface string, with {name} holes filled from vars. */
export function t(key, vars) {
  const s = dict[key] ?? EN[key] ?? key;
  return vars ? s.replace(/\{(\w+)\}/g, (m, k) => (k in vars ? String(vars[k]) : m)) : s;
}

/** Text that stays English on a page in another language: mark it so a
 *  screen reader pronounces it as English. */
export function english(node) {
  if (lang !== 'en' && node && node.setAttribute) node.setAttribute('lang', 'en');
  return node;
}

export function exerciseText(id, field, fallback) {
  const e = tr.exercises[id];
  return (e && e[field]) || fallback;
}
export function isTranslated(id, field) {
  const e = tr.exercises[id];
  return lang === 'en' || !!(e && e[field]);
}
export function paramText(id, name, field, fallback) {
  const e = tr.exercises[id];
  const p = e && e.params && e.params[name];
  return (p && p[field]) || fallback;
}
export function outputLabel(id, name, fallback) {
  const e = tr.exercises[id];
  return (e && e.outputs && e.outputs[name]) || fallback;
}
export function chapterTitle(n, fallback) { return tr.chapters[n] || fallback; }
export function sectionTitle(sec, fallback) { return tr.sections[sec] || fallback; }
export function hasTheory(id) { return lang !== 'en' && (tr.theory || []).includes(id); }

/** Fill the static page: elements with data-i18n get their text, and
 *  data-i18n-attr="aria-label:key;placeholder:key" their attributes. */
export function translateDocument(root = document) {
  if (lang === 'en') return;
  for (const e of root.querySelectorAll('[data-i18n]')) e.textContent = t(e.dataset.i18n);
  for (const e of root.querySelectorAll('[data-i18n-attr]')) {
    for (const pair of e.dataset.i18nAttr.split(';')) {
      const [attr, key] = pair.split(':');
      e.setAttribute(attr, t(key));
    }
  }
}

/** An address on this site that keeps the page-wide choices (language,
 *  colours) of the current one. */
export function siteUrl(path, params = {}) {
  const here = new URLSearchParams(location.search);
  const q = new URLSearchParams();
  for (const [k, v] of Object.entries(params)) if (v != null && v !== '') q.set(k, v);
  for (const k of ['lang', 'scheme']) if (here.get(k)) q.set(k, here.get(k));
  const s = q.toString().replace(/%2C/g, ',');
  return s ? `${path}?${s}` : path;
}
