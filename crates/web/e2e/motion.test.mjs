// End-to-end tests of the motion player and of the page to share, in
// Debian's headless chromium: on every lattice with a shipped example the
// pieces move from one figure to the other; at t = 0, 0.5 and 1 the page's
// own state puts every piece where the solution says (checked here against
// cell centres computed from the solution's cells, not against the
// server's motions), and the screenshot shows the piece's colour there. The
// HTML page downloaded from the studio opens from file:// with the network
// off and animates. The 3D view frames every figure whole.
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
async function checkAt(frame, handle, solution, t) {
  const lattice = solution.lattice;
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
    for (const t of [0, 0.5, 1]) {
      const { moved } = await checkAt(page, studioPlayer, solution, t);
      if (data.dim === 2 && t !== 0.5) await checkPixels(page, '#motion', data, moved);
      const name = `motion-${ex.lattice}-t${Math.round(t * 100)}.png`;
      const keep = (ex.lattice === 'square') || t === 0.5;
      await host.screenshot({ path: path.join(keep ? DOCS : downloads, name) });
    }
    // One at a time: half way, the pieces early in the assembly order have arrived, the last not yet left.
    await page.evaluate(() => { const p = document.querySelector('#motion').player; p.setOneAtATime(true); p.setT(0.5); });
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
    for (const t of [0, 0.5, 1]) await checkAt(p, handle, solution, t);
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
