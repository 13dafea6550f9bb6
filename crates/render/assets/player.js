// dissect motion player: the figures of a dissection and the motion of its
// pieces from one figure to another, on a canvas (2D lattices) or in a small
// built-in 3D view (cubic: shaded cubes, piece edges, exploded view, drag to
// turn). Plain ES module without imports, used by the studio (/player.js)
// and inlined in the HTML page of `dissect render --format html`.
//
// The data is `dissect-animation/1` from dissect_render::animation: every
// figure's pieces (outline rings or cubes, in lattice units), the rigid map
// `x -> matrix·x + shift` carrying each piece from figure 0 to that figure,
// and an assembly order per figure. A 3D figure that comes apart carries its
// disassembly plan (`plan`: moves of a piece or a group by a displacement, in
// order): the motion takes the first figure apart by its plan's moves, carries
// the pieces over, turning, to where the next figure's plan leaves them, and
// puts the next figure together by its plan in reverse. This module only
// interpolates those maps and moves.

const STYLE = `
.dp { font: 14px system-ui, sans-serif; color: #1d1d1f; }
.dp-bar { display: flex; flex-wrap: wrap; gap: 8px 14px; align-items: center; margin: 6px 0; }
.dp-bar label { display: inline-flex; gap: 4px; align-items: center; }
.dp-bar input[type=range] { width: 180px; }
.dp-bar button { font: inherit; padding: 3px 10px; border: 1px solid #bbb; border-radius: 5px; background: #fff; cursor: pointer; }
.dp-legend { display: flex; flex-wrap: wrap; gap: 6px; margin: 4px 0; }
.dp-legend label { display: inline-flex; align-items: center; gap: 4px; padding: 2px 8px; border-radius: 4px; border: 1px solid #0002; cursor: pointer; }
.dp-stage { position: relative; border: 1px solid #ddd; border-radius: 6px; background: #fff; touch-action: none; }
.dp-stage canvas { display: block; width: 100%; }
.dp-plan { color: #555; font-size: 13px; }
.dp-hint { position: absolute; right: 8px; bottom: 6px; color: #888; font-size: 12px; pointer-events: none; }
`;

const smooth = (s) => s * s * (3 - 2 * s);
const clamp01 = (v) => Math.max(0, Math.min(1, v));
const lerp = (a, b, s) => a.map((v, j) => v + (b[j] - v) * s);
const add3 = (a, b) => a.map((v, j) => v + b[j]);

// ------------------------------------------------------------ linear algebra

const matMul = (a, b) => a.map((row) => b[0].map((_, c) => row.reduce((s, v, k) => s + v * b[k][c], 0)));
const transpose = (a) => a[0].map((_, c) => a.map((row) => row[c]));
const apply = (m, x) => m.map((row) => row.reduce((s, v, k) => s + v * x[k], 0));
const det = (m) => (m.length === 2
  ? m[0][0] * m[1][1] - m[0][1] * m[1][0]
  : m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
    + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]));

/** The rotation/flip at fraction s of the way from the identity to the orthogonal map r. */
export function partialMap(r, s) {
  if (r.length === 2) {
    const th = Math.atan2(r[1][0], r[0][0]);
    const a = th * s, c = Math.cos(a), n = Math.sin(a);
    // A flip (det -1) turns the piece over about its own x axis: y scales by cos(πs).
    const f = det(r) < 0 ? Math.cos(Math.PI * s) : 1;
    return [[c, -n * f], [n, c * f]];
  }
  // 3D: rotation by s·angle about the rotation's axis (quaternion slerp from 1).
  let [w, x, y, z] = quaternion(r);
  if (w < 0) { w = -w; x = -x; y = -y; z = -z; }
  const half = Math.acos(Math.min(1, w));
  const sn = Math.sin(half);
  if (sn < 1e-9) return [[1, 0, 0], [0, 1, 0], [0, 0, 1]];
  const h = half * s, k = Math.sin(h) / sn;
  return quatMatrix([Math.cos(h), x * k, y * k, z * k]);
}

function quaternion(m) {
  const t = m[0][0] + m[1][1] + m[2][2];
  if (t > 0) {
    const s = Math.sqrt(t + 1) * 2;
    return [s / 4, (m[2][1] - m[1][2]) / s, (m[0][2] - m[2][0]) / s, (m[1][0] - m[0][1]) / s];
  }
  if (m[0][0] > m[1][1] && m[0][0] > m[2][2]) {
    const s = Math.sqrt(1 + m[0][0] - m[1][1] - m[2][2]) * 2;
    return [(m[2][1] - m[1][2]) / s, s / 4, (m[0][1] + m[1][0]) / s, (m[0][2] + m[2][0]) / s];
  }
  if (m[1][1] > m[2][2]) {
    const s = Math.sqrt(1 + m[1][1] - m[0][0] - m[2][2]) * 2;
    return [(m[0][2] - m[2][0]) / s, (m[0][1] + m[1][0]) / s, s / 4, (m[1][2] + m[2][1]) / s];
  }
  const s = Math.sqrt(1 + m[2][2] - m[0][0] - m[1][1]) * 2;
  return [(m[1][0] - m[0][1]) / s, (m[0][2] + m[2][0]) / s, (m[1][2] + m[2][1]) / s, s / 4];
}

function quatMatrix([w, x, y, z]) {
  return [
    [1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)],
    [2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)],
    [2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)],
  ];
}

// ------------------------------------------------------------------ 3D faces

const AXES = [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]];
const ckey = (c) => c.join(',');

/** The outer faces of a piece's cubes, with which edges are piece edges (dark) and which are inner cube edges (faint). */
function pieceFaces(cubes) {
  const has = new Set(cubes.map(ckey));
  const add = (a, b) => a.map((v, j) => v + b[j]);
  const faces = [];
  for (const c of cubes) {
    for (const n of AXES) {
      if (has.has(ckey(add(c, n)))) continue;
      const axis = n.findIndex((v) => v !== 0);
      const [u, v] = [0, 1, 2].filter((j) => j !== axis);
      const base = c.slice();
      if (n[axis] > 0) base[axis] += 1;
      const corner = (du, dv) => { const p = base.slice(); p[u] += du; p[v] += dv; return p; };
      const pts = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
      // Edge k joins pts[k] and pts[k+1]; the coplanar neighbour across it:
      const across = [[v, -1], [u, 1], [v, 1], [u, -1]].map(([j, d]) => {
        const t = [0, 0, 0]; t[j] = d;
        const m = add(c, t);
        return !(has.has(ckey(m)) && !has.has(ckey(add(m, n))));
      });
      faces.push({ pts, normal: n, dark: across });
    }
  }
  return faces;
}

// -------------------------------------------------------------------- player

let styled = false;

/**
 * Builds the player in `host` for the animation `data`. Returns its API
 * (also stored as host.player): state(), setT(t), setFigures(a, b),
 * setMode('motion'|'figures'), map(i, x), play(), pause(), redraw().
 */
export function createPlayer(host, data, options = {}) {
  if (!styled && typeof document !== 'undefined') {
    const st = document.createElement('style');
    st.textContent = STYLE;
    document.head.append(st);
    styled = true;
  }
  const dim = data.dim;
  const nPieces = data.pieces.length;
  const nFigs = data.figures.length;
  const st = {
    mode: options.mode || (dim === 3 ? 'figures' : 'motion'),
    from: 0,
    to: Math.min(1, nFigs - 1),
    t: options.t ?? 0,
    oneAtATime: false,
    explode: 0,
    hidden: new Set(),
    yaw: 0.55,
    pitch: 0.62,
    zoom: 1,
    playing: false,
    hot: -1,
  };
  const faces = dim === 3 ? data.figures.map((f) => f.pieces.map((p) => pieceFaces(p.cubes))) : null;
  // How far a piece reaches from its centre (it turns within this ball).
  const radius = data.figures[0].pieces.map((p) => {
    const pts = dim === 3
      ? p.cubes.flatMap((c) => [0, 1, 2, 3, 4, 5, 6, 7].map((k) => c.map((v, j) => v + ((k >> j) & 1))))
      : p.rings.flat();
    return Math.sqrt(Math.max(...pts.map((q) => q.reduce((a, v, j) => a + (v - p.centre[j]) ** 2, 0))));
  });
  // In 3D a moving piece rises and comes down again, so pieces pass over each other.
  const lift = dim === 3 ? 1 + Math.max(...data.figures.map((f) => f.max[2] - f.min[2])) : 0;

  host.textContent = '';
  host.classList.add('dp');
  const el = (tag, props = {}, ...kids) => {
    const e = document.createElement(tag);
    Object.assign(e, props);
    e.append(...kids);
    return e;
  };
  const figOptions = () => data.figures.map((f, i) => el('option', { value: String(i), textContent: f.name }));
  const mode = el('select', { title: 'What to show' },
    el('option', { value: 'motion', textContent: 'motion' }), el('option', { value: 'figures', textContent: 'all figures' }));
  const fromSel = el('select', { title: 'from figure' }, ...figOptions());
  const toSel = el('select', { title: 'to figure' }, ...figOptions());
  const play = el('button', { type: 'button', textContent: '▶ Play' });
  const slider = el('input', { type: 'range', min: 0, max: 1000, value: String(Math.round(st.t * 1000)), title: 'motion' });
  const one = el('input', { type: 'checkbox' });
  const explode = el('input', { type: 'range', min: 0, max: 100, value: '0', title: 'exploded view' });
  const reset = el('button', { type: 'button', textContent: 'Reset view' });
  const motionBits = el('span', { className: 'dp-motion', style: 'display:inline-flex;gap:8px;align-items:center' },
    fromSel, el('span', { textContent: '→' }), toSel, play, slider,
    el('label', { title: 'move the pieces one at a time, in an order a person could lay them down' }, one, 'one at a time'));
  const planInfo = el('span', { className: 'dp-plan' });
  planInfo.dataset.testid = 'plan-step';
  const bar = el('div', { className: 'dp-bar' }, mode, motionBits, planInfo);
  if (dim === 3) bar.append(el('label', {}, 'explode', explode), reset);
  const legend = el('div', { className: 'dp-legend' });
  const canvas = el('canvas');
  const stage = el('div', { className: 'dp-stage' }, canvas);
  if (dim === 3) stage.append(el('div', { className: 'dp-hint', textContent: 'drag to turn · wheel to zoom' }));
  host.append(bar, legend, stage);
  data.pieces.forEach((p, i) => {
    const box = el('input', { type: 'checkbox', checked: true, title: `show piece ${p.label}` });
    box.dataset.piece = String(i);
    box.onchange = () => { if (box.checked) st.hidden.delete(i); else st.hidden.add(i); draw(); };
    const lab = el('label', {}, box, `${p.label} · ${p.area}`);
    lab.style.background = p.colour;
    lab.onmouseenter = () => { st.hot = i; draw(); };
    lab.onmouseleave = () => { st.hot = -1; draw(); };
    legend.append(lab);
  });
  toSel.value = String(st.to);
  mode.value = st.mode;

  // ------------------------------------------------------------- layout

  // Room between figures: in 3D enough that turned figures do not overlap on screen.
  const gap = dim === 3
    ? Math.max(2, 0.6 * Math.max(...data.figures.map((f) => Math.max(f.max[1] - f.min[1], f.max[2] - f.min[2]))))
    : 1.5;
  /** Offsets placing the figures `list` in a row (x), each starting at 0 in the other coordinates. */
  function row(list) {
    const off = new Map();
    let x = 0;
    for (const f of list) {
      const fig = data.figures[f];
      const o = fig.min.map((v) => -v);
      o[0] += x;
      off.set(f, o);
      x += fig.max[0] - fig.min[0] + gap;
    }
    return off;
  }

  const explodeOffset = (f, i) => {
    if (!st.explode) return new Array(dim).fill(0);
    const fig = data.figures[f];
    const mid = fig.min.map((v, j) => (v + fig.max[j]) / 2);
    return fig.pieces[i].centre.map((v, j) => (v - mid[j]) * st.explode);
  };

  /** The pieces as drawn now: {piece, fig (its geometry), m, c (centre in fig coords), p (stage position), s}. */
  function instances() {
    const out = [];
    if (st.mode === 'figures') {
      const off = row(data.figures.map((_, f) => f));
      const id = dim === 3 ? [[1, 0, 0], [0, 1, 0], [0, 0, 1]] : [[1, 0], [0, 1]];
      data.figures.forEach((fig, f) => fig.pieces.forEach((pc, i) => {
        const e = explodeOffset(f, i);
        out.push({ piece: i, fig: f, m: id, c: pc.centre, p: pc.centre.map((v, j) => v + off.get(f)[j] + e[j]), s: 0 });
      }));
      return { out, off };
    }
    const a = st.from, b = st.to;
    const off = row(a === b ? [a] : [a, b]);
    const order = data.figures[b].order;
    const tl = timeline(a, b);
    if (tl) return { out: planned(a, b, off, order, tl), off, moving: true };
    for (let i = 0; i < nPieces; i++) {
      let s = st.t;
      if (st.oneAtATime) s = clamp01(st.t * nPieces - order.indexOf(i));
      s = smooth(clamp01(s));
      const pa = data.figures[a].pieces[i], pb = data.figures[b].pieces[i];
      const r = matMul(pb.matrix, transpose(pa.matrix));
      const ea = explodeOffset(a, i), eb = explodeOffset(b, i);
      const from = pa.centre.map((v, j) => v + off.get(a)[j] + ea[j]);
      const to = pb.centre.map((v, j) => v + off.get(b)[j] + eb[j]);
      const p = lerp(from, to, s);
      if (dim === 3) p[2] += lift * Math.sin(Math.PI * s);
      out.push({ piece: i, fig: a, m: partialMap(r, s), c: pa.centre, p, s, from, to });
    }
    return { out, off, moving: true };
  }

  // ------------------------------------------------ disassembly plans (3D)

  // The carrying over from one figure to the next lasts as long as TRANSIT moves of a plan.
  const TRANSIT = 3;
  /** A plan's moves with every piece's offset after each: cum[k][i] after k moves. */
  function staged(moves) {
    const cum = [Array.from({ length: nPieces }, () => [0, 0, 0])];
    for (const m of moves) {
      const prev = cum[cum.length - 1];
      cum.push(prev.map((o, i) => (m.pieces.includes(i) ? o.map((v, j) => v + m.by[j]) : o)));
    }
    return { moves, cum, apart: cum[cum.length - 1] };
  }
  const plans = data.figures.map((f) => (dim === 3 && Array.isArray(f.plan) ? staged(f.plan) : null));
  /** The motion from figure a to b in moves: a's plan, the carrying over, b's plan in reverse (null: no plan on either side). */
  function timeline(a, b) {
    const pa = plans[a], pb = plans[b];
    if (!pa && !pb) return null;
    const na = pa ? pa.moves.length : 0, nb = pb ? pb.moves.length : 0;
    return { pa, pb, na, nb, total: na + TRANSIT + nb };
  }
  /** Piece i's offset in plan pl after k moves and the fraction f of move k. */
  function offsetAt(pl, k, f, i) {
    if (!pl) return [0, 0, 0];
    const o = pl.cum[Math.min(k, pl.moves.length)][i];
    const m = pl.moves[k];
    if (f <= 0 || !m || !m.pieces.includes(i)) return o;
    return o.map((v, j) => v + m.by[j] * f);
  }
  /** The pieces at st.t when a plan is played (see timeline). */
  function planned(a, b, off, order, tl) {
    const u = st.t * tl.total;
    const out = [];
    for (let i = 0; i < nPieces; i++) {
      const pa = data.figures[a].pieces[i], pb = data.figures[b].pieces[i];
      const r = matMul(pb.matrix, transpose(pa.matrix));
      const home = pa.centre.map((v, j) => v + off.get(a)[j]);
      const dest = pb.centre.map((v, j) => v + off.get(b)[j]);
      const zero = [0, 0, 0];
      const from = add3(home, tl.pa ? tl.pa.apart[i] : zero);
      const to = add3(dest, tl.pb ? tl.pb.apart[i] : zero);
      // Every place the piece passes through, for the frame.
      const rest = [...(tl.pa ? tl.pa.cum : [[zero]]).map((c) => add3(home, c[i] || zero)),
        ...(tl.pb ? tl.pb.cum : [[zero]]).map((c) => add3(dest, c[i] || zero))];
      let p, m, s;
      if (u < tl.na) {
        const k = Math.floor(u);
        p = add3(home, offsetAt(tl.pa, k, smooth(u - k), i));
        m = partialMap(r, 0);
        s = 0;
      } else if (u <= tl.na + TRANSIT) {
        s = (u - tl.na) / TRANSIT;
        if (st.oneAtATime) s = clamp01(s * nPieces - order.indexOf(i));
        s = smooth(clamp01(s));
        p = lerp(from, to, s);
        p[2] += lift * Math.sin(Math.PI * s);
        m = partialMap(r, s);
      } else {
        const v = Math.min(tl.nb, u - tl.na - TRANSIT), j = Math.floor(v);
        p = add3(dest, j >= tl.nb ? zero : offsetAt(tl.pb, tl.nb - 1 - j, 1 - smooth(v - j), i));
        m = r;
        s = 1;
      }
      out.push({ piece: i, fig: a, m, c: pa.centre, p, s, from, to, rest });
    }
    return out;
  }

  const letter = (i) => data.pieces[i].label;
  /** What the plan is doing now, in words (empty without a plan). */
  function planText() {
    const tl = st.mode === 'motion' ? timeline(st.from, st.to) : null;
    if (!tl) return '';
    const u = st.t * tl.total;
    const say = (fig, pl, k, verb) => {
      const m = pl.moves[k];
      const what = m.pieces.map(letter).join('+');
      return `${data.figures[fig].name}: move ${k + 1} of ${pl.moves.length} (level ${data.figures[fig].level}): ${what} ${m.removed ? verb : 'slides'}`;
    };
    if (u < tl.na) return say(st.from, tl.pa, Math.floor(u), 'comes out');
    if (u <= tl.na + TRANSIT) return 'to the next figure';
    const j = Math.min(tl.nb - 1, Math.floor(u - tl.na - TRANSIT));
    return say(st.to, tl.pb, tl.nb - 1 - j, 'goes in');
  }

  const place = (inst, x) => {
    const d = x.map((v, j) => v - inst.c[j]);
    return apply(inst.m, d).map((v, j) => v + inst.p[j]);
  };

  // -------------------------------------------------------------- drawing

  let view = null; // the last frame's projection, for tests
  function size() {
    const w = Math.max(200, host.clientWidth || options.width || 800);
    const h = options.height || (dim === 3 ? 420 : 360);
    const dpr = (typeof window !== 'undefined' && window.devicePixelRatio) || 1;
    canvas.width = Math.round(w * dpr);
    canvas.height = Math.round(h * dpr);
    canvas.style.height = `${h}px`;
    return { w, h, dpr };
  }

  function draw() {
    const { w, h, dpr } = size();
    const g = canvas.getContext('2d');
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    g.fillStyle = '#ffffff';
    g.fillRect(0, 0, w, h);
    const { out, off, moving } = instances();
    if (dim === 3) draw3d(g, w, h, out, off, moving); else draw2d(g, w, h, out, off, moving);
    slider.value = String(Math.round(st.t * 1000));
    host.dataset.t = String(st.t);
    planInfo.textContent = planText();
  }

  function draw2d(g, w, h, out, off, moving) {
    // Frame every figure slot (and where moving pieces may pass).
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    for (const [f, o] of off) {
      const fig = data.figures[f];
      for (let j = 0; j < 2; j++) { lo[j] = Math.min(lo[j], fig.min[j] + o[j]); hi[j] = Math.max(hi[j], fig.max[j] + o[j]); }
    }
    if (moving) {
      // Room for every piece turning on its way (a disc round its path).
      for (const inst of out) {
        const rad = radius[inst.piece];
        for (const q of [inst.from, inst.to]) {
          for (let j = 0; j < 2; j++) { lo[j] = Math.min(lo[j], q[j] - rad); hi[j] = Math.max(hi[j], q[j] + rad); }
        }
      }
    }
    const margin = 24;
    const k = Math.min((w - 2 * margin) / (hi[0] - lo[0]), (h - 2 * margin - 18) / (hi[1] - lo[1]));
    const ox = (w - k * (hi[0] - lo[0])) / 2 - k * lo[0];
    const oy = margin - k * lo[1];
    const px = ([x, y]) => [ox + k * x, oy + k * y];
    view = { k, ox, oy };
    const path = (rings, map) => {
      g.beginPath();
      for (const ring of rings) {
        ring.forEach((pt, j) => { const [x, y] = px(map(pt)); if (j) g.lineTo(x, y); else g.moveTo(x, y); });
        g.closePath();
      }
    };
    // Ghosts of the figures' outlines.
    for (const [f, o] of off) {
      const fig = data.figures[f];
      // All pieces' rings in one path (outer rings and holes run opposite ways): no seams.
      path(fig.pieces.flatMap((pc) => pc.rings), (pt) => [pt[0] + o[0], pt[1] + o[1]]);
      g.fillStyle = '#eef0f4';
      g.fill('nonzero');
    }
    // Pieces still at rest first, moving pieces on top.
    const sorted = out.slice().sort((a, b) => (a.s > 0 && a.s < 1) - (b.s > 0 && b.s < 1));
    for (const inst of sorted) {
      if (st.hidden.has(inst.piece)) continue;
      const pc = data.figures[inst.fig].pieces[inst.piece];
      path(pc.rings, (pt) => place(inst, pt));
      g.globalAlpha = st.hot < 0 || st.hot === inst.piece ? 1 : 0.3;
      g.fillStyle = data.pieces[inst.piece].colour;
      g.fill('evenodd');
      g.lineWidth = st.hot === inst.piece ? 3 : 1.5;
      g.strokeStyle = '#1d1d1f';
      g.lineJoin = 'round';
      g.stroke();
      if (k >= 14) {
        const [lx, ly] = px(place(inst, pc.label_at));
        g.fillStyle = '#1d1d1f';
        g.font = `${Math.min(16, Math.round(k * 0.6))}px system-ui, sans-serif`;
        g.textAlign = 'center';
        g.textBaseline = 'middle';
        g.fillText(data.pieces[inst.piece].label, lx, ly);
        g.textBaseline = 'alphabetic';
      }
      g.globalAlpha = 1;
    }
    // The figures' names last, on a white halo: pieces passing by never hide them.
    g.font = '13px system-ui, sans-serif';
    g.textAlign = 'center';
    g.lineJoin = 'round';
    for (const [f, o] of off) {
      const fig = data.figures[f];
      const [cx] = px([(fig.min[0] + fig.max[0]) / 2 + o[0], 0]);
      const cy = oy + k * (fig.max[1] + o[1]) + 16;
      g.strokeStyle = 'rgba(255,255,255,0.85)';
      g.lineWidth = 4;
      g.strokeText(fig.name, cx, cy);
      g.fillStyle = '#6b6b70';
      g.fillText(fig.name, cx, cy);
    }
  }

  function basis() {
    const { yaw, pitch } = st;
    const e = [Math.cos(pitch) * Math.sin(yaw), Math.cos(pitch) * Math.cos(yaw), Math.sin(pitch)];
    const r = [Math.cos(yaw), -Math.sin(yaw), 0];
    const u = [-Math.sin(pitch) * Math.sin(yaw), -Math.sin(pitch) * Math.cos(yaw), Math.cos(pitch)];
    // Screen up is +z; seen from above, rows (y) run down the screen as in the layer editor.
    return { e, r, u };
  }

  function draw3d(g, w, h, out, off, moving) {
    const { e, r, u } = basis();
    const dot = (a, b) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    // Frame: the corners of every figure slot (exploded), projected.
    let lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
    const widen = (p) => {
      const s = [dot(p, r), -dot(p, u)];
      for (let j = 0; j < 2; j++) { lo[j] = Math.min(lo[j], s[j]); hi[j] = Math.max(hi[j], s[j]); }
    };
    for (const [f, o] of off) {
      const fig = data.figures[f];
      const grow = 1 + st.explode;
      const mid = fig.min.map((v, j) => (v + fig.max[j]) / 2);
      for (let c = 0; c < 8; c++) {
        const p = [0, 1, 2].map((j) => {
          const v = (c >> j) & 1 ? fig.max[j] : fig.min[j];
          return mid[j] + (v - mid[j]) * grow + o[j];
        });
        widen(p);
      }
    }
    if (moving) {
      for (const inst of out) {
        const rad = radius[inst.piece];
        const top = lerp(inst.from, inst.to, 0.5);
        top[2] += lift;
        for (const q of [inst.from, inst.to, top, ...(inst.rest || [])]) {
          const s = [dot(q, r), -dot(q, u)];
          for (let j = 0; j < 2; j++) { lo[j] = Math.min(lo[j], s[j] - rad); hi[j] = Math.max(hi[j], s[j] + rad); }
        }
      }
    }
    const margin = 16, names = 22; // room below for the figures' names
    const k = st.zoom * Math.min((w - 2 * margin) / (hi[0] - lo[0]), (h - 2 * margin - names) / (hi[1] - lo[1]));
    const ox = w / 2 - k * (lo[0] + hi[0]) / 2;
    const oy = (h - names) / 2 - k * (lo[1] + hi[1]) / 2;
    view = { k, ox, oy, r, u, e };
    const px = (p) => [ox + k * dot(p, r), oy - k * dot(p, u)];
    const light = [0.35, 0.55, 0.76];
    const quads = [];
    for (const inst of out) {
      if (st.hidden.has(inst.piece)) continue;
      for (const fc of faces[inst.fig][inst.piece]) {
        const n = apply(inst.m, fc.normal);
        if (dot(n, e) <= 1e-6) continue;
        const pts = fc.pts.map((p) => place(inst, p));
        const mid = pts.reduce((a, p) => a.map((v, j) => v + p[j] / 4), [0, 0, 0]);
        quads.push({ inst, pts, n, dark: fc.dark, depth: dot(mid, e) });
      }
    }
    quads.sort((a, b) => a.depth - b.depth);
    g.lineJoin = 'round';
    for (const q of quads) {
      const i = q.inst.piece;
      const col = data.pieces[i].colour;
      const shade = 0.62 + 0.38 * Math.max(0, dot(q.n, light.map((v) => v)));
      const pts = q.pts.map(px);
      g.beginPath();
      pts.forEach(([x, y], j) => (j ? g.lineTo(x, y) : g.moveTo(x, y)));
      g.closePath();
      g.globalAlpha = st.hot < 0 || st.hot === i ? 1 : 0.25;
      g.fillStyle = shadeColour(col, shade);
      g.fill();
      g.strokeStyle = shadeColour(col, shade);
      g.lineWidth = 1;
      g.stroke(); // hides the seams between faces
      for (let j = 0; j < 4; j++) {
        const [a, b] = [pts[j], pts[(j + 1) % 4]];
        g.beginPath(); g.moveTo(...a); g.lineTo(...b);
        g.strokeStyle = q.dark[j] ? '#1d1d1f' : 'rgba(0,0,0,0.12)';
        g.lineWidth = q.dark[j] ? 1.6 : 1;
        g.stroke();
      }
      g.globalAlpha = 1;
    }
    g.fillStyle = '#6b6b70';
    g.font = '13px system-ui, sans-serif';
    g.textAlign = 'center';
    for (const [f, o] of off) {
      // Under the lowest corner of the figure's box on screen.
      const fig = data.figures[f];
      let bottom = -Infinity;
      for (let c = 0; c < 8; c++) {
        const p = [0, 1, 2].map((j) => ((c >> j) & 1 ? fig.max[j] : fig.min[j]) + o[j]);
        bottom = Math.max(bottom, px(p)[1]);
      }
      const [x] = px([(fig.min[0] + fig.max[0]) / 2 + o[0], (fig.min[1] + fig.max[1]) / 2 + o[1], fig.min[2] + o[2]]);
      g.fillText(fig.name, x, Math.min(h - 4, bottom + 16));
    }
  }

  // ------------------------------------------------------------- controls

  let raf = 0, last = 0;
  const duration = () => {
    const tl = timeline(st.from, st.to);
    return 2500 + 500 * (st.oneAtATime ? nPieces : 1) + (tl ? 700 * (tl.na + tl.nb) : 0);
  };
  function tick(now) {
    if (!st.playing) return;
    if (last) st.t = Math.min(1, st.t + (now - last) / duration());
    last = now;
    draw();
    if (st.t >= 1) { api.pause(); return; }
    raf = requestAnimationFrame(tick);
  }
  const api = {
    data,
    state() {
      const { out, off } = instances();
      return {
        mode: st.mode, from: st.from, to: st.to, t: st.t, oneAtATime: st.oneAtATime, explode: st.explode,
        hidden: [...st.hidden], lift, yaw: st.yaw, pitch: st.pitch, zoom: st.zoom,
        offsets: Object.fromEntries([...off].map(([f, o]) => [f, o])),
        pieces: out.map((p) => ({ piece: p.piece, figure: p.fig, s: p.s, matrix: p.m, centre: p.p })),
        // The plan's timeline (3D figures with a disassembly plan): moves of the first figure, the carrying over, moves of the second; in moves.
        timeline: (() => {
          const tl = st.mode === 'motion' ? timeline(st.from, st.to) : null;
          return tl && { from_moves: tl.na, transit: TRANSIT, to_moves: tl.nb, total: tl.total };
        })(),
        view,
      };
    },
    /** Where the point x (in the coordinates of the figure the piece is drawn from) of piece i is drawn now (stage coordinates). */
    map(i, x) {
      const inst = instances().out.find((p) => p.piece === i);
      return place(inst, x);
    },
    setT(t) { st.t = clamp01(t); draw(); },
    setFigures(a, b) { st.from = a; st.to = b; fromSel.value = String(a); toSel.value = String(b); draw(); },
    setMode(m) { st.mode = m; mode.value = m; sync(); draw(); },
    setOneAtATime(on) { st.oneAtATime = !!on; one.checked = !!on; draw(); },
    setExplode(v) { st.explode = v; explode.value = String(Math.round(v * 100)); draw(); },
    setVisible(i, on) { if (on) st.hidden.delete(i); else st.hidden.add(i); draw(); },
    play() {
      if (st.mode !== 'motion') api.setMode('motion');
      if (st.t >= 1) st.t = 0;
      st.playing = true; last = 0; play.textContent = '❚❚ Pause';
      raf = requestAnimationFrame(tick);
    },
    pause() { st.playing = false; cancelAnimationFrame(raf); play.textContent = '▶ Play'; },
    highlight(i) { st.hot = i; draw(); },
    redraw: draw,
  };
  function sync() {
    motionBits.style.display = st.mode === 'motion' ? 'inline-flex' : 'none';
  }
  mode.onchange = () => api.setMode(mode.value);
  fromSel.onchange = () => api.setFigures(Number(fromSel.value), Number(toSel.value));
  toSel.onchange = () => api.setFigures(Number(fromSel.value), Number(toSel.value));
  play.onclick = () => (st.playing ? api.pause() : api.play());
  slider.oninput = () => { api.pause(); st.t = Number(slider.value) / 1000; draw(); };
  one.onchange = () => api.setOneAtATime(one.checked);
  explode.oninput = () => api.setExplode(Number(explode.value) / 100);
  reset.onclick = () => { st.yaw = 0.55; st.pitch = 0.62; st.zoom = 1; draw(); };
  if (dim === 3) {
    let drag = null;
    canvas.addEventListener('pointerdown', (ev) => { drag = [ev.clientX, ev.clientY]; canvas.setPointerCapture(ev.pointerId); });
    canvas.addEventListener('pointermove', (ev) => {
      if (!drag) return;
      st.yaw += (ev.clientX - drag[0]) * 0.01;
      st.pitch = Math.max(-1.5, Math.min(1.5, st.pitch + (ev.clientY - drag[1]) * 0.01));
      drag = [ev.clientX, ev.clientY];
      draw();
    });
    const end = () => { drag = null; };
    canvas.addEventListener('pointerup', end);
    canvas.addEventListener('pointercancel', end);
    canvas.addEventListener('wheel', (ev) => {
      ev.preventDefault();
      st.zoom = Math.max(0.3, Math.min(5, st.zoom * Math.exp(-ev.deltaY * 0.001)));
      draw();
    }, { passive: false });
  }
  if (typeof ResizeObserver !== 'undefined') {
    let lastW = 0;
    new ResizeObserver(() => { if (host.clientWidth !== lastW) { lastW = host.clientWidth; draw(); } }).observe(host);
  }
  sync();
  draw();
  host.player = api;
  return api;
}

function shadeColour(hex, f) {
  const v = parseInt(hex.slice(1), 16);
  const c = [(v >> 16) & 255, (v >> 8) & 255, v & 255].map((x) => Math.round(Math.min(255, x * f)));
  return `rgb(${c[0]},${c[1]},${c[2]})`;
}
