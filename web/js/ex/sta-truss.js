// sta-truss.js — draw a truss on sta-truss's page (the extension contract of
// ./registry.js): click on empty space to add a joint, drag from a joint to
// another for a member; the tools put supports and loads on joints or delete.
// Every edit goes to the page as parameters (api.setParams), so the drawing
// lives in the URL and the page solves it; every answer colours the members
// (tension / compression, with their forces) and draws the reactions.
// The parameters are API.md's: nodes "x,y;...", members "i,j;..." (1-based),
// supports "joint,fix_x,fix_y;...", loads "joint,Fx,Fy;...".

const SVGNS = 'http://www.w3.org/2000/svg';
const GRID = 0.5;            // m: new joints snap to it, so the URL stays short
const PICK = 14;             // px: how near a click must be to a joint

const STYLE = `
.truss-ed { border: 1px solid #d9d6cf; border-radius: 6px; padding: 0.5rem; background: #fff; margin: 0.5rem 0;
  color: #1d232a; color-scheme: light; }   /* a light drawing board in every scheme: its colours are fixed */
.truss-ed .tools { display: flex; flex-wrap: wrap; gap: 0.3rem; align-items: center; margin-bottom: 0.4rem; }
.truss-ed .tools button { font: inherit; font-size: 0.9rem; padding: 0.2rem 0.6rem; border: 1px solid #b9b4aa;
  background: #f6f4ef; color: #1d232a; border-radius: 4px; cursor: pointer; }
.truss-ed .tools button[aria-pressed="true"] { background: #1f5fa8; color: #fff; border-color: #1f5fa8; }
.truss-ed .tools label { font-size: 0.85rem; color: #505a64; }
.truss-ed .tools input { width: 5.5em; font: inherit; font-size: 0.9rem; }
.truss-ed svg { width: 100%; height: auto; touch-action: none; user-select: none; background: #fcfbf8; }
.truss-ed svg * { vector-effect: non-scaling-stroke; }
.truss-ed .status { font-size: 0.9rem; margin-top: 0.3rem; min-height: 1.4em; }
.truss-ed .status.bad { color: #a8231b; }
.truss-ed .status.ok { color: #1e6b2a; }
.truss-ed .member { stroke: #1d232a; stroke-width: 3; stroke-linecap: round; }
.truss-ed .member.tension { stroke: #b1361e; }
.truss-ed .member.compression { stroke: #1f5fa8; }
.truss-ed .member.zero { stroke: #8a9098; stroke-dasharray: 4 3; }
.truss-ed .member.selected { stroke-width: 6; }
.truss-ed .joint { fill: #fff; stroke: #1d232a; stroke-width: 2; cursor: pointer; }
.truss-ed .force-label { font-family: system-ui, sans-serif; fill: #1d232a; paint-order: stroke; stroke: #fff; stroke-width: 3; }
.truss-ed .joint-label { font-family: system-ui, sans-serif; fill: #505a64; }
.truss-ed .support { fill: #d9d6cf; stroke: #505a64; stroke-width: 1.5; }
.truss-ed .load { stroke: #1d232a; stroke-width: 2; fill: none; }
.truss-ed .reaction { stroke: #1e6b2a; stroke-width: 2; fill: none; }
.truss-ed .rubber { stroke: #1f5fa8; stroke-width: 2; stroke-dasharray: 6 4; }
`;

// ---- the truss as data, to and from the parameter texts ---------------------------

function rows(text) {
  return String(text || '').replace(/^\s*\[|\]\s*$/g, '').split(/[;\n]/)
    .map((r) => r.trim()).filter((r) => r !== '')
    .map((r) => r.split(/[\s,]+/).filter((x) => x !== '').map(Number));
}

function fromParams(p) {
  const asRows = (v) => (Array.isArray(v) ? v.map((r) => r.map(Number)) : rows(v));
  return {
    nodes: asRows(p.nodes).map(([x, y]) => ({ x, y })),
    members: asRows(p.members).map(([i, j]) => [i - 1, j - 1]),
    supports: asRows(p.supports).map(([n, fx, fy]) => ({ node: n - 1, fx, fy })),
    loads: asRows(p.loads).map(([n, Fx, Fy]) => ({ node: n - 1, Fx, Fy })),
  };
}

// shortest text that reads back to v rounded to a micrometre
const num = (v) => String(Math.round(v * 1e6) / 1e6);

function toParams(t) {
  return {
    nodes: t.nodes.map((n) => `${num(n.x)},${num(n.y)}`).join(';'),
    members: t.members.map(([i, j]) => `${i + 1},${j + 1}`).join(';'),
    supports: t.supports.map((s) => `${s.node + 1},${s.fx},${s.fy}`).join(';'),
    loads: t.loads.map((l) => `${l.node + 1},${num(l.Fx)},${num(l.Fy)}`).join(';'),
  };
}

function fmtForce(v) {
  const a = Math.abs(v);
  if (a === 0) return '0';
  if (a >= 1e6) return `${Number((v / 1e6).toPrecision(3))} MN`;
  if (a >= 1e3) return `${Number((v / 1e3).toPrecision(3))} kN`;
  return `${Number(v.toPrecision(3))} N`;
}

function el(tag, attrs = {}, parent = null) {
  const e = document.createElementNS(SVGNS, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (parent) parent.appendChild(e);
  return e;
}

// ---- the editor ----------------------------------------------------------------------

export function mount(host, api) {
  const style = document.createElement('style');
  style.textContent = STYLE;
  const root = document.createElement('div');
  root.className = 'truss-ed';
  const tools = document.createElement('div');
  tools.className = 'tools';
  tools.setAttribute('role', 'toolbar');
  tools.setAttribute('aria-label', 'truss drawing tools');
  const modes = [
    ['draw', 'Draw', 'click: add a joint; drag from a joint to a joint: add a member'],
    ['pin', 'Pin', 'click a joint: fixed in x and y'],
    ['roller', 'Roller', 'click a joint: a roller on level ground (fixed in y); again: on a wall; again: free'],
    ['load', 'Load', 'click a joint: put the load (Fx, Fy) on it; again: take it off'],
    ['delete', 'Delete', 'click a joint or a member to remove it'],
  ];
  const buttons = {};
  for (const [m, label, title] of modes) {
    const b = document.createElement('button');
    b.type = 'button';
    b.textContent = label;
    b.title = title;
    b.dataset.mode = m;
    b.setAttribute('aria-pressed', m === 'draw' ? 'true' : 'false');
    b.addEventListener('click', () => setMode(m));
    buttons[m] = b;
    tools.appendChild(b);
  }
  const fx = document.createElement('input');
  const fy = document.createElement('input');
  for (const [inp, name, val] of [[fx, 'Fx', '0'], [fy, 'Fy', '-10000']]) {
    const lab = document.createElement('label');
    lab.textContent = `${name} [N] `;
    inp.type = 'number';
    inp.value = val;
    inp.step = 'any';
    inp.dataset.load = name;
    lab.appendChild(inp);
    tools.appendChild(lab);
  }
  const clear = document.createElement('button');
  clear.type = 'button';
  clear.textContent = 'Clear';
  clear.title = 'start from an empty drawing';
  clear.addEventListener('click', () => {
    truss = { nodes: [], members: [], supports: [], loads: [] };
    forces = null;
    root.dataset.state = 'pending';
    render();
    status('Click to add joints; drag between joints for members.', '');
  });
  tools.appendChild(clear);

  const svg = el('svg', { class: 'truss-editor', role: 'img', 'aria-label': 'the truss: click to add a joint, drag between joints for a member' });
  const world = el('g', {}, svg);
  const statusLine = document.createElement('div');
  statusLine.className = 'status';
  statusLine.setAttribute('role', 'status');
  statusLine.setAttribute('aria-live', 'polite');
  root.append(tools, svg, statusLine);
  host.append(style, root);

  let mode = 'draw';
  let truss = fromParams(api.getParams());
  let forces = null;         // { members: [F], reactions: [{node, Rx, Ry}] } of the drawn truss
  let selected = null;       // a member index, briefly, after a click in delete mode
  let drag = null;           // { from, x, y } while dragging a member
  let view = { x0: 0, y0: 0, w: 10, h: 6 };

  function setMode(m) {
    mode = m;
    for (const [k, b] of Object.entries(buttons)) b.setAttribute('aria-pressed', k === m ? 'true' : 'false');
  }

  function status(text, kind) {
    statusLine.textContent = text;
    statusLine.className = `status ${kind || ''}`;
  }

  // the view: the joints' bounding box with room around it to draw on (a
  // quarter of its size each way), at least 12 x 6 m
  function fit() {
    const xs = truss.nodes.map((n) => n.x), ys = truss.nodes.map((n) => n.y);
    let x0 = Math.min(0, ...xs), x1 = Math.max(12, ...xs), y0 = Math.min(-1, ...ys), y1 = Math.max(5, ...ys);
    const m = 0.25 * Math.max(x1 - x0, y1 - y0, 4);
    x0 -= m; x1 += m; y0 -= m; y1 += m;
    view = { x0, y0, w: x1 - x0, h: y1 - y0 };
    svg.setAttribute('viewBox', `${x0} ${-y1} ${view.w} ${view.h}`);
  }

  // svg user units are metres with y down; the world has y up
  function toWorld(evt) {
    const pt = svg.createSVGPoint();
    pt.x = evt.clientX;
    pt.y = evt.clientY;
    const p = pt.matrixTransform(svg.getScreenCTM().inverse());
    return { x: p.x, y: -p.y };
  }

  function pxPerMetre() {
    const r = svg.getBoundingClientRect();
    return r.width / view.w || 1;
  }

  function jointAt(p) {
    const tol = PICK / pxPerMetre();
    let best = -1, bd = Infinity;
    truss.nodes.forEach((n, i) => {
      const d = Math.hypot(n.x - p.x, n.y - p.y);
      if (d < tol && d < bd) { best = i; bd = d; }
    });
    return best;
  }

  function memberAt(p) {
    const tol = 8 / pxPerMetre();
    let best = -1, bd = Infinity;
    truss.members.forEach(([i, j], k) => {
      const a = truss.nodes[i], b = truss.nodes[j];
      if (!a || !b) return;
      const ex = b.x - a.x, ey = b.y - a.y, L2 = ex * ex + ey * ey;
      const t = Math.max(0, Math.min(1, ((p.x - a.x) * ex + (p.y - a.y) * ey) / (L2 || 1)));
      const d = Math.hypot(p.x - a.x - t * ex, p.y - a.y - t * ey);
      if (d < tol && d < bd) { best = k; bd = d; }
    });
    return best;
  }

  // ---- edits: each one goes to the page, which solves it ----------------------------

  function commit() {
    forces = null;
    root.dataset.state = 'pending';
    render();
    const t = truss;
    if (t.nodes.length && t.members.length && t.supports.length && t.loads.length) {
      status('solving…', '');
      api.setParams(toParams(t));
    } else {
      status(t.members.length ? 'Add supports (Pin, Roller) and a load (Load) to solve.' : 'Drag from joint to joint to add members.', '');
    }
  }

  function removeJoint(i) {
    const re = (k) => (k > i ? k - 1 : k);
    truss.members = truss.members.filter(([a, b]) => a !== i && b !== i).map(([a, b]) => [re(a), re(b)]);
    truss.supports = truss.supports.filter((s) => s.node !== i).map((s) => ({ ...s, node: re(s.node) }));
    truss.loads = truss.loads.filter((l) => l.node !== i).map((l) => ({ ...l, node: re(l.node) }));
    truss.nodes.splice(i, 1);
  }

  function onDown(evt) {
    const p = toWorld(evt);
    const j = jointAt(p);
    if (mode === 'draw' && j >= 0) {
      drag = { from: j, x: p.x, y: p.y };
      svg.setPointerCapture?.(evt.pointerId);
      render();
    }
  }

  function onMove(evt) {
    if (!drag) return;
    const p = toWorld(evt);
    drag.x = p.x;
    drag.y = p.y;
    render();
  }

  function onUp(evt) {
    const p = toWorld(evt);
    const j = jointAt(p);
    if (drag) {
      const from = drag.from;
      drag = null;
      if (j >= 0 && j !== from && !truss.members.some(([a, b]) => (a === from && b === j) || (a === j && b === from))) {
        truss.members.push([from, j]);
        commit();
      } else {
        render();
      }
      return;
    }
    if (mode === 'draw') {
      if (j >= 0) return;
      const x = Math.round(p.x / GRID) * GRID, y = Math.round(p.y / GRID) * GRID;
      if (truss.nodes.some((n) => n.x === x && n.y === y)) return;
      truss.nodes.push({ x, y });
      commit();
    } else if (mode === 'pin' && j >= 0) {
      truss.supports = truss.supports.filter((s) => s.node !== j);
      truss.supports.push({ node: j, fx: 1, fy: 1 });
      commit();
    } else if (mode === 'roller' && j >= 0) {
      const s = truss.supports.find((q) => q.node === j);
      truss.supports = truss.supports.filter((q) => q.node !== j);
      if (!s || (s.fx && s.fy)) truss.supports.push({ node: j, fx: 0, fy: 1 });
      else if (!s.fx && s.fy) truss.supports.push({ node: j, fx: 1, fy: 0 });
      commit();
    } else if (mode === 'load' && j >= 0) {
      const had = truss.loads.some((l) => l.node === j);
      truss.loads = truss.loads.filter((l) => l.node !== j);
      const Fx = Number(fx.value) || 0, Fy = Number(fy.value) || 0;
      if (!had && (Fx || Fy)) truss.loads.push({ node: j, Fx, Fy });
      commit();
    } else if (mode === 'delete') {
      if (j >= 0) removeJoint(j);
      else {
        const m = memberAt(p);
        if (m < 0) return;
        truss.members.splice(m, 1);
      }
      commit();
    }
  }

  svg.addEventListener('pointerdown', onDown);
  svg.addEventListener('pointermove', onMove);
  svg.addEventListener('pointerup', onUp);

  // ---- drawing -----------------------------------------------------------------------------

  function arrow(x, y, dx, dy, cls, parent) {
    // from (x - dx, y - dy) to (x, y) in world coordinates, head at (x, y)
    const L = Math.hypot(dx, dy);
    if (!(L > 0)) return;
    const ux = dx / L, uy = dy / L, h = Math.min(0.25 * L, 0.02 * view.w);
    const g = el('g', { class: cls }, parent);
    el('line', { x1: x - dx, y1: -(y - dy), x2: x, y2: -y }, g);
    el('polyline', {
      points: `${x - h * ux + 0.5 * h * uy},${-(y - h * uy - 0.5 * h * ux)} ${x},${-y} ${x - h * ux - 0.5 * h * uy},${-(y - h * uy + 0.5 * h * ux)}`,
    }, g);
  }

  function render() {
    fit();
    world.replaceChildren();
    const s = 0.01 * view.w;                        // a joint's radius, a support's size
    const fs = 0.017 * view.w;                      // label size
    const labelled = truss.members.length <= 40;    // force labels while they stay readable
    // members, coloured by their force when the answer is for this drawing
    truss.members.forEach(([i, j], k) => {
      const a = truss.nodes[i], b = truss.nodes[j];
      if (!a || !b) return;
      let cls = 'member';
      const F = forces ? forces.members[k] : undefined;
      if (F !== undefined) cls += F > 0 ? ' tension' : F < 0 ? ' compression' : ' zero';
      const line = el('line', { class: cls, x1: a.x, y1: -a.y, x2: b.x, y2: -b.y, 'vector-effect': 'non-scaling-stroke' }, world);
      line.dataset.member = String(k + 1);
      if (F !== undefined) {
        line.dataset.force = String(F);
        const t = el('text', { class: 'force-label', x: (a.x + b.x) / 2, y: -(a.y + b.y) / 2, 'font-size': fs,
          'text-anchor': 'middle', 'dominant-baseline': 'middle' }, world);
        t.textContent = fmtForce(F);
        if (!labelled) t.setAttribute('visibility', 'hidden');
        const title = el('title', {}, line);
        title.textContent = `member ${k + 1}: ${fmtForce(F)} (${F > 0 ? 'tension' : F < 0 ? 'compression' : 'no force'})`;
      }
    });
    if (drag) {
      const a = truss.nodes[drag.from];
      el('line', { class: 'rubber', x1: a.x, y1: -a.y, x2: drag.x, y2: -drag.y, 'vector-effect': 'non-scaling-stroke' }, world);
    }
    // supports under their joints
    for (const sp of truss.supports) {
      const n = truss.nodes[sp.node];
      if (!n) continue;
      const g = el('g', { class: 'support' }, world);
      g.dataset.support = `${sp.node + 1},${sp.fx},${sp.fy}`;
      if (sp.fy) {
        el('polygon', { points: `${n.x},${-n.y} ${n.x - 1.6 * s},${-(n.y - 2.6 * s)} ${n.x + 1.6 * s},${-(n.y - 2.6 * s)}` }, g);
        if (!sp.fx) el('line', { x1: n.x - 2 * s, y1: -(n.y - 3.3 * s), x2: n.x + 2 * s, y2: -(n.y - 3.3 * s), 'vector-effect': 'non-scaling-stroke' }, g);
      } else {
        el('polygon', { points: `${n.x},${-n.y} ${n.x - 2.6 * s},${-(n.y + 1.6 * s)} ${n.x - 2.6 * s},${-(n.y - 1.6 * s)}` }, g);
        el('line', { x1: n.x - 3.3 * s, y1: -(n.y + 2 * s), x2: n.x - 3.3 * s, y2: -(n.y - 2 * s), 'vector-effect': 'non-scaling-stroke' }, g);
      }
    }
    // loads and reactions: one arrow length scale for both
    const all = truss.loads.map((l) => Math.hypot(l.Fx, l.Fy))
      .concat(forces ? forces.reactions.map((r) => Math.hypot(r.Rx, r.Ry)) : []);
    const big = Math.max(1e-300, ...all), sc = 0.18 * Math.max(view.w, view.h) / big;
    for (const l of truss.loads) {
      const n = truss.nodes[l.node];
      if (n) arrow(n.x, n.y, sc * l.Fx, sc * l.Fy, 'load', world);
    }
    if (forces) {
      for (const r of forces.reactions) {
        const n = truss.nodes[r.node];
        if (!n) continue;
        if (r.Rx) arrow(n.x, n.y, sc * r.Rx, 0, 'reaction', world);
        if (r.Ry) arrow(n.x, n.y, 0, sc * r.Ry, 'reaction', world);
        const t = el('text', { class: 'force-label', x: n.x, y: -(n.y - 5 * s), 'font-size': fs, 'text-anchor': 'middle' }, world);
        t.textContent = `R ${fmtForce(Math.hypot(r.Rx, r.Ry))}`;
      }
    }
    truss.nodes.forEach((n, i) => {
      const c = el('circle', { class: 'joint', cx: n.x, cy: -n.y, r: s, 'vector-effect': 'non-scaling-stroke' }, world);
      c.dataset.joint = String(i + 1);
      const t = el('text', { class: 'joint-label', x: n.x + 1.3 * s, y: -(n.y + 1.3 * s), 'font-size': 0.8 * fs }, world);
      t.textContent = String(i + 1);
    });
    root.dataset.joints = String(truss.nodes.length);
    root.dataset.members = String(truss.members.length);
  }

  // ---- answers ---------------------------------------------------------------------------------

  function sameTruss(a, b) {
    return JSON.stringify(toParams(a)) === JSON.stringify(toParams(b));
  }

  const offAnswer = api.onAnswer((answer) => {
    if (!answer) return;
    if (answer.error) {
      forces = null;
      render();
      status(answer.error.message || 'no solution', 'bad');
      root.dataset.state = 'error';
      return;
    }
    const t = answer.params ? fromParams(answer.params) : fromParams(api.getParams());
    if (!sameTruss(t, fromParams(api.getParams()))) return;   // stale: a newer drawing is being solved
    if (!sameTruss(t, truss)) truss = t;      // edited in the form, or loaded from a URL
    const mt = (answer.tables || []).find((x) => x.name === 'members');
    const rt = (answer.tables || []).find((x) => x.name === 'reactions');
    if (mt) {
      const fi = mt.columns.indexOf('force');
      const ri = rt ? { node: rt.columns.indexOf('node'), Rx: rt.columns.indexOf('Rx'), Ry: rt.columns.indexOf('Ry') } : null;
      forces = {
        members: mt.rows.map((r) => Number(r[fi])),
        reactions: rt ? rt.rows.map((r) => ({ node: Number(r[ri.node]) - 1, Rx: Number(r[ri.Rx]), Ry: Number(r[ri.Ry]) })) : [],
      };
    }
    render();
    const det = (answer.scalars || []).find((x) => x.name === 'determinacy');
    const warn = (answer.warnings || []).join(' ');
    status(`Determinate (m + r − 2j = ${det ? det.value : 0}). Red: tension, blue: compression.${warn ? ' ' + warn : ''}`,
      warn ? 'bad' : 'ok');
    root.dataset.state = 'solved';
  });

  render();
  return () => {
    if (typeof offAnswer === 'function') offAnswer();
    svg.removeEventListener('pointerdown', onDown);
    svg.removeEventListener('pointermove', onMove);
    svg.removeEventListener('pointerup', onUp);
    root.remove();
    style.remove();
  };
}
