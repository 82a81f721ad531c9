// plot.js — the exercise's series as textbook figures, drawn with
// Observable Plot (on d3), both loaded as globals from /vendor/.
//
// What Plot lacks and is added here: the grouping of series into figures
// (same x quantity and unit, same y unit → one figure), tick values chosen
// and formatted the SI way (no thousands commas; a power of ten moved into
// the axis label), a legend drawn inside the SVG (so an exported figure
// keeps it), and a standalone SVG for download.

import { fmtNumber, unitText } from './format.js';

const SVGNS = 'http://www.w3.org/2000/svg';
export const PALETTE = ['#1f5fa8', '#c0392b', '#2e7d32', '#7b3fa0', '#b36200', '#00838f', '#5d4037', '#ad1457'];
const SUP = { '0': '⁰', '1': '¹', '2': '²', '3': '³', '4': '⁴', '5': '⁵', '6': '⁶', '7': '⁷', '8': '⁸', '9': '⁹', '-': '⁻' };

/** Series that share the x quantity, its unit and the y unit go on one figure. */
export function groupSeries(series) {
  const groups = new Map();
  for (const s of series || []) {
    const key = [s.x_label, s.x_unit, s.unit].join('\u0000');
    if (!groups.has(key)) groups.set(key, { key, x_label: s.x_label, x_unit: s.x_unit, unit: s.unit, series: [] });
    groups.get(key).series.push(s);
  }
  return [...groups.values()];
}

export function seriesName(s) {
  return s.label || s.name;
}

function commonPrefix(strings) {
  if (!strings.length) return '';
  let p = strings[0];
  for (const t of strings) while (!t.startsWith(p)) p = p.slice(0, -1);
  return p;
}

/** How a figure names its y quantity, and each series in its legend.
 *  Labels "max error, rk4" and "max error, dopri5" give the quantity
 *  "max error" and the legend entries "rk4", "dopri5". */
export function figureNames(g) {
  const r = namesOf(g);
  // a y quantity is what is measured up the axis: "error against step" → "error"
  const q = r.quantity.replace(/\s+against\s+.*$/, '');
  return { quantity: q || r.quantity, legend: r.legend };
}

function namesOf(g) {
  const labels = g.series.map((s) => s.label || s.name);
  const names = g.series.map((s) => s.name);
  const unique = new Set(labels).size === labels.length;
  let legend = unique ? labels : labels.map((l, i) => (l === names[i] ? l : `${l} (${names[i]})`));
  if (g.series.length === 1) return { quantity: labels[0], legend };
  if (new Set(labels).size === 1) return { quantity: labels[0], legend: names };
  const pre = commonPrefix(labels);
  const comma = pre.lastIndexOf(', ');
  if (comma >= 3 && labels.every((l) => l.length > comma + 2)) {
    const stem = pre.slice(0, comma);
    return { quantity: stem, legend: unique ? labels.map((l) => l.slice(comma + 2)) : legend };
  }
  const word = pre.match(/^(.*\w)(?=[\s,;:])/) || (labels.every((l) => l === pre || /^[\s,;:]/.test(l.slice(pre.length))) ? [pre, pre] : null);
  if (word && word[1].length >= 4) return { quantity: word[1], legend };
  const joined = names.join(', ');
  if (joined.length <= 40) return { quantity: joined, legend };
  const np = commonPrefix(names).replace(/[\s_\-.,]+$/, '');
  return { quantity: np || 'value', legend };
}

/** The y quantity of a figure. */
export function yQuantity(g) {
  return figureNames(g).quantity;
}

function supText(n) {
  return [...String(n)].map((c) => SUP[c]).join('');
}

function axisLabel(quantity, unit, exp) {
  const scale = exp ? `10${supText(exp)}` : '';
  const u = [scale, unitText(unit)].filter(Boolean).join(' ');
  return u ? `${quantity} [${u}]` : quantity;
}

/** Nice domain, ticks and a formatter for values in [lo, hi]. */
function linearAxis(lo, hi, count) {
  const d3 = globalThis.d3;
  if (!(Number.isFinite(lo) && Number.isFinite(hi))) { lo = 0; hi = 1; }
  if (lo === hi) {
    const d = lo === 0 ? 1 : Math.abs(lo) * 0.1;
    lo -= d; hi += d;
  }
  const scale = d3.scaleLinear().domain([lo, hi]).nice(count);
  const [a, b] = scale.domain();
  const ticks = scale.ticks(count);
  const m = Math.max(Math.abs(a), Math.abs(b));
  // a power of ten (a multiple of 3, as SI prefixes go) moves into the label
  let exp = 0;
  if (m >= 1e4 || m < 1e-2) exp = 3 * Math.floor(Math.log10(m) / 3);
  const k = 10 ** exp;
  const step = d3.tickStep(a / k, b / k, count);
  const f = d3.format(`.${d3.precisionFixed(step)}f`);
  return { type: 'linear', domain: [a, b], ticks, exp, format: (v) => f(v / k) };
}

/** A logarithmic axis: whole decades labelled 10ⁿ, or 1-2-5 steps within a decade or two. */
function logAxis(lo, hi, count, nice) {
  const d3 = globalThis.d3;
  let a = lo, b = hi;
  if (nice) { a = 10 ** Math.floor(Math.log10(lo) + 1e-9); b = 10 ** Math.ceil(Math.log10(hi) - 1e-9); }
  const decades = Math.log10(b / a);
  let ticks, format;
  if (decades >= 1.5) {
    const k0 = Math.ceil(Math.log10(a) - 1e-9), k1 = Math.floor(Math.log10(b) + 1e-9);
    const every = Math.max(1, Math.ceil((k1 - k0 + 1) / count));
    ticks = [];
    for (let k = k0; k <= k1; k++) if ((k - k0) % every === 0) ticks.push(10 ** k);
    format = (v) => `10${supText(Math.round(Math.log10(v)))}`;
  } else {
    ticks = d3.scaleLog().domain([a, b]).ticks(count);
    if (ticks.length > count * 1.6) ticks = ticks.filter((t) => [1, 2, 5].includes(Math.round(t / 10 ** Math.floor(Math.log10(t) + 1e-9))));
    format = (v) => fmtNumber(v, 3).text;
  }
  return { type: 'log', domain: [a, b], ticks, exp: 0, format };
}

/** Whether values (all > 0) read better on a log scale: over two decades,
 *  or in geometric steps (step sizes halved, say) over about one. */
function wantsLog(seriesValues) {
  let lo = Infinity, hi = -Infinity, geometric = true, n = 0;
  for (const v of seriesValues) {
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

function d3range(a, b) {
  const r = [];
  for (let i = a; i <= b; i++) r.push(i);
  return r;
}

function textWidth(s, px = 12) {
  return [...String(s)].length * px * 0.6;
}

/** How each series is drawn: a dense series as a line; a sparse one (few
 *  points, or far fewer than a curve beside it) as dots, joined by a line
 *  only when it stands alone with x in order. */
function seriesStyles(g) {
  const counts = g.series.map((s) => Math.min(s.x.length, s.y.length));
  const most = Math.max(...counts);
  return g.series.map((s, k) => {
    const n = counts[k];
    const sparse = n <= 40 || most >= 4 * n;
    if (!sparse) return { line: true, dots: false };
    const up = s.x.every((x, i) => i === 0 || x > s.x[i - 1]);
    const down = s.x.every((x, i) => i === 0 || x < s.x[i - 1]);
    return { line: (up || down) && most <= 40, dots: true };
  });
}

/**
 * One figure as an <svg>: the series of group g, `width` px wide.
 * Returns the svg element (Plot's, with our legend added).
 */
export function drawFigure(g, width, opts = {}) {
  const Plot = globalThis.Plot;
  const X = [], Y = [], Z = [];
  const { quantity: yName, legend: names } = figureNames(g);
  const styles = seriesStyles(g);
  const lineIdx = [], dotIdx = [];
  g.series.forEach((s, k) => {
    const n = Math.min(s.x.length, s.y.length);
    for (let i = 0; i < n; i++) {
      const j = X.length;
      X.push(s.x[i]); Y.push(s.y[i]); Z.push(names[k]);
      if (styles[k].line) lineIdx.push(j);
      if (styles[k].dots) dotIdx.push(j);
    }
  });
  let xlo = Infinity, xhi = -Infinity, ylo = Infinity, yhi = -Infinity;
  for (let i = 0; i < X.length; i++) {
    if (X[i] < xlo) xlo = X[i];
    if (X[i] > xhi) xhi = X[i];
    if (Y[i] < ylo) ylo = Y[i];
    if (Y[i] > yhi) yhi = Y[i];
  }
  const narrow = width < 520;
  const legendRows = g.series.length > 1 ? legendLayout(names, width - 70).rows : 0;
  const height = Math.round(Math.max(220, Math.min(400, width * (narrow ? 0.72 : 0.42)))) + legendRows * 18;
  const xCount = Math.max(3, Math.round(width / 90)), yCount = Math.max(3, Math.round(height / 55));
  const logX = wantsLog(g.series.map((s) => s.x));
  const logY = logX && wantsLog(g.series.map((s) => s.y));
  const allDots = styles.every((st) => st.dots);
  const anyDots = styles.some((st) => st.dots);
  const pad = (lo, hi, f) => (hi > lo ? [lo - f * (hi - lo), hi + f * (hi - lo)] : [lo, hi]);
  if (!logY && anyDots) [ylo, yhi] = pad(ylo, yhi, 0.04);     // no dot on the frame
  const xa = logX ? logAxis(xlo, xhi, xCount, false) : linearAxis(...(allDots ? pad(xlo, xhi, 0.04) : [xlo, xhi]), xCount);
  if (!logX && !allDots && xlo < xhi) {           // x: the data's span, ticks inside it
    xa.domain = [xlo, xhi];
    const eps = (xhi - xlo) * 1e-9;
    xa.ticks = xa.ticks.filter((t) => t >= xlo - eps && t <= xhi + eps);
  }
  if (!logX && X.every(Number.isInteger)) {       // counts (a degree of freedom, a mode): whole ticks
    const whole = xa.ticks.filter(Number.isInteger);
    xa.ticks = whole.length >= 2 ? whole : d3range(Math.ceil(xa.domain[0]), Math.floor(xa.domain[1]));
  }
  const ya = logY ? logAxis(ylo, yhi, yCount, true) : linearAxis(ylo, yhi, yCount);
  const yTickWidth = Math.max(...ya.ticks.map((t) => textWidth(ya.format(t), 11)));
  const marginLeft = Math.ceil(yTickWidth + 34);
  const xName = g.x_label || 'x';
  const all = Array.from(X, (_, i) => i);
  const fx = (i) => X[i], fy = (i) => Y[i], fz = (i) => Z[i];
  const readout = (i) => {
    const xs = fmtNumber(X[i]).text, ys = fmtNumber(Y[i]).text;
    const head = g.series.length > 1 ? `${Z[i]}\n` : '';
    const yq = yName.length <= 30 ? yName : 'value';
    return `${head}${xName} = ${xs}${g.x_unit ? ' ' + unitText(g.x_unit) : ''}\n${yq} = ${ys}${g.unit ? ' ' + unitText(g.unit) : ''}`;
  };
  const marks = [];
  if (!logY && ya.domain[0] < 0 && ya.domain[1] > 0) marks.push(Plot.ruleY([0], { stroke: '#9aa3ad', strokeWidth: 1 }));
  if (lineIdx.length) marks.push(Plot.line(lineIdx, { x: fx, y: fy, z: fz, stroke: fz, strokeWidth: 1.75, curve: 'linear', className: 'mm-series' }));
  if (dotIdx.length) marks.push(Plot.dot(dotIdx, { x: fx, y: fy, stroke: fz, fill: fz, fillOpacity: 0.25, r: 3, strokeWidth: 1.25, className: 'mm-series mm-dots' }));
  marks.push(
    Plot.ruleX(all, Plot.pointerX({ x: fx, stroke: '#6b7580', strokeDasharray: '3,3', strokeWidth: 1, className: 'mm-pointer' })),
    Plot.dot(all, Plot.pointerX({ x: fx, y: fy, fill: fz, r: 3.5, stroke: 'white', className: 'mm-pointer' })),
    Plot.tip(all, Plot.pointerX({ x: fx, y: fy, title: readout, fontSize: 12, lineHeight: 1.25, className: 'mm-pointer' })),
  );
  const svg = Plot.plot({
    width,
    height,
    marginTop: 14 + legendRows * 18,
    marginRight: 22,
    marginBottom: 46,
    marginLeft,
    style: { fontSize: '12px', background: 'transparent', color: '#1d232a', overflow: 'visible' },
    x: {
      type: xa.type, domain: xa.domain, ticks: xa.ticks, tickFormat: xa.format, line: true,
      label: axisLabel(xName, g.x_unit, xa.exp), labelAnchor: 'center', labelArrow: 'none', labelOffset: 38,
    },
    y: {
      type: ya.type, domain: ya.domain, ticks: ya.ticks, tickFormat: ya.format, line: true, grid: true,
      label: axisLabel(yName, g.unit, ya.exp), labelAnchor: 'center', labelArrow: 'none', labelOffset: marginLeft - 12,
    },
    color: { type: 'ordinal', domain: names, range: PALETTE },
    marks,
  });
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-label', opts.title || `${yName} against ${xName}`);
  svg.dataset.scales = `${xa.type},${ya.type}`;
  if (g.series.length > 1) addLegend(svg, names, styles, marginLeft, width - 70);
  return svg;
}

function legendLayout(names, maxWidth) {
  const pos = [];
  let x = 0, row = 0;
  for (const n of names) {
    const w = 26 + textWidth(n, 12) + 18;
    if (x > 0 && x + w > maxWidth) { row++; x = 0; }
    pos.push({ x, row });
    x += w;
  }
  return { pos, rows: names.length ? row + 1 : 0 };
}

function addLegend(svg, names, styles, left, maxWidth) {
  const { pos } = legendLayout(names, maxWidth);
  const g = document.createElementNS(SVGNS, 'g');
  g.setAttribute('class', 'mm-legend');
  g.setAttribute('font-size', '12');
  g.setAttribute('text-anchor', 'start');
  const put = (tag, attrs) => {
    const e = document.createElementNS(SVGNS, tag);
    for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
    g.append(e);
    return e;
  };
  names.forEach((n, i) => {
    const { x, row } = pos[i];
    const y = 10 + row * 18;
    const color = PALETTE[i % PALETTE.length];
    if (styles[i].line) put('line', { x1: left + x, x2: left + x + 20, y1: y, y2: y, stroke: color, 'stroke-width': 2.5 });
    if (styles[i].dots) put('circle', { cx: left + x + 10, cy: y, r: 3, stroke: color, fill: color, 'fill-opacity': 0.25, 'stroke-width': 1.25 });
    put('text', { x: left + x + 26, y, dy: '0.35em', fill: 'currentColor' }).textContent = n;
  });
  svg.append(g);
}

/** A standalone SVG file of a drawn figure: no hover marks, white ground. */
export function standaloneSvg(svg, title) {
  const c = svg.cloneNode(true);
  c.setAttribute('xmlns', SVGNS);
  c.removeAttribute('class');
  const w = c.getAttribute('width'), h = c.getAttribute('height');
  c.setAttribute('viewBox', c.getAttribute('viewBox') || `0 0 ${w} ${h}`);
  c.setAttribute('font-family', 'DejaVu Sans, Helvetica, Arial, sans-serif');
  c.setAttribute('font-size', '12');
  c.setAttribute('style', 'color:#1d232a;background:white');
  // the pointer marks (rule, dot, tip) are empty without a pointer; drop them
  for (const e of c.querySelectorAll('.mm-pointer')) e.remove();
  const bg = document.createElementNS(SVGNS, 'rect');
  Object.entries({ width: '100%', height: '100%', fill: 'white' }).forEach(([k, v]) => bg.setAttribute(k, v));
  c.insertBefore(bg, c.firstChild);
  if (title) {
    const t = document.createElementNS(SVGNS, 'title');
    t.textContent = title;
    c.insertBefore(t, c.firstChild);
  }
  return '<?xml version="1.0" encoding="UTF-8"?>\n' + new XMLSerializer().serializeToString(c) + '\n';
}
