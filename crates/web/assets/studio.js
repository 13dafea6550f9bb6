// dissect studio: figure editor, solver client and solution viewer.
// Plain ES module, no build step. Talks to the JSON API of crates/web.

const $ = (sel, root = document) => root.querySelector(sel);
const $$ = (sel, root = document) => [...root.querySelectorAll(sel)];

// Piece colours: the one palette of dissect_core::palette, served by the
// server as /palette.js (the same colours as SVG, PNG and the terminal).
import { PALETTE, pieceColour } from '/palette.js';
import { createPlayer } from '/player.js';

export { PALETTE, pieceColour };

const key = (x, y, t) => `${x},${y},${t}`;
const unkey = (k) => k.split(',').map(Number);

// ---------------------------------------------------------------- geometry
//
// The page keeps no geometry of its own: every lattice's cells come from
// the server (GET /api/lattices, made by dissect_render::tiling from the
// lattice itself). A lattice is a periodic block of tiles: cell
// (x + px, y, t) is cell (x, y, t) moved by the plane vector steps[0],
// (x, y + py, t) moved by steps[1]; each tile has its polygon, centre and,
// per edge, the neighbour across it. On a layered lattice (cubic) the third
// coordinate is the layer and each layer is drawn on its own. Plane units:
// the side of a square or triangle, the distance between hexagon centres.

const LATTICES = new Map(); // name -> description (+ tileAt index)

/** Stores the server's lattice descriptions. */
function setLattices(list) {
  for (const L of list) {
    L.tileAt = new Map(L.tiles.map((t) => [key(...t.cell), t]));
    LATTICES.set(L.lattice, L);
  }
}

function geo(lattice = state.lattice) {
  const L = LATTICES.get(lattice);
  if (!L) throw new Error(`the server describes no lattice ${lattice}`);
  return L;
}

/** The tile of a cell and the plane offset of its period block. */
function tileOf(L, [x, y, t = 0]) {
  const [px, py] = L.period;
  const bx = Math.floor(x / px), by = Math.floor(y / py);
  const tile = L.tileAt.get(key(x - bx * px, y - by * py, L.layers ? 0 : t));
  if (!tile) throw new Error(`${[x, y, t]} is not a ${L.lattice} cell`);
  const [s, u] = L.steps;
  return { tile, off: [bx * s[0] + by * u[0], bx * s[1] + by * u[1]] };
}

/** The polygon of a cell in plane units. */
function cellPolygon(lattice, c) {
  const { tile, off } = tileOf(geo(lattice), c);
  return tile.polygon.map(([px, py]) => [px + off[0], py + off[1]]);
}

/** Edges of a cell with the key of the neighbour across each: [[p, q], neighbourKey, sameBlock]. */
function cellEdges(lattice, c) {
  const L = geo(lattice);
  const { tile, off } = tileOf(L, c);
  const [x, y, t = 0] = c;
  const pts = tile.polygon.map(([px, py]) => [px + off[0], py + off[1]]);
  return tile.across.map(([dx, dy, dt], i) => [
    [pts[i], pts[(i + 1) % pts.length]],
    key(x + dx, y + dy, t + dt),
    dx === 0 && dy === 0,
  ]);
}

/** Neighbours of an editor cell inside one layer (for flood fill). */
function neighbours(lattice, c) {
  return cellEdges(lattice, c).map((e) => unkey(e[1]));
}

function insidePolygon(pts, [fx, fy]) {
  let inside = false;
  for (let i = 0, j = pts.length - 1; i < pts.length; j = i++) {
    const [xi, yi] = pts[i], [xj, yj] = pts[j];
    if ((yi > fy) !== (yj > fy) && fx < ((xj - xi) * (fy - yi)) / (yj - yi) + xi) inside = !inside;
  }
  return inside;
}

/** The cell under a plane point (the nearest centre when on an edge). */
function cellAt(lattice, fx, fy, layer) {
  const L = geo(lattice);
  const [[a, b], [c, d]] = L.steps; // plane = i·steps[0] + j·steps[1]
  const det = a * d - c * b;
  const i0 = Math.floor((fx * d - fy * c) / det), j0 = Math.floor((a * fy - b * fx) / det);
  let best = null, bestD = Infinity;
  for (let j = j0 - 1; j <= j0 + 1; j++) {
    for (let i = i0 - 1; i <= i0 + 1; i++) {
      const off = [i * a + j * c, i * b + j * d];
      for (const tile of L.tiles) {
        const cell = [i * L.period[0] + tile.cell[0], j * L.period[1] + tile.cell[1], L.layers ? layer : tile.cell[2]];
        const pts = tile.polygon.map(([px, py]) => [px + off[0], py + off[1]]);
        if (insidePolygon(pts, [fx, fy])) return cell;
        const dd = (tile.centre[0] + off[0] - fx) ** 2 + (tile.centre[1] + off[1] - fy) ** 2;
        if (dd < bestD) { bestD = dd; best = cell; }
      }
    }
  }
  return best;
}

/** All cells at position (x, y) (the 4 triangles of a tri4 square; the cell on the current layer). */
function blockCells(lattice, x, y, layer) {
  const L = geo(lattice);
  const [px, py] = L.period;
  const rx = ((x % px) + px) % px, ry = ((y % py) + py) % py;
  return L.tiles.filter((t) => t.cell[0] === rx && t.cell[1] === ry).map((t) => [x, y, L.layers ? layer : t.cell[2]]);
}

/** The plane bounding box [[x0, y0], [x1, y1]] of some cells' polygons. */
function boundsOf(lattice, cells) {
  const lo = [Infinity, Infinity], hi = [-Infinity, -Infinity];
  for (const c of cells) {
    for (const [px, py] of cellPolygon(lattice, c)) {
      lo[0] = Math.min(lo[0], px); lo[1] = Math.min(lo[1], py);
      hi[0] = Math.max(hi[0], px); hi[1] = Math.max(hi[1], py);
    }
  }
  return cells.length ? [lo, hi] : [[0, 0], [1, 1]];
}

/** Every cell of a w × h editor grid (one layer). */
function gridCells(lattice, w, h, layer = 0) {
  const out = [];
  for (let y = 0; y < h; y++) for (let x = 0; x < w; x++) out.push(...blockCells(lattice, x, y, layer));
  return out;
}

const gridBoundsCache = new Map();
/** The plane box of a w × h editor grid. */
function gridBounds(lattice, w, h) {
  const k = `${lattice},${w},${h}`;
  if (!gridBoundsCache.has(k)) gridBoundsCache.set(k, boundsOf(lattice, gridCells(lattice, w, h)));
  return gridBoundsCache.get(k);
}

/** A cell as solution files and the API write it. */
function cellJson(lattice, [x, y, t]) {
  return geo(lattice).arity === 2 ? [x, y] : [x, y, t];
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
  // keep: cell key -> letter a-z (the keep-whole regions painted on it).
  return { name, w, h, d, layer: 0, cells: new Set(), keep: new Map() };
}

/** A figure's cells and regions, for undo. */
function snap(fig) {
  return { cells: new Set(fig.cells), keep: new Map(fig.keep) };
}

const LETTERS = 'abcdefghijklmnopqrstuvwxyz';
/** The colour of keep region `letter`: the shared palette, one colour a letter. */
function letterColour(letter) {
  return pieceColour(LETTERS.indexOf(letter));
}

function figureName(i) {
  return `figure-${String.fromCharCode(97 + (i % 26))}.txt`;
}

// ----------------------------------------------------------------- editor

const CANVAS_MAX = 360;

/** The editor's scale (pixels per plane unit) and plane box of a figure. */
function editorView(fig) {
  const [lo, hi] = gridBounds(state.lattice, fig.w, fig.h);
  const span = Math.max(hi[0] - lo[0], hi[1] - lo[1]);
  const cs = Math.max(8, Math.min(36, Math.floor(CANVAS_MAX / span)));
  return { cs, lo, hi };
}

function drawEditor(fig, card, preview = null) {
  const canvas = $('canvas.grid', card);
  const { cs, lo, hi } = editorView(fig);
  const dpr = window.devicePixelRatio || 1;
  const wPx = Math.ceil((hi[0] - lo[0]) * cs), hPx = Math.ceil((hi[1] - lo[1]) * cs);
  canvas.width = wPx * dpr + 1;
  canvas.height = hPx * dpr + 1;
  canvas.style.width = `${wPx + 1}px`;
  canvas.style.height = `${hPx + 1}px`;
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, 0.5, 0.5);
  g.clearRect(-1, -1, canvas.width, canvas.height);
  const L = state.lattice;
  const layers = geo(L).layers;
  const path = (pts) => {
    g.beginPath();
    pts.forEach(([px, py], i) => (i ? g.lineTo : g.moveTo).call(g, (px - lo[0]) * cs, (py - lo[1]) * cs));
    g.closePath();
  };
  const poly = (pts, fill) => { path(pts); g.fillStyle = fill; g.fill(); };
  const inGrid = (c) => c[0] >= 0 && c[1] >= 0 && c[0] < fig.w && c[1] < fig.h;
  // Ghost of the layer below (layered lattices).
  if (layers && fig.layer > 0) {
    for (const k of fig.cells) {
      const c = unkey(k);
      if (c[2] === fig.layer - 1 && inGrid(c)) poly(cellPolygon(L, c), '#dfe6f3');
    }
  }
  for (const k of fig.cells) {
    const c = unkey(k);
    if (layers && c[2] !== fig.layer) continue;
    if (inGrid(c)) poly(cellPolygon(L, c), '#2b2d42');
  }
  // Keep-whole regions: the region's colour inset in its cells, its letter
  // on top when the cells are large enough to read it.
  for (const [k, letter] of fig.keep) {
    if (!fig.cells.has(k)) continue;
    const c = unkey(k);
    if ((layers && c[2] !== fig.layer) || !inGrid(c)) continue;
    const pts = cellPolygon(L, c);
    const cx = pts.reduce((a, p) => a + p[0], 0) / pts.length, cy = pts.reduce((a, p) => a + p[1], 0) / pts.length;
    const inset = pts.map(([px, py]) => [cx + (px - cx) * 0.8, cy + (py - cy) * 0.8]);
    poly(inset, letterColour(letter));
    if (cs >= 16) {
      g.fillStyle = '#1d1d1f';
      g.font = `600 ${Math.round(cs * 0.45)}px system-ui, sans-serif`;
      g.textAlign = 'center';
      g.textBaseline = 'middle';
      g.fillText(letter, (cx - lo[0]) * cs, (cy - lo[1]) * cs);
    }
  }
  if (preview) {
    const fill = preview.fill ? 'rgba(37,99,235,.35)' : 'rgba(185,28,28,.3)';
    for (let y = preview.y0; y <= preview.y1; y++) {
      for (let x = preview.x0; x <= preview.x1; x++) {
        for (const c of blockCells(L, x, y, fig.layer)) poly(cellPolygon(L, c), fill);
      }
    }
  }
  // Grid: every cell edge once; edges inside a block (tri4's diagonals) faint.
  g.lineWidth = 1;
  for (const faint of [true, false]) {
    g.strokeStyle = faint ? '#eceef2' : '#d9dbe1';
    g.beginPath();
    for (const c of gridCells(L, fig.w, fig.h, fig.layer)) {
      for (const [[p, q], n, sameBlock] of cellEdges(L, c)) {
        if (sameBlock !== faint) continue;
        const m = unkey(n);
        if (inGrid(m) && key(...m) < key(...c)) continue; // drawn from the other side
        g.moveTo((p[0] - lo[0]) * cs, (p[1] - lo[1]) * cs);
        g.lineTo((q[0] - lo[0]) * cs, (q[1] - lo[1]) * cs);
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
  $('#enumerate').disabled = $('#solve').disabled;
  updateKeepSummary();
}

/** What the closed Puzzle section holds, in a few words (so that nothing set there is hidden). */
function updatePuzzleSet() {
  const set = [];
  const n = Number($('#opt-solutions').value);
  if (n > 1) set.push(`${n} solutions`);
  if ($('#opt-rank').value !== 'variance') set.push(`by ${$('#opt-rank').selectedOptions[0].textContent}`);
  if ($('#opt-min-piece').value.trim()) set.push(`min ${$('#opt-min-piece').value}`);
  if ($('#opt-max-piece').value.trim()) set.push(`max ${$('#opt-max-piece').value}`);
  if (Number($('#opt-symmetry').value)) set.push(`symmetry ${$('#opt-symmetry').value}`);
  if ($('#opt-checkerboard').checked) set.push('checkerboard');
  if ($('#opt-assemblable').checked) set.push('assemblable');
  if ($('#opt-min-level').value.trim()) set.push(`level ≥ ${$('#opt-min-level').value}`);
  if (keepJson().length) set.push('keep regions');
  $('#puzzle-set').textContent = set.length ? `(${set.join(', ')})` : '';
}

/** The keep-whole regions of figure `fig` by letter (cells as the API takes them), painted on its cells. */
function keepRegions(fig) {
  const regions = {};
  for (const [k, letter] of [...fig.keep].sort((a, b) => (a[1] < b[1] ? -1 : a[1] > b[1] ? 1 : 0))) {
    const [x, y, t] = unkey(k);
    if (!fig.cells.has(k) || x >= fig.w || y >= fig.h) continue;
    (regions[letter] ??= []).push(cellJson(state.lattice, [x, y, t]));
  }
  return regions;
}

/** The `keep` option of a solve: every figure's painted regions. */
function keepJson() {
  return state.figures
    .map((f, i) => ({ figure: i + 1, regions: keepRegions(f) }))
    .filter((k) => Object.keys(k.regions).length > 0);
}

function updateKeepSummary() {
  const el = $('#keep-summary');
  if (!el) return;
  const keep = keepJson();
  state.figures.forEach((f, i) => {
    const b = cards()[i] && $('.clear-keep', cards()[i]);
    if (b) b.hidden = !keep.some((k) => k.figure === i + 1);
  });
  updatePuzzleSet();
  el.textContent = keep.length
    ? 'Kept whole: ' + keep.map((k) => `${state.figures[k.figure - 1].name}: ` +
        Object.entries(k.regions).map(([l, c]) => `${l} (${c.length})`).join(', ')).join(' · ')
    : 'Keep whole: paint regions with the ◼ Keep tool.';
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
      const before = snap(fig);
      fig[dim] = v;
      for (const k of [...fig.cells]) {
        const [x, y, t] = unkey(k);
        if (x >= fig.w || y >= fig.h || (geo().layers && t >= fig.d)) fig.cells.delete(k);
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
    const before = snap(fig);
    fig.cells.clear();
    fig.keep.clear();
    record(i, before);
    drawEditor(fig, card);
    updateAreas();
  };
  $('.clear-keep', card).onclick = () => {
    const before = snap(fig);
    fig.keep.clear();
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
    const { cs, lo } = editorView(fig);
    return [(ev.clientX - r.left) / cs + lo[0], (ev.clientY - r.top) / cs + lo[1]];
  };
  const inside = ([x, y]) => x >= 0 && y >= 0 && x < fig.w && y < fig.h;
  const set = (c, on) => {
    if (!inside(c)) return;
    const k = key(...c);
    if (on) fig.cells.add(k); else fig.cells.delete(k);
  };
  const paint = (c, letter) => {
    const k = key(...c);
    if (!inside(c) || !fig.cells.has(k)) return;
    if (letter) fig.keep.set(k, letter); else fig.keep.delete(k);
  };
  canvas.addEventListener('contextmenu', (ev) => ev.preventDefault());
  canvas.addEventListener('pointerdown', (ev) => {
    ev.preventDefault();
    canvas.setPointerCapture(ev.pointerId);
    const [fx, fy] = at(ev);
    const c = cellAt(state.lattice, fx, fy, fig.layer);
    if (!inside(c)) return;
    const before = snap(fig);
    const filled = fig.cells.has(key(...c));
    const tool = ev.button === 2 && state.tool !== 'keep' ? 'erase' : state.tool;
    if (tool === 'keep') {
      // Paint the current letter on filled cells; starting on a cell of
      // that letter, or with the right button, unpaints.
      const letter = state.keepLetter;
      stroke = { tool, before, value: ev.button === 2 || fig.keep.get(key(...c)) === letter ? null : letter };
      paint(c, stroke.value);
      drawEditor(fig, card);
      updateAreas();
      return;
    }
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
    if (stroke.tool === 'keep') paint(c, stroke.value); else set(c, stroke.value);
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
  const after = snap(state.figures[i]);
  const sameCells = before.cells.size === after.cells.size && [...before.cells].every((k) => after.cells.has(k));
  const sameKeep = before.keep.size === after.keep.size && [...before.keep].every(([k, l]) => after.keep.get(k) === l);
  if (sameCells && sameKeep) return;
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
  fig.cells = new Set(entry[field].cells);
  fig.keep = new Map(entry[field].keep);
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
    out.push(cellJson(state.lattice, [x, y, t]));
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
    if (geo().layers) fig.d = Math.max(fig.d, t + 1);
  }
  fig.w = Math.min(128, Math.max(fig.w, 4));
  fig.h = Math.min(128, Math.max(fig.h, 4));
  return fig;
}

async function loadFigureText(i, name, text) {
  try {
    const data = await api('POST', '/api/figures', { lattice: state.lattice, figures: [{ name, text }] });
    const before = snap(state.figures[i]);
    state.figures[i] = figureFromCells(name, data.figures[0].cells);
    state.undo.push({ i, before, after: snap(state.figures[i]) });
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
    const before = snap(fig);
    if (geo().layers) {
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
    solutions: Math.max(1, Math.round(Number($('#opt-solutions').value) || 1)),
    rank: $('#opt-rank').value,
  };
  // The designer's constraints: only what is set is sent.
  const size = (sel) => ($(sel).value.trim() === '' ? null : Math.round(Number($(sel).value)));
  const minPiece = size('#opt-min-piece'), maxPiece = size('#opt-max-piece');
  if (minPiece !== null) body.min_piece = minPiece;
  if (maxPiece !== null) body.max_piece = maxPiece;
  if ($('#opt-checkerboard').checked && !$('#opt-checkerboard').disabled) body.checkerboard = true;
  if ($('#opt-assemblable').checked) body.assemblable = true;
  const minLevel = size('#opt-min-level');
  if (minLevel !== null) body.min_level = minLevel;
  const weight = Number($('#opt-symmetry').value);
  if (weight) body.symmetry_weight = weight;
  const keep = keepJson();
  if (keep.length) body.keep = keep;
  await runJob(body);
}

/** "All solutions": every dissection with the fewest pieces, counted (the time limit and Stop apply). */
async function startEnumerate() {
  showMessage('');
  $('#enumerate-count').textContent = '';
  await runJob({
    lattice: state.lattice,
    figures: state.figures.map((f) => ({ name: f.name, cells: cellsJson(f) })),
    mirror: $('#opt-mirror').checked,
    time_limit: Number($('#opt-time').value),
    rank: $('#opt-rank').value,
    enumerate: true,
  });
}

/** Starts a job (a solve or an enumeration) and follows it to its end. */
async function runJob(body) {
  try {
    const started = await api('POST', '/api/solve', body);
    state.job = { id: started.id, figures: body.figures, lattice: body.lattice };
    $('#stop').disabled = false;
    $('#solve').disabled = true;
    $('#enumerate').disabled = true;
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
  $('#p-state').textContent = s.state === 'running'
    ? (s.counting ? 'counting assemblies…' : s.stop_requested ? 'stopping…' : 'running')
    : s.state;
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
  const e = s.enumeration;
  if (e) {
    $('#p-done').textContent = `${e.dissections} dissections (${e.classes} up to symmetry)`;
    if (s.state === 'running') {
      $('#enumerate-count').textContent = `${e.dissections} dissections with ${e.pieces} pieces (${e.classes} up to symmetry) so far${e.minimum ? '' : ', minimum not yet proved'}…`;
    }
  }
}

/** An enumeration's count in words, as `dissect enumerate` ends: complete, or at least N when stopped. */
function enumerationText(e) {
  const counted = `${e.dissections} dissection${e.dissections === 1 ? '' : 's'} with ${e.pieces} pieces (${e.classes} up to the first figure's symmetries)`;
  return e.complete ? `${counted}, complete` : `at least ${counted}, stopped`;
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
  if (r && r.enumeration) $('#enumerate-count').textContent = enumerationText(r.enumeration);
  if (r && r.enumeration && !r.found) {
    showMessage(`No dissection with ${r.enumeration.pieces} pieces found${r.stopped ? ' before the stop (the minimum is at least that)' : ''}.`);
    return;
  }
  if (!r || !r.found) {
    const constrained = r && r.ranking && Object.keys(r.ranking.constraints || {}).length > 0;
    showMessage(`No dissection found${r && r.stopped ? ' before the stop' : ''}${constrained ? ' that honours the constraints' : ''}: the best candidate with ${r ? r.last_pieces : '?'} pieces had matching score E_M = ${r ? r.best_mismatch : '?'}.`);
    return;
  }
  state.run = { lattice: job.lattice, ...r, solutions: r.solutions?.length ? r.solutions : [{ ...r, position: 1, assemblies: [] }] };
  renderBrowser();
  selectSolution(0);
}

// ------------------------------------------------------- solutions browser

const RANKS = { variance: 'area variance', smallest: 'largest smallest piece', shapes: 'fewest shapes', symmetry: 'most symmetric', unique: 'fewest assemblies', level: 'highest disassembly level' };

/** A solution's scores in words. */
function scoresText(sc) {
  if (!sc) return '';
  const parts = [`variance ${fmt(sc.variance, 2)}`, `smallest ${sc.smallest}`, `${sc.shapes} shape${sc.shapes === 1 ? '' : 's'}`, `symmetry ${sc.symmetry}`];
  if (sc.objective !== undefined && sc.objective !== sc.variance) parts.push(`objective ${fmt(sc.objective, 2)}`);
  return parts.join(' · ');
}

/** One figure's assembly count in words: `8 tilings (1 up to symmetry)`. */
function countText(c) {
  if (c.complete) return `${c.tilings} tiling${c.tilings === 1 ? '' : 's'} (${c.up_to_symmetry} up to symmetry)`;
  return c.tilings > 0
    ? `at least ${c.tilings} tilings (count cut short)`
    : `count not finished (stopped after ${fmt(c.seconds, 1)} s)`;
}

function uniqueMark() {
  const u = document.createElement('span');
  u.className = 'unique';
  u.dataset.testid = 'unique';
  u.textContent = 'unique';
  u.title = 'the pieces assemble into this figure in one way only (up to its symmetries)';
  return u;
}

/** The list of solutions with their scores and rank (shown when there are several). */
function renderBrowser() {
  const run = state.run;
  const list = $('#sol-list');
  list.textContent = '';
  const n = run.solutions.length;
  $('#browser').hidden = n < 2 && !run.ranking && !run.enumeration;
  const by = run.ranking ? RANKS[run.ranking.by] || run.ranking.by : null;
  $('#sol-ranking').textContent = run.ranking
    ? `ranked by ${by}; ${run.ranking.found} found of ${run.ranking.asked} asked for`
    : '';
  if (run.enumeration) {
    const e = run.enumeration;
    $('#sol-ranking').textContent = `${enumerationText(e)}; one per class${e.listed < e.classes ? `, the first ${e.listed} listed` : ''}`;
  }
  run.solutions.forEach((s, i) => {
    const li = document.createElement('li');
    li.dataset.testid = `sol-${i}`;
    const head = document.createElement('b');
    head.textContent = `#${s.position ?? i + 1}`;
    const body = document.createElement('span');
    body.textContent = `${s.pieces} pieces`;
    const sc = document.createElement('span');
    sc.className = 'scores';
    sc.textContent = scoresText(s.scores);
    const asm = document.createElement('span');
    asm.textContent = (s.assemblies || []).map((c) => (c.complete ? c.up_to_symmetry : `≥${c.up_to_symmetry}`)).join(' + ');
    asm.title = 'assemblies up to symmetry, per figure';
    li.append(head, body, sc, asm);
    if (s.class_size) {
      const size = document.createElement('span');
      size.textContent = `× ${s.class_size}`;
      size.title = 'dissections in this class (images of this cut under the first figure\'s symmetries)';
      li.append(size);
    }
    if (s.unique) li.append(uniqueMark());
    li.onclick = () => selectSolution(i);
    list.append(li);
  });
}

/** Shows solution i of the run (0-based): its pieces, counts, motion and downloads. */
function selectSolution(i) {
  const run = state.run;
  const n = run.solutions.length;
  const k = Math.max(0, Math.min(n - 1, i));
  const s = run.solutions[k];
  state.current = k;
  state.result = {
    ...run,
    pieces: s.pieces, areas: s.areas, area_variance: s.area_variance,
    solution: s.solution, solution_text: s.solution_text,
    optimal: s.solution?.optimal ?? run.optimal,
    current: s,
  };
  $('#sol-position').textContent = run.enumeration
    ? `Class ${k + 1} of ${n} (${s.class_size} dissection${s.class_size === 1 ? '' : 's'})`
    : `Solution ${k + 1} of ${n}`;
  $('#sol-prev').disabled = k === 0;
  $('#sol-next').disabled = k === n - 1;
  $$('#sol-list li').forEach((li, j) => li.classList.toggle('current', j === k));
  showResult();
}

/** The assembly count per figure of the solution shown, with the unique mark. */
function showAssemblies(s) {
  const el = $('#assemblies');
  el.textContent = '';
  const counts = s?.assemblies || [];
  if (!counts.length) return;
  const label = document.createElement('span');
  label.textContent = 'Assemblies:';
  el.append(label);
  counts.forEach((c, fi) => {
    const item = document.createElement('span');
    item.dataset.testid = `assemblies-${fi}`;
    item.textContent = `${c.figure}: ${countText(c)} `;
    if (!c.complete) item.classList.add('partial');
    if (c.unique) item.append(uniqueMark());
    el.append(item);
  });
}

// ----------------------------------------------------------------- result

function resultCellSize(w, h) {
  return Math.max(6, Math.min(28, Math.floor(320 / Math.max(w, h))));
}

/**
 * Draws one solved figure (layers of a layered lattice side by side).
 * Returns the hit test: CSS pixel offset in the canvas -> piece or -1.
 */
function drawSolved(canvas, lattice, pieces, hot) {
  const L = geo(lattice);
  const owner = new Map();
  pieces.forEach((p, i) => p.forEach((c) => owner.set(key(c[0], c[1], c.length > 2 ? c[2] : 0), i)));
  const cells = [...owner.keys()].map(unkey);
  const [lo, hi] = boundsOf(lattice, cells);
  const d = L.layers ? Math.max(1, ...cells.map((c) => c[2] + 1)) : 1;
  const gap = L.layers ? 1 : 0;
  const layerW = hi[0] - lo[0];
  const totalW = d * layerW + (d - 1) * gap;
  const cs = resultCellSize(totalW, hi[1] - lo[1]);
  const dpr = window.devicePixelRatio || 1;
  const wPx = Math.ceil(totalW * cs) + 2, hPx = Math.ceil((hi[1] - lo[1]) * cs) + 2;
  canvas.width = wPx * dpr;
  canvas.height = hPx * dpr;
  canvas.style.width = `${wPx}px`;
  canvas.style.height = `${hPx}px`;
  const g = canvas.getContext('2d');
  g.setTransform(dpr, 0, 0, dpr, dpr, dpr);
  const shift = (c) => (L.layers ? c[2] * (layerW + gap) : 0);
  const toPx = (c) => ([px, py]) => [(px - lo[0] + shift(c)) * cs, (py - lo[1]) * cs];
  for (const [k, i] of owner) {
    const c = unkey(k);
    const pts = cellPolygon(lattice, c).map(toPx(c));
    g.beginPath();
    pts.forEach(([px, py], j) => (j ? g.lineTo(px, py) : g.moveTo(px, py)));
    g.closePath();
    g.globalAlpha = hot < 0 || hot === i ? 1 : 0.25;
    g.fillStyle = pieceColour(i);
    g.fill();
    // The same colour along the cell's edges hides the seams between cells.
    g.strokeStyle = pieceColour(i);
    g.lineWidth = 0.75;
    g.stroke();
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
  return (cssX, cssY) => {
    let fx = (cssX - 1) / cs, layer = 0;
    if (L.layers) { layer = Math.floor(fx / (layerW + gap)); fx -= layer * (layerW + gap); }
    const c = cellAt(lattice, fx + lo[0], (cssY - 1) / cs + lo[1], layer);
    const i = c ? owner.get(key(...c)) : undefined;
    return i === undefined ? -1 : i;
  };
}

function showResult() {
  const r = state.result;
  const sol = r.solution;
  $('#result').hidden = false;
  $('#result-summary').textContent =
    `${r.pieces} pieces${r.optimal ? ' (optimal)' : ` (lower bound ${r.lower_bound})`} · area variance ${Number(r.area_variance).toFixed(2)} · piece areas ${r.areas.join(', ')} · ` +
    `${r.seconds.toFixed(2)} s${r.stopped ? (r.enumeration ? ' (stopped: the list is not complete)' : ' (stopped: best found so far)') : ''}` +
    (r.current?.scores ? ` · ${scoresText(r.current.scores)}` : '') +
    (r.current?.rank ? ` · rank ${r.current.rank.position} by ${RANKS[r.current.rank.by] || r.current.rank.by}` : '');
  showAssemblies(r.current);
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
    cap.textContent = f.name + (geo(r.lattice).layers ? ' (layers z0, z1, … left to right)' : '');
    const canvas = document.createElement('canvas');
    canvas.className = 'solved';
    canvas.dataset.testid = `solved-${fi}`;
    fig.append(cap, canvas);
    host.append(fig);
    canvas.addEventListener('mousemove', (ev) => {
      const rect = canvas.getBoundingClientRect();
      highlight(state.hitTests[fi](ev.clientX - rect.left, ev.clientY - rect.top));
    });
    canvas.addEventListener('mouseleave', () => highlight(-1));
  });
  state.hot = -1;
  redrawResult();
  enableDownloads(r.lattice);
  showMotion(sol);
}

/**
 * 3D answers: each figure's disassembly level (moves until the first piece
 * comes free, from the server's plan), or a warning that it cannot be built
 * (no straight moves take it apart: the pieces that lock) or was not decided.
 */
function showDisassembly(data) {
  const el = $('#disassembly');
  el.textContent = '';
  el.hidden = data.dim !== 3;
  if (el.hidden) return;
  const label = document.createElement('span');
  label.textContent = 'Disassembly:';
  el.append(label);
  data.figures.forEach((f, fi) => {
    const item = document.createElement('span');
    item.dataset.testid = `level-${fi}`;
    if (f.level !== null && f.level !== undefined) {
      const n = f.plan ? f.plan.length : 0;
      item.textContent = `${f.name}: level ${f.level} (apart in ${n} move${n === 1 ? '' : 's'})`;
      item.title = 'how many straight moves until the first piece comes free (1: a piece lifts off at once; higher: the pieces interlock)';
    } else if (f.locked) {
      item.className = 'cannot-build';
      const names = f.locked.map((i) => data.pieces[i].label).join(', ');
      item.textContent = `${f.name}: ⚠ cannot be built (pieces ${names} locked)`;
      item.title = 'no sequence of straight moves takes this figure apart, so no hand can put it together';
    } else {
      item.className = 'partial';
      item.textContent = `${f.name}: not decided (too many positions)`;
    }
    el.append(item);
  });
}

/** The motion player (and for cubic the 3D view): its data is made by the server (dissect-render). */
async function showMotion(sol) {
  const host = $('#motion');
  host.textContent = '';
  $('#disassembly').hidden = true;
  try {
    const res = await fetch('/api/export/animation', {
      method: 'POST',
      headers: { 'content-type': 'application/json' },
      body: JSON.stringify({ solution: sol }),
    });
    const data = await res.json();
    if (!res.ok) throw new Error(data.error?.message || `HTTP ${res.status}`);
    if (state.result?.solution !== sol) return; // a newer result is shown
    state.player = createPlayer(host, data);
    showDisassembly(data);
  } catch (e) {
    host.textContent = `motion view unavailable: ${e.message}`;
  }
}

function redrawResult() {
  const r = state.result;
  if (!r) return;
  $$('#result-figures canvas').forEach((canvas, fi) => {
    const pieces = r.solution.figures[fi].pieces;
    state.hitTests[fi] = drawSolved(canvas, r.lattice, pieces, state.hot);
  });
  $$('#legend span').forEach((s) => s.classList.toggle('hot', Number(s.dataset.piece) === state.hot));
  state.player?.highlight(state.hot);
}

function highlight(i) {
  if (state.hot === i) return;
  state.hot = i;
  redrawResult();
  document.dispatchEvent(new CustomEvent('piece-highlight', { detail: i }));
}

// -------------------------------------------------------------- downloads

/** The export buttons, by format. */
const EXPORT_BUTTONS = { html: '#dl-html', svg: '#dl-svg', png: '#dl-png', 'cut-sheet': '#dl-cut', stl: '#dl-stl', ldraw: '#dl-ldraw' };

/** Turns on the downloads this server makes for the lattice (its description lists them). */
function enableDownloads(lattice) {
  const made = geo(lattice).exports;
  for (const [format, sel] of Object.entries(EXPORT_BUTTONS)) {
    const server = state.exports.includes(format);
    $(sel).disabled = !server || !made.includes(format);
    $(sel).title = !server ? 'this server cannot make this format yet' : made.includes(format) ? '' : `not made for the ${lattice} lattice`;
  }
}

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
    state.figures.forEach((f) => { f.cells.clear(); f.keep.clear(); f.d = 1; f.layer = 0; });
    state.undo = []; state.redo = [];
  }
  document.body.classList.toggle('cubic', geo(l).layers);
  $('#opt-mirror').disabled = !geo(l).mirror;
  // The checkerboard rule only where the engine offers it (its lattice description says so).
  const board = !!geo(l).checkerboard;
  $('#opt-checkerboard').disabled = !board;
  if (!board) $('#opt-checkerboard').checked = false;
  $('#checkerboard-label').classList.toggle('off', !board);
  $('#checkerboard-label').title = board ? 'every piece keeps the colour of each of its cells in a checkerboard colouring' : `no checkerboard colouring on the ${l} lattice`;
}

function selectTool(tool) {
  state.tool = tool;
  // Painting keep regions opens the Puzzle options, where they are listed.
  if (tool === 'keep') $('details.puzzle').open = true;
  $$('.tool').forEach((b) => b.classList.toggle('active', b.dataset.tool === tool));
}

/** The lattices the server describes: their geometry and the lattice menu. */
async function loadLattices() {
  const { lattices } = await api('GET', '/api/lattices');
  setLattices(lattices);
  const menu = $('#lattice');
  menu.textContent = '';
  for (const L of lattices) {
    const o = document.createElement('option');
    o.value = L.lattice;
    o.textContent = L.title;
    menu.append(o);
  }
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
      const tool = { p: 'pen', e: 'erase', r: 'rect', f: 'fill', k: 'keep' }[k];
      if (tool) selectTool(tool);
    }
  });
  window.addEventListener('studio-hover-piece', (ev) => highlight(ev.detail));
  $('#solve').onclick = startSolve;
  $('#enumerate').onclick = startEnumerate;
  // The keep tool's letters, each in its palette colour.
  const letters = $('#keep-letter');
  for (const l of LETTERS) {
    const o = document.createElement('option');
    o.value = l;
    o.textContent = l;
    o.style.background = letterColour(l);
    letters.append(o);
  }
  state.keepLetter = 'a';
  const showLetter = () => { letters.style.background = letterColour(state.keepLetter); };
  letters.onchange = () => { state.keepLetter = letters.value; showLetter(); selectTool('keep'); };
  showLetter();
  for (const sel of ['#opt-solutions', '#opt-rank', '#opt-min-piece', '#opt-max-piece', '#opt-symmetry', '#opt-checkerboard', '#opt-assemblable', '#opt-min-level']) {
    // On every keystroke: the summary's height settles before a click on Solve.
    $(sel).addEventListener('input', updatePuzzleSet);
    $(sel).addEventListener('change', updatePuzzleSet);
  }
  $('#sol-prev').onclick = () => selectSolution(state.current - 1);
  $('#sol-next').onclick = () => selectSolution(state.current + 1);
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
  $('#dl-html').onclick = () => exportFile('html');
  try {
    await loadLattices();
  } catch (e) {
    showMessage(`cannot read the lattices from the server: ${e.message}`);
    return;
  }
  setLattice('square');
  renderFigures();
  updateUndo();
  try {
    const info = await api('GET', '/api/info');
    state.exports = info.exports;
    for (const [format, sel] of Object.entries(EXPORT_BUTTONS)) {
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
window.studioShowDisassembly = showDisassembly; // for the end-to-end tests
// The editor's scale and plane origin of figure i (for the end-to-end tests).
window.studioEditorView = (i) => { const { cs, lo } = editorView(state.figures[i]); return { cs, lo }; };
window.studioPalette = PALETTE;
init();
