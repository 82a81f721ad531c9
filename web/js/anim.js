// anim.js — the physical system of an answer drawn over time (API.md
// "animation"): frames of shapes in metres, x right and y up, drawn to one
// scale both ways inside the answer's bounds.
//
//   const p = createPlayer(anim, {label, theme, t: i18n, reducedMotion})
//   host.append(p.el); p.layout(width, maxHeight);
//   p.update(anim)       a new answer: same place in time, same play state
//   p.seek(t) / p.setFrame(i), p.onFrame(cb(i, t)), p.play(), p.pause()
//
// One frame (a free-body diagram, a truss) is a static drawing without
// controls.  Kinds: line, polygon, circle, arrow (with its value and unit),
// path (a traced curve, drawn whole), label.  Styles: tension and
// compression (coloured by the sign of the shape's value when it has one),
// ground (hatched), highlight.

import { fmtNumber, unitText, escapeHtml, el, decimalSep } from './format.js?v=__MM_ASSET_VERSION__';

const SVGNS = 'http://www.w3.org/2000/svg';
let uid = 0;

function frameOf(arr, f) {
  return arr.length === 1 ? arr[0] : arr[Math.min(f, arr.length - 1)];
}

function framesOf(anim) {
  let n = (anim.t || []).length;
  for (const s of anim.shapes || []) n = Math.max(n, (s.x || []).length);
  return Math.max(1, n);
}

/** The frame whose time is nearest t (t need not be evenly spaced). */
function frameAt(ts, t) {
  if (!ts.length) return 0;
  let lo = 0, hi = ts.length - 1;
  const up = ts[hi] >= ts[0];
  while (hi - lo > 1) { const mid = (lo + hi) >> 1; if ((ts[mid] < t) === up) lo = mid; else hi = mid; }
  return Math.abs(ts[lo] - t) <= Math.abs(ts[hi] - t) ? lo : hi;
}

export function createPlayer(anim, opts = {}) {
  const tr = opts.t || ((k) => k);
  const id = ++uid;
  const state = {
    anim, frame: 0, playing: false, speed: 1, loop: true, raf: 0, t0: 0, wall0: 0,
    width: 0, height: 0, s: 1, ox: 0, oy: 0, listeners: [], scrubbing: false,
  };
  const still = () => framesOf(state.anim) < 2;

  const svg = document.createElementNS(SVGNS, 'svg');
  svg.setAttribute('class', 'mm-anim');
  svg.setAttribute('role', 'img');
  svg.setAttribute('aria-label', opts.label || tr('anim'));
  const holder = el('div', { class: 'anim-svg' });
  holder.append(svg);

  const playBtn = el('button', { type: 'button', class: 'anim-play', 'aria-label': tr('play'), title: tr('play') });
  const scrub = el('input', { type: 'range', class: 'anim-scrub', min: 0, max: 0, step: 1, value: 0, 'aria-label': tr('anim_frame') });
  const readout = el('output', { class: 'anim-t', 'aria-hidden': 'true' });
  const speedSel = el('select', { class: 'anim-speed', 'aria-label': tr('speed') },
    [0.1, 0.25, 0.5, 1, 2, 4].map((v) => el('option', { value: v, text: `${String(v).replace('.', decimalSep())}×`, selected: v === 1 ? true : null })));
  const loopBox = el('input', { type: 'checkbox', class: 'anim-loop', checked: true, id: `anim-loop-${id}` });
  const rateNote = el('span', { class: 'anim-rate muted' });
  const controls = el('div', { class: 'anim-controls' },
    playBtn, scrub, readout,
    el('span', { class: 'anim-opts' }, speedSel, el('label', { for: `anim-loop-${id}` }, loopBox, ' ', tr('loop'))), rateNote);
  const values = el('p', { class: 'anim-values', 'aria-live': 'off' });
  // the first frame, for print (a printed page shows the start of the motion)
  const printCopy = el('div', { class: 'anim-print', 'aria-hidden': 'true' });
  const root = el('figure', { class: 'anim', 'data-anim': '' }, holder, printCopy, controls, values,
    el('figcaption', {}, el('span', { class: 'fignum', text: tr('anim') }), ' ', el('span', { class: 'figtext', text: opts.label || '' })));

  // ---- time ----
  function duration() {
    const ts = state.anim.t || [];
    return ts.length > 1 ? Math.abs(ts[ts.length - 1] - ts[0]) : 0;
  }
  /** Units of t per second of playback at speed 1: real time when t is a
   *  time of a few seconds, else the whole animation in about six seconds. */
  function baseRate() {
    const d = duration();
    if (!(d > 0)) return 1;
    if (state.anim.t_unit === 's' && d >= 1 && d <= 30) return 1;
    return d / 6;
  }
  function tOf(f) {
    const ts = state.anim.t || [];
    return ts.length ? ts[Math.min(f, ts.length - 1)] : f;
  }
  function tText(f) {
    const u = state.anim.t_unit ? ` ${unitText(state.anim.t_unit)}` : '';
    return `${state.anim.t_label || 't'} = ${fmtNumber(tOf(f), 4).uni}${u}`;
  }

  // ---- drawing ----
  const px = (x) => state.ox + (x - state.anim.bounds[0]) * state.s;
  const py = (y) => state.oy + (state.anim.bounds[3] - y) * state.s;
  const pts = (xs, ys) => xs.map((x, i) => `${(Math.round(px(x) * 10) / 10)},${(Math.round(py(ys[i]) * 10) / 10)}`).join(' ');

  function colourOf(shape, v) {
    const th = opts.theme || {};
    if ((shape.style === 'tension' || shape.style === 'compression') && typeof v === 'number') {
      return v > 0 ? th.tension : v < 0 ? th.compression : th.muted;
    }
    if (shape.style === 'tension') return th.tension;
    if (shape.style === 'compression') return th.compression;
    if (shape.style === 'highlight') return th.highlight;
    if (shape.kind === 'arrow') return th.arrow;
    return th.ink;
  }

  let nodes = [];
  function build() {
    const th = opts.theme || {};
    const W = state.width, H = state.height;
    svg.setAttribute('width', W);
    svg.setAttribute('height', H);
    svg.setAttribute('viewBox', `0 0 ${W} ${H}`);
    const hatch = `mm-hatch-${id}`;
    let defs = `<defs><pattern id="${hatch}" width="7" height="7" patternUnits="userSpaceOnUse" patternTransform="rotate(45)"><line x1="0" y1="0" x2="0" y2="7" stroke="${th.muted}" stroke-width="1.2"/></pattern></defs>`;
    svg.innerHTML = defs;
    nodes = (state.anim.shapes || []).map((shape) => {
      const g = document.createElementNS(SVGNS, 'g');
      g.setAttribute('class', `shape kind-${shape.kind}${shape.style ? ' style-' + shape.style : ''}`);
      g.dataset.name = shape.name || '';
      svg.append(g);
      return { shape, g };
    });
    draw(0);
    const copy = svg.cloneNode(true);
    copy.removeAttribute('role');
    copy.removeAttribute('aria-label');
    for (const e of copy.querySelectorAll('[id]')) e.id = `${e.id}-p`;
    copy.innerHTML = copy.innerHTML.replace(/url\(#mm-hatch-(\d+)\)/g, 'url(#mm-hatch-$1-p)');
    printCopy.replaceChildren(copy);
    draw(state.frame);
  }

  function hatchMarks(xs, ys) {
    // short strokes on the side away from the middle of the picture
    const b = state.anim.bounds;
    const cx = px((b[0] + b[2]) / 2), cy = py((b[1] + b[3]) / 2);
    let d = '';
    for (let i = 1; i < xs.length; i++) {
      const x0 = px(xs[i - 1]), y0 = py(ys[i - 1]), x1 = px(xs[i]), y1 = py(ys[i]);
      const L = Math.hypot(x1 - x0, y1 - y0);
      if (L < 1) continue;
      const tx = (x1 - x0) / L, ty = (y1 - y0) / L;
      let nx = -ty, ny = tx;
      const mx = (x0 + x1) / 2, my = (y0 + y1) / 2;
      if ((cx - mx) * nx + (cy - my) * ny > 0) { nx = -nx; ny = -ny; }
      const n = Math.max(2, Math.floor(L / 8));
      for (let k = 0; k <= n; k++) {
        const ax = x0 + tx * L * k / n, ay = y0 + ty * L * k / n;
        d += `M${ax.toFixed(1)},${ay.toFixed(1)}l${(nx * 7 - tx * 5).toFixed(1)},${(ny * 7 - ty * 5).toFixed(1)}`;
      }
    }
    return d;
  }

  function draw(f) {
    const th = opts.theme || {};
    const valueTexts = [];
    for (const { shape, g } of nodes) {
      const xs = frameOf(shape.x || [[]], f) || [], ys = frameOf(shape.y || [[]], f) || [];
      const v = shape.value ? shape.value[Math.min(f, shape.value.length - 1)] : undefined;
      const c = colourOf(shape, v);
      const heavy = shape.style === 'highlight' ? 3 : shape.style === 'tension' || shape.style === 'compression' ? 3 : 2;
      let h = '';
      switch (shape.kind) {
        case 'polygon':
          h = `<polygon points="${pts(xs, ys)}" fill="${shape.style === 'ground' ? `url(#mm-hatch-${id})` : th.body}" fill-opacity="${shape.style === 'ground' ? 1 : 0.9}" stroke="${c}" stroke-width="1.5" stroke-linejoin="round"/>`;
          break;
        case 'circle': {
          const r = Math.max(1.5, (shape.r || 0) * state.s);
          for (let i = 0; i < xs.length; i++) h += `<circle cx="${px(xs[i]).toFixed(1)}" cy="${py(ys[i]).toFixed(1)}" r="${r.toFixed(1)}" fill="${th.body}" stroke="${c}" stroke-width="1.5"/>`;
          break;
        }
        case 'arrow': {
          if (xs.length < 2) break;
          const x0 = px(xs[0]), y0 = py(ys[0]), x1 = px(xs[1]), y1 = py(ys[1]);
          const L = Math.hypot(x1 - x0, y1 - y0);
          if (L >= 1) {
            const hl = Math.min(10, L * 0.6), hw = hl * 0.45;
            const tx = (x1 - x0) / L, ty = (y1 - y0) / L;
            const bx = x1 - tx * hl, by = y1 - ty * hl;
            h += `<line x1="${x0.toFixed(1)}" y1="${y0.toFixed(1)}" x2="${bx.toFixed(1)}" y2="${by.toFixed(1)}" stroke="${c}" stroke-width="2.25"/>`;
            h += `<polygon points="${x1.toFixed(1)},${y1.toFixed(1)} ${(bx - ty * hw).toFixed(1)},${(by + tx * hw).toFixed(1)} ${(bx + ty * hw).toFixed(1)},${(by - tx * hw).toFixed(1)}" fill="${c}"/>`;
          }
          if (typeof v === 'number') {
            const txt = `${shape.name} = ${fmtNumber(v, 3).uni}${shape.unit ? ' ' + unitText(shape.unit) : ''}`;
            valueTexts.push(txt);
            // beside the tip, kept inside the picture
            const fsz = th.fontSize || 12, tw = txt.length * fsz * 0.6;
            let anchor = x1 >= x0 ? 'start' : 'end', lx = x1 + (x1 >= x0 ? 6 : -6), ly = y1 - 6;
            if (anchor === 'start' && lx + tw > state.width - 2) { anchor = 'end'; lx = state.width - 2; ly = Math.min(y0, y1) - 8; }
            if (anchor === 'end' && lx - tw < 2) { anchor = 'start'; lx = 2; ly = Math.min(y0, y1) - 8; }
            if (ly < fsz) ly = Math.max(y0, y1) + fsz + 4;
            h += `<text x="${lx.toFixed(1)}" y="${ly.toFixed(1)}" text-anchor="${anchor}" fill="${c}" font-size="${fsz}" paint-order="stroke" stroke="${th.bg}" stroke-width="3">${escapeHtml(txt)}</text>`;
          }
          break;
        }
        case 'label':
          if (xs.length) h = `<text x="${px(xs[0]).toFixed(1)}" y="${py(ys[0]).toFixed(1)}" fill="${c}" font-size="${th.fontSize || 12}" text-anchor="middle" dy="0.32em" paint-order="stroke" stroke="${th.bg}" stroke-width="3">${escapeHtml(shape.text || shape.name || '')}</text>`;
          break;
        case 'path':
          h = `<polyline points="${pts(xs, ys)}" fill="none" stroke="${shape.style ? c : th.path}" stroke-width="1.5" stroke-dasharray="${shape.style ? '' : '4 3'}" stroke-linejoin="round"/>`;
          break;
        default: // line
          h = `<polyline points="${pts(xs, ys)}" fill="none" stroke="${c}" stroke-width="${shape.style === 'ground' ? 2.5 : heavy}" stroke-linejoin="round" stroke-linecap="round"/>`;
          if (shape.style === 'ground') h = `<path d="${hatchMarks(xs, ys)}" stroke="${th.muted}" stroke-width="1.1"/>` + h;
      }
      if (shape.kind !== 'arrow' && typeof v === 'number' && xs.length) {
        const txt = `${shape.name} = ${fmtNumber(v, 3).uni}${shape.unit ? ' ' + unitText(shape.unit) : ''}`;
        valueTexts.push(txt);
        if (shape.kind === 'line' && xs.length >= 2) {
          const mx = (px(xs[0]) + px(xs[xs.length - 1])) / 2, my = (py(ys[0]) + py(ys[ys.length - 1])) / 2;
          h += `<text x="${mx.toFixed(1)}" y="${my.toFixed(1)}" dy="-0.4em" text-anchor="middle" fill="${c}" font-size="${(th.fontSize || 12) - 1}" paint-order="stroke" stroke="${th.bg}" stroke-width="3">${escapeHtml(fmtNumber(v, 3).uni)}</text>`;
        }
      }
      g.innerHTML = h;
    }
    values.textContent = valueTexts.join(' · ');
    values.hidden = !values.textContent;
    root.dataset.frame = String(f);
  }

  // ---- state changes ----
  function setFrame(f, from) {
    const n = framesOf(state.anim);
    f = Math.max(0, Math.min(n - 1, Math.round(f)));
    state.frame = f;
    draw(f);
    scrub.value = String(f);
    const tt = tText(f);
    readout.textContent = tt;
    scrub.setAttribute('aria-valuetext', tt);
    for (const cb of state.listeners) cb(f, tOf(f), from);
  }

  function tick(now) {
    if (!state.playing) return;
    const ts = state.anim.t || [];
    const t0 = ts[0] ?? 0, d = duration();
    let t = state.t0 + (now - state.wall0) / 1000 * state.speed * baseRate();
    if (t > t0 + d) {
      if (state.loop && d > 0) { t = t0 + ((t - t0) % d); state.t0 = t; state.wall0 = now; } else { setFrame(ts.length - 1); pause(); return; }
    }
    const f = frameAt(ts, t);
    if (f !== state.frame) setFrame(f, 'play');
    state.raf = requestAnimationFrame(tick);
  }

  function play() {
    if (still() || state.playing) return;
    const ts = state.anim.t || [];
    if (state.frame >= ts.length - 1) state.frame = 0;
    state.playing = true;
    state.t0 = tOf(state.frame);
    state.wall0 = performance.now();
    root.classList.add('playing');
    playBtn.setAttribute('aria-label', tr('pause'));
    playBtn.title = tr('pause');
    state.raf = requestAnimationFrame(tick);
  }
  function pause() {
    state.playing = false;
    cancelAnimationFrame(state.raf);
    root.classList.remove('playing');
    playBtn.setAttribute('aria-label', tr('play'));
    playBtn.title = tr('play');
  }

  function noteRate() {
    const r = baseRate() * state.speed;
    if (state.anim.t_unit !== 's' || !(duration() > 0)) { rateNote.textContent = ''; return; }
    rateNote.textContent = Math.abs(r - 1) < 1e-9 ? tr('real_time')
      : r < 1 ? tr('slowed', { x: fmtNumber(1 / r, 2).uni }) : tr('sped', { x: fmtNumber(r, 2).uni });
  }

  playBtn.addEventListener('click', () => (state.playing ? pause() : play()));
  scrub.addEventListener('input', () => { pause(); setFrame(Number(scrub.value), 'scrub'); });
  speedSel.addEventListener('change', () => {
    state.speed = Number(speedSel.value);
    if (state.playing) { state.t0 = tOf(state.frame); state.wall0 = performance.now(); }
    noteRate();
  });
  loopBox.addEventListener('change', () => { state.loop = loopBox.checked; });
  // a drag across the picture scrubs (a touch too: vertical moves still scroll)
  let drag = null;
  svg.addEventListener('pointerdown', (e) => {
    if (still()) return;
    drag = { x: e.clientX, f: state.frame, moved: false, id: e.pointerId };
  });
  svg.addEventListener('pointermove', (e) => {
    if (!drag || e.pointerId !== drag.id) return;
    const dx = e.clientX - drag.x;
    if (!drag.moved && Math.abs(dx) < 6) return;
    if (!drag.moved) { drag.moved = true; pause(); try { svg.setPointerCapture(e.pointerId); } catch { /* gone */ } }
    const n = framesOf(state.anim);
    setFrame(drag.f + dx / Math.max(1, state.width) * n, 'scrub');
  });
  const endDrag = (e) => {
    if (!drag || e.pointerId !== drag.id) return;
    const tap = !drag.moved;
    drag = null;
    if (tap && e.type === 'pointerup') (state.playing ? pause() : play());
  };
  svg.addEventListener('pointerup', endDrag);
  svg.addEventListener('pointercancel', endDrag);

  function refreshControls() {
    const n = framesOf(state.anim);
    controls.hidden = still();
    root.classList.toggle('still', still());
    scrub.max = String(Math.max(0, n - 1));
    noteRate();
  }

  const player = {
    el: root,
    svg,
    get frame() { return state.frame; },
    get playing() { return state.playing; },
    get frames() { return framesOf(state.anim); },
    get anim() { return state.anim; },
    tOf,
    /** Lay the drawing out `width` px wide, at most maxHeight high. */
    layout(width, maxHeight) {
      const b = state.anim.bounds || [0, 0, 1, 1];
      const bw = Math.max(1e-12, b[2] - b[0]), bh = Math.max(1e-12, b[3] - b[1]);
      const W = Math.max(120, Math.floor(width));
      let H = Math.round(W * bh / bw);
      H = Math.max(80, Math.min(H, Math.floor(maxHeight || 420)));
      state.s = Math.min(W / bw, H / bh);
      state.width = W;
      state.height = H;
      state.ox = (W - bw * state.s) / 2;
      state.oy = (H - bh * state.s) / 2;
      build();
    },
    update(anim) {
      const wasT = tOf(state.frame);
      state.anim = anim;
      refreshControls();
      const f = frameAt(anim.t || [], wasT);
      state.frame = Math.min(f, framesOf(anim) - 1);
      if (state.width) player.layout(state.width, state.maxH);
      setFrame(state.frame);
      if (state.playing) { state.t0 = tOf(state.frame); state.wall0 = performance.now(); }
    },
    setFrame: (f) => { pause(); setFrame(f, 'seek'); },
    seek(t) { pause(); setFrame(frameAt(state.anim.t || [], t), 'seek'); },
    onFrame(cb) { state.listeners.push(cb); },
    play, pause,
    setTheme(theme) { opts.theme = theme; if (state.width) build(); },
    destroy() { pause(); state.listeners = []; },
  };
  const layout0 = player.layout;
  player.layout = (w, mh) => { state.maxH = mh; layout0(w, mh); };
  refreshControls();
  setFrame(0);
  return player;
}

/** The SVG of the animation at one frame, standalone (print, download). */
export function animFrameSvg(player) {
  const c = player.svg.cloneNode(true);
  c.setAttribute('xmlns', SVGNS);
  c.removeAttribute('class');
  c.removeAttribute('role');
  return c;
}
