// format.js — numbers and units as a textbook prints them.
//
// Three forms of a number:  text  ASCII with a dot and "e" (copyable, read
// back by the server); uni  the page's language (decimal comma in Czech and
// German), a real minus and "× 10⁻⁷" (SVG text, screen readers); html  the
// same with <sup>.  How many digits: the answer's accuracy decides
// (fmtScalar): an exact number shows every digit of its shortest form, a
// number with an error no digit beyond the error, others six significant.

const MINUS = '\u2212';
const SUP = { '0': '⁰', '1': '¹', '2': '²', '3': '³', '4': '⁴', '5': '⁵', '6': '⁶', '7': '⁷', '8': '⁸', '9': '⁹', '-': '⁻' };
let DEC = '.';

/** The decimal separator of the page's numbers ("." or ","). */
export function setDecimal(sep) { DEC = sep; }
export function decimalSep() { return DEC; }

export function supText(n) {
  return [...String(n)].map((c) => SUP[c] ?? c).join('');
}

function stripZeros(digits) {
  return digits.replace(/0+$/, '') || '0';
}

/** |v| as significant digits and the exponent of the first: 0.0253 → {d:'253', e:-2}.
 *  sig = null: the shortest digits that read back to v. */
function digitsOf(v, sig) {
  const s = sig == null ? Math.abs(v).toExponential() : Math.abs(v).toExponential(Math.max(0, Math.min(100, sig - 1)));
  const [m, e] = s.split('e');
  return { d: m.replace('.', ''), e: Number(e) };
}

/** Digits in groups of three with a thin space (ISO 80000), from the
 *  decimal point outwards, when there are more than four of them. */
const THIN = '\u2009';
function groupInt(s) {
  return s.length > 4 ? s.replace(/\B(?=(\d{3})+$)/g, THIN) : s;
}
function groupFrac(s) {
  return s.length > 4 ? s.replace(/(\d{3})(?=\d)/g, `$1${THIN}`) : s;
}

/** Lay out digits d (first at 10^e) as decimal or scientific. */
function layout(neg, d, e) {
  const sign = neg ? '-' : '';
  if (e >= -4 && e < 6) {
    let int, frac;
    if (e >= 0) {
      const padded = d.length < e + 1 ? d + '0'.repeat(e + 1 - d.length) : d;
      int = padded.slice(0, e + 1);
      frac = padded.slice(e + 1);
    } else {
      int = '0';
      frac = '0'.repeat(-e - 1) + d;
    }
    const text = frac ? `${sign}${int}.${frac}` : `${sign}${int}`;
    const loc = frac ? `${groupInt(int)}${DEC}${groupFrac(frac)}` : groupInt(int);
    const uni = (neg ? MINUS : '') + loc;
    return { text, uni, html: uni };
  }
  const mant = d.length > 1 ? `${d[0]}.${d.slice(1)}` : d;
  const mantLoc = d.length > 1 ? `${d[0]}${DEC}${groupFrac(d.slice(1))}` : d;
  const m = (neg ? MINUS : '') + mantLoc;
  return {
    text: `${sign}${mant}e${e}`,
    uni: `${m}\u2009×\u200910${supText(e)}`,
    html: `${m}\u2009×\u200910<sup>${String(e).replace('-', MINUS)}</sup>`,
  };
}

function special(v) {
  const s = String(v);
  return { text: s, uni: s, html: escapeHtml(s) };
}

/** A number to `sig` significant digits (trailing zeros dropped). */
export function fmtNumber(v, sig = 6) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return special(v);
  if (v === 0) return { text: '0', uni: '0', html: '0' };
  const { d, e } = digitsOf(v, sig);
  return layout(v < 0, stripZeros(d), e);
}

/** Every digit of the shortest form that reads back to v. */
export function fmtExact(v) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return special(v);
  if (v === 0) return { text: '0', uni: '0', html: '0' };
  const { d, e } = digitsOf(v, null);
  return layout(v < 0, d, e);
}

/** v with no digit beyond its absolute error err (> 0): the last digit is
 *  the one at the decade of err's leading digit.  Trailing zeros are kept:
 *  they are known digits. */
export function fmtWithError(v, err) {
  if (typeof v !== 'number' || !Number.isFinite(v)) return special(v);
  if (!(err > 0)) return fmtExact(v);
  const p = Math.floor(Math.log10(err) + 1e-12);
  if (v === 0 || Math.abs(v) < 10 ** p) {
    // the error is larger than the value: only the order of magnitude is known
    return layout(false, '0', 0);
  }
  const { e } = digitsOf(v, 17);
  const sig = Math.min(17, Math.max(1, e - p + 1));
  const r = digitsOf(v, sig);
  // rounding carried into a new leading digit (9.996 to 0.01 is 10.00): the
  // digit at the error's decade is then a known 0
  const d = r.e > e && sig < 17 ? r.d + '0' : r.d;
  return layout(v < 0, d, r.e);
}

/** A scalar of an answer with the digits its accuracy supports, and a note
 *  on that accuracy: {text, uni, html, kind: 'exact'|'bound'|'estimate'|'', err}. */
export function fmtScalar(s) {
  if (s.exact) return { ...fmtExact(s.value), kind: 'exact' };
  if (typeof s.error === 'number' && s.error >= 0) {
    const kind = s.error_kind === 'bound' ? 'bound' : 'estimate';
    return { ...fmtWithError(s.value, s.error), kind, err: fmtNumber(s.error, 2) };
  }
  return { ...fmtNumber(s.value), kind: '' };
}

/** A number for an input field: short, exact, and readable back by the
 *  server (which takes constant expressions such as pi/2).  Always a dot. */
export function inputText(v) {
  if (typeof v !== 'number') return v == null ? '' : String(v);
  if (v !== 0) {
    for (const q of [1, 2, 3, 4, 6]) {         // multiples of pi read as such
      const p = (v * q) / Math.PI;
      const r = Math.round(p);
      if (r !== 0 && Math.abs(r) <= 24 && Math.abs(p - r) < 1e-13 * Math.abs(p)) {
        const num = r === 1 ? 'pi' : r === -1 ? '-pi' : `${r}*pi`;
        return q === 1 ? num : `${num}/${q}`;
      }
    }
  }
  const a = Math.abs(v);
  if (v !== 0 && (a >= 1e6 || a < 1e-4)) return v.toExponential().replace('e+', 'e');
  return String(v);
}

/** A unit for display: "m^2" → m², "N s/m" stays (SI allows the space). */
export function unitHtml(u) {
  if (!u) return '';
  return escapeHtml(u).replace(/\^\(?(-?\d+)\)?/g, (_, n) => `<sup>${n.replace('-', MINUS)}</sup>`);
}

export function unitText(u) {
  return (u || '').replace(/\^\(?(-?\d+)\)?/g, (_, n) => supText(n));
}

export function escapeHtml(s) {
  return String(s).replace(/[&<>"']/g, (c) => ({ '&': '&amp;', '<': '&lt;', '>': '&gt;', '"': '&quot;', "'": '&#39;' })[c]);
}

/** Query-string encoding that the server and a shell both read back as is:
 *  space → %20 (the server reads + as a space), quotes and brackets escaped
 *  for a shell, while , ; / : stay readable in matrices and expressions. */
export function encodeValue(s) {
  return encodeURIComponent(s)
    .replace(/[!'()*]/g, (c) => '%' + c.charCodeAt(0).toString(16).toUpperCase())
    .replace(/%2C/g, ',').replace(/%3B/g, ';').replace(/%2F/g, '/').replace(/%3A/g, ':');
}

export function el(tag, attrs = {}, ...children) {
  const e = document.createElement(tag);
  for (const [k, v] of Object.entries(attrs)) {
    if (v == null || v === false) continue;
    if (k === 'class') e.className = v;
    else if (k === 'html') e.innerHTML = v;
    else if (k === 'text') e.textContent = v;
    else if (k.startsWith('on')) e.addEventListener(k.slice(2), v);
    else e.setAttribute(k, v === true ? '' : v);
  }
  for (const c of children.flat()) if (c != null && c !== '') e.append(c);
  return e;
}
