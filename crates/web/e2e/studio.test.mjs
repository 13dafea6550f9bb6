// End-to-end tests of the studio page in Debian's headless chromium.
//
// Needs a running `dissect serve` (DISSECT_URL) and a folder for the
// screenshots (DISSECT_DOCS); solutions are checked by check.mjs (the
// repository's tools/check_solution.py, and the external verify.py named by
// DISSECT_VERIFY when present). .ci/steps/50-web-e2e.sh sets them.

import { test, before, after } from 'node:test';
import assert from 'node:assert/strict';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chromium } from 'playwright-core';
import { checkSolution } from './check.mjs';

const URL = process.env.DISSECT_URL;
const DOCS = process.env.DISSECT_DOCS;
assert.ok(URL && DOCS, 'set DISSECT_URL and DISSECT_DOCS');

let context;
let page;
let profile;
let downloads;
const pageErrors = [];

before(async () => {
  profile = fs.mkdtempSync(path.join(os.tmpdir(), 'dissect-chromium-'));
  downloads = fs.mkdtempSync(path.join(os.tmpdir(), 'dissect-downloads-'));
  context = await chromium.launchPersistentContext(profile, {
    executablePath: '/usr/bin/chromium',
    headless: true,
    acceptDownloads: true,
    viewport: { width: 1280, height: 860 },
    args: [
      '--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync',
    ],
  });
  page = await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(e.message));
  page.setDefaultTimeout(20_000);
});

after(async () => {
  await context?.close();
  fs.rmSync(profile, { recursive: true, force: true });
  fs.rmSync(downloads, { recursive: true, force: true });
});

async function open() {
  await page.goto(URL);
  await page.waitForSelector('body[data-ready=true]');
}

const card = (i) => page.locator('#figures .card').nth(i);
const count = (i) => card(i).locator('[data-testid=count]');

/** Page coordinates of the centre of cell (x, y) of figure i's editor (dx, dy: offset inside the cell, 0..1). */
async function cellPoint(i, x, y, dx = 0.5, dy = 0.5) {
  const box = await card(i).locator('canvas.grid').boundingBox();
  const fig = await page.evaluate((j) => ({ w: window.studio.figures[j].w, h: window.studio.figures[j].h }), i);
  const cs = (box.width - 1) / fig.w;
  return [box.x + (x + dx) * cs, box.y + (y + dy) * cs];
}

async function drag(i, from, to) {
  const [x0, y0] = await cellPoint(i, ...from);
  const [x1, y1] = await cellPoint(i, ...to);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move((x0 + x1) / 2, (y0 + y1) / 2, { steps: 4 });
  await page.mouse.move(x1, y1, { steps: 4 });
  await page.mouse.up();
}

async function click(i, x, y, dx, dy) {
  const [px, py] = await cellPoint(i, x, y, dx, dy);
  await page.mouse.click(px, py);
}

async function tool(name) {
  await page.click(`.tool[data-tool=${name}]`);
}

async function setSize(i, w, h) {
  await card(i).locator('input.w').fill(String(w));
  await card(i).locator('input.w').dispatchEvent('change');
  await card(i).locator('input.h').fill(String(h));
  await card(i).locator('input.h').dispatchEvent('change');
}

async function saveDownload(trigger) {
  const [dl] = await Promise.all([page.waitForEvent('download'), trigger()]);
  const file = path.join(downloads, dl.suggestedFilename());
  await dl.saveAs(file);
  return file;
}

/** The distinct piece colours painted on a solved canvas. */
async function coloursOn(testid) {
  return page.evaluate((id) => {
    const c = document.querySelector(`canvas[data-testid="${id}"]`);
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const seen = new Set();
    for (let p = 0; p < d.length; p += 4) {
      if (d[p + 3] < 255) continue;
      const hex = '#' + [d[p], d[p + 1], d[p + 2]].map((v) => v.toString(16).padStart(2, '0')).join('');
      seen.add(hex);
    }
    const palette = new Set(window.studioPalette);
    return [...seen].filter((h) => palette.has(h));
  }, testid);
}

async function solveAndWait(timeLimit) {
  await page.fill('#opt-time', String(timeLimit));
  await page.click('[data-testid=solve]');
  await page.waitForSelector('#progress:not([hidden])');
  await page.waitForSelector('#result:not([hidden])', { timeout: (timeLimit + 15) * 1000 });
}

test('draw two figures, see the counts, solve, check the downloaded solution', async () => {
  await open();
  assert.match(await page.textContent('[data-testid=areas]'), /Draw your figures/);

  // Figure a: a 4x3 rectangle with the rectangle tool.
  await tool('rect');
  await drag(0, [0, 0], [3, 2]);
  assert.equal(await count(0).textContent(), '12 cells');

  // Figure b: a 6x2 grid flood-filled, then one cell erased with the pen.
  await setSize(1, 6, 2);
  await tool('fill');
  await click(1, 2, 1);
  assert.equal(await count(1).textContent(), '12 cells');
  await tool('pen');
  await click(1, 5, 1);
  assert.equal(await count(1).textContent(), '11 cells (−1)');
  const areas = await page.textContent('[data-testid=areas]');
  assert.match(areas, /Areas differ by 1 cell \(/);
  assert.match(areas, /figure-b\.txt needs 1 more/);
  assert.ok(await page.isDisabled('[data-testid=solve]'), 'Solve is off while areas differ');
  await page.screenshot({ path: path.join(DOCS, 'studio-editor.png') });

  // Undo brings the cell back, redo removes it, undo again.
  await page.click('[data-testid=undo]');
  assert.equal(await count(1).textContent(), '12 cells');
  await page.click('[data-testid=redo]');
  assert.equal(await count(1).textContent(), '11 cells (−1)');
  await page.keyboard.press('Control+z');
  assert.equal(await count(1).textContent(), '12 cells');
  assert.match(await page.textContent('[data-testid=areas]'), /Equal areas: every figure has 12 cells/);

  // A pen drag on figure a adds a row of cells, the eraser takes it away.
  await drag(0, [0, 4], [3, 4]);
  assert.equal(await count(0).textContent(), '16 cells');
  await tool('erase');
  await drag(0, [0, 4], [3, 4]);
  assert.equal(await count(0).textContent(), '12 cells');

  await solveAndWait(20);
  const summary = await page.textContent('[data-testid=result-summary]');
  const pieces = Number(/^(\d+) pieces/.exec(summary)[1]);
  assert.ok(pieces >= 2 && pieces <= 12, summary);
  assert.match(summary, /area variance \d/);
  // Both figures are drawn with the same piece colours.
  const c0 = await coloursOn('solved-0');
  const c1 = await coloursOn('solved-1');
  assert.equal(c0.length, pieces, `figure a shows ${c0} for ${pieces} pieces`);
  assert.deepEqual([...c1].sort(), [...c0].sort());

  // The solution JSON and the figures, checked by the independent verifier.
  const json = await saveDownload(() => page.click('[data-testid=download-json]'));
  const a = await saveDownload(() => card(0).locator('button.save').click());
  const b = await saveDownload(() => card(1).locator('button.save').click());
  const solution = JSON.parse(fs.readFileSync(json, 'utf8'));
  assert.equal(solution.format, 'dissection-solution/1');
  assert.equal(solution.figures[0].pieces.length, pieces);
  const out = checkSolution('square', json, [a, b]);
  assert.match(out, new RegExp(`valid: ${pieces} pieces`));
});

test('a shipped example solves with live progress; hovering a piece highlights it everywhere', async () => {
  await open();
  await page.selectOption('[data-testid=example]', 'squares-3-4-to-5');
  await page.waitForFunction(() => window.studio.figures.length === 2 && window.studio.figures[1].cells.size === 25);
  assert.match(await page.textContent('[data-testid=areas]'), /every figure has 25 cells/);
  await solveAndWait(30);
  // Progress was shown: a level and an elapsed time.
  assert.match(await page.textContent('#p-level'), /\d+ \(\d+ pieces\)/);
  assert.match(await page.textContent('#p-elapsed'), /\d+\.\d s/);
  const summary = await page.textContent('[data-testid=result-summary]');
  const pieces = Number(/^(\d+) pieces/.exec(summary)[1]);
  assert.ok(pieces >= 4, summary);

  // Hover the top-left cell of the first figure: its piece is highlighted
  // (the legend entry and the same piece in the other figure).
  const box = await page.locator('canvas[data-testid=solved-0]').boundingBox();
  await page.mouse.move(box.x + 6, box.y + 6);
  await page.waitForFunction(() => window.studio.hot >= 0);
  const hot = await page.evaluate(() => window.studio.hot);
  assert.equal(await page.locator('#legend span.hot').count(), 1);
  assert.equal(await page.getAttribute('#legend span.hot', 'data-piece'), String(hot));
  await page.locator('#result').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(DOCS, 'studio-solved.png'), fullPage: true });

  const json = await saveDownload(() => page.click('[data-testid=download-json]'));
  const figs = [];
  for (const i of [0, 1]) figs.push(await saveDownload(() => card(i).locator('button.save').click()));
  const out = checkSolution('square', json, figs);
  assert.match(out, new RegExp(`valid: ${pieces} pieces`));

  // Pictures and meshes made by the server's renderer.
  const svg = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-svg]')), 'utf8');
  assert.match(svg, /<svg[\s\S]*<\/svg>/);
  const png = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-png]')));
  assert.equal(png.subarray(1, 4).toString(), 'PNG');
  const zip = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-stl]')));
  assert.equal(zip.subarray(0, 2).toString(), 'PK');
  assert.match(zip.toString('latin1'), /piece-01-A\.stl/);
  const sheet = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-cut]')), 'utf8');
  assert.match(sheet, /<svg[^>]*mm/);
  const ldraw = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-ldraw]')));
  assert.equal(ldraw.subarray(0, 2).toString(), 'PK');
  assert.match(ldraw.toString('latin1'), /\.ldr/);
});

test('an uploaded picture is rasterized to the asked number of cells', async () => {
  await open();
  // A black disc on white, drawn by the browser itself.
  const b64 = await page.evaluate(() => {
    const c = document.createElement('canvas');
    c.width = 120; c.height = 90;
    const g = c.getContext('2d');
    g.fillStyle = '#fff'; g.fillRect(0, 0, 120, 90);
    g.fillStyle = '#000'; g.beginPath(); g.arc(60, 45, 40, 0, 2 * Math.PI); g.fill();
    return c.toDataURL('image/png').split(',')[1];
  });
  await card(0).locator('input.cells').fill('50');
  await card(0).locator('input.picture').setInputFiles({ name: 'disc.png', mimeType: 'image/png', buffer: Buffer.from(b64, 'base64') });
  await page.waitForFunction(() => window.studio.figures[0].cells.size > 0);
  assert.equal(await count(0).textContent(), '50 cells');
  assert.match(await page.textContent('[data-testid=areas]'), /Areas differ by 50 cells/);
});

test('tri4: a click fills the triangle under the mouse; a tri4 solution is checked', async () => {
  await open();
  await page.selectOption('[data-testid=lattice]', 'tri4');
  await tool('pen');
  await click(0, 1, 1, 0.5, 0.15); // top triangle of square (1, 1)
  await click(0, 2, 1, 0.85, 0.5); // right triangle of square (2, 1)
  assert.equal(await count(0).textContent(), '2 cells');
  const cells = await page.evaluate(() => [...window.studio.figures[0].cells].sort());
  assert.deepEqual(cells, ['1,1,0', '2,1,1']);
  await tool('rect');
  await drag(1, [0, 0], [1, 0]);
  assert.equal(await count(1).textContent(), '8 cells');

  // The shipped tri4 example: solved, drawn in triangles, checked by the independent checkers (check.mjs).
  await page.selectOption('[data-testid=example]', 'tri-triangle8-to-rect4x8');
  await page.waitForFunction(() => window.studio.figures.length === 2 && window.studio.figures[1].cells.size === 128);
  await solveAndWait(30);
  const pieces = Number(/^(\d+) pieces/.exec(await page.textContent('[data-testid=result-summary]'))[1]);
  assert.equal((await coloursOn('solved-0')).length, pieces);
  const json = await saveDownload(() => page.click('[data-testid=download-json]'));
  const figs = [];
  for (const i of [0, 1]) figs.push(await saveDownload(() => card(i).locator('button.save').click()));
  const out = checkSolution('tri4', json, figs);
  assert.match(out, new RegExp(`valid: ${pieces} pieces`));
  assert.ok(await page.isDisabled('[data-testid=download-ldraw]'), 'no LEGO triangles');
});

test('cubic: layers are edited apart; the solution turns in 3D', async () => {
  await open();
  await page.selectOption('[data-testid=lattice]', 'cubic');
  await setSize(0, 2, 2);
  await card(0).locator('input.d').fill('2');
  await card(0).locator('input.d').dispatchEvent('change');
  await tool('fill');
  await click(0, 0, 0); // layer z0: 4 cubes
  await card(0).locator('.layers button', { hasText: 'z1' }).click();
  await click(0, 0, 0); // layer z1: 4 more
  assert.equal(await count(0).textContent(), '8 cells');
  const zs = await page.evaluate(() => [...new Set([...window.studio.figures[0].cells].map((k) => k.split(',')[2]))].sort());
  assert.deepEqual(zs, ['0', '1']);

  // The cubic example solves and shows a 3D view that can be turned.
  await page.selectOption('[data-testid=example]', 'cube4-cavity-to-7x4x2');
  await page.waitForFunction(() => window.studio.figures.length === 2 && window.studio.figures[1].cells.size === 56);
  assert.match(await page.textContent('[data-testid=areas]'), /every figure has 56 cells/);
  await solveAndWait(90);
  const pieces = Number(/^(\d+) pieces/.exec(await page.textContent('[data-testid=result-summary]'))[1]);
  const json = await saveDownload(() => page.click('[data-testid=download-json]'));
  const figs = [];
  for (const i of [0, 1]) figs.push(await saveDownload(() => card(i).locator('button.save').click()));
  const out = checkSolution('cubic', json, figs);
  assert.match(out, new RegExp(`valid: ${pieces} pieces`));
  await page.waitForSelector('#motion canvas');
  const v3 = await page.locator('#motion canvas').boundingBox();
  await page.mouse.move(v3.x + v3.width / 2, v3.y + v3.height / 2);
  await page.mouse.down();
  await page.mouse.move(v3.x + v3.width / 2 + 80, v3.y + v3.height / 2 + 20, { steps: 5 });
  await page.mouse.up();
  await page.locator('#result').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(DOCS, 'studio-cubic.png'), fullPage: true });
});

test('figure files load from disk; Stop ends a long solve and keeps what was found', async () => {
  await open();
  // A 12x12 square and a 144-cell staircase: the engine proves a 12x12 square to a 2x72 bar optimal in
  // 0.1 s, but finds 4 pieces here and cannot close the gap to its lower bound of 3 in a minute.
  const square = `${'#'.repeat(12)}\n`.repeat(12);
  const bar = [3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 11].map((w) => `${'#'.repeat(w)}\n`).join('');
  await card(0).locator('input.load').setInputFiles({ name: 'square12.txt', mimeType: 'text/plain', buffer: Buffer.from(square) });
  await page.waitForFunction(() => window.studio.figures[0].cells.size === 144);
  await card(1).locator('input.load').setInputFiles({ name: 'staircase.txt', mimeType: 'text/plain', buffer: Buffer.from(bar) });
  await page.waitForFunction(() => window.studio.figures[1].cells.size === 144);
  assert.match(await page.textContent('[data-testid=areas]'), /every figure has 144 cells/);
  assert.equal(await card(0).locator('input.name').inputValue(), 'square12.txt');

  // A bad file gets a message naming the file, line and column.
  await card(1).locator('input.load').setInputFiles({ name: 'bad.txt', mimeType: 'text/plain', buffer: Buffer.from('##\n#x\n') });
  await page.waitForSelector('#message:not([hidden])');
  assert.match(await page.textContent('#message'), /bad\.txt: line 2, column 2/);
  assert.equal(await count(1).textContent(), '144 cells');

  await page.fill('#opt-time', '120');
  const t0 = Date.now();
  await page.click('[data-testid=solve]');
  await page.waitForFunction(() => document.querySelector('#p-state').textContent === 'running');
  await page.click('[data-testid=stop]');
  await page.waitForSelector('[data-testid=solve]:not([disabled])', { timeout: 60_000 });
  assert.ok(Date.now() - t0 < 60_000, 'stopped well before the time limit');
  assert.equal(await page.textContent('#p-state'), 'done');
  // Either a dissection (shown) or a clear message that none was found yet.
  const shown = await page.isVisible('#result');
  const message = await page.textContent('#message');
  assert.ok(shown || /No dissection found before the stop/.test(message), message);
  assert.deepEqual(pageErrors, []);
});

// ------------------------------------------------------------- puzzles (issue 14)

/** Downloads the JSON of the solution shown and checks it against the figures (check.mjs). */
async function verifyShown(lattice) {
  const json = await saveDownload(() => page.click('[data-testid=download-json]'));
  const figs = [];
  for (const i of [0, 1]) figs.push(await saveDownload(() => card(i).locator('button.save').click()));
  const solution = JSON.parse(fs.readFileSync(json, 'utf8'));
  const out = checkSolution(lattice, json, figs);
  assert.match(out, new RegExp(`valid: ${solution.figures[0].pieces.length} pieces`));
  return solution;
}

test('several solutions: the browser steps through them with their scores, rank and assembly counts', async () => {
  await open();
  await page.selectOption('[data-testid=example]', 'squares-3-4-to-5');
  await page.waitForFunction(() => window.studio.figures.length === 2 && window.studio.figures[1].cells.size === 25);
  assert.ok(!(await page.isVisible('[data-testid=opt-solutions]')), 'the Puzzle options start closed');
  await page.click('[data-testid=puzzle] summary');
  await page.fill('[data-testid=opt-solutions]', '3');
  await page.selectOption('[data-testid=opt-rank]', 'smallest');
  assert.match(await page.textContent('#puzzle-set'), /3 solutions, by smallest piece/);
  await solveAndWait(40);
  assert.ok(await page.isVisible('[data-testid=solutions]'), 'the solutions browser is shown');
  const n = await page.locator('#sol-list li').count();
  assert.ok(n >= 2 && n <= 3, `${n} solutions listed`);
  assert.equal(await page.textContent('[data-testid=sol-position]'), `Solution 1 of ${n}`);
  assert.match(await page.textContent('#sol-ranking'), /ranked by largest smallest piece/);
  assert.ok(await page.isDisabled('[data-testid=sol-prev]'));
  const seen = new Set();
  let smallest = Infinity;
  for (let i = 0; i < n; i++) {
    if (i > 0) await page.click('[data-testid=sol-next]');
    assert.equal(await page.textContent('[data-testid=sol-position]'), `Solution ${i + 1} of ${n}`);
    assert.equal(await page.locator('#sol-list li.current').getAttribute('data-testid'), `sol-${i}`);
    const summary = await page.textContent('[data-testid=result-summary]');
    assert.match(summary, new RegExp(`rank ${i + 1} by largest smallest piece`));
    // Ranked: the smallest piece never grows down the list.
    const small = Number(/smallest (\d+)/.exec(summary)[1]);
    assert.ok(small <= smallest, summary);
    smallest = small;
    // One assembly count per figure, the unique mark where the count is 1.
    const counts = await page.evaluate(() => window.studio.result.current.assemblies);
    assert.equal(counts.length, 2);
    for (const [fi, c] of counts.entries()) {
      const text = await page.textContent(`[data-testid=assemblies-${fi}]`);
      assert.match(text, /tilings? \(\d+ up to symmetry\)|at least/);
      const marked = await page.locator(`[data-testid=assemblies-${fi}] [data-testid=unique]`).count();
      assert.equal(marked, c.unique ? 1 : 0, text);
    }
    const solution = await verifyShown('square');
    assert.equal(solution.rank.position, i + 1);
    seen.add(JSON.stringify(solution.figures[0].pieces));
  }
  assert.equal(seen.size, n, 'different solutions');
  assert.ok(await page.isDisabled('[data-testid=sol-next]'));
  await page.click('[data-testid=sol-0]');
  assert.equal(await page.textContent('[data-testid=sol-position]'), `Solution 1 of ${n}`);
  await page.locator('#result').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(DOCS, 'studio-solutions.png'), fullPage: true });
});

test('keep-whole regions painted on a figure, piece sizes and the checkerboard switch reach the solver', async () => {
  await open();
  // A 3×2 rectangle and a 6×1 bar: two bars of 3 without constraints.
  await tool('rect');
  await drag(0, [0, 0], [2, 1]);
  await drag(1, [0, 0], [5, 0]);
  assert.match(await page.textContent('[data-testid=areas]'), /every figure has 6 cells/);
  // Paint the left column as region a (the K key picks the tool); painting
  // an empty cell does nothing; a click on a painted cell unpaints it.
  await page.keyboard.press('k');
  assert.equal(await page.getAttribute('.tool.active', 'data-tool'), 'keep');
  assert.ok(await page.isVisible('[data-testid=keep-summary]'), 'the keep tool opens the Puzzle options');
  assert.ok(!(await card(0).locator('.clear-keep').isVisible()), 'nothing to clear yet');
  await drag(0, [0, 0], [0, 1]);
  await click(0, 5, 5);
  assert.deepEqual(await page.evaluate(() => [...window.studio.figures[0].keep].sort()), [['0,0,0', 'a'], ['0,1,0', 'a']]);
  await click(0, 1, 0);
  await click(0, 1, 0);
  assert.equal(await page.evaluate(() => window.studio.figures[0].keep.size), 2);
  assert.match(await page.textContent('[data-testid=keep-summary]'), /figure-a\.txt: a \(2\)/);
  // Undo takes the painting back, redo brings it again.
  await page.click('[data-testid=undo]');
  await page.click('[data-testid=redo]');
  assert.equal(await page.evaluate(() => window.studio.figures[0].keep.size), 2);
  assert.ok(await card(0).locator('.clear-keep').isVisible());
  assert.ok(!(await card(1).locator('.clear-keep').isVisible()));
  await page.screenshot({ path: path.join(DOCS, 'studio-keep.png') });
  assert.ok(!(await page.isDisabled('[data-testid=opt-checkerboard]')), 'square has a checkerboard');
  await page.fill('[data-testid=opt-max-piece]', '4');
  await solveAndWait(20);
  const solution = await verifyShown('square');
  // The column is one piece: three dominoes, as the file records.
  assert.deepEqual(solution.constraints, { keep: [{ figure: 1, regions: { a: [[0, 0], [0, 1]] } }], max_piece: 4 });
  const pieces = solution.figures[0].pieces;
  assert.equal(pieces.length, 3);
  assert.ok(pieces.some((p) => JSON.stringify(p.map(String).sort()) === JSON.stringify(['0,0', '0,1'])), JSON.stringify(pieces));
  // The bar assembles in one way: unique; the rectangle in more.
  assert.equal(await page.locator('[data-testid=assemblies-1] [data-testid=unique]').count(), 1);
  assert.equal(await page.locator('[data-testid=assemblies-0] [data-testid=unique]').count(), 0);

  // Impossible bounds: a clear message, no solve.
  await page.fill('[data-testid=opt-min-piece]', '5');
  await page.click('[data-testid=solve]');
  await page.waitForSelector('#message:not([hidden])');
  assert.match(await page.textContent('#message'), /cannot all hold: impossible: min_piece 5 is larger than max_piece 4/);

  // No checkerboard on hexagons.
  await page.selectOption('[data-testid=lattice]', 'hex');
  assert.ok(await page.isDisabled('[data-testid=opt-checkerboard]'));
  assert.deepEqual(pageErrors, []);
});

test('cubic: assemblable and a minimum level reach the solver; the answer reports its levels', async () => {
  await open();
  await page.selectOption('[data-testid=lattice]', 'cubic');
  // A 2×2×2 cube and a 4×2×1 slab.
  await setSize(0, 2, 2);
  await card(0).locator('input.d').fill('2');
  await card(0).locator('input.d').dispatchEvent('change');
  await tool('fill');
  await click(0, 0, 0);
  await card(0).locator('.layers button', { hasText: 'z1' }).click();
  await click(0, 0, 0);
  await setSize(1, 4, 2);
  await click(1, 0, 0);
  assert.match(await page.textContent('[data-testid=areas]'), /every figure has 8 cells/);
  await page.click('[data-testid=puzzle] summary');
  await page.check('[data-testid=opt-assemblable]');
  await page.fill('[data-testid=opt-min-level]', '1');
  assert.match(await page.textContent('#puzzle-set'), /assemblable, level ≥ 1/);
  await solveAndWait(10);
  const solution = await verifyShown('cubic');
  assert.deepEqual(solution.constraints, { assemblable: true, min_level: 1 });
  assert.equal(solution.levels.length, 2, JSON.stringify(solution.levels));
  assert.ok(solution.levels.every((l) => l >= 1), JSON.stringify(solution.levels));
  // The studio shows each figure's level.
  await page.waitForSelector('#disassembly:not([hidden])');
  assert.match(await page.textContent('[data-testid=level-0]'), /level \d+ \(apart in \d+ moves?\)/);
  assert.match(await page.textContent('[data-testid=level-1]'), /level \d+/);
  // Level 2 in a box is impossible: said at once, no solve.
  await page.fill('[data-testid=opt-min-level]', '2');
  await page.click('[data-testid=solve]');
  await page.waitForSelector('#message:not([hidden])');
  assert.match(await page.textContent('#message'), /cannot all hold: impossible: min_level 2: figure 1 meets every line/);
  assert.deepEqual(pageErrors, []);
});

test('all solutions: every minimum dissection counted, complete, and stepped through class by class', async () => {
  await open();
  // Figure a: a 3x2 rectangle; figure b: an L of 4 + 2 cells (10
  // dissections in 3 classes, as `dissect enumerate` counts them).
  await tool('rect');
  await drag(0, [0, 0], [2, 1]);
  assert.equal(await count(0).textContent(), '6 cells');
  await setSize(1, 4, 2);
  await drag(1, [0, 0], [3, 0]);
  await drag(1, [0, 1], [1, 1]);
  assert.equal(await count(1).textContent(), '6 cells');
  await page.click('[data-testid=puzzle] summary');
  await page.fill('#opt-time', '30');
  await page.click('[data-testid=enumerate]');
  await page.waitForSelector('#progress:not([hidden])');
  await page.waitForSelector('#result:not([hidden])', { timeout: 45_000 });
  const line = await page.textContent('[data-testid=enumerate-count]');
  const m = /^(\d+) dissections? with (\d+) pieces \((\d+) up to the first figure's symmetries\), complete$/.exec(line);
  assert.ok(m, line);
  const [total, pieces, classes] = [Number(m[1]), Number(m[2]), Number(m[3])];
  assert.deepEqual([total, pieces, classes], [10, 2, 3], line);
  assert.ok(await page.isVisible('[data-testid=solutions]'), 'the browser lists the classes');
  assert.equal(await page.locator('#sol-list li').count(), classes);
  assert.match(await page.textContent('#sol-ranking'), /, complete; one per class/);
  const sizes = await page.evaluate(() => window.studio.run.solutions.map((s) => s.class_size));
  assert.equal(sizes.reduce((a, b) => a + b, 0), total, 'the class sizes add up to the count');
  const seen = new Set();
  for (let i = 0; i < classes; i++) {
    if (i > 0) await page.click('[data-testid=sol-next]');
    assert.match(await page.textContent('[data-testid=sol-position]'), new RegExp(`^Class ${i + 1} of ${classes} \\(${sizes[i]} dissections?\\)$`));
    const solution = await verifyShown('square');
    assert.equal(solution.figures[0].pieces.length, pieces);
    assert.equal(solution.enumeration.class, i + 1);
    seen.add(JSON.stringify(solution.figures[0].pieces));
  }
  assert.equal(seen.size, classes, 'one different cut per class');
  assert.ok(await page.isDisabled('[data-testid=sol-next]'));
  await page.locator('#result').scrollIntoViewIfNeeded();
  await page.screenshot({ path: path.join(DOCS, 'studio-all-solutions.png'), fullPage: true });
  assert.deepEqual(pageErrors, []);
});
