// catalog.js — the book's contents from GET /api/exercises (boot.js has
// started the request), with a search box that filters as you type (title,
// summary, tags, id, section; in the page's language and in English).

import { el } from './format.js?v=__MM_ASSET_VERSION__';
import {
  initLang, t, english, translateDocument, exerciseText, chapterTitle, sectionTitle, siteUrl,
} from './i18n.js?v=__MM_ASSET_VERSION__';
import { wirePrefs } from './prefs.js?v=__MM_ASSET_VERSION__';

const $ = (s) => document.querySelector(s);
const boot = window.mmBoot || {};

function haystack(e) {
  return [e.id, e.section, e.title, e.summary, exerciseText(e.id, 'title', ''), exerciseText(e.id, 'summary', ''),
    e.section_title, sectionTitle(e.section, ''), ...(e.tags || [])].join(' \u0000 ').toLowerCase();
}

function render(list) {
  const toc = $('#toc');
  toc.textContent = '';
  const chapters = new Map();
  for (const e of list) {
    if (!chapters.has(e.chapter)) chapters.set(e.chapter, { n: e.chapter, title: e.chapter_title, items: [] });
    chapters.get(e.chapter).items.push(e);
  }
  for (const ch of chapters.values()) {
    const ol = el('ol', { class: 'exercises' });
    for (const e of ch.items) {
      const title = exerciseText(e.id, 'title', e.title), summary = exerciseText(e.id, 'summary', e.summary);
      const tt = el('span', { class: 'extitle', text: title }), sm = el('p', { class: 'exsummary', text: summary });
      if (title === e.title) english(tt);
      if (summary === e.summary) english(sm);
      ol.append(el('li', { class: 'exercise', 'data-id': e.id, 'data-search': haystack(e) },
        el('a', { href: siteUrl('exercise.html', { id: e.id }) },
          el('span', { class: 'secnum', text: e.section }), tt),
        sm,
        el('p', { class: 'exmeta' },
          el('code', { text: e.id }),
          (e.tags || []).map((tg) => english(el('span', { class: 'tag', text: tg }))))));
    }
    const chTitle = chapterTitle(ch.n, ch.title || '');
    const h = el('h2', {}, el('span', { class: 'chnum', text: t('chapter_n', { n: ch.n }) }), ' ', chTitle);
    toc.append(el('section', { class: 'chapter', id: `ch-${ch.n}`, 'data-chapter': ch.n }, h, ol));
  }
}

function filter(q) {
  const words = q.toLowerCase().split(/\s+/).filter(Boolean);
  let shown = 0, total = 0;
  for (const sec of document.querySelectorAll('.chapter')) {
    let any = false;
    for (const li of sec.querySelectorAll('.exercise')) {
      const hit = words.every((w) => li.dataset.search.includes(w));
      li.hidden = !hit;
      total++;
      if (hit) { shown++; any = true; }
    }
    sec.hidden = !any;
  }
  $('#count').textContent = words.length
    ? (shown ? t('count_some', { shown, n: total, q: q.trim() }) : t('count_none', { q: q.trim() }))
    : t('count_all', { n: total });
}

async function main() {
  await initLang(boot.dict);
  translateDocument();
  wirePrefs(() => {
    for (const a of document.querySelectorAll('#toc li.exercise > a')) a.href = siteUrl('exercise.html', { id: a.closest('li').dataset.id });
  });
  const q = $('#q');
  let list;
  try {
    const r = boot.catalog ? await boot.catalog : await fetch('api/exercises').then(async (x) => ({ ok: x.ok, body: await x.json() }));
    list = r.body;
    if (!r.ok) throw new Error(list.error ? list.error.message : 'HTTP error');
  } catch (e) {
    $('#toc').append(el('p', { class: 'answer-error', role: 'alert', text: t('contents_failed', { msg: e.message }) }));
    document.documentElement.dataset.ready = 'failed';
    return;
  }
  render(list);
  const initial = new URLSearchParams(location.search).get('q') || '';
  q.value = initial;
  filter(initial);
  q.addEventListener('input', () => {
    filter(q.value);
    const u = new URL(location.href);
    if (q.value.trim()) u.searchParams.set('q', q.value.trim()); else u.searchParams.delete('q');
    const s = u.searchParams.toString();
    history.replaceState(null, '', location.pathname + (s ? `?${s}` : '') + location.hash);
  });
  q.addEventListener('keydown', (e) => {
    if (e.key === 'Escape') { q.value = ''; q.dispatchEvent(new Event('input')); }
    if (e.key === 'Enter') {
      const first = document.querySelector('.exercise:not([hidden]) a');
      if (first) first.click();
    }
  });
  document.addEventListener('keydown', (e) => {
    if (e.key === '/' && document.activeElement !== q) { e.preventDefault(); q.focus(); }
  });
  document.documentElement.dataset.ready = 'true';
  if (location.hash) document.getElementById(location.hash.slice(1))?.scrollIntoView();
}

main();
