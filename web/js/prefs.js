// prefs.js — the page-wide choices in the header: language (the page is
// loaded again in it) and colour scheme (applied at once; onScheme redraws
// what is drawn in colours).  Both are kept in the address (?lang=, ?scheme=)
// so that a link or a bookmark keeps them; boot.js applies the scheme
// before the first paint.

import { el } from './format.js?v=__MM_ASSET_VERSION__';
import { t, currentLang, LANGS } from './i18n.js?v=__MM_ASSET_VERSION__';

function setParam(k, v) {
  const u = new URL(location.href);
  if (v) u.searchParams.set(k, v); else u.searchParams.delete(k);
  const s = u.searchParams.toString().replace(/%2C/g, ',');
  return u.pathname + (s ? `?${s}` : '') + u.hash;
}

export function wirePrefs(onScheme = () => {}) {
  const langSel = document.getElementById('pref-lang'), schemeSel = document.getElementById('pref-scheme');
  if (langSel) {
    for (const [k, name] of Object.entries(LANGS)) langSel.append(el('option', { value: k, text: name, lang: k, selected: k === currentLang() ? true : null }));
    langSel.addEventListener('change', () => location.replace(setParam('lang', langSel.value)));
  }
  if (schemeSel) {
    const cur = document.documentElement.dataset.scheme || '';
    for (const k of ['', 'light', 'dark', 'projector']) schemeSel.append(el('option', { value: k, text: t(`scheme_${k || 'auto'}`), selected: k === cur ? true : null }));
    schemeSel.addEventListener('change', () => {
      const v = schemeSel.value;
      if (v) document.documentElement.dataset.scheme = v; else delete document.documentElement.dataset.scheme;
      history.replaceState(history.state, '', setParam('scheme', v));
      onScheme(v);
    });
  }
  matchMedia('(prefers-color-scheme: dark)').addEventListener('change', () => onScheme(document.documentElement.dataset.scheme || ''));
}
