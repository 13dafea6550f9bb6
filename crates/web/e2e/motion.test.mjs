// End-to-end tests of the motion player and of the page to share, in
// Debian's headless chromium: on every lattice with a shipped example the
// pieces move from one figure to the other; at t = 0, 0.5 and 1 the page's
// own state puts every piece where the solution says (checked here against
// cell centres computed from the solution's cells, not against the
// server's motions), and the screenshot shows the piece's colour there. The
// HTML page downloaded from the studio opens from file:// with the network
// off and animates. The 3D view frames every figure whole. A 3D answer plays
// its disassembly plan (replayed here move by move from the drawn cells:
// the plan's pieces move, along one axis, never through their part), and
// the studio shows each figure's level or warns that it cannot be built.
//
// Needs DISSECT_URL (a running `dissect serve`) and DISSECT_DOCS (where the
// screenshots go); .ci/steps/50-web-e2e.sh sets both.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';

const URL = process.env.DISSECT_URL;
const DOCS = process.env.DISSECT_DOCS;
assert.ok(URL && DOCS, 'set DISSECT_URL and DISSECT_DOCS');

let browser;
let page;
let downloads;
const pageErrors = [];
const saved = {}; // lattice -> downloaded HTML page

const ARGS = ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
  '--disable-background-networking', '--disable-component-update', '--disable-sync'];

before(async () => {
  downloads = fs.mkdtempSync(path.join(os.tmpdir(), 'dissect-motion-'));
  browser = await chromium.launch({ executablePath: '/usr/bin/chromium', headless: true, args: ARGS });
  const context = await browser.newContext({ viewport: { width: 1100, height: 900 }, acceptDownloads: true });
  page = await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(e.message));
  page.setDefaultTimeout(20_000);
});

after(async () => {
  await browser?.close();
  fs.rmSync(downloads, { recursive: true, force: true });
});

// ------------------------------------------------ geometry of FORMAT.md

/** The centre of a cell in lattice units (2D: image orientation; cubic: [x, y, z]). */
function centre(lattice, c) {
  const H = Math.sqrt(3) / 2;
  const [x, y, t = 0] = c;
  switch (lattice) {
    case 'square': return [x + 0.5, y + 0.5];
    case 'tri4': return [[x + 0.5, y + 1 / 6], [x + 5 / 6, y + 0.5], [x + 0.5, y + 5 / 6], [x + 1 / 6, y + 0.5]][t];
    case 'cubic': return [x + 0.5, y + 0.5, t + 0.5];
    case 'tri3': return [(x + 1) / 2, y * H + ((x + y) % 2 === 0 ? 2 * H / 3 : H / 3)];
    case 'hex': return [x + (((y % 2) + 2) % 2) / 2, y * H];
    default: throw new Error(`no geometry for ${lattice}`);
  }
}

const add = (a, b) => a.map((v, j) => v + b[j]);
const mean = (ps) => ps[0].map((_, j) => ps.reduce((s, p) => s + p[j], 0) / ps.length);
const near = (a, b, eps = 1e-6) => a.length === b.length && a.every((v, j) => Math.abs(v - b[j]) < eps);
const sortPts = (ps) => ps.map((p) => p.map((v) => Math.round(v * 1e6) / 1e6)).sort((p, q) => p[0] - q[0] || p[1] - q[1] || (p[2] ?? 0) - (q[2] ?? 0));

/**
 * Checks the player `handle` (an expression) in `frame` (a Page) at t against the solution: every
 * piece's cells are drawn where the solution puts them at t = 0 and t = 1,
 * and its centre is half way (lifted in 3D) at t = 0.5. Returns the state.
 */
async function checkAt(frame, handle, solution, when) {
  const lattice = solution.lattice;
  // 'mid': half way (3D figures with a disassembly plan: half way through
  // the carrying over, between the plans' moves).
  const tl = await frame.evaluate((h) => { const p = new Function(`return ${h}`)(); p.setT(0); return p.state().timeline; }, handle);
  const t = when === 'mid' ? (tl ? (tl.from_moves + tl.transit / 2) / tl.total : 0.5) : when;
  const plans = await frame.evaluate((h) => new Function(`return ${h}`)().data.figures.map((f) => f.plan), handle);
  /** Where the plan of figure f leaves piece i (the sum of its moves). */
  const apart = (f, i) => (plans[f] || []).filter((m) => m.pieces.includes(i)).reduce((o, m) => add(o, m.by), [0, 0, 0]);
  await frame.evaluate(([h, v]) => new Function(`return ${h}`)().setT(v), [handle, t]);
  const got = await frame.evaluate(([h, sol, lat, src]) => {
    const centreOf = new Function(`return (${src})`)();
    const p = new Function(`return ${h}`)();
    const st = p.state();
    const moved = sol.figures[st.from].pieces.map((cells, i) => cells.map((c) => p.map(i, centreOf(lat, c))));
    return { st, moved };
  }, [handle, solution, lattice, centre.toString()]);
  const { st, moved } = got;
  assert.equal(st.mode, 'motion');
  assert.equal(st.t, t);
  const offA = st.offsets[st.from], offB = st.offsets[st.to];
  solution.figures[st.from].pieces.forEach((cells, i) => {
    const a = cells.map((c) => add(centre(lattice, c), offA));
    const b = solution.figures[st.to].pieces[i].map((c) => add(centre(lattice, c), offB));
    if (t === 0) {
      a.forEach((p, k) => assert.ok(near(moved[i][k], p), `${lattice} t=0 piece ${i}: ${moved[i][k]} vs ${p}`));
    } else if (t === 1) {
      assert.deepEqual(sortPts(moved[i]), sortPts(b), `${lattice} t=1: piece ${i} lies on its cells in the other figure`);
    } else if (tl) {
      const mid = mean([add(mean(a), apart(st.from, i)), add(mean(b), apart(st.to, i))]);
      mid[2] += st.lift;
      assert.ok(near(mean(moved[i]), mid), `${lattice} mid-way piece ${i}: centre ${mean(moved[i])} vs ${mid}`);
    } else {
      const mid = mean([mean(a), mean(b)]);
      if (mid.length === 3) mid[2] += st.lift; // 3D pieces rise on their way
      assert.ok(near(mean(moved[i]), mid), `${lattice} t=0.5 piece ${i}: centre ${mean(moved[i])} vs ${mid}`);
    }
  });
  return { st, moved };
}

/** In 2D: the canvas pixel at each moved cell centre has the piece's colour (most cells; labels may cover some). */
async function checkPixels(frame, selector, data, moved) {
  const bad = await frame.evaluate(([sel, mv, colours]) => {
    const c = document.querySelector(`${sel} canvas`);
    const v = document.querySelector(sel).player.state().view;
    const g = c.getContext('2d');
    const dpr = c.width / c.clientWidth;
    let wrong = 0, all = 0;
    mv.forEach((pts, i) => pts.forEach(([x, y]) => {
      const d = g.getImageData(Math.round((v.ox + v.k * x) * dpr), Math.round((v.oy + v.k * y) * dpr), 1, 1).data;
      const hex = '#' + [d[0], d[1], d[2]].map((q) => q.toString(16).padStart(2, '0')).join('');
      all++;
      if (hex !== colours[i]) wrong++;
    }));
    return wrong / all;
  }, [selector, moved, data.pieces.map((p) => p.colour)]);
  assert.ok(bad < 0.2, `${Math.round(bad * 100)}% of the cell centres do not show their piece's colour`);
}

const studioPlayer = "document.querySelector('#motion').player";

test('the studio moves the pieces of every lattice; t = 0, 0.5, 1 match the solution', async () => {
  await page.goto(URL);
  await page.waitForSelector('body[data-ready=true]');
  const examples = await page.evaluate(() => window.studio.examples);
  const wanted = ['square', 'tri4', 'cubic', 'tri3', 'hex'];
  const chosen = wanted.map((l) => examples.find((e) => e.lattice === l)).filter(Boolean);
  assert.deepEqual(chosen.map((e) => e.lattice), wanted, 'an example is shipped for every lattice');
  for (const ex of chosen) {
    await page.goto(URL);
    await page.waitForSelector('body[data-ready=true]');
    await page.selectOption('[data-testid=example]', ex.id);
    await page.waitForFunction(() => window.studio.figures.length >= 2 && window.studio.figures.every((f) => f.cells.size > 0));
    await page.fill('#opt-time', '30');
    await page.click('[data-testid=solve]');
    await page.waitForSelector('#result:not([hidden])', { timeout: 60_000 });
    await page.waitForFunction(() => document.querySelector('#motion')?.player || /unavailable/.test(document.querySelector('#motion').textContent));
    const unavailable = await page.evaluate(() => !document.querySelector('#motion').player && document.querySelector('#motion').textContent);
    assert.equal(unavailable, false, `${ex.lattice}: ${unavailable}`);
    const solution = await page.evaluate(() => window.studio.result.solution);
    const data = await page.evaluate(() => document.querySelector('#motion').player.data);
    assert.equal(data.lattice, ex.lattice);
    // The studio's piece colours are the player's (one palette).
    const palette = await page.evaluate(() => window.studioPalette);
    data.pieces.forEach((p, i) => assert.equal(p.colour, palette[i % palette.length], `piece ${i}`));

    await page.evaluate(() => document.querySelector('#motion').player.setMode('motion'));
    const host = page.locator('#motion');
    await host.scrollIntoViewIfNeeded();
    for (const t of [0, 'mid', 1]) {
      const { moved } = await checkAt(page, studioPlayer, solution, t);
      if (data.dim === 2 && t !== 'mid') await checkPixels(page, '#motion', data, moved);
      const name = `motion-${ex.lattice}-t${t === 'mid' ? 50 : Math.round(t * 100)}.png`;
      const keep = (ex.lattice === 'square') || t === 'mid';
      await host.screenshot({ path: path.join(keep ? DOCS : downloads, name) });
    }
    // One at a time: half way (through the carrying over, with plans), the pieces early in the assembly order have arrived, the last not yet left.
    await page.evaluate(() => {
      const p = document.querySelector('#motion').player;
      p.setOneAtATime(true);
      const tl = p.state().timeline;
      p.setT(tl ? (tl.from_moves + tl.transit / 2) / tl.total : 0.5);
    });
    const st = await page.evaluate(() => document.querySelector('#motion').player.state());
    const order = data.figures[st.to].order;
    assert.deepEqual([...order].sort((a, b) => a - b), data.pieces.map((_, i) => i), 'the order lists every piece once');
    const s = (i) => st.pieces.find((p) => p.piece === i).s;
    if (order.length >= 2) {
      assert.equal(s(order[0]), 1, 'the first piece is in place');
      assert.equal(s(order[order.length - 1]), 0, 'the last piece has not moved yet');
    }
    // The page to share, downloaded from the studio.
    const [dl] = await Promise.all([page.waitForEvent('download'), page.click('[data-testid=download-html]')]);
    const file = path.join(downloads, `${ex.lattice}.html`);
    await dl.saveAs(file);
    saved[ex.lattice] = { file, solution };
  }
  assert.deepEqual(pageErrors, []);
});

test('the 3D view shows every figure whole at its default camera', async () => {
  await page.goto(URL);
  await page.waitForSelector('body[data-ready=true]');
  await page.selectOption('[data-testid=example]', 'cube4-cavity-to-7x4x2');
  await page.waitForFunction(() => window.studio.figures.length === 2 && window.studio.figures[1].cells.size === 56);
  await page.click('[data-testid=solve]');
  await page.waitForSelector('#result:not([hidden])', { timeout: 60_000 });
  await page.waitForFunction(() => document.querySelector('#motion')?.player);
  const check = () => page.evaluate(() => {
    const c = document.querySelector('#motion canvas');
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const bg = (p) => d[p] === 255 && d[p + 1] === 255 && d[p + 2] === 255;
    let edge = 0, inside = 0;
    const m = 2;
    for (let y = 0; y < c.height; y++) {
      for (let x = 0; x < c.width; x++) {
        if (bg((y * c.width + x) * 4)) continue;
        if (x < m || y < m || x >= c.width - m || y >= c.height - m) edge++; else inside++;
      }
    }
    return { edge, inside, mode: document.querySelector('#motion').player.state().mode };
  });
  const st = await check();
  assert.equal(st.mode, 'figures', 'cubic opens on the figures');
  assert.equal(st.edge, 0, 'no piece pixel touches the frame');
  assert.ok(st.inside > 2000, 'the figures are drawn');
  // Every piece of every figure has faces drawn: hide all but one piece, it still shows.
  const n = await page.evaluate(() => document.querySelector('#motion').player.data.pieces.length);
  for (let i = 0; i < n; i++) {
    await page.evaluate(([k, all]) => { const p = document.querySelector('#motion').player; for (let j = 0; j < all; j++) p.setVisible(j, j === k); }, [i, n]);
    const one = await check();
    assert.ok(one.inside > 100 && one.edge === 0, `piece ${i} alone is drawn inside the frame`);
  }
  await page.evaluate((all) => { const p = document.querySelector('#motion').player; for (let j = 0; j < all; j++) p.setVisible(j, true); p.setExplode(0.6); }, n);
  const exploded = await check();
  assert.equal(exploded.edge, 0, 'the exploded view fits too');
  await page.evaluate(() => document.querySelector('#motion').player.setExplode(0));
  await page.locator('#motion').screenshot({ path: path.join(DOCS, 'motion-cubic-3d.png') });
});

/** The integer cells [x, y, z] piece i of figure `from` is drawn on now (the player's own map of its cell centres). */
async function drawnCells(solution, from) {
  return page.evaluate(([sol, f]) => {
    const p = document.querySelector('#motion').player;
    return sol.figures[f].pieces.map((cells, i) => cells.map((c) => p.map(i, [c[0] + 0.5, c[1] + 0.5, c[2] + 0.5]).map((v) => v - 0.5)));
  }, [solution, from]);
}

test('a 3D answer plays its disassembly plan: moves in order and groups, none impossible, then the next figure goes together', async () => {
  await page.goto(URL);
  await page.waitForSelector('body[data-ready=true]');
  await page.selectOption('[data-testid=example]', 'cube4-cavity-to-7x4x2');
  await page.waitForFunction(() => window.studio.figures.length === 2 && window.studio.figures[1].cells.size === 56);
  await page.click('[data-testid=solve]');
  await page.waitForSelector('#result:not([hidden])', { timeout: 60_000 });
  await page.waitForFunction(() => document.querySelector('#motion')?.player);
  const solution = await page.evaluate(() => window.studio.result.solution);
  const data = await page.evaluate(() => document.querySelector('#motion').player.data);
  // The studio shows each figure's level.
  await page.waitForSelector('#disassembly:not([hidden])');
  for (let f = 0; f < 2; f++) {
    const text = await page.textContent(`[data-testid=level-${f}]`);
    assert.match(text, /: level [1-9]\d* \(apart in \d+ moves?\)$/, text);
    assert.equal(data.figures[f].level >= 1, true);
  }
  await page.evaluate(() => { const p = document.querySelector('#motion').player; p.setMode('motion'); p.setFigures(0, 1); });
  const tl = await page.evaluate(() => document.querySelector('#motion').player.state().timeline);
  assert.ok(tl, 'cubic figures that come apart have a timeline');
  assert.equal(tl.from_moves, data.figures[0].plan.length);
  assert.equal(tl.to_moves, data.figures[1].plan.length);
  assert.ok(tl.from_moves >= 1 && tl.to_moves >= 1);
  const n = data.pieces.length;
  const key = (c) => c.map((v) => Math.round(v)).join(',');
  const asInts = (cells) => cells.map((p) => p.map((q) => q.map((v) => Math.round(v * 1e6) / 1e6)));
  const setT = (t) => page.evaluate((v) => document.querySelector('#motion').player.setT(v), t);
  /**
   * Replays one figure's plan as the player draws it, a move at a time from
   * t0 (dir 1: the first figure coming apart; dir -1: from the end back in
   * time, the next figure coming apart, which is its assembly in reverse).
   */
  async function replay(f, plan, t0, dir) {
    const part = new Array(n).fill(0);
    let parts = 1;
    await setT(t0);
    let before = asInts(await drawnCells(solution, 0));
    for (let k = 0; k < plan.length; k++) {
      const m = plan[k];
      await setT(t0 + dir * (k + 1) / tl.total);
      const after = asInts(await drawnCells(solution, 0));
      // Moved: exactly the move's pieces, all by the plan's displacement.
      for (let i = 0; i < n; i++) {
        const d = after[i][0].map((v, j) => v - before[i][0][j]);
        const want = m.pieces.includes(i) ? m.by : [0, 0, 0];
        assert.ok(near(d, want, 1e-6), `figure ${f} move ${k}: piece ${i} moved by ${d}, the plan says ${want}`);
        after[i].forEach((c, q) => assert.ok(near(c, before[i][q].map((v, j) => v + d[j]), 1e-6), 'a move is a translation'));
      }
      assert.equal(m.by.filter((v) => v !== 0).length, 1, 'one axis');
      assert.ok(m.by.every((v) => Number.isInteger(v)), 'whole cubes');
      // Every unit step is free of the other pieces of its part.
      const axis = m.by.findIndex((v) => v !== 0), len = Math.abs(m.by[axis]), sign = Math.sign(m.by[axis]);
      const owner = part[m.pieces[0]];
      assert.ok(m.pieces.every((i) => part[i] === owner), 'a group lies in one part');
      const rest = new Set();
      for (let i = 0; i < n; i++) if (!m.pieces.includes(i) && part[i] === owner) before[i].forEach((c) => rest.add(key(c)));
      for (let step = 1; step <= len; step++) {
        for (const i of m.pieces) {
          for (const c of before[i]) {
            const q = c.slice(); q[axis] += step * sign;
            assert.ok(!rest.has(key(q)), `figure ${f} move ${k}: piece ${i} would pass through its part at step ${step}`);
          }
        }
      }
      if (m.removed) { m.pieces.forEach((i) => { part[i] = parts; }); parts++; }
      // No two pieces overlap after any move.
      const seen = new Map();
      after.forEach((cells, i) => cells.forEach((c) => {
        assert.ok(!seen.has(key(c)), `figure ${f} after move ${k}: pieces ${seen.get(key(c))} and ${i} overlap`);
        seen.set(key(c), i);
      }));
      before = after;
    }
    assert.equal(new Set(part).size, n, `figure ${f}: every piece ends in a part of its own`);
  }
  await replay(0, data.figures[0].plan, 0, 1);
  // The bar says which move plays.
  await setT(0.5 / tl.total);
  const step = await page.textContent('#motion [data-testid=plan-step]');
  assert.match(step, new RegExp(`^${data.figures[0].name}: move 1 of ${tl.from_moves} \\(level \\d+\\): `), step);
  await replay(1, data.figures[1].plan, 1, -1);
  // At the end the pieces lie on the next figure's cells.
  await checkAt(page, studioPlayer, solution, 1);
  // Screenshots of the plan being played: coming apart, carried over, going together.
  const host = page.locator('#motion');
  await host.scrollIntoViewIfNeeded();
  const shots = [[Math.max(1, tl.from_moves - 1), 'apart'], [tl.from_moves + tl.transit / 2, 'carry'], [tl.total - 1, 'together']];
  for (const [u, name] of shots) {
    await setT(u / tl.total);
    await host.screenshot({ path: path.join(DOCS, `motion-cubic-plan-${name}.png`) });
  }
  // Play runs the whole plan to the end.
  await page.evaluate(() => { const p = document.querySelector('#motion').player; p.setT(0); p.play(); });
  await page.waitForFunction(() => Number(document.querySelector('#motion').dataset.t) === 1, null, { timeout: 30_000 });
  assert.deepEqual(pageErrors, []);
});

test('the studio warns when a 3D answer cannot be built', async () => {
  // Two linked voxel rings (no straight moves part them), twice.
  const sq = [[0, 0], [1, 0], [2, 0], [0, 1], [2, 1], [0, 2], [1, 2], [2, 2]];
  const a = sq.map(([x, y]) => [x, y, 1]);
  const b = sq.map(([y, z]) => [1, y + 1, z]);
  const rings = { format: 'dissection-solution/1', lattice: 'cubic', mirror: true,
    figures: [{ name: 'rings', pieces: [a, b] }, { name: 'rings again', pieces: [a, b] }] };
  await page.goto(URL);
  await page.waitForSelector('body[data-ready=true]');
  const data = await page.evaluate(async (sol) => {
    const res = await fetch('/api/export/animation', { method: 'POST', headers: { 'content-type': 'application/json' }, body: JSON.stringify({ solution: sol }) });
    return res.json();
  }, rings);
  assert.deepEqual(data.figures.map((f) => [f.level, f.locked, f.plan]), [[null, [0, 1], null], [null, [0, 1], null]]);
  await page.evaluate((d) => { document.querySelector('#result').hidden = false; window.studioShowDisassembly(d); }, data);
  const text = await page.textContent('[data-testid=level-0]');
  assert.equal(text, 'rings: ⚠ cannot be built (pieces A, B locked)');
  assert.equal(await page.getAttribute('[data-testid=level-0]', 'class'), 'cannot-build');
});

test('the downloaded page opens from file:// with the network off and animates', async () => {
  assert.deepEqual(Object.keys(saved), ['square', 'tri4', 'cubic', 'tri3', 'hex'], 'the first test saved the pages');
  const context = await browser.newContext({ viewport: { width: 1000, height: 800 }, offline: true });
  const requests = [];
  await context.route('**/*', (route) => {
    const u = route.request().url();
    if (u.startsWith('file:')) return route.continue();
    requests.push(u);
    return route.abort();
  });
  const p = await context.newPage();
  const errors = [];
  p.on('pageerror', (e) => errors.push(e.message));
  for (const [lattice, { file, solution }] of Object.entries(saved)) {
    await p.goto(`file://${file}`);
    await p.waitForSelector('body[data-ready=true]', { timeout: 10_000 });
    const handle = 'window.dissectPlayer';
    await p.evaluate(() => window.dissectPlayer.setMode('motion'));
    for (const t of [0, 'mid', 1]) await checkAt(p, handle, solution, t);
    // Play runs the animation to the end.
    await p.evaluate(() => { window.dissectPlayer.setT(0); window.dissectPlayer.play(); });
    await p.waitForFunction(() => Number(document.querySelector('#player').dataset.t) > 0.2, null, { timeout: 10_000 });
    await p.waitForFunction(() => Number(document.querySelector('#player').dataset.t) === 1, null, { timeout: 20_000 });
    if (lattice === 'square') await p.screenshot({ path: path.join(DOCS, 'motion-page.png') });
  }
  assert.deepEqual(requests, [], 'the page fetched nothing');
  assert.deepEqual(errors, []);
  await context.close();
});
