// plot.js — an answer's series as textbook figures, in plain SVG.
//
//   planFigures(series, ctx)  which series share a figure, how each is drawn
//                             (the answer's figure hints first: figure, mark,
//                             role, x_scale, y_scale, aspect; then guesses),
//                             the names on the axes and in the legend (from
//                             the declared outputs, never internal names)
//   drawFigure(fig, width, o) one figure as an <svg>, with a cursor that
//                             reads values (pointer or keyboard) and a marker
//                             an animation moves
//   exportSvg / figureTable   the figure as a file, and as a table of numbers
//
// No library: the figures are drawn at the width they are shown, in the
// colours of the page's scheme, with tick labels measured so that nothing
// overlaps.  One colour per quantity across the figures of a page (a method
// keeps its colour in every figure), a reference dashed under the result.

import { fmtNumber, unitText, supText, escapeHtml, decimalSep } from './format.js?v=__MM_ASSET_VERSION__';

const SVGNS = 'http://www.w3.org/2000/svg';
const MINUS = '\u2212';

export const LIGHT = {
  ink: '#1d232a', muted: '#505a64', grid: '#e4e1da', axis: '#6b7580', zero: '#9aa3ad', bg: '#ffffff',
  palette: ['#1f5fa8', '#c0392b', '#2e7d32', '#7b3fa0', '#b36200', '#00838f', '#5d4037', '#ad1457'],
  reference: '#4a525b', fontSize: 12, lineWidth: 1.75, font: 'DejaVu Sans, Helvetica, Arial, sans-serif',
};

/** The figure colours of the page's scheme (CSS custom properties --plot-*). */
export function pageTheme() {
  const cs = getComputedStyle(document.documentElement);
  const v = (k, d) => (cs.getPropertyValue(k) || '').trim() || d;
  const palette = LIGHT.palette.map((c, i) => v(`--plot-${i + 1}`, c));
  return {
    ink: v('--plot-ink', LIGHT.ink), muted: v('--plot-muted', LIGHT.muted), grid: v('--plot-grid', LIGHT.grid),
    axis: v('--plot-axis', LIGHT.axis), zero: v('--plot-zero', LIGHT.zero), bg: v('--plot-bg', LIGHT.bg),
    reference: v('--plot-reference', LIGHT.reference), palette,
    fontSize: Number(v('--plot-font-size', '12')) || 12,
    lineWidth: Number(v('--plot-line-width', '1.75')) || 1.75,
    font: getComputedStyle(document.body).fontFamily || LIGHT.font,
  };
}

// ---- which series go together ------------------------------------------------------

const REF_NAME = /(_reference|_exact|_analytic|_closed_form)$/;
const DASHES = ['', '8 3', '3 2.5', '11 3 2 3', '1.5 2.5', '6 2 1.5 2'];

function familyKey(name, outputs) {
  const o = outputs && outputs.get(name);
  if (!o || !o.family) return name;
  const re = new RegExp('^' + o.family.replace(/[.*+?^${}()|[\]\\]/g, '\\$&').replace('%s', '(.+)').replace('%d', '(\\d+)') + '$');
  const m = name.match(re);
  return m ? `#${m[1]}` : name;
}

function monotonic(xs) {
  let up = true, down = true;
  for (let i = 1; i < xs.length; i++) {
    if (!(xs[i] > xs[i - 1])) up = false;
    if (!(xs[i] < xs[i - 1])) down = false;
  }
  return up || down;
}

function maxAbs(a) {
  let m = 0;
  for (const v of a) if (Number.isFinite(v) && Math.abs(v) > m) m = Math.abs(v);
  return m;
}

function span(a) {
  let lo = Infinity, hi = -Infinity;
  for (const v of a) if (Number.isFinite(v)) { if (v < lo) lo = v; if (v > hi) hi = v; }
  return hi >= lo ? [lo, hi] : [0, 0];
}

/** Split an unhinted group where its series live on scales too far apart to
 *  share an axis (a solution near 2000 beside singular values near 10), or
 *  over x ranges of which one is a zoom into the other. */
function splitByScale(items) {
  const main = items.filter((s) => s.role !== 'reference');
  // series over decades (errors against steps) share a log axis whatever their size
  if (main.length < 2 || wantsLog(main.map((s) => s.raw.x))) return [items];
  const clusters = [];
  for (const s of main) {
    const m = maxAbs(s.raw.y), [a, b] = span(s.raw.x);
    const c = clusters.find((c) => {
      const r = Math.max(m, c.m) / Math.max(Math.min(m, c.m), 1e-300);
      // a dense curve over a part of another's x range is a zoom into it
      const w1 = b - a, w2 = c.b - c.a;
      const inside = (a >= c.a && b <= c.b) || (c.a >= a && c.b <= b);
      const dense = s.raw.x.length >= 100 && c.items.every((q) => q.raw.x.length >= 100);
      const zoom = dense && inside && Math.min(w1, w2) > 0 && Math.max(w1, w2) > 2 * Math.min(w1, w2);
      return (r <= 30 || (m === 0 || c.m === 0)) && !zoom;
    });
    if (c) { c.items.push(s); c.m = Math.max(c.m, m); c.a = Math.min(c.a, a); c.b = Math.max(c.b, b); } else clusters.push({ items: [s], m, a, b });
  }
  if (clusters.length === 1) return [items];
  for (const r of items.filter((s) => s.role === 'reference')) {
    const partner = clusters.find((c) => c.items.some((s) => isPartner(r, s, main)));
    const [a, b] = span(r.raw.x);
    const near = partner || clusters.reduce((best, c) => {
      const d = Math.abs(Math.log(Math.max(maxAbs(r.raw.y), 1e-300) / Math.max(c.m, 1e-300))) + Math.abs(Math.log((b - a + 1e-300) / (c.b - c.a + 1e-300)));
      return !best || d < best.d ? { c, d } : best;
    }, null).c;
    near.items.push(r);
  }
  return clusters.map((c) => items.filter((s) => c.items.includes(s)));
}

function isPartner(ref, s, all) {
  const stem = ref.name.replace(REF_NAME, '');
  if (s.name === stem) return true;
  const like = (q) => stem !== ref.name && q.name.startsWith(stem) && q.name.length > stem.length && /[_\-]/.test(q.name[stem.length]);
  // x_exact is the reference of x_rk4 and x_dopri5 alike: of none in particular
  return like(s) && (!all || all.filter((q) => q.role !== 'reference' && like(q)).length === 1);
}

/** Whether two curves run on top of each other over a good part of their
 *  common x range: within 1.5 % of the y range at a third of 100 samples. */
function overlaps(a, b) {
  const [a0, a1] = span(a.x), [b0, b1] = span(b.x);
  const lo = Math.max(a0, b0), hi = Math.min(a1, b1);
  if (!(hi > lo) || !monotonic(a.x) || !monotonic(b.x)) return false;
  const [ya0, ya1] = span(a.y), [yb0, yb1] = span(b.y);
  const tol = 0.015 * (Math.max(ya1, yb1) - Math.min(ya0, yb0) || 1);
  let close = 0, n = 0;
  for (let k = 0; k <= 100; k++) {
    const x = lo + (hi - lo) * k / 100;
    const ya = interp(a.x, a.y, x), yb = interp(b.x, b.y, x);
    if (!Number.isFinite(ya) || !Number.isFinite(yb)) continue;
    n++;
    if (Math.abs(ya - yb) <= tol) close++;
  }
  return n > 0 && close >= n / 3;
}

function commonPrefix(strings) {
  let p = strings[0] || '';
  for (const t of strings) while (!t.startsWith(p)) p = p.slice(0, -1);
  return p;
}
function commonSuffix(strings) {
  const rev = (s) => [...s].reverse().join('');
  return rev(commonPrefix(strings.map(rev)));
}
const SEP = /[\s,;:(]/;
/** The longest common prefix that ends between words; when it holds a
 *  comma, only up to the last one ("|H|, zeta = 0.05" → "|H|"). */
function wordPrefix(labels) {
  let p = commonPrefix(labels);
  while (p && !labels.every((l) => l.length === p.length || SEP.test(l[p.length]))) p = p.slice(0, -1);
  p = p.replace(/[\s,;:(]+$/, '');
  const c = p.lastIndexOf(',');
  if (c > 0 && labels.every((l) => l.length > c + 1)) p = p.slice(0, c);
  return p;
}
function wordSuffix(labels) {
  let s = commonSuffix(labels);
  while (s && !labels.every((l) => l.length === s.length || SEP.test(l[l.length - s.length - 1]))) s = s.slice(1);
  return s.replace(/^[\s,;:)]+/, '');
}

/** The y quantity of a figure and each series' legend entry, from labels:
 *  "max error against evaluations, rk4" and "…, dopri5" give "max error"
 *  and "rk4", "dopri5"; "mass displacement" and "support displacement"
 *  give "displacement".  Never the internal names. */
export function figureNames(items) {
  const main = items.filter((s) => s.role !== 'reference');
  const base = main.length ? main : items;
  const labels = base.map((s) => s.label);
  let quantity = '', cut = (l) => l;
  if (labels.length === 1 || new Set(labels).size === 1) quantity = labels[0];
  else {
    const pre = wordPrefix(labels), suf = wordSuffix(labels);
    if (pre.length >= 4) {
      quantity = pre;
      // "mode shape 1" → "1" says too little: a bare number keeps its label
      cut = (l) => { const r = l.slice(pre.length).replace(/^[\s,;:]+/, ''); return r && !/^[\d.+\-−]+$/.test(r) ? r : l; };
    } else if (suf.length >= 4) {
      quantity = suf;
      cut = (l) => l.slice(0, l.length - suf.length).replace(/[\s,;:]+$/, '') || l;
    } else if (labels.join(', ').length <= 40) quantity = labels.join(', ');
  }
  quantity = quantity.replace(/\s+against\s+.*$/, '');
  const legend = items.map((s) => (base.includes(s) && base.length > 1 ? cut(s.label) || s.label : s.label));
  // two entries alike: say which output each is
  const seen = new Map();
  legend.forEach((l, i) => seen.set(l, (seen.get(l) || 0) + 1));
  return { quantity, legend: legend.map((l, i) => (seen.get(l) > 1 ? `${l} (${items[i].label})` : l)) };
}

/**
 * The figures of an answer.  ctx: {outputs: Map name → declared output,
 * label(name, fallback) → the label to show, colours: Map key → palette
 * index (kept by the page, so a quantity keeps its colour from answer to
 * answer), pinned: the kept run's series or null}.
 */
export function planFigures(series, ctx = {}) {
  const outputs = ctx.outputs || new Map();
  const colours = ctx.colours || new Map();
  const label = ctx.label || ((n, l) => l);
  const hinted = (series || []).some((s) => s.figure || s.role || s.mark || s.aspect || s.x_scale || s.y_scale);
  const items = (series || []).filter((s) => s.x && s.y && Math.min(s.x.length, s.y.length) > 0).map((s, i) => {
    const decl = outputs.get(s.name) || {};
    const role = s.role || (!hinted && REF_NAME.test(s.name) ? 'reference' : '');
    return {
      raw: s, name: s.name, order: i, role, mark: s.mark || '',
      // names and units as the exercise declares them (the answer repeats them)
      label: label(s.name, decl.label || s.label || s.name),
      ckey: familyKey(s.name, outputs),
      xLabel: decl.x_label || s.x_label || 'x', xUnit: decl.x_unit ?? s.x_unit ?? '', unit: decl.unit ?? s.unit ?? '',
    };
  });
  // groups: by the figure hint, else by the x quantity, its unit and the y unit
  const groups = new Map();
  for (const s of items) {
    const key = s.raw.figure ? `f:${s.raw.figure}` : `a:${s.xLabel}\u0000${s.xUnit}\u0000${s.unit}`;
    if (!groups.has(key)) groups.set(key, []);
    groups.get(key).push(s);
  }
  const figs = [];
  for (const [key, g] of groups) {
    const parts = key.startsWith('a:') ? splitByScale(g) : [g];
    parts.forEach((p, k) => figs.push(makeFigure(parts.length > 1 ? `${key}#${k}` : key, p, hinted, colours, ctx.pinned)));
  }
  return figs;
}

/** "average acceleration" in one figure is "newmark average acceleration"
 *  in another: whole words at the end or the start of a known name. */
function colourOfAlias(colours, key) {
  if (!key.startsWith('@')) return undefined;
  const w = key.slice(1).split('-');
  for (const [k, c] of colours) {
    if (!k.startsWith('@')) continue;
    const v = k.slice(1).split('-');
    const [a, b] = w.length <= v.length ? [w, v] : [v, w];
    if (a.join('-').length < 5 || a.length === b.length) continue;
    if (a.every((x, i) => x === b[i]) || a.every((x, i) => x === b[b.length - a.length + i])) return c;
  }
  return undefined;
}
function nextColour(colours) {
  return colours.size ? Math.max(...colours.values()) + 1 : 0;
}

function makeFigure(key, items, hinted, colours, pinned) {
  const first = items[0];
  const fig = {
    key, items, xLabel: first.xLabel, xUnit: first.xUnit, unit: first.unit,
    xScale: items.map((s) => s.raw.x_scale).find(Boolean) || '',
    yScale: items.map((s) => s.raw.y_scale).find(Boolean) || '',
    aspect: items.map((s) => s.raw.aspect).find(Boolean) || '',
  };
  if (!hinted && !fig.aspect) {
    // a path in a plane: the same unit both ways and x not in order (a
    // Lissajous figure), or the complex plane
    const planar = fig.xUnit === fig.unit && items.some((s) => s.raw.x.length > 2 && !monotonic(s.raw.x));
    if (planar || /^(re|real part)$/i.test(fig.xLabel)) fig.aspect = 'equal';
  }
  const names = figureNames(items);
  fig.quantity = names.quantity;
  items.forEach((s, i) => { s.legend = names.legend[i]; });
  // marks: the hint, else dots for sparse data, lines for curves
  const counts = items.map((s) => Math.min(s.raw.x.length, s.raw.y.length));
  const most = Math.max(...counts);
  items.forEach((s, k) => {
    if (s.mark) return;
    const n = counts[k];
    const sparse = n <= 40 || most >= 4 * n;
    s.mark = !sparse ? 'line' : (monotonic(s.raw.x) && most <= 40 ? 'line+dots' : 'dots');
  });
  // colours: one per quantity across the page; a reference takes its
  // partner's, or the neutral ink when it is the reference of many
  // the key of a colour: a family's member key, else what the legend calls
  // the series ("rk4" in the error figure and in the energy figure alike)
  // (alone in its figure, a series is named by the last part of its label:
  // "relative energy error, RK4" is RK4's)
  const norm = (t) => `@${t.toLowerCase().split(/[^\p{L}\p{N}.=]+/u).filter(Boolean).join('-')}`;
  for (const s of items) {
    if (s.ckey.startsWith('#')) continue;
    s.ckey = items.length > 1 ? norm(s.legend) : s.label.includes(', ') ? norm(s.label.slice(s.label.lastIndexOf(', ') + 2)) : s.name;
  }
  const used = new Set();
  const mains = items.filter((s) => s.role !== 'reference');
  for (const s of mains) {
    if (!colours.has(s.ckey)) colours.set(s.ckey, colourOfAlias(colours, s.ckey) ?? nextColour(colours));
    let c = colours.get(s.ckey);
    while (used.has(c % 8) && used.size < 8) c++;
    used.add(c % 8);
    s.colour = c % 8;
  }
  // a curve that lies on an earlier one is dashed, so that both stay in sight
  const lineMains = mains.filter((s) => s.mark.includes('line') || s.mark === 'step');
  let nd = 0;
  lineMains.forEach((s, j) => {
    s.dash = lineMains.slice(0, j).some((q) => overlaps(q.raw, s.raw)) ? DASHES[1 + (nd++ % (DASHES.length - 1))] : '';
  });
  for (const s of items.filter((x) => x.role === 'reference')) {
    const partner = mains.find((m) => isPartner(s, m, mains));
    s.colour = partner ? partner.colour : -1;
    s.dash = '7 4';
  }
  // the kept run: the same series of the kept answer
  fig.pinned = [];
  if (pinned) {
    for (const s of items) {
      const p = pinned.find((q) => q.name === s.name);
      if (p) fig.pinned.push({ raw: p, name: s.name, colour: s.colour, legend: s.legend, mark: s.mark, role: s.role });
    }
  }
  fig.linkedX = true;
  return fig;
}

// ---- axes ---------------------------------------------------------------------------

function niceStep(spanv, count) {
  const raw = spanv / Math.max(1, count);
  const mag = 10 ** Math.floor(Math.log10(raw));
  const r = raw / mag;
  return (r >= 7.071 ? 10 : r >= 3.162 ? 5 : r >= 1.414 ? 2 : 1) * mag;
}

function locNum(s) {
  const d = decimalSep();
  return s.replace('-', MINUS).replace('.', d);
}

/** A linear axis over [lo, hi]: ticks on a 1-2-5 step, a power of ten (a
 *  multiple of 3) moved into the label, decimals only as the step needs
 *  (none for whole numbers). */
function linearAxis(lo, hi, count, { nice = true, integer = false } = {}) {
  if (!(Number.isFinite(lo) && Number.isFinite(hi))) { lo = 0; hi = 1; }
  // a flat series (equal values, or equal but for round-off: 84.40971508067067
  // and …068) gets a range around its value; a step of 1e-15 beside 84 would
  // count ticks past 2^53, where i++ no longer moves
  if (hi - lo <= 1e-9 * Math.max(Math.abs(lo), Math.abs(hi))) {
    const mid = (lo + hi) / 2;
    const d = mid === 0 ? 1 : Math.abs(mid) * 0.1;
    lo = mid - d; hi = mid + d;
  }
  let step = niceStep(hi - lo, count);
  if (integer && step < 1) step = 1;
  let a = lo, b = hi;
  if (nice) { a = Math.floor(lo / step + 1e-9) * step; b = Math.ceil(hi / step - 1e-9) * step; }
  const ticks = [];
  const i0 = Math.ceil(a / step - 1e-9), i1 = Math.min(Math.floor(b / step + 1e-9), i0 + 100);
  for (let i = i0; i <= i1; i++) ticks.push(Number((i * step).toPrecision(12)));
  const m = Math.max(Math.abs(a), Math.abs(b));
  let exp = 0;
  if (m > 0 && (m >= 1e4 || m < 1e-2)) exp = 3 * Math.floor(Math.log10(m) / 3);
  const k = 10 ** exp;
  const dec = Math.max(0, -Math.floor(Math.log10(step / k) + 1e-9));
  const format = (v) => locNum((Math.abs(v / k) < 1e-12 * (step / k) ? 0 : v / k).toFixed(dec));
  return { type: 'linear', domain: [a, b], ticks, exp, format, step };
}

/** A logarithmic axis: whole decades labelled 10ⁿ, or 1-2-5 steps within a decade or two. */
function logAxis(lo, hi, count, nice) {
  let a = lo, b = hi;
  if (!(a > 0)) a = b > 0 ? b / 10 : 1;
  if (!(b > a)) b = a * 10;
  if (nice) { a = 10 ** Math.floor(Math.log10(a) + 1e-9); b = 10 ** Math.ceil(Math.log10(b) - 1e-9); }
  const decades = Math.log10(b / a);
  let ticks, format;
  if (decades >= 1.5) {
    const k0 = Math.ceil(Math.log10(a) - 1e-9), k1 = Math.floor(Math.log10(b) + 1e-9);
    const every = Math.max(1, Math.ceil((k1 - k0 + 1) / count));
    ticks = [];
    for (let k = k0; k <= k1; k++) if ((k - k0) % every === 0) ticks.push(10 ** k);
    format = (v) => `10${supText(Math.round(Math.log10(v)))}`;
  } else {
    ticks = [];
    for (let k = Math.floor(Math.log10(a)); k <= Math.ceil(Math.log10(b)); k++) {
      for (const m of [1, 2, 5]) { const v = m * 10 ** k; if (v >= a * (1 - 1e-9) && v <= b * (1 + 1e-9)) ticks.push(Number(v.toPrecision(12))); }
    }
    if (ticks.length < 3) {
      ticks = [];
      for (let k = Math.floor(Math.log10(a)); k <= Math.ceil(Math.log10(b)); k++) {
        for (let m = 1; m <= 9; m++) { const v = m * 10 ** k; if (v >= a * (1 - 1e-9) && v <= b * (1 + 1e-9)) ticks.push(Number(v.toPrecision(12))); }
      }
    }
    format = (v) => fmtNumber(v, 3).uni;
  }
  return { type: 'log', domain: [a, b], ticks, exp: 0, format };
}

/** Whether values (all > 0) read better on a log scale: over two decades,
 *  or in geometric steps (step sizes halved, say) over about one. */
function wantsLog(arrays) {
  let lo = Infinity, hi = -Infinity, geometric = true, n = 0;
  for (const v of arrays) {
    for (const x of v) { if (!(x > 0)) return false; if (x < lo) lo = x; if (x > hi) hi = x; }
    if (v.length >= 3) {
      n++;
      const r = v.slice(1).map((x, i) => x / v[i]);
      const r0 = r[0];
      if (!(Math.abs(r0 - 1) > 0.2) || r.some((q) => Math.abs(Math.log(q / r0)) > 0.25)) geometric = false;
    }
  }
  return hi / lo >= 100 || (geometric && n > 0 && hi / lo >= 8);
}

function axisLabel(quantity, unit, exp) {
  const scale = exp ? `10${supText(exp)}` : '';
  const u = [scale, unitText(unit)].filter(Boolean).join(' ');
  return u ? (quantity ? `${quantity} [${u}]` : `[${u}]`) : quantity;
}

let measureCtx = null;
const widthCache = new Map();
/** The width of a text in the figure's font, measured (not guessed). */
export function textWidth(s, fontSize, font) {
  const key = `${fontSize}|${font}|${s}`;
  let w = widthCache.get(key);
  if (w === undefined) {
    if (!measureCtx) measureCtx = document.createElement('canvas').getContext('2d');
    measureCtx.font = `${fontSize}px ${font}`;
    w = measureCtx.measureText(String(s)).width;
    if (widthCache.size > 5000) widthCache.clear();
    widthCache.set(key, w);
  }
  return w;
}

// ---- drawing ------------------------------------------------------------------------

const r1 = (v) => Math.round(v * 10) / 10;

function seriesPoints(s, fx, fy, logX, logY) {
  const out = [];
  const n = Math.min(s.x.length, s.y.length);
  for (let i = 0; i < n; i++) {
    const x = s.x[i], y = s.y[i];
    if (!Number.isFinite(x) || !Number.isFinite(y) || (logX && !(x > 0)) || (logY && !(y > 0))) { out.push(null); continue; }
    out.push([fx(x), fy(y)]);
  }
  return out;
}

function linePath(pts, step) {
  let d = '', pen = false, prev = null;
  for (const p of pts) {
    if (!p) { pen = false; continue; }
    if (!pen) { d += `M${r1(p[0])},${r1(p[1])}`; pen = true; } else if (step) d += `H${r1(p[0])}V${r1(p[1])}`;
    else d += `L${r1(p[0])},${r1(p[1])}`;
    prev = p;
  }
  return prev ? d : '';
}

function attrs(o) {
  let s = '';
  for (const [k, v] of Object.entries(o)) if (v !== '' && v != null) s += ` ${k}="${escapeHtml(String(v))}"`;
  return s;
}

function legendLayout(entries, maxWidth, fs, font) {
  const pos = [];
  let x = 0, row = 0;
  for (const e of entries) {
    const w = 28 + textWidth(e.text, fs, font) + 16;
    if (x > 0 && x + w > maxWidth) { row++; x = 0; }
    pos.push({ x, row });
    x += w;
  }
  return { pos, rows: entries.length ? row + 1 : 0 };
}

/**
 * One figure as an <svg> `width` px wide.  o: {theme, title, maxHeight,
 * pinnedLabel, mark: t for the animation's marker}.  Returns a view:
 * {svg, fig, width, height, cursorAt(px, py), cursorIndex(i), clearCursor(),
 * setMarker(t), xOf(px), readout(i), master}.
 */
export function drawFigure(fig, width, o = {}) {
  const th = o.theme || LIGHT;
  const fs = th.fontSize, font = th.font, lw = th.lineWidth;
  const all = [...fig.pinned.map((p) => p.raw), ...fig.items.map((s) => s.raw)];
  const xs = [], ys = [];
  for (const s of all) { xs.push(s.x); ys.push(s.y); }
  let [xlo, xhi] = span(xs.flat()), [ylo, yhi] = span(ys.flat());
  const logX = fig.xScale ? fig.xScale === 'log' : fig.aspect !== 'equal' && wantsLog(xs);
  const logY = fig.yScale ? fig.yScale === 'log' : logX && fig.aspect !== 'equal' && wantsLog(ys);
  if (logX) [xlo, xhi] = span(xs.flat().filter((v) => v > 0));
  if (logY) [ylo, yhi] = span(ys.flat().filter((v) => v > 0));
  const anyDots = fig.items.some((s) => s.mark.includes('dots') || s.mark === 'bars');
  const bars = fig.items.some((s) => s.mark === 'bars');
  const pad = (lo, hi, f) => (hi > lo ? [lo - f * (hi - lo), hi + f * (hi - lo)] : [lo, hi]);
  if (bars && !logY) { ylo = Math.min(0, ylo); yhi = Math.max(0, yhi); }
  if (!logY && anyDots && !bars) [ylo, yhi] = pad(ylo, yhi, 0.04);
  const padX = !logX && (anyDots || bars);       // no dot or bar cut by the frame
  if (padX) [xlo, xhi] = pad(xlo, xhi, bars ? 0.03 : 0.04);
  const intX = !logX && xs.every((a) => a.every(Number.isInteger));
  const intY = !logY && ys.every((a) => a.every(Number.isInteger));

  // the legend: one entry per series, and one for the kept run
  const entries = fig.items.map((s) => ({ text: s.legend, s }));
  if (fig.pinned.length) entries.push({ text: o.pinnedLabel || 'kept run', kept: true });
  const showLegend = entries.length > 1;
  const legend = showLegend ? legendLayout(entries, width - 16, fs, font) : { pos: [], rows: 0 };
  const lh = Math.round(fs * 1.5);

  const narrow = width < 520;
  let height = Math.round(Math.max(200, Math.min(400 * fs / 12, width * (narrow ? 0.72 : 0.42))));
  if (o.maxHeight) height = Math.min(height, o.maxHeight);
  height = Math.max(height, 150) + legend.rows * lh;
  const top = 10 + legend.rows * lh + (showLegend ? 4 : 0);
  const bottom = Math.round(fs * 2 + 20);
  const right = 14;

  // axes: equal aspect fixes data units per pixel both ways
  let xa, ya, left, iw, ih;
  const xCountFor = (w) => Math.max(2, Math.round(w / (fs * 7.5)));
  const yCountFor = (h) => Math.max(2, Math.round(h / (fs * 4)));
  const makeY = (lo, hi, h, nice) => (logY ? logAxis(lo, hi, yCountFor(h), true) : linearAxis(lo, hi, yCountFor(h), { nice, integer: intY }));
  const makeX = (lo, hi, w, nice) => (logX ? logAxis(lo, hi, xCountFor(w), false) : linearAxis(lo, hi, xCountFor(w), { nice, integer: intX }));
  const leftFor = (axis) => Math.ceil(Math.max(...axis.ticks.map((t) => textWidth(axis.format(t), fs, font)), fs) + 7 + fs * 1.2 + 10);
  if (fig.aspect === 'equal' && !logX && !logY) {
    [xlo, xhi] = pad(xlo, xhi, 0.05);
    [ylo, yhi] = pad(ylo, yhi, 0.05);
    if (xhi === xlo) { xlo -= 1; xhi += 1; }
    if (yhi === ylo) { ylo -= 1; yhi += 1; }
    const maxIh = (o.maxHeight ? o.maxHeight : Math.min(width * 0.9, 560)) - top - bottom;
    const minIh = Math.min(160, maxIh);
    left = 50;
    for (let pass = 0; pass < 2; pass++) {
      iw = width - left - right;
      let X = xhi - xlo, Y = yhi - ylo;
      ih = iw * Y / X;
      let x0 = xlo, x1 = xhi, y0 = ylo, y1 = yhi;
      if (ih > maxIh) { ih = maxIh; const X2 = Y * iw / ih; x0 = (xlo + xhi) / 2 - X2 / 2; x1 = x0 + X2; } else if (ih < minIh) { ih = minIh; const Y2 = X * ih / iw; y0 = (ylo + yhi) / 2 - Y2 / 2; y1 = y0 + Y2; }
      ya = linearAxis(y0, y1, yCountFor(ih), { nice: false });
      xa = linearAxis(x0, x1, xCountFor(iw), { nice: false });
      // the same tick step both ways, so that squares look square
      const stp = Math.max(xa.step, ya.step);
      if (xa.exp === ya.exp) {
        xa = linearAxis(x0, x1, Math.max(1, (x1 - x0) / stp), { nice: false });
        ya = linearAxis(y0, y1, Math.max(1, (y1 - y0) / stp), { nice: false });
      }
      xa.domain = [x0, x1]; ya.domain = [y0, y1];
      xa.ticks = xa.ticks.filter((t) => t >= x0 - 1e-9 * X && t <= x1 + 1e-9 * X);
      ya.ticks = ya.ticks.filter((t) => t >= y0 - 1e-9 * Y && t <= y1 + 1e-9 * Y);
      left = leftFor(ya);
    }
    height = Math.round(top + ih + bottom);
  } else {
    ih = height - top - bottom;
    ya = makeY(ylo, yhi, ih, true);
    left = leftFor(ya);
    iw = width - left - right;
    xa = makeX(xlo, xhi, iw, false);
    if (!logX && xlo < xhi) {                        // x: the data's span, ticks inside it
      xa.domain = [xlo, xhi];
      const eps = (xhi - xlo) * 1e-9;
      xa.ticks = xa.ticks.filter((t) => t >= xlo - eps && t <= xhi + eps);
    }
  }
  const [xd0, xd1] = xa.domain, [yd0, yd1] = ya.domain;
  const lx0 = logX ? Math.log10(xd0) : xd0, lx1 = logX ? Math.log10(xd1) : xd1;
  const ly0 = logY ? Math.log10(yd0) : yd0, ly1 = logY ? Math.log10(yd1) : yd1;
  const fx = (v) => left + ((logX ? Math.log10(v) : v) - lx0) / (lx1 - lx0 || 1) * iw;
  const fy = (v) => top + ih - ((logY ? Math.log10(v) : v) - ly0) / (ly1 - ly0 || 1) * ih;
  const invx = (px) => { const l = lx0 + (px - left) / iw * (lx1 - lx0); return logX ? 10 ** l : l; };

  let g = '';
  // grid and axes
  g += '<g class="mm-grid">';
  for (const t of ya.ticks) g += `<line x1="${left}" x2="${left + iw}" y1="${r1(fy(t))}" y2="${r1(fy(t))}" stroke="${th.grid}"/>`;
  if (fig.aspect === 'equal') for (const t of xa.ticks) g += `<line y1="${top}" y2="${top + ih}" x1="${r1(fx(t))}" x2="${r1(fx(t))}" stroke="${th.grid}"/>`;
  g += '</g>';
  if (!logY && yd0 < 0 && yd1 > 0) g += `<line class="mm-zero" x1="${left}" x2="${left + iw}" y1="${r1(fy(0))}" y2="${r1(fy(0))}" stroke="${th.zero}"/>`;
  if (fig.aspect === 'equal' && !logX && xd0 < 0 && xd1 > 0) g += `<line class="mm-zero" y1="${top}" y2="${top + ih}" x1="${r1(fx(0))}" x2="${r1(fx(0))}" stroke="${th.zero}"/>`;
  g += `<g class="mm-axis" fill="${th.ink}" font-size="${fs}">`;
  g += `<line x1="${left}" x2="${left + iw}" y1="${top + ih}" y2="${top + ih}" stroke="${th.axis}"/>`;
  g += `<line x1="${left}" x2="${left}" y1="${top}" y2="${top + ih}" stroke="${th.axis}"/>`;
  for (const t of xa.ticks) {
    const x = r1(fx(t));
    g += `<line x1="${x}" x2="${x}" y1="${top + ih}" y2="${top + ih + 5}" stroke="${th.axis}"/>`;
    g += `<text class="mm-xtick" x="${x}" y="${top + ih + 7 + fs * 0.8}" text-anchor="middle">${escapeHtml(xa.format(t))}</text>`;
  }
  for (const t of ya.ticks) {
    const y = r1(fy(t));
    g += `<line x1="${left - 5}" x2="${left}" y1="${y}" y2="${y}" stroke="${th.axis}"/>`;
    g += `<text class="mm-ytick" x="${left - 7}" y="${y}" dy="0.32em" text-anchor="end">${escapeHtml(ya.format(t))}</text>`;
  }
  const xl = axisLabel(fig.xLabel, fig.xUnit, xa.exp), yl = axisLabel(fig.quantity, fig.unit, ya.exp);
  g += `<text class="mm-xlabel" x="${r1(left + iw / 2)}" y="${height - 5}" text-anchor="middle">${escapeHtml(xl)}</text>`;
  g += `<text class="mm-ylabel" transform="translate(${r1(fs * 0.95)},${r1(top + ih / 2)}) rotate(-90)" text-anchor="middle">${escapeHtml(yl)}</text>`;
  g += '</g>';

  // series: the kept run under the references under the results
  const colourOf = (s) => (s.colour >= 0 ? th.palette[s.colour % th.palette.length] : th.reference);
  const drawOne = (s, raw, kind) => {
    const pts = seriesPoints(raw, fx, fy, logX, logY);
    const c = colourOf(s);
    let out = '';
    const cls = `mm-series${kind ? ' mm-' + kind : ''}`;
    const data = ` data-series="${escapeHtml(s.name)}"`;
    if (s.mark === 'bars') {
      const xsPx = pts.filter(Boolean).map((p) => p[0]).sort((a, b) => a - b);
      let gap = iw;
      for (let i = 1; i < xsPx.length; i++) gap = Math.min(gap, xsPx[i] - xsPx[i - 1]);
      const bw = Math.max(1, Math.min(gap * 0.7, 14));
      const y0 = logY ? top + ih : fy(Math.max(yd0, Math.min(yd1, 0)));
      out += `<g class="${cls}"${data} fill="${c}"${kind === 'kept' ? ' fill-opacity="0.35"' : ''}>`;
      for (const p of pts) if (p) out += `<rect x="${r1(p[0] - bw / 2)}" y="${r1(Math.min(p[1], y0))}" width="${r1(bw)}" height="${r1(Math.max(0.5, Math.abs(y0 - p[1])))}"/>`;
      return out + '</g>';
    }
    if (s.mark.includes('line') || s.mark === 'step') {
      const d = linePath(pts, s.mark === 'step');
      const w = kind === 'reference' ? lw * 1.6 : kind === 'kept' ? lw * 0.9 : lw;
      const dash = kind === 'kept' ? '1.5 3' : s.dash;
      out += `<path class="${cls}"${data}${attrs({ d, fill: 'none', stroke: c, 'stroke-width': r1(w), 'stroke-dasharray': dash, 'stroke-opacity': kind === 'reference' ? 0.75 : kind === 'kept' ? 0.8 : '', 'stroke-linejoin': 'round', 'stroke-linecap': kind === 'kept' ? 'round' : '' })}/>`;
    }
    if (s.mark.includes('dots')) {
      out += `<g class="${cls} mm-dots"${data} stroke="${c}" fill="${c}" fill-opacity="${kind === 'kept' ? 0.08 : 0.25}" stroke-width="1.25"${kind === 'kept' ? ' stroke-dasharray="1.5 1.5"' : ''}>`;
      for (const p of pts) if (p) out += `<circle cx="${r1(p[0])}" cy="${r1(p[1])}" r="${kind === 'kept' ? 4 : 3}"/>`;
      out += '</g>';
    }
    return out;
  };
  g += '<g class="mm-plotarea">';
  for (const p of fig.pinned) g += drawOne(p, p.raw, 'kept');
  for (const s of fig.items) if (s.role === 'reference') g += drawOne(s, s.raw, 'reference');
  for (const s of fig.items) if (s.role !== 'reference') g += drawOne(s, s.raw, '');
  g += '</g>';

  // legend, inside the SVG so that an exported figure keeps it
  if (showLegend) {
    g += `<g class="mm-legend" font-size="${fs}" fill="${th.ink}">`;
    entries.forEach((e, i) => {
      const { x, row } = legend.pos[i];
      const X = 8 + x, Y = 10 + row * lh;
      if (e.kept) g += `<line x1="${X}" x2="${X + 22}" y1="${Y}" y2="${Y}" stroke="${th.ink}" stroke-width="${lw}" stroke-dasharray="1.5 3" stroke-linecap="round"/>`;
      else {
        const s = e.s, c = colourOf(s);
        if (s.mark === 'bars') g += `<rect x="${X + 6}" y="${Y - 5}" width="10" height="10" fill="${c}"/>`;
        if (s.mark.includes('line') || s.mark === 'step') g += `<line x1="${X}" x2="${X + 22}" y1="${Y}" y2="${Y}"${attrs({ stroke: c, 'stroke-width': r1(s.role === 'reference' ? lw * 1.6 : lw + 0.5), 'stroke-dasharray': s.dash, 'stroke-opacity': s.role === 'reference' ? 0.75 : '' })}/>`;
        if (s.mark.includes('dots')) g += `<circle cx="${X + 11}" cy="${Y}" r="3" stroke="${c}" fill="${c}" fill-opacity="0.25" stroke-width="1.25"/>`;
      }
      g += `<text x="${X + 28}" y="${Y}" dy="0.32em">${escapeHtml(e.text)}</text>`;
    });
    g += '</g>';
  }
  g += `<g class="mm-marker" visibility="hidden"><line y1="${top}" y2="${top + ih}" stroke="${th.ink}" stroke-width="1.5"/></g>`;
  g += `<g class="mm-cursor" visibility="hidden"></g>`;

  const svg = document.createElementNS(SVGNS, 'svg');
  svg.setAttribute('width', width);
  svg.setAttribute('height', height);
  svg.setAttribute('viewBox', `0 0 ${width} ${height}`);
  svg.setAttribute('class', 'mm-plot');
  svg.setAttribute('role', 'img');
  svg.setAttribute('font-family', font);
  svg.setAttribute('font-size', fs);
  if (o.title) svg.setAttribute('aria-label', o.title);
  svg.dataset.scales = `${logX ? 'log' : 'linear'},${logY ? 'log' : 'linear'}`;
  if (fig.aspect === 'equal') svg.dataset.aspect = `${r1((xd1 - xd0) / iw * 1e6)}:${r1((yd1 - yd0) / ih * 1e6)}`;
  svg.innerHTML = g;

  // the cursor follows one series (the longest result), the others by nearest x
  const mains = fig.items.filter((s) => s.role !== 'reference');
  const master = (mains.length ? mains : fig.items).reduce((a, b) => (b.raw.x.length > a.raw.x.length ? b : a));
  const sorted = (s) => s._mono ?? (s._mono = monotonic(s.raw.x) ? (s.raw.x[0] <= s.raw.x[s.raw.x.length - 1] ? 1 : -1) : 0);
  const nearestX = (s, x) => {
    const a = s.raw.x, n = a.length;
    if (!n) return -1;
    if (sorted(s)) {
      let lo = 0, hi = n - 1;
      const up = sorted(s) > 0;
      while (hi - lo > 1) { const mid = (lo + hi) >> 1; if ((a[mid] < x) === up) lo = mid; else hi = mid; }
      return Math.abs(a[lo] - x) <= Math.abs(a[hi] - x) ? lo : hi;
    }
    let best = 0;
    for (let i = 1; i < n; i++) if (Math.abs(a[i] - x) < Math.abs(a[best] - x)) best = i;
    return best;
  };
  const nearestXY = (s, px, py) => {
    let best = -1, bd = Infinity;
    for (let i = 0; i < Math.min(s.raw.x.length, s.raw.y.length); i++) {
      const d = (fx(s.raw.x[i]) - px) ** 2 + (fy(s.raw.y[i]) - py) ** 2;
      if (d < bd) { bd = d; best = i; }
    }
    return best;
  };
  const xu = fig.xUnit ? ` ${unitText(fig.xUnit)}` : '', yu = fig.unit ? ` ${unitText(fig.unit)}` : '';
  const cursorG = svg.querySelector('.mm-cursor'), markerG = svg.querySelector('.mm-marker');

  const view = {
    svg, fig, width, height, master, left, top, iw, ih, fx, fy,
    xOf: (px) => invx(Math.max(left, Math.min(left + iw, px))),
    inPlot: (px, py) => px >= left - 4 && px <= left + iw + 4 && py >= top - 4 && py <= top + ih + 4,
    /** The values at point i of the master series: [{label, x, y, s}]. */
    pointsAt(i) {
      const x = master.raw.x[i];
      const out = [];
      for (const s of fig.items) {
        const j = s === master ? i : sorted(s) ? nearestX(s, x) : -1;
        if (j >= 0 && Number.isFinite(s.raw.y[j])) out.push({ s, x: s.raw.x[j], y: s.raw.y[j], j });
      }
      return out;
    },
    readout(i) {
      const x = master.raw.x[i];
      const lines = [`${fig.xLabel} = ${fmtNumber(x).uni}${xu}`];
      for (const p of this.pointsAt(i)) {
        const name = fig.items.length > 1 ? p.s.legend : (fig.quantity || p.s.legend);
        lines.push(`${name} = ${fmtNumber(p.y).uni}${yu}`);
      }
      return lines;
    },
    /** Show the cursor at point i of the master series; returns the readout lines. */
    cursorIndex(i) {
      i = Math.max(0, Math.min(master.raw.x.length - 1, i));
      view.index = i;
      const pts = this.pointsAt(i);
      const x = fx(master.raw.x[i]);
      let h = `<line x1="${r1(x)}" x2="${r1(x)}" y1="${top}" y2="${top + ih}" stroke="${th.muted}" stroke-dasharray="3 3"/>`;
      for (const p of pts) {
        if ((logY && !(p.y > 0)) || (logX && !(p.x > 0))) continue;
        h += `<circle cx="${r1(fx(p.x))}" cy="${r1(fy(p.y))}" r="3.5" fill="${colourOf(p.s)}" stroke="${th.bg}" stroke-width="1.5"/>`;
      }
      const lines = this.readout(i);
      const tw = Math.max(...lines.map((l) => textWidth(l, fs, font))) + 12, tlh = fs * 1.3, tht = lines.length * tlh + 8;
      let tx = x + 10, ty = top + 4;
      if (tx + tw > width - 2) tx = x - 10 - tw;
      if (tx < 2) tx = 2;
      if (pts.length) { const py = fy(pts[0].y); ty = Math.min(top + ih - tht, Math.max(top, py - tht - 8)); if (!Number.isFinite(ty)) ty = top; }
      h += `<g class="mm-tip"><rect x="${r1(tx)}" y="${r1(ty)}" width="${r1(tw)}" height="${r1(tht)}" rx="4" fill="${th.bg}" fill-opacity="0.94" stroke="${th.axis}"/>`;
      lines.forEach((l, k) => { h += `<text x="${r1(tx + 6)}" y="${r1(ty + 4 + tlh * (k + 0.5))}" dy="0.32em" fill="${th.ink}">${escapeHtml(l)}</text>`; });
      h += '</g>';
      cursorG.innerHTML = h;
      cursorG.setAttribute('visibility', 'visible');
      return lines;
    },
    cursorAt(px, py) {
      if (!sorted(master)) return this.cursorIndex(nearestXY(master, px, py));
      return this.cursorIndex(nearestX(master, invx(px)));
    },
    indexOfX(x) { return nearestX(master, x); },
    clearCursor() { cursorG.setAttribute('visibility', 'hidden'); cursorG.textContent = ''; view.index = -1; },
    /** The animation's marker at x = t: a line and a dot on each curve. */
    setMarker(t) {
      if (t == null || !(t >= Math.min(xd0, xd1) && t <= Math.max(xd0, xd1))) { markerG.setAttribute('visibility', 'hidden'); return; }
      const x = fx(t);
      let h = `<line x1="${r1(x)}" x2="${r1(x)}" y1="${top}" y2="${top + ih}" stroke="${th.ink}" stroke-width="1.5" stroke-opacity="0.7"/>`;
      for (const s of fig.items) {
        if (!sorted(s)) continue;
        const y = interp(s.raw.x, s.raw.y, t);
        if (Number.isFinite(y) && (!logY || y > 0)) h += `<circle cx="${r1(x)}" cy="${r1(fy(y))}" r="4.5" fill="${colourOf(s)}" stroke="${th.bg}" stroke-width="1.5"/>`;
      }
      markerG.innerHTML = h;
      markerG.setAttribute('visibility', 'visible');
      markerG.dataset.t = String(t);
    },
    index: -1,
  };
  return view;
}

function interp(xs, ys, t) {
  const n = Math.min(xs.length, ys.length);
  if (!n) return NaN;
  const up = xs[n - 1] >= xs[0];
  let lo = 0, hi = n - 1;
  if ((up && (t < xs[0] || t > xs[n - 1])) || (!up && (t > xs[0] || t < xs[n - 1]))) return NaN;
  while (hi - lo > 1) { const mid = (lo + hi) >> 1; if ((xs[mid] < t) === up) lo = mid; else hi = mid; }
  const d = xs[hi] - xs[lo];
  return d === 0 ? ys[lo] : ys[lo] + (ys[hi] - ys[lo]) * (t - xs[lo]) / d;
}

// ---- the figure as numbers, and as a file ---------------------------------------------

/** The figure's data as a table of at most maxRows rows (every k-th
 *  point): {head: [...], rows: [[...]], k, n}. One table per x when the
 *  series do not share their x values. */
export function figureTables(fig, maxRows = 60) {
  const groups = [];
  for (const s of fig.items) {
    const g = groups.find((q) => q.x.length === s.raw.x.length && q.x.every((v, i) => v === s.raw.x[i]));
    if (g) g.items.push(s); else groups.push({ x: s.raw.x, items: [s] });
  }
  const xh = fig.xUnit ? `${fig.xLabel} [${unitText(fig.xUnit)}]` : fig.xLabel;
  return groups.map((g) => {
    const n = g.x.length, k = Math.max(1, Math.ceil(n / maxRows));
    const rows = [];
    for (let i = 0; i < n; i += k) rows.push([g.x[i], ...g.items.map((s) => s.raw.y[i])]);
    if ((n - 1) % k !== 0 && n > 1) rows.push([g.x[n - 1], ...g.items.map((s) => s.raw.y[n - 1])]);
    const yh = (s) => (fig.unit ? `${s.legend} [${unitText(fig.unit)}]` : s.legend);
    return { head: [xh, ...g.items.map(yh)], rows, k, n };
  });
}

/** A standalone SVG document of a drawn svg: no cursor, a white ground. */
export function standaloneSvg(svg, title) {
  const c = svg.cloneNode(true);
  c.setAttribute('xmlns', SVGNS);
  c.removeAttribute('class');
  c.removeAttribute('role');
  c.removeAttribute('aria-label');
  for (const e of c.querySelectorAll('.mm-cursor, .mm-marker')) e.remove();
  const bg = document.createElementNS(SVGNS, 'rect');
  Object.entries({ width: '100%', height: '100%', fill: 'white' }).forEach(([k, v]) => bg.setAttribute(k, v));
  c.insertBefore(bg, c.firstChild);
  if (title) {
    const t = document.createElementNS(SVGNS, 'title');
    t.textContent = title;
    c.insertBefore(t, c.firstChild);
  }
  return c;
}

/** Several standalone svgs stacked in one SVG file, each with its caption. */
export function svgDocument(parts) {
  const gap = 16, capH = 22;
  const width = Math.max(...parts.map((p) => Number(p.svg.getAttribute('width'))));
  let y = 0;
  let inner = '';
  const ser = new XMLSerializer();
  for (const p of parts) {
    const h = Number(p.svg.getAttribute('height'));
    const s = p.svg.cloneNode(true);
    s.setAttribute('x', 0);
    s.setAttribute('y', y);
    s.removeAttribute('xmlns');
    inner += ser.serializeToString(s).replace(/ xmlns="http:\/\/www\.w3\.org\/2000\/svg"/, '');
    if (p.caption) inner += `<text x="8" y="${y + h + 15}" font-size="13" font-family="${escapeHtml(LIGHT.font)}" fill="#1d232a">${escapeHtml(p.caption)}</text>`;
    y += h + (p.caption ? capH : 0) + gap;
  }
  const total = Math.max(1, y - gap);
  return `<?xml version="1.0" encoding="UTF-8"?>\n<svg xmlns="${SVGNS}" width="${width}" height="${total}" viewBox="0 0 ${width} ${total}">` +
    `<rect width="100%" height="100%" fill="white"/>${inner}</svg>\n`;
}
