// catalog.js — the book's contents from GET /api/exercises, with a search
// box that filters as you type (title, summary, tags, id, section).

import { el, encodeValue } from './format.js';

const $ = (s) => document.querySelector(s);

function haystack(e) {
  return [e.id, e.section, e.title, e.summary, ...(e.tags || [])].join(' \u0000 ').toLowerCase();
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
      ol.append(el('li', { class: 'exercise', 'data-id': e.id, 'data-search': haystack(e) },
        el('a', { href: `/exercise.html?id=${encodeValue(e.id)}` },
          el('span', { class: 'secnum', text: e.section }),
          el('span', { class: 'extitle', text: e.title })),
        el('p', { class: 'exsummary', text: e.summary }),
        el('p', { class: 'exmeta' },
          el('code', { text: e.id }),
          (e.tags || []).map((t) => el('span', { class: 'tag', text: t })))));
    }
    toc.append(el('section', { class: 'chapter', id: `ch-${ch.n}`, 'data-chapter': ch.n },
      el('h2', {}, el('span', { class: 'chnum', text: `Chapter ${ch.n}` }), ' ', ch.title || ''), ol));
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
    ? (shown ? `${shown} of ${total} exercises match “${q.trim()}”.` : `No exercise matches “${q.trim()}”.`)
    : `${total} exercises.`;
}

async function main() {
  const q = $('#q');
  let list;
  try {
    const r = await fetch('/api/exercises');
    list = await r.json();
    if (!r.ok) throw new Error(list.error ? list.error.message : `HTTP ${r.status}`);
  } catch (e) {
    $('#toc').append(el('p', { class: 'answer-error', role: 'alert', text: `The contents could not be loaded: ${e.message}` }));
    return;
  }
  render(list);
  const initial = new URLSearchParams(location.search).get('q') || '';
  q.value = initial;
  filter(initial);
  q.addEventListener('input', () => {
    filter(q.value);
    const url = q.value.trim() ? `/?q=${encodeValue(q.value.trim())}` : '/';
    history.replaceState(null, '', url + location.hash);
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
