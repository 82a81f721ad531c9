// format.js — numbers and units as a textbook prints them.

const MINUS = '\u2212';

function stripZeros(mantissa) {
  return mantissa.includes('.') ? mantissa.replace(/0+$/, '').replace(/\.$/, '') : mantissa;
}

/** A number to `sig` significant digits: {text, html}.  text is plain ASCII
 *  (copyable: "1.2345e-7"), html uses a real minus and "× 10^n". */
export function fmtNumber(v, sig = 6) {
  if (typeof v !== 'number') return { text: String(v), html: escapeHtml(String(v)) };
  if (!Number.isFinite(v)) return { text: String(v), html: escapeHtml(String(v)) };
  if (v === 0) return { text: '0', html: '0' };
  const a = Math.abs(v);
  if (a >= 1e-4 && a < 1e6) {
    let s = v.toPrecision(sig);
    if (s.includes('e')) s = Number(s).toString();       // 999999.7 → "1.00000e+6"
    s = stripZeros(s);
    return { text: s, html: s.replace('-', MINUS) };
  }
  const [m, e] = v.toExponential(sig - 1).split('e');
  const mant = stripZeros(m), exp = Number(e);
  return {
    text: `${mant}e${exp}`,
    html: `${mant.replace('-', MINUS)}\u2009×\u200910<sup>${String(exp).replace('-', MINUS)}</sup>`,
  };
}

/** A number for an input field: short, exact, and readable back by the
 *  server (which takes constant expressions such as pi/2). */
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
  const sup = { '0': '⁰', '1': '¹', '2': '²', '3': '³', '4': '⁴', '5': '⁵', '6': '⁶', '7': '⁷', '8': '⁸', '9': '⁹', '-': '⁻' };
  return (u || '').replace(/\^\(?(-?\d+)\)?/g, (_, n) => [...n].map((c) => sup[c]).join(''));
}

/** "label [unit]", or just the label for a pure number. */
export function withUnit(label, unit) {
  return unit ? `${label} [${unitText(unit)}]` : label;
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
  for (const c of children.flat()) if (c != null) e.append(c);
  return e;
}
