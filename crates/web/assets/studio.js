// dissect studio: figure editor, solver client and solution viewer.
// Plain ES module, no build step. Talks to the JSON API of crates/web.

const $ = (sel, root = document) => root.querySelector(sel);
const $$ = (sel, root = document) => [...root.querySelectorAll(sel)];

// Piece colours (distinct, light enough for dark outlines).
export const PALETTE = [
  '#e6194b', '#3cb44b', '#4363d8', '#ffe119', '#f58231', '#911eb4', '#42d4f4', '#f032e6',
  '#bfef45', '#fabed4', '#469990', '#dcbeff', '#9a6324', '#fffac8', '#800000', '#aaffc3',
  '#808000', '#ffd8b1', '#000075', '#a9a9a9',
];
export const pieceColour = (i) => PALETTE[i % PALETTE.length];

const key = (x, y, t) => `${x},${y},${t}`;
const unkey = (k) => k.split(',').map(Number);

// ---------------------------------------------------------------- geometry

const CORNERS = (x, y) => [[x, y], [x + 1, y], [x + 1, y + 1], [x, y + 1]];

/** Polygons (in cell units) of a cell: [x,y,t] where t is the triangle on tri4, z on cubic. */
function cellPolygon(lattice, [x, y, t]) {
  if (lattice !== 'tri4') return CORNERS(x, y);
  const c = CORNERS(x, y);
  return [c[t], c[(t + 1) % 4], [x + 0.5, y + 0.5]];
}

/** Edges of a cell with the neighbour across each: [[p, q], neighbourKey]. */
function cellEdges(lattice, [x, y, t]) {
  const c = CORNERS(x, y);
  if (lattice !== 'tri4') {
    return [
      [[c[0], c[1]], key(x, y - 1, t)],
      [[c[1], c[2]], key(x + 1, y, t)],
      [[c[2], c[3]], key(x, y + 1, t)],
      [[c[3], c[0]], key(x - 1, y, t)],
    ];
  }
  const centre = [x + 0.5, y + 0.5];
  const across = [key(x, y - 1, 2), key(x + 1, y, 3), key(x, y + 1, 0), key(x - 1, y, 1)][t];
  return [
    [[c[t], c[(t + 1) % 4]], across],
    [[c[t], centre], key(x, y, (t + 3) % 4)],
    [[c[(t + 1) % 4], centre], key(x, y, (t + 1) % 4)],
  ];
}

/** Neighbours of an editor cell inside one layer (for flood fill). */
function neighbours(lattice, [x, y, t]) {
  if (lattice === 'tri4') return cellEdges(lattice, [x, y, t]).map((e) => unkey(e[1]));
  return [[x + 1, y, t], [x - 1, y, t], [x, y + 1, t], [x, y - 1, t]];
}

/** The cell under a point given in cell units (tri4 picks the triangle). */
function cellAt(lattice, fx, fy, layer) {
  const x = Math.floor(fx), y = Math.floor(fy);
  if (lattice === 'tri4') {
    const dx = fx - x - 0.5, dy = fy - y - 0.5;
    const t = Math.abs(dy) > Math.abs(dx) ? (dy < 0 ? 0 : 2) : (dx > 0 ? 1 : 3);
    return [x, y, t];
  }
  return [x, y, lattice === 'cubic' ? layer : 0];
}

/** All cells of block (x, y) on the current layer. */
function blockCells(lattice, x, y, layer) {
  if (lattice === 'tri4') return [0, 1, 2, 3].map((t) => [x, y, t]);
  return [[x, y, lattice === 'cubic' ? layer : 0]];
}

// ------------------------------------------------------------------- state

const state = {
  lattice: 'square',
  figures: [],
  tool: 'pen',
  undo: [],
  redo: [],
  job: null,
  events: null,
  result: null, // {lattice, solution, summary}
  hot: -1, // highlighted piece
  exports: [], // the server's download formats
};

function newFigure(name, w = 8, h = 8, d = 1) {
  return { name, w, h, d, layer: 0, cells: new Set() };
}

function figureName(i) {
  return `figure-${String.fromCharCode(97 + (i % 26))}.txt`;
}

// ----------------------------------------------------------------- editor

const CANVAS_MAX = 360;

function cellSize(fig) {
  return Math.max(8, Math.min(36, Math.floor(CANVAS_MAX / Math.max(fig.w, fig.h))));
}

function drawEditor(fig, card, preview = null) {
  const canvas = $('canvas.grid', card);
  const cs = cellSize(fig);
  const dpr = window.devicePixelRatio || 1;
  canvas.width = fig.w * cs * dpr + 1;
  canvas.height = fig.h * cs * dpr + 1;
  canvas.style.width = `${fig.w * cs + 1}px`;
  canvas.style.height = `${fig.h * cs + 1}px`;
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0.5, 0.5);
  g.clearRect(-1, -1, canvas.width, canvas.height);
  const L = state.lattice;
  const poly = (pts, fill) => {
    g.beginPath();
    pts.forEach(([px, py], i) => (i ? g.lineTo(px * cs, py * cs) : g.moveTo(px * cs, py * cs)));
    g.closePath();
    g.fillStyle = fill;
    g.fill();
  };
  // Ghost of the layer below (cubic).
  if (L === 'cubic' && fig.layer > 0) {
    for (const k of fig.cells) {
      const c = unkey(k);
      if (c[2] === fig.layer - 1) poly(cellPolygon(L, c), '#dfe6f3');
    }
  }
  for (const k of fig.cells) {
    const c = unkey(k);
    if (L === 'cubic' && c[2] !== fig.layer) continue;
    if (c[0] >= fig.w || c[1] >= fig.h) continue;
    poly(cellPolygon(L, c), '#2b2d42');
  }
  if (preview) {
    g.fillStyle = preview.fill ? 'rgba(37,99,235,.35)' : 'rgba(185,28,28,.3)';
    g.fillRect(preview.x0 * cs, preview.y0 * cs, (preview.x1 - preview.x0 + 1) * cs, (preview.y1 - preview.y0 + 1) * cs);
  }
  // Grid.
  g.strokeStyle = '#d9dbe1';
  g.lineWidth = 1;
  g.beginPath();
  for (let x = 0; x <= fig.w; x++) { g.moveTo(x * cs, 0); g.lineTo(x * cs, fig.h * cs); }
  for (let y = 0; y <= fig.h; y++) { g.moveTo(0, y * cs); g.lineTo(fig.w * cs, y * cs); }
  g.stroke();
  if (L === 'tri4') {
    g.strokeStyle = '#eceef2';
    g.beginPath();
    for (let y = 0; y < fig.h; y++) {
      for (let x = 0; x < fig.w; x++) {
        g.moveTo(x * cs, y * cs); g.lineTo((x + 1) * cs, (y + 1) * cs);
        g.moveTo((x + 1) * cs, y * cs); g.lineTo(x * cs, (y + 1) * cs);
      }
    }
    g.stroke();
  }
}

function countOf(fig) {
  return fig.cells.size;
}

function updateAreas() {
  const counts = state.figures.map(countOf);
  const max = Math.max(0, ...counts);
  const equal = counts.length > 0 && counts.every((c) => c === counts[0]);
  state.figures.forEach((fig, i) => {
    const card = cards()[i];
    if (!card) return;
    const short = max - counts[i];
    $('.count', card).textContent = short > 0 ? `${counts[i]} cells (−${short})` : `${counts[i]} cells`;
    card.classList.toggle('mismatch', !equal);
  });
  const el = $('#areas');
  const list = state.figures.map((f, i) => `${f.name}: ${counts[i]}`).join(' · ');
  const empty = state.figures.filter((f, i) => counts[i] === 0).map((f) => f.name);
  if (state.figures.length < 2) {
    el.className = 'areas bad';
    el.textContent = `A dissection needs two or more figures. ${list}`;
  } else if (empty.length === state.figures.length) {
    el.className = 'areas';
    el.textContent = 'Draw your figures (or start from an example): each needs the same number of cells.';
  } else if (equal && counts[0] > 0) {
    el.className = 'areas ok';
    el.textContent = `✓ Equal areas: every figure has ${counts[0]} cells`;
  } else {
    const diffs = state.figures
      .map((f, i) => (max - counts[i] > 0 ? `${f.name} needs ${max - counts[i]} more` : null))
      .filter(Boolean)
      .join(', ');
    el.className = 'areas bad';
    const diff = max - Math.min(...counts);
    el.textContent = `✗ Areas differ by ${diff} cell${diff === 1 ? '' : 's'} (${list}): ${diffs}`;
  }
  $('#solve').disabled = !(equal && counts[0] > 0 && state.figures.length >= 2) || !!state.job;
}

function cards() {
  return $$('#figures .card');
}

function renderFigures() {
  const host = $('#figures');
  host.textContent = '';
  state.figures.forEach((fig, i) => host.append(makeCard(fig, i)));
  updateAreas();
}

function redrawCard(i) {
  const card = cards()[i];
  if (card) drawEditor(state.figures[i], card);
}

function renderLayers(fig, card, i) {
  const host = $('.layers', card);
  host.textContent = '';
  for (let z = 0; z < fig.d; z++) {
    const b = document.createElement('button');
    b.textContent = `z${z}`;
    b.className = z === fig.layer ? 'active' : '';
    b.title = `Edit layer ${z}`;
    b.onclick = () => { fig.layer = z; renderLayers(fig, card, i); redrawCard(i); };
    host.append(b);
  }
}

function makeCard(fig, i) {
  const card = $('#figure-card').content.firstElementChild.cloneNode(true);
  card.dataset.index = i;
  card.dataset.testid = `figure-${i}`;
  const name = $('.name', card);
  name.value = fig.name;
  name.onchange = () => { fig.name = name.value.trim() || figureName(i); updateAreas(); };
  for (const dim of ['w', 'h', 'd']) {
    const input = $(`.${dim}`, card);
    input.value = fig[dim];
    input.onchange = () => {
      const v = Math.max(1, Math.min(dim === 'd' ? 64 : 128, Math.round(Number(input.value) || 1)));
      input.value = v;
      const before = new Set(fig.cells);
      fig[dim] = v;
      for (const k of [...fig.cells]) {
        const [x, y, t] = unkey(k);
        if (x >= fig.w || y >= fig.h || (state.lattice === 'cubic' && t >= fig.d)) fig.cells.delete(k);
      }
      fig.layer = Math.min(fig.layer, fig.d - 1);
      record(i, before);
      renderLayers(fig, card, i);
      drawEditor(fig, card);
      updateAreas();
    };
  }
  renderLayers(fig, card, i);
  $('.remove', card).onclick = () => {
    state.figures.splice(i, 1);
    state.undo = []; state.redo = [];
    renderFigures();
  };
  $('.clear', card).onclick = () => {
    const before = new Set(fig.cells);
    fig.cells.clear();
    record(i, before);
    drawEditor(fig, card);
    updateAreas();
  };
  $('.load', card).onchange = async (ev) => {
    const file = ev.target.files[0];
    ev.target.value = '';
    if (file) await loadFigureText(i, file.name, await file.text());
  };
  $('.picture', card).onchange = async (ev) => {
    const file = ev.target.files[0];
    ev.target.value = '';
    if (file) await loadPicture(i, file, Number($('.cells', card).value));
  };
  $('.save', card).onclick = () => saveFigures([i]);
  attachPointer(fig, card, i);
  drawEditor(fig, card);
  return card;
}

// Mouse: pen/erase strokes, rectangles, flood fill.
function attachPointer(fig, card, i) {
  const canvas = $('canvas.grid', card);
  let stroke = null;
  const at = (ev) => {
    const r = canvas.getBoundingClientRect();
    const cs = cellSize(fig);
    return [(ev.clientX - r.left) / cs, (ev.clientY - r.top) / cs];
  };
  const inside = ([x, y]) => x >= 0 && y >= 0 && x < fig.w && y < fig.h;
  const set = (c, on) => {
    if (!inside(c)) return;
    const k = key(...c);
    if (on) fig.cells.add(k); else fig.cells.delete(k);
  };
  canvas.addEventListener('contextmenu', (ev) => ev.preventDefault());
  canvas.addEventListener('pointerdown', (ev) => {
    ev.preventDefault();
    canvas.setPointerCapture(ev.pointerId);
    const [fx, fy] = at(ev);
    const c = cellAt(state.lattice, fx, fy, fig.layer);
    if (!inside(c)) return;
    const before = new Set(fig.cells);
    const filled = fig.cells.has(key(...c));
    const tool = ev.button === 2 ? 'erase' : state.tool;
    if (tool === 'fill') {
      floodFill(fig, c, !filled);
      record(i, before);
      drawEditor(fig, card);
      updateAreas();
      return;
    }
    if (tool === 'rect') {
      stroke = { tool, before, x0: c[0], y0: c[1], x1: c[0], y1: c[1], fill: !filled };
      drawEditor(fig, card, rectOf(stroke));
      return;
    }
    stroke = { tool, before, value: tool === 'erase' ? false : !filled };
    set(c, stroke.value);
    drawEditor(fig, card);
    updateAreas();
  });
  canvas.addEventListener('pointermove', (ev) => {
    if (!stroke) return;
    const [fx, fy] = at(ev);
    const c = cellAt(state.lattice, fx, fy, fig.layer);
    if (stroke.tool === 'rect') {
      stroke.x1 = Math.max(0, Math.min(fig.w - 1, c[0]));
      stroke.y1 = Math.max(0, Math.min(fig.h - 1, c[1]));
      drawEditor(fig, card, rectOf(stroke));
      return;
    }
    set(c, stroke.value);
    drawEditor(fig, card);
    updateAreas();
  });
  const end = () => {
    if (!stroke) return;
    if (stroke.tool === 'rect') {
      const r = rectOf(stroke);
      for (let y = r.y0; y <= r.y1; y++) {
        for (let x = r.x0; x <= r.x1; x++) {
          for (const c of blockCells(state.lattice, x, y, fig.layer)) set(c, r.fill);
        }
      }
    }
    record(i, stroke.before);
    stroke = null;
    drawEditor(fig, card);
    updateAreas();
  };
  canvas.addEventListener('pointerup', end);
  canvas.addEventListener('pointercancel', end);
}

function rectOf(s) {
  return {
    x0: Math.min(s.x0, s.x1), x1: Math.max(s.x0, s.x1),
    y0: Math.min(s.y0, s.y1), y1: Math.max(s.y0, s.y1), fill: s.fill,
  };
}

/** Sets the connected region of cells in the same state as `start` (one layer, inside the grid). */
function floodFill(fig, start, value) {
  const want = !value; // the state of the region
  const seen = new Set([key(...start)]);
  const stack = [start];
  while (stack.length) {
    const c = stack.pop();
    if (value) fig.cells.add(key(...c)); else fig.cells.delete(key(...c));
    for (const n of neighbours(state.lattice, c)) {
      const k = key(...n);
      if (seen.has(k) || n[0] < 0 || n[1] < 0 || n[0] >= fig.w || n[1] >= fig.h) continue;
      if (fig.cells.has(k) !== want) continue;
      seen.add(k);
      stack.push(n);
    }
  }
}

// Undo/redo: one entry per stroke, the figure's cells before and after.
function record(i, before) {
  const after = new Set(state.figures[i].cells);
  if (before.size === after.size && [...before].every((k) => after.has(k))) return;
  state.undo.push({ i, before, after });
  if (state.undo.length > 200) state.undo.shift();
  state.redo = [];
  updateUndo();
}

function applyHistory(from, to, field) {
  const entry = from.pop();
  if (!entry) return;
  const fig = state.figures[entry.i];
  if (!fig) return;
  fig.cells = new Set(entry[field]);
  to.push(entry);
  redrawCard(entry.i);
  updateAreas();
  updateUndo();
}

function updateUndo() {
  $('#undo').disabled = state.undo.length === 0;
  $('#redo').disabled = state.redo.length === 0;
}

// ------------------------------------------------------------ API helpers

async function api(method, path, body) {
  const res = await fetch(path, {
    method,
    headers: body ? { 'content-type': 'application/json' } : {},
    body: body ? JSON.stringify(body) : undefined,
  });
  const text = await res.text();
  let data;
  try { data = JSON.parse(text); } catch { data = { error: { message: text || res.statusText } }; }
  if (!res.ok) throw new Error(data.error?.message || `HTTP ${res.status}`);
  return data;
}

function showMessage(text) {
  const el = $('#message');
  el.textContent = text;
  el.hidden = !text;
}

function cellsJson(fig) {
  const out = [];
  for (const k of fig.cells) {
    const [x, y, t] = unkey(k);
    if (x >= fig.w || y >= fig.h) continue;
    out.push(state.lattice === 'square' ? [x, y] : [x, y, t]);
  }
  return out;
}

/** Fits a figure's grid around cells from the API (normalised to start at 0). */
function figureFromCells(name, cells) {
  const fig = newFigure(name, 1, 1, 1);
  for (const c of cells) {
    const [x, y, t = 0] = c;
    fig.cells.add(key(x, y, t));
    fig.w = Math.max(fig.w, x + 2);
    fig.h = Math.max(fig.h, y + 2);
    if (state.lattice === 'cubic') fig.d = Math.max(fig.d, t + 1);
  }
  fig.w = Math.min(128, Math.max(fig.w, 4));
  fig.h = Math.min(128, Math.max(fig.h, 4));
  return fig;
}

async function loadFigureText(i, name, text) {
  try {
    const data = await api('POST', '/api/figures', { lattice: state.lattice, figures: [{ name, text }] });
    const before = new Set(state.figures[i].cells);
    state.figures[i] = figureFromCells(name, data.figures[0].cells);
    state.undo.push({ i, before, after: new Set(state.figures[i].cells) });
    showMessage('');
    renderFigures();
  } catch (e) {
    showMessage(e.message);
  }
}

async function loadExample(id) {
  const ex = state.examples.find((e) => e.id === id);
  if (!ex) return;
  try {
    const data = await api('POST', '/api/figures', {
      lattice: ex.lattice,
      figures: ex.figures.map((f) => ({ name: `${ex.id}-${f.name}`, text: f.text })),
    });
    setLattice(ex.lattice);
    state.figures = data.figures.map((f) => figureFromCells(f.name, f.cells));
    state.undo = []; state.redo = [];
    showMessage('');
    renderFigures();
    updateUndo();
  } catch (e) {
    showMessage(e.message);
  }
}

/** Rasterizes a picture on the server (dissect-render) to exactly `want` cells. */
async function loadPicture(i, file, want) {
  try {
    if (!(want >= 1)) throw new Error('give the number of cells the figure should have');
    const q = new URLSearchParams({ lattice: state.lattice, cells: String(want), name: file.name.replace(/\.[^.]*$/, '') + '.txt' });
    const res = await fetch(`/api/rasterize?${q}`, { method: 'POST', body: file });
    const data = await res.json().catch(() => ({ error: { message: `HTTP ${res.status}` } }));
    if (!res.ok) throw new Error(data.error?.message || `HTTP ${res.status}`);
    const fig = state.figures[i];
    const before = new Set(fig.cells);
    if (state.lattice === 'cubic') {
      // The picture becomes the current layer.
      for (const k of [...fig.cells]) if (unkey(k)[2] === fig.layer) fig.cells.delete(k);
      for (const [x, y] of data.cells) fig.cells.add(key(x, y, fig.layer));
    } else {
      fig.cells.clear();
      for (const [x, y, t = 0] of data.cells) fig.cells.add(key(x, y, t));
    }
    fig.w = Math.min(128, Math.max(fig.w, data.max[0] + 1));
    fig.h = Math.min(128, Math.max(fig.h, data.max[1] + 1));
    record(i, before);
    showMessage('');
    renderFigures();
    $('#areas').title = `${file.name}: ${data.changed} cells changed to hit ${want}`;
  } catch (e) {
    showMessage(e.message || String(e));
  }
}

function download(name, text, type = 'text/plain') {
  const blob = text instanceof Blob ? text : new Blob([text], { type });
  const a = document.createElement('a');
  a.href = URL.createObjectURL(blob);
  a.download = name;
  document.body.append(a);
  a.click();
  setTimeout(() => { URL.revokeObjectURL(a.href); a.remove(); }, 1000);
}

async function saveFigures(indices) {
  try {
    const figs = indices.map((i) => ({ name: state.figures[i].name, cells: cellsJson(state.figures[i]) }));
    const data = await api('POST', '/api/figures', { lattice: state.lattice, figures: figs });
    for (const [j, f] of data.figures.entries()) {
      const name = /\.txt$/.test(f.name) ? f.name : `${f.name}.txt`;
      download(name, f.text);
      if (j + 1 < data.figures.length) await new Promise((r) => setTimeout(r, 300));
    }
  } catch (e) {
    showMessage(e.message);
  }
}

// ------------------------------------------------------------------ solve

async function startSolve() {
  showMessage('');
  const body = {
    lattice: state.lattice,
    figures: state.figures.map((f) => ({ name: f.name, cells: cellsJson(f) })),
    seed: Math.max(0, Math.round(Number($('#opt-seed').value) || 0)),
    mirror: $('#opt-mirror').checked,
    area_weight: Number($('#opt-area').value),
    time_limit: Number($('#opt-time').value),
  };
  try {
    const started = await api('POST', '/api/solve', body);
    state.job = { id: started.id, figures: body.figures, lattice: body.lattice };
    $('#stop').disabled = false;
    $('#solve').disabled = true;
    $('#progress').hidden = false;
    $('#result').hidden = true;
    const es = new EventSource(started.events);
    state.events = es;
    es.addEventListener('progress', (ev) => showProgress(JSON.parse(ev.data)));
    es.addEventListener('done', (ev) => { es.close(); finish(JSON.parse(ev.data)); });
    es.onerror = () => {
      if (es.readyState === EventSource.CLOSED && state.job) {
        api('GET', started.status).then(finish, (e) => { showMessage(e.message); endJob(); });
      }
    };
  } catch (e) {
    showMessage(e.message);
  }
}

function fmt(v, digits = 1) {
  return v === null || v === undefined ? '—' : Number(v).toFixed(digits);
}

function showProgress(s) {
  $('#p-state').textContent = s.state === 'running' ? (s.stop_requested ? 'stopping…' : 'running') : s.state;
  $('#p-level').textContent = `${s.level} (${s.pieces} pieces)`;
  $('#p-done').textContent = s.total ? `${s.done} / ${s.total} (all: ${s.explorations})` : `${s.explorations}`;
  $('#p-score').textContent = fmt(s.best_score, 2);
  $('#p-mismatch').textContent = s.best_mismatch ?? '—';
  // Improvements live: the fewest pieces so far, when, and the optimal mark
  // once the lower bound meets it.
  const last = s.history && s.history.length ? s.history[s.history.length - 1] : null;
  $('#p-best').textContent = last ? `${last.pieces} pieces at ${fmt(last.seconds, 1)} s (${last.by})` : '—';
  $('#p-bound').textContent = s.lower_bound == null ? '—' : `${s.lower_bound}${s.optimal ? ' — optimal' : ''}`;
  $('#p-bound').classList.toggle('optimal', !!s.optimal);
  $('#p-elapsed').textContent = `${fmt(s.elapsed, 1)} s`;
  $('#meter-fill').style.width = s.total ? `${Math.min(100, (100 * s.done) / s.total)}%` : '0';
}

function endJob() {
  state.job = null;
  state.events = null;
  $('#stop').disabled = true;
  updateAreas();
}

function finish(s) {
  showProgress(s);
  const job = state.job;
  endJob();
  if (s.state === 'failed') { showMessage(s.error || 'the solve failed'); return; }
  const r = s.result;
  if (!r || !r.found) {
    showMessage(`No dissection found${r && r.stopped ? ' before the stop' : ''}: the best candidate with ${r ? r.last_pieces : '?'} pieces had matching score E_M = ${r ? r.best_mismatch : '?'}.`);
    return;
  }
  state.result = { lattice: job.lattice, ...r };
  showResult();
}

// ----------------------------------------------------------------- result

function resultCellSize(w, h) {
  return Math.max(6, Math.min(28, Math.floor(320 / Math.max(w, h))));
}

/** Draws one solved figure; cubic layers side by side. Returns the hit-test function. */
function drawSolved(canvas, lattice, pieces, hot) {
  const owner = new Map();
  pieces.forEach((p, i) => p.forEach((c) => owner.set(key(c[0], c[1], c.length > 2 ? c[2] : 0), i)));
  let w = 0, h = 0, d = 1;
  for (const k of owner.keys()) {
    const [x, y, t] = unkey(k);
    w = Math.max(w, x + 1); h = Math.max(h, y + 1);
    if (lattice === 'cubic') d = Math.max(d, t + 1);
  }
  const gap = lattice === 'cubic' ? 1 : 0;
  const totalW = lattice === 'cubic' ? d * w + (d - 1) * gap : w;
  const cs = resultCellSize(totalW, h);
  const dpr = window.devicePixelRatio || 1;
  canvas.width = (totalW * cs + 2) * dpr;
  canvas.height = (h * cs + 2) * dpr;
  canvas.style.width = `${totalW * cs + 2}px`;
  canvas.style.height = `${h * cs + 2}px`;
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 1, 1);
  const shift = (c) => (lattice === 'cubic' ? c[2] * (w + gap) : 0);
  const toPx = (c) => ([px, py]) => [(px + shift(c)) * cs, py * cs];
  for (const [k, i] of owner) {
    const c = unkey(k);
    const pts = cellPolygon(lattice, c).map(toPx(c));
    g.beginPath();
    pts.forEach(([px, py], j) => (j ? g.lineTo(px, py) : g.moveTo(px, py)));
    g.closePath();
    g.globalAlpha = hot < 0 || hot === i ? 1 : 0.25;
    g.fillStyle = pieceColour(i);
    g.fill();
    g.globalAlpha = 1;
  }
  // Piece outlines: edges between different pieces or to the outside.
  g.strokeStyle = '#1d1d1f';
  g.lineCap = 'round';
  for (const [k, i] of owner) {
    const c = unkey(k);
    for (const [[p, q], n] of cellEdges(lattice, c)) {
      if (owner.get(n) === i) continue;
      const [a, b] = [toPx(c)(p), toPx(c)(q)];
      g.lineWidth = hot === i ? 3 : 1.5;
      g.beginPath(); g.moveTo(...a); g.lineTo(...b); g.stroke();
    }
  }
  if (lattice === 'cubic') {
    g.fillStyle = '#6b6b70';
    g.font = '11px sans-serif';
  }
  return (fx, fy) => {
    let layer = 0, x = fx;
    if (lattice === 'cubic') { layer = Math.floor(fx / (w + gap)); x = fx - layer * (w + gap); }
    const c = cellAt(lattice, x, fy, layer);
    const i = owner.get(key(...c));
    return i === undefined ? -1 : i;
  };
}

function showResult() {
  const r = state.result;
  const sol = r.solution;
  $('#result').hidden = false;
  $('#result-summary').textContent =
    `${r.pieces} pieces${r.optimal ? ' (optimal)' : ` (lower bound ${r.lower_bound})`} · area variance ${Number(r.area_variance).toFixed(2)} · piece areas ${r.areas.join(', ')} · ` +
    `${r.seconds.toFixed(2)} s${r.stopped ? ' (stopped: best found so far)' : ''}`;
  const legend = $('#legend');
  legend.textContent = '';
  r.areas.forEach((a, i) => {
    const s = document.createElement('span');
    s.textContent = `${String.fromCharCode(65 + (i % 26))}${i >= 26 ? i : ''} · ${a}`;
    s.style.background = pieceColour(i);
    s.dataset.piece = i;
    s.onmouseenter = () => highlight(i);
    s.onmouseleave = () => highlight(-1);
    legend.append(s);
  });
  const host = $('#result-figures');
  host.textContent = '';
  state.hitTests = [];
  sol.figures.forEach((f, fi) => {
    const fig = document.createElement('figure');
    const cap = document.createElement('figcaption');
    cap.textContent = f.name + (r.lattice === 'cubic' ? ' (layers z0, z1, … left to right)' : '');
    const canvas = document.createElement('canvas');
    canvas.className = 'solved';
    canvas.dataset.testid = `solved-${fi}`;
    fig.append(cap, canvas);
    host.append(fig);
    canvas.addEventListener('mousemove', (ev) => {
      const rect = canvas.getBoundingClientRect();
      const cs = canvas._cs;
      highlight(state.hitTests[fi]((ev.clientX - rect.left - 1) / cs, (ev.clientY - rect.top - 1) / cs));
    });
    canvas.addEventListener('mouseleave', () => highlight(-1));
  });
  state.hot = -1;
  redrawResult();
  $('#dl-cut').disabled = !state.exports.includes('cut-sheet') || r.lattice === 'cubic';
  $('#dl-ldraw').disabled = !state.exports.includes('ldraw') || r.lattice === 'tri4';
  const v3 = $('#view3d');
  v3.hidden = r.lattice !== 'cubic';
  if (r.lattice === 'cubic') {
    import('/view3d.js')
      .then((m) => m.show(v3, sol, pieceColour))
      .catch((e) => { v3.textContent = `3D view unavailable: ${e.message}`; });
  }
}

function redrawResult() {
  const r = state.result;
  if (!r) return;
  $$('#result-figures canvas').forEach((canvas, fi) => {
    const pieces = r.solution.figures[fi].pieces;
    state.hitTests[fi] = drawSolved(canvas, r.lattice, pieces, state.hot);
    canvas._cs = parseFloat(canvas.style.width) > 0 ? cellSizeOfCanvas(canvas, r.lattice, pieces) : 1;
  });
  $$('#legend span').forEach((s) => s.classList.toggle('hot', Number(s.dataset.piece) === state.hot));
}

function cellSizeOfCanvas(canvas, lattice, pieces) {
  let w = 0, h = 0, d = 1;
  for (const p of pieces) for (const c of p) { w = Math.max(w, c[0] + 1); h = Math.max(h, c[1] + 1); if (lattice === 'cubic') d = Math.max(d, c[2] + 1); }
  const totalW = lattice === 'cubic' ? d * w + (d - 1) : w;
  return resultCellSize(totalW, h);
}

function highlight(i) {
  if (state.hot === i) return;
  state.hot = i;
  redrawResult();
  document.dispatchEvent(new CustomEvent('piece-highlight', { detail: i }));
}

// -------------------------------------------------------------- downloads

async function exportFile(format) {
  const r = state.result;
  if (!r) return;
  try {
    const res = await fetch(`/api/export/${format}`, {
      method: 'POST',
      headers: { 'content-type': 'application/json' },
      body: JSON.stringify({ solution: r.solution }),
    });
    if (!res.ok) {
      const data = await res.json().catch(() => ({}));
      throw new Error(data.error?.message || `HTTP ${res.status}`);
    }
    const name = /filename="([^"]+)"/.exec(res.headers.get('content-disposition') || '')?.[1] || `dissection.${format}`;
    download(name, await res.blob());
  } catch (e) {
    showMessage(e.message);
  }
}

// ------------------------------------------------------------------ wiring

function setLattice(l) {
  if (state.lattice !== l) {
    state.lattice = l;
    $('#lattice').value = l;
    state.figures.forEach((f) => { f.cells.clear(); f.d = 1; f.layer = 0; });
    state.undo = []; state.redo = [];
  }
  document.body.classList.toggle('cubic', l === 'cubic');
  $('#opt-mirror').disabled = l === 'cubic';
}

function selectTool(tool) {
  state.tool = tool;
  $$('.tool').forEach((b) => b.classList.toggle('active', b.dataset.tool === tool));
}

async function init() {
  state.figures = [newFigure(figureName(0)), newFigure(figureName(1))];
  $('#lattice').onchange = (ev) => { setLattice(ev.target.value); renderFigures(); };
  $('#add-figure').onclick = () => {
    const last = state.figures[state.figures.length - 1];
    state.figures.push(newFigure(figureName(state.figures.length), last?.w ?? 8, last?.h ?? 8, last?.d ?? 1));
    renderFigures();
  };
  $$('.tool').forEach((b) => (b.onclick = () => selectTool(b.dataset.tool)));
  $('#undo').onclick = () => applyHistory(state.undo, state.redo, 'before');
  $('#redo').onclick = () => applyHistory(state.redo, state.undo, 'after');
  document.addEventListener('keydown', (ev) => {
    if (ev.target.matches('input, select')) return;
    const k = ev.key.toLowerCase();
    if ((ev.ctrlKey || ev.metaKey) && k === 'z' && !ev.shiftKey) { ev.preventDefault(); $('#undo').click(); }
    else if ((ev.ctrlKey || ev.metaKey) && (k === 'y' || (k === 'z' && ev.shiftKey))) { ev.preventDefault(); $('#redo').click(); }
    else if (!ev.ctrlKey && !ev.metaKey) {
      const tool = { p: 'pen', e: 'erase', r: 'rect', f: 'fill' }[k];
      if (tool) selectTool(tool);
    }
  });
  window.addEventListener('studio-hover-piece', (ev) => highlight(ev.detail));
  $('#solve').onclick = startSolve;
  $('#stop').onclick = () => { if (state.job) api('POST', `/api/solve/${state.job.id}/stop`).catch((e) => showMessage(e.message)); };
  $('#dl-json').onclick = () => download('dissection.json', state.result.solution_text, 'application/json');
  $('#dl-figures').onclick = async () => {
    const r = state.result;
    for (const [j, f] of r.solution.figures.entries()) {
      const cells = f.pieces.flat();
      const data = await api('POST', '/api/figures', { lattice: r.lattice, figures: [{ name: f.name, cells }] });
      download(/\.txt$/.test(f.name) ? f.name : `${f.name}.txt`, data.figures[0].text);
      if (j + 1 < r.solution.figures.length) await new Promise((res) => setTimeout(res, 300));
    }
  };
  $('#dl-svg').onclick = () => exportFile('svg');
  $('#dl-png').onclick = () => exportFile('png');
  $('#dl-cut').onclick = () => exportFile('cut-sheet');
  $('#dl-stl').onclick = () => exportFile('stl');
  $('#dl-ldraw').onclick = () => exportFile('ldraw');
  setLattice('square');
  renderFigures();
  updateUndo();
  try {
    const info = await api('GET', '/api/info');
    state.exports = info.exports;
    const buttons = { svg: '#dl-svg', png: '#dl-png', 'cut-sheet': '#dl-cut', stl: '#dl-stl', ldraw: '#dl-ldraw' };
    for (const [format, sel] of Object.entries(buttons)) {
      if (!info.exports.includes(format)) {
        $(sel).disabled = true;
        $(sel).title = 'this server cannot make this format yet';
      }
    }
  } catch (e) {
    showMessage(`cannot read the server's info: ${e.message}`);
  }
  try {
    state.examples = await api('GET', '/api/examples');
    for (const ex of state.examples) {
      const o = document.createElement('option');
      o.value = ex.id;
      o.textContent = `${ex.title} [${ex.lattice}]`;
      $('#example').append(o);
    }
    $('#example').onchange = (ev) => ev.target.value && loadExample(ev.target.value);
  } catch (e) {
    showMessage(`cannot list the examples: ${e.message}`);
  }
  document.body.dataset.ready = 'true';
}

window.studio = state; // for the end-to-end tests and the curious
window.studioPalette = PALETTE;
init();
