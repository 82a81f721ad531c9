// boot.js — the first script of a page, run in its head before anything
// else: it starts the requests the page will need (on an exercise page the
// solve and the metadata, on the contents the catalog) so that they travel
// while the modules load, and applies the colour scheme and the embed mode
// from the address before the first paint.  exercise.js and catalog.js pick
// the requests up from window.mmBoot.
(function () {
  'use strict';
  var q = new URLSearchParams(location.search);
  var html = document.documentElement;
  var scheme = q.get('scheme');
  if (scheme === 'light' || scheme === 'dark' || scheme === 'projector') html.setAttribute('data-scheme', scheme);
  if (q.get('embed')) html.setAttribute('data-embed', q.get('embed'));
  // the same encoding as format.js encodeValue: the query must match exactly
  function enc(s) {
    return encodeURIComponent(s)
      .replace(/[!'()*]/g, function (c) { return '%' + c.charCodeAt(0).toString(16).toUpperCase(); })
      .replace(/%2C/g, ',').replace(/%3B/g, ';').replace(/%2F/g, '/').replace(/%3A/g, ':');
  }
  var boot = window.mmBoot = {};
  var langs = ['en', 'cs', 'de'];
  var lang = q.get('lang');
  if (langs.indexOf(lang) < 0) {
    lang = 'en';
    var nav = navigator.languages || [navigator.language || 'en'];
    for (var i = 0; i < nav.length; i++) {
      var b = String(nav[i]).toLowerCase().split('-')[0];
      if (langs.indexOf(b) >= 0) { lang = b; break; }
    }
  }
  if (lang !== 'en') boot.dict = import('/i18n/' + lang + '.js');
  var id = q.get('id');
  if (/\/exercise\.html$/.test(location.pathname) && id) {
    var reserved = { id: 1, lang: 1, scheme: 1, embed: 1 };
    var parts = [];
    q.forEach(function (v, k) { if (!reserved[k]) parts.push(enc(k) + '=' + enc(v)); });
    var base = '/api/exercises/' + encodeURIComponent(id);
    boot.id = id;
    boot.query = parts.join('&');
    boot.solve = fetch(base + '/solve' + (boot.query ? '?' + boot.query : '')).then(function (r) {
      return r.text().then(function (text) { return { ok: r.ok, status: r.status, text: text }; });
    });
    boot.meta = fetch(base).then(function (r) {
      return r.json().then(function (body) { return { ok: r.ok, body: body }; });
    });
    // a rejected request is handled where it is used; do not report it twice
    boot.solve.catch(function () {});
    boot.meta.catch(function () {});
  } else if (location.pathname === '/' || /\/index\.html$/.test(location.pathname)) {
    boot.catalog = fetch('/api/exercises').then(function (r) {
      return r.json().then(function (body) { return { ok: r.ok, body: body }; });
    });
    boot.catalog.catch(function () {});
  }
})();
