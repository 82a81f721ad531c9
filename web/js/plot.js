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
  return s.label ? (s.label === s.name ? s.label : `${s.label} ${s.name}`) : s.name;
}

/** The y quantity of a figure: the label when there is one series. */
export function yQuantity(g) {
  const labels = [...new Set(g.series.map((s) => s.label || s.name))];
  if (labels.length === 1) return labels[0];
  return g.series.map((s) => s.name).join(', ');
}

function axisLabel(quantity, unit, exp) {
  const scale = exp ? `10${[...String(exp)].map((c) => SUP[c]).join('')}` : '';
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
  return { domain: [a, b], ticks, exp, format: (v) => f(v / k) };
}

function textWidth(s, px = 12) {
  return [...String(s)].length * px * 0.6;
}

/**
 * One figure as an <svg>: the series of group g, `width` px wide.
 * Returns the svg element (Plot's, with our legend added).
 */
export function drawFigure(g, width, opts = {}) {
  const Plot = globalThis.Plot;
  const X = [], Y = [], Z = [];
  let xlo = Infinity, xhi = -Infinity, ylo = Infinity, yhi = -Infinity;
  const names = g.series.map(seriesName);
  g.series.forEach((s, k) => {
    const n = Math.min(s.x.length, s.y.length);
    for (let i = 0; i < n; i++) {
      const x = s.x[i], y = s.y[i];
      X.push(x); Y.push(y); Z.push(names[k]);
      if (x < xlo) xlo = x;
      if (x > xhi) xhi = x;
      if (y < ylo) ylo = y;
      if (y > yhi) yhi = y;
    }
  });
  const narrow = width < 520;
  const legendRows = g.series.length > 1 ? legendLayout(names, width - 60).rows : 0;
  const height = Math.round(Math.max(220, Math.min(400, width * (narrow ? 0.72 : 0.42)))) + legendRows * 18;
  const xa = linearAxis(xlo, xhi, Math.max(3, Math.round(width / 90)));
  xa.domain = [xlo === xhi ? xa.domain[0] : xlo, xlo === xhi ? xa.domain[1] : xhi];   // x: the data's span
  const ya = linearAxis(ylo, yhi, Math.max(3, Math.round(height / 55)));
  const yTickWidth = Math.max(...ya.ticks.map((t) => textWidth(ya.format(t), 11)));
  const marginLeft = Math.ceil(yTickWidth + 34);
  const xName = g.x_label || 'x';
  const yName = yQuantity(g);
  const idx = Array.from(X, (_, i) => i);
  const readout = (i) => {
    const xs = fmtNumber(X[i]).text, ys = fmtNumber(Y[i]).text;
    const head = g.series.length > 1 ? `${Z[i]}\n` : '';
    return `${head}${xName} = ${xs}${g.x_unit ? ' ' + unitText(g.x_unit) : ''}\n${yName.length < 30 && g.series.length === 1 ? yName : 'value'} = ${ys}${g.unit ? ' ' + unitText(g.unit) : ''}`;
  };
  const marks = [];
  if (ya.domain[0] < 0 && ya.domain[1] > 0) marks.push(Plot.ruleY([0], { stroke: '#9aa3ad', strokeWidth: 1 }));
  marks.push(
    Plot.line(idx, { x: X, y: Y, z: Z, stroke: Z, strokeWidth: 1.75, curve: 'linear', className: 'mm-series' }),
    Plot.ruleX(idx, Plot.pointerX({ x: X, stroke: '#6b7580', strokeDasharray: '3,3', strokeWidth: 1, className: 'mm-pointer' })),
    Plot.dot(idx, Plot.pointerX({ x: X, y: Y, fill: Z, r: 3.5, stroke: 'white', className: 'mm-pointer' })),
    Plot.tip(idx, Plot.pointerX({ x: X, y: Y, title: readout, fontSize: 12, lineHeight: 1.25, className: 'mm-pointer' })),
  );
  const svg = Plot.plot({
    width,
    height,
    marginTop: 14 + legendRows * 18,
    marginRight: 18,
    marginBottom: 46,
    marginLeft,
    style: { fontSize: '12px', background: 'transparent', color: '#1d232a', overflow: 'visible' },
    x: {
      type: 'linear', domain: xa.domain, ticks: xa.ticks, tickFormat: xa.format, line: true,
      label: axisLabel(xName, g.x_unit, xa.exp), labelAnchor: 'center', labelArrow: 'none', labelOffset: 38,
    },
    y: {
      type: 'linear', domain: ya.domain, ticks: ya.ticks, tickFormat: ya.format, line: true, grid: true,
      label: axisLabel(yName, g.unit, ya.exp), labelAnchor: 'center', labelArrow: 'none', labelOffset: marginLeft - 12,
    },
    color: { type: 'ordinal', domain: names, range: PALETTE },
    marks,
  });
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-label', opts.title || `${yName} against ${xName}`);
  if (g.series.length > 1) addLegend(svg, names, marginLeft, width - 60);
  return svg;
}

function legendLayout(names, maxWidth) {
  const pos = [];
  let x = 0, row = 0;
  for (const n of names) {
    const w = 26 + textWidth(n, 12) + 16;
    if (x > 0 && x + w > maxWidth) { row++; x = 0; }
    pos.push({ x, row });
    x += w;
  }
  return { pos, rows: names.length ? row + 1 : 0 };
}

function addLegend(svg, names, left, maxWidth) {
  const { pos } = legendLayout(names, maxWidth);
  const g = document.createElementNS(SVGNS, 'g');
  g.setAttribute('class', 'mm-legend');
  g.setAttribute('font-size', '12');
  names.forEach((n, i) => {
    const { x, row } = pos[i];
    const y = 10 + row * 18;
    const line = document.createElementNS(SVGNS, 'line');
    Object.entries({ x1: left + x, x2: left + x + 20, y1: y, y2: y, stroke: PALETTE[i % PALETTE.length], 'stroke-width': 2.5 })
      .forEach(([k, v]) => line.setAttribute(k, v));
    const t = document.createElementNS(SVGNS, 'text');
    Object.entries({ x: left + x + 26, y, dy: '0.35em', fill: 'currentColor' }).forEach(([k, v]) => t.setAttribute(k, v));
    t.textContent = n;
    g.append(line, t);
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
