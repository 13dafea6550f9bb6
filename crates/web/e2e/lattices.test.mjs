// End-to-end tests of the studio on the tri3 (equilateral triangles) and
// hex (hexagons) lattices, in Debian's headless chromium: a click lands in
// the cell FORMAT.md puts there (the geometry below is the test's own, not
// the page's), the rectangle and fill tools count cells, the shipped
// example solves, every piece is drawn in its colour and the downloads are
// made: solution and figures (checked by check.mjs), SVG, PNG, STL, cut
// sheet and the HTML page; LDraw is off.
//
// Needs DISSECT_URL and DISSECT_DOCS, DISSECT_VERIFY when present
// (.ci/steps/50-web-e2e.sh).

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

let browser;
let page;
let downloads;
const pageErrors = [];

before(async () => {
  downloads = fs.mkdtempSync(path.join(os.tmpdir(), 'dissect-lattices-'));
  browser = await chromium.launch({
    executablePath: '/usr/bin/chromium',
    headless: true,
    args: ['--headless', '--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run',
      '--disable-background-networking', '--disable-component-update', '--disable-sync'],
  });
  const context = await browser.newContext({ viewport: { width: 1280, height: 900 }, acceptDownloads: true });
  page = await context.newPage();
  page.on('pageerror', (e) => pageErrors.push(e.message));
  page.setDefaultTimeout(20_000);
});

after(async () => {
  await browser?.close();
  fs.rmSync(downloads, { recursive: true, force: true });
});

// ------------------------------------------------ geometry of FORMAT.md

const H = Math.sqrt(3) / 2;

/** The centre of a cell (centroid for triangles), lattice units, y down. */
function centre(lattice, [x, y]) {
  if (lattice === 'tri3') return [(x + 1) / 2, y * H + ((x + y) % 2 === 0 ? (2 * H) / 3 : H / 3)];
  return [x + (((y % 2) + 2) % 2) / 2, y * H];
}

const card = (i) => page.locator('#figures .card').nth(i);
const count = (i) => card(i).locator('[data-testid=count]');

/** The page point of plane point p in figure i's editor (scale and origin read from the page). */
async function pagePoint(i, p) {
  const box = await card(i).locator('canvas.grid').boundingBox();
  const v = await page.evaluate((j) => window.studioEditorView(j), i);
  return [box.x + (p[0] - v.lo[0]) * v.cs, box.y + (p[1] - v.lo[1]) * v.cs];
}

/** A point inside cell c, `f` of the way from its centre towards plane direction `dir`. */
async function cellPoint(lattice, i, c, dir = [0, 0], f = 0) {
  const m = centre(lattice, c);
  // The inradius: 1/(2√3) for a triangle of side 1, √3/2·(1/√3)… = 1/2 for a hexagon of centre distance 1.
  const r = lattice === 'tri3' ? 1 / (2 * Math.sqrt(3)) : 0.5;
  return pagePoint(i, [m[0] + dir[0] * r * f, m[1] + dir[1] * r * f]);
}

async function click(lattice, i, c, dir, f) {
  const [x, y] = await cellPoint(lattice, i, c, dir, f);
  await page.mouse.click(x, y);
}

async function drag(lattice, i, from, to) {
  const [x0, y0] = await cellPoint(lattice, i, from);
  const [x1, y1] = await cellPoint(lattice, i, to);
  await page.mouse.move(x0, y0);
  await page.mouse.down();
  await page.mouse.move((x0 + x1) / 2, (y0 + y1) / 2, { steps: 4 });
  await page.mouse.move(x1, y1, { steps: 4 });
  await page.mouse.up();
}

async function tool(name) {
  await page.click(`.tool[data-tool=${name}]`);
}

async function setSize(i, w, h) {
  for (const [dim, v] of [['w', w], ['h', h]]) {
    await card(i).locator(`input.${dim}`).fill(String(v));
    await card(i).locator(`input.${dim}`).dispatchEvent('change');
  }
}

async function saveDownload(trigger) {
  const [dl] = await Promise.all([page.waitForEvent('download'), trigger()]);
  const file = path.join(downloads, dl.suggestedFilename());
  await dl.saveAs(file);
  return file;
}

/** The palette colours painted on a solved canvas, and how many pixels each. */
async function coloursOn(testid) {
  return page.evaluate((id) => {
    const c = document.querySelector(`canvas[data-testid="${id}"]`);
    const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
    const seen = new Map();
    for (let p = 0; p < d.length; p += 4) {
      if (d[p + 3] < 255) continue;
      const hex = '#' + [d[p], d[p + 1], d[p + 2]].map((v) => v.toString(16).padStart(2, '0')).join('');
      seen.set(hex, (seen.get(hex) || 0) + 1);
    }
    const palette = window.studioPalette;
    return palette.filter((h) => seen.has(h)).map((h) => [palette.indexOf(h), seen.get(h)]);
  }, testid);
}

const cellsOf = (i) => page.evaluate((j) => [...window.studio.figures[j].cells].sort(), i);

// Cells to click, with points near their edges ([direction, fraction of the inradius]).
const PROBES = {
  tri3: [[[0, 0], [0, 1], 0.8], [[1, 0], [0, -1], 0.8], [[2, 1], [1, 0], 0.6], [[3, 1], [-1, 0], 0.6], [[4, 2], [0, 0], 0]],
  hex: [[[0, 0], [1, 0], 0.85], [[1, 1], [-1, 0], 0.85], [[2, 1], [0, 1], 0.85], [[3, 2], [0, -1], 0.85], [[0, 3], [0.7, 0.7], 0.8]],
};
const EXAMPLES = { tri3: 'tri3-hexagon2-to-parallelogram4x3', hex: 'hex-three-hexagons2-to-rhombus7x3' };

for (const lattice of ['tri3', 'hex']) {
  test(`${lattice}: clicks land in the cells of FORMAT.md; rect and fill count cells; the example solves and downloads`, async () => {
    await page.goto(URL);
    await page.waitForSelector('body[data-ready=true]');
    await page.selectOption('[data-testid=lattice]', lattice);
    await setSize(0, 6, 4);
    await tool('pen');
    const want = [];
    for (const [c, dir, f] of PROBES[lattice]) {
      await click(lattice, 0, c, dir, f);
      want.push(`${c[0]},${c[1]},0`);
      assert.deepEqual(await cellsOf(0), [...want].sort(), `${lattice}: click in ${c} (towards ${dir})`);
    }
    assert.equal(await count(0).textContent(), `${want.length} cells`);
    // Clicking a filled cell again empties it (the pen starts by erasing).
    await click(lattice, 0, PROBES[lattice][0][0]);
    assert.equal(await count(0).textContent(), `${want.length - 1} cells`);

    // Rectangle: rows 0..1, columns 0..3 are 8 cells; flood fill of an empty 5 × 3 grid is 15.
    await tool('rect');
    await drag(lattice, 1, [0, 0], [3, 1]);
    assert.equal(await count(1).textContent(), '8 cells');
    await card(1).locator('button.clear').click();
    await setSize(1, 5, 3);
    await tool('fill');
    await click(lattice, 1, [2, 1]);
    assert.equal(await count(1).textContent(), '15 cells');
    await page.locator('#figures').screenshot({ path: path.join(DOCS, `studio-${lattice}-editor.png`) });

    // The shipped example: solved, drawn, downloaded, checked by the independent checkers (check.mjs).
    await page.selectOption('[data-testid=example]', EXAMPLES[lattice]);
    await page.waitForFunction((l) => window.studio.lattice === l && window.studio.figures.length === 2
      && window.studio.figures.every((f) => f.cells.size > 0), lattice);
    assert.equal(await page.inputValue('[data-testid=lattice]'), lattice);
    const sizes = await page.evaluate(() => window.studio.figures.map((f) => f.cells.size));
    assert.equal(sizes[0], sizes[1]);
    assert.match(await page.textContent('[data-testid=areas]'), new RegExp(`every figure has ${sizes[0]} cells`));
    await page.fill('#opt-time', '30');
    await page.click('[data-testid=solve]');
    await page.waitForSelector('#result:not([hidden])', { timeout: 40_000 });
    const summary = await page.textContent('[data-testid=result-summary]');
    const pieces = Number(/^(\d+) pieces/.exec(summary)[1]);
    assert.ok(pieces >= 2, summary);
    // Every piece is painted in its colour in both figures, in proportion to its area.
    const solution = await page.evaluate(() => window.studio.result.solution);
    for (const fi of [0, 1]) {
      const seen = await coloursOn(`solved-${fi}`);
      assert.deepEqual(seen.map(([i]) => i), [...Array(pieces).keys()], `${lattice} figure ${fi}: ${JSON.stringify(seen)}`);
      const areas = solution.figures[fi].pieces.map((p) => p.length);
      const total = seen.reduce((s, [, n]) => s + n, 0), cells = areas.reduce((s, a) => s + a, 0);
      seen.forEach(([i, n]) => assert.ok(Math.abs(n / total - areas[i] / cells) < 0.1, `${lattice}: piece ${i} painted ${n} of ${total} pixels for ${areas[i]} of ${cells} cells`));
    }
    // Hovering a solved figure highlights the piece under the mouse.
    const box = await page.locator('canvas[data-testid=solved-0]').boundingBox();
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.waitForFunction(() => window.studio.hot >= 0);
    await page.mouse.move(0, 0);
    await page.waitForFunction(() => document.querySelector('#motion')?.player);
    await page.locator('#result').scrollIntoViewIfNeeded();
    await page.screenshot({ path: path.join(DOCS, `studio-${lattice}.png`), fullPage: true });

    const json = await saveDownload(() => page.click('[data-testid=download-json]'));
    const figs = [];
    for (const i of [0, 1]) figs.push(await saveDownload(() => card(i).locator('button.save').click()));
    const out = checkSolution(lattice, json, figs);
    assert.match(out, new RegExp(`valid: ${pieces} pieces`));
    const svg = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-svg]')), 'utf8');
    assert.match(svg, /<svg[\s\S]*<\/svg>/);
    const png = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-png]')));
    assert.equal(png.subarray(1, 4).toString(), 'PNG');
    const zip = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-stl]')));
    assert.equal(zip.subarray(0, 2).toString(), 'PK');
    assert.match(zip.toString('latin1'), /piece-01-A\.stl/);
    const sheet = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-cut]')), 'utf8');
    assert.match(sheet, /<svg[^>]*mm/);
    const html = fs.readFileSync(await saveDownload(() => page.click('[data-testid=download-html]')), 'utf8');
    assert.match(html, new RegExp(`"lattice":\\s*"${lattice}"`));
    assert.ok(await page.isDisabled('[data-testid=download-ldraw]'), 'no LEGO triangles or hexagons');
    assert.deepEqual(pageErrors, []);
  });
}

test('tri3 and hex: figure files and pictures load with their cell counts', async () => {
  const b64 = await (async () => {
    await page.goto(URL);
    await page.waitForSelector('body[data-ready=true]');
    return page.evaluate(() => {
      const c = document.createElement('canvas');
      c.width = 120; c.height = 90;
      const g = c.getContext('2d');
      g.fillStyle = '#fff'; g.fillRect(0, 0, 120, 90);
      g.fillStyle = '#000'; g.beginPath(); g.arc(60, 45, 40, 0, 2 * Math.PI); g.fill();
      return c.toDataURL('image/png').split(',')[1];
    });
  })();
  // A tri3 hexagon of side 2 (24 triangles) and a hex hexagon of side 2 (7 cells), as FORMAT.md writes them.
  const files = { tri3: ['..#####\n.#######\n.#######\n..#####\n', 24], hex: ['.##\n###\n.##\n', 7] };
  for (const lattice of ['tri3', 'hex']) {
    await page.goto(URL);
    await page.waitForSelector('body[data-ready=true]');
    await page.selectOption('[data-testid=lattice]', lattice);
    const [text, n] = files[lattice];
    await card(0).locator('input.load').setInputFiles({ name: `${lattice}.txt`, mimeType: 'text/plain', buffer: Buffer.from(text) });
    await page.waitForFunction(() => window.studio.figures[0].cells.size > 0);
    assert.equal(await count(0).textContent(), `${n} cells`, lattice);
    // The figure saved again is the same text.
    const saved = await saveDownload(() => card(0).locator('button.save').click());
    assert.equal(fs.readFileSync(saved, 'utf8').trim(), text.trim(), lattice);
    await card(1).locator('input.cells').fill('40');
    await card(1).locator('input.picture').setInputFiles({ name: 'disc.png', mimeType: 'image/png', buffer: Buffer.from(b64, 'base64') });
    await page.waitForFunction(() => window.studio.figures[1].cells.size > 0);
    assert.equal(await count(1).textContent(), '40 cells', lattice);
  }
  assert.deepEqual(pageErrors, []);
});
