// Browser tests of assembly.html: the real papercraft binary makes a model's files, Chromium
// opens the page from file:// with the network blocked, and the test drives it as a person
// would (clicks, keys, the slider) and reads back the viewer's state.
//
//   node tests/viewer/viewer_test.mjs CASE     (ctest runs every case: tests/CMakeLists.txt)
//
// Environment: PAPERCRAFT (the binary), PAPERCRAFT_VIEWER_MODULES (npm packages),
// PAPERCRAFT_SOURCE_DIR, CHROMIUM (default /usr/bin/chromium); PAPERCRAFT_VIEWER_SHOTS: a
// folder to save screenshots in (optional). A browser that cannot start fails the test.

import assert from 'node:assert/strict';
import { copyFileSync, mkdirSync, mkdtempSync, readFileSync, rmSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { launchChromium, openViewer, papercraft, screenshotContent, state } from './harness.mjs';

const SIZE_BOUND = 5_000_000;
const source = process.env.PAPERCRAFT_SOURCE_DIR || new URL('../..', import.meta.url).pathname;

function readJson(file) {
  return JSON.parse(readFileSync(file, 'utf8'));
}

// Runs papercraft on `mesh` into a fresh folder; returns the model's output folder.
function makeModel(work, mesh, name, args = []) {
  papercraft(['run', mesh, '--tolerance', '2%', '-q', '-o', join(work, 'out'), ...args]);
  return join(work, 'out', name);
}

function generate(work, shape, file, params = []) {
  const path = join(work, file);
  papercraft(['generate', shape, path, ...params.flatMap((p) => ['--param', p])]);
  return path;
}

// Copies of an OBJ mesh in a grid of columns x rows, `spacing` apart along x and y: a model of
// as many separate parts.
function gridOfCopies(objText, columns, rows, spacing) {
  const lines = objText.split('\n');
  const vertices = lines.filter((line) => line.startsWith('v ')).map((line) => line.trim().split(/\s+/).slice(1, 4).map(Number));
  const faces = lines.filter((line) => line.startsWith('f ')).map((line) => line.trim().split(/\s+/).slice(1).map((corner) => Number(corner.split('/')[0])));
  const out = [];
  for (let i = 0; i < columns; ++i)
    for (let j = 0; j < rows; ++j)
      for (const [x, y, z] of vertices) out.push(`v ${x + i * spacing} ${y + j * spacing} ${z}`);
  for (let copy = 0; copy < columns * rows; ++copy)
    for (const face of faces) out.push(`f ${face.map((v) => v + copy * vertices.length).join(' ')}`);
  return `${out.join('\n')}\n`;
}

async function withViewer(dir, check, file = join(dir, 'assembly.html')) {
  const browser = await launchChromium();
  try {
    const opened = await openViewer(browser, file);
    await check(opened);
    assert.deepEqual(opened.errors, [], 'console errors');
    assert.deepEqual(opened.requests, [], 'requests other than file://');
  } finally {
    await browser.close();
  }
}

function report(name, dir, firstRenderMs) {
  const bytes = statSync(join(dir, 'assembly.html')).size;
  console.log(`${name}: assembly.html ${(bytes / 1e6).toFixed(2)} MB, first render ${Math.round(firstRenderMs)} ms`);
}

async function saveShot(page, name) {
  if (process.env.PAPERCRAFT_VIEWER_SHOTS)
    await page.screenshot({ path: join(process.env.PAPERCRAFT_VIEWER_SHOTS, `${name}.png`) });
}

// What every model's page must do: load offline, count the pieces as pieces.json does, show
// something in 3D, and show exactly the pieces of steps 1..k at step k.
async function expectLoadsAndSteps(page, pieces) {
  const count = await page.locator('#piece-count').textContent();
  assert.equal(Number.parseInt(count, 10), pieces.length, `shown: "${count}"`);
  const shot = await screenshotContent(page, '#view3d canvas');
  assert.ok(shot.unlikeShare > 0.03, `3D view nearly blank: ${JSON.stringify(shot)}`);
  assert.ok(shot.colours >= Math.min(4, pieces.length + 1), `3D view of few colours: ${JSON.stringify(shot)}`);
  const all = await state(page);
  assert.equal(all.steps, pieces.length);
  assert.equal(all.step, pieces.length, 'opens with the whole model built');
  assert.deepEqual([...all.visible].sort(), pieces.map((p) => p.name).sort());
  const k = Math.ceil(pieces.length / 2);
  if (pieces.length > 1) await page.locator('#step').fill(String(k));  // else it is disabled
  await expectStep(page, pieces, k);
  if (k > 1) {
    await page.keyboard.press('ArrowLeft');
    await expectStep(page, pieces, k - 1);
    await page.keyboard.press('ArrowRight');
    await expectStep(page, pieces, k);
  }
  await page.keyboard.press('End');
  await expectStep(page, pieces, pieces.length);
}

async function expectStep(page, pieces, k) {
  const now = await state(page);
  assert.equal(now.step, k);
  const expected = pieces.filter((p) => p.step <= k).map((p) => p.name).sort();
  assert.deepEqual([...now.visible].sort(), expected, `pieces shown at step ${k}`);
  const current = await page.locator('.overlay .piece.current').evaluateAll((paths) => paths.map((p) => p.dataset.piece));
  assert.deepEqual(current, pieces.filter((p) => p.step === k).map((p) => p.name), `new piece at step ${k}`);
  const text = await page.locator('#step-text').textContent();
  assert.ok(text.startsWith(`Step ${k}: `), `step text "${text}"`);
}

// Page -> 3D and 3D -> page selection, and the partner of a hovered seam label.
async function expectLinkedSelection(page, pieces) {
  const target = pieces.find((p) => p.name === '3') ? '3' : pieces[0].name;
  const onPage = await page.evaluate((name) => window.viewer.pagePointOf(name), target);
  await page.mouse.click(onPage.x, onPage.y);
  let now = await state(page);
  assert.equal(now.selected, target, 'picked on the page');
  assert.deepEqual(now.selected3d, [target], 'highlighted in 3D');
  assert.deepEqual(now.selectedOnPage, [target], 'highlighted on the page');
  const info = await page.locator('#info').textContent();
  const piece = pieces.find((p) => p.name === target);
  assert.ok(info.includes(`Piece ${target}`) && info.includes(`page ${piece.page}`), `info "${info}"`);
  for (const seam of piece.seams) assert.ok(info.includes(seam.label), `info lacks ${seam.label}`);

  await page.keyboard.press('Escape');
  assert.equal((await state(page)).selected, null, 'Escape clears the selection');
  // The 3D view turned to the piece picked on the page: its anchor is in sight; click it there.
  const seen = await page.evaluate((name) => window.viewer.screenPointOf(name), target);
  assert.ok(seen.visible, `piece ${target} not in sight after picking it on the page`);
  await page.mouse.click(seen.x, seen.y);
  now = await state(page);
  assert.equal(now.selected, target, 'picked in 3D');
  assert.deepEqual(now.selectedOnPage, [target]);
  // And another piece the current view shows.
  const other = await page.evaluate((names) => names.find((name) => window.viewer.screenPointOf(name).visible), pieces.map((p) => p.name).filter((n) => n !== target));
  if (other) {
    const point = await page.evaluate((name) => window.viewer.screenPointOf(name), other);
    await page.mouse.click(point.x, point.y);
    now = await state(page);
    assert.equal(now.selected, other, `picked ${other} in 3D`);
    assert.deepEqual(now.selected3d, [other]);
    assert.deepEqual(now.selectedOnPage, [other]);
  }
  await page.keyboard.press('Escape');

  // A label of the piece that nothing covers: hover its centre.
  const spot = await page.evaluate((name) => {
    for (const rect of document.querySelectorAll(`.overlay .label[data-piece="${name}"]`)) {
      rect.scrollIntoView({ block: 'center' });
      const box = rect.getBoundingClientRect();
      const x = box.left + box.width / 2, y = box.top + box.height / 2;
      if (document.elementFromPoint(x, y) === rect) return { x, y, label: rect.dataset.label };
    }
    return null;
  }, target);
  assert.ok(spot || piece.seams.length === 0, `no seam label of piece ${target} to hover`);
  if (!spot) return;
  const partner = piece.seams.find((s) => s.label === spot.label).partner;
  await page.mouse.move(spot.x, spot.y);
  const tooltip = await page.locator('#tooltip').textContent();
  assert.ok(tooltip.includes(`piece ${partner}`), `tooltip "${tooltip}" for ${spot.label}, partner ${partner}`);
  assert.deepEqual((await state(page)).hovered, { piece: target, label: spot.label, partner });
  const partnerLabels = await page.locator('.overlay .label.partner').evaluateAll((rects) => rects.map((r) => [r.dataset.piece, r.dataset.label]));
  for (const [on, text] of partnerLabels) assert.deepEqual([on, text], [partner, spot.label]);
  if (partner !== target) {
    const printed = await page.locator(`.overlay .label[data-piece="${partner}"][data-label="${spot.label}"]`).count();
    assert.equal(partnerLabels.length, printed, 'every printed partner label lights up');
  }
  await page.mouse.move(1, 1);
  assert.equal((await state(page)).hovered, null);
}

async function fullCheck(name, dir) {
  const pieces = readJson(join(dir, 'pieces.json')).pieces;
  assert.ok(pieces.length >= 3, `${name}: a model of ${pieces.length} pieces`);
  assert.ok(statSync(join(dir, 'assembly.html')).size < SIZE_BOUND);
  await withViewer(dir, async ({ page, firstRenderMs }) => {
    report(name, dir, firstRenderMs);
    await expectLoadsAndSteps(page, pieces);
    await expectLinkedSelection(page, pieces);
    await saveShot(page, name);
  });
}

const cases = {
  async pawn(work) {
    const dir = makeModel(work, join(source, 'examples', 'pawn.obj'), 'pawn', ['--height', '150']);
    await fullCheck('pawn', dir);
  },

  async generated(work) {
    const dir = makeModel(work, generate(work, 'torus', 'torus.obj'), 'torus');
    await fullCheck('torus', dir);
  },

  async one_piece(work) {
    // A tube printed small enough to stay one piece (larger, the page splits it).
    const dir = makeModel(work, generate(work, 'open_cylinder', 'tube.obj'), 'tube', ['--height', '60']);
    const pieces = readJson(join(dir, 'pieces.json')).pieces;
    assert.equal(pieces.length, 1);
    await withViewer(dir, async ({ page }) => {
      await expectLoadsAndSteps(page, pieces);
      assert.equal(await page.locator('#step').isDisabled(), true, 'a slider of one step');
    });
  },

  async separate_parts(work) {
    const torus = readFileSync(generate(work, 'torus', 'torus.obj'), 'utf8');
    writeFileSync(join(work, 'two.obj'), gridOfCopies(torus, 2, 1, 4));
    const dir = makeModel(work, join(work, 'two.obj'), 'two');
    const json = readJson(join(dir, 'pieces.json'));
    assert.equal(json.parts, 2);
    const pieces = json.pieces;
    const firstOfPart2 = pieces.filter((p) => p.part === 2).reduce((a, b) => (a.step < b.step ? a : b));
    await withViewer(dir, async ({ page }) => {
      await expectLoadsAndSteps(page, pieces);
      await page.locator('#step').fill(String(firstOfPart2.step - 1));
      const part1 = (await state(page)).visible;
      assert.deepEqual([...part1].sort(), pieces.filter((p) => p.part === 1).map((p) => p.name).sort());
      await page.keyboard.press('ArrowRight');
      const text = await page.locator('#step-text').textContent();
      const start = `Step ${firstOfPart2.step}: start part 2 with ${firstOfPart2.name}`;
      assert.ok(text === start || text.startsWith(`${start}; `), `step text "${text}"`);
    });
  },

  async many_pieces(work) {
    // 500 cubes of 12 triangles, each a piece of its own, on a dozen pages.
    const cube = readFileSync(generate(work, 'box', 'cube.obj', ['divisions_x=1', 'divisions_y=1', 'divisions_z=1']), 'utf8');
    writeFileSync(join(work, 'cubes.obj'), gridOfCopies(cube, 25, 20, 3));
    const dir = makeModel(work, join(work, 'cubes.obj'), 'cubes', ['--scale', '8', '--max-pages', '1000']);
    const pieces = readJson(join(dir, 'pieces.json')).pieces;
    assert.equal(pieces.length, 500);
    const bytes = statSync(join(dir, 'assembly.html')).size;
    const notes = readJson(join(dir, 'report.json')).notes.filter((n) => n.startsWith('assembly.html'));
    assert.ok(bytes < SIZE_BOUND, `${bytes} bytes`);
    await withViewer(dir, async ({ page, firstRenderMs }) => {
      report('cubes (500 pieces)', dir, firstRenderMs);
      await expectLoadsAndSteps(page, pieces);
      assert.equal(await page.locator('#notes').isVisible(), notes.length > 0);
      await saveShot(page, 'many_pieces');
    });
    // Under a bound 0.1 MB short of that, too small for the pages (their SVG is 0.3 MB
    // compressed), the page view draws the pieces' outlines.
    const bound = ((bytes - 100_000) / 1e6).toFixed(3);
    const config = readFileSync(join(source, 'configs', 'default.yaml'), 'utf8')
      .replace(/params: \{formats: \[[^\]]*\]\}/, `params: {formats: [json, html], html_max_mb: ${bound}}`);
    assert.ok(config.includes(`html_max_mb: ${bound}`));
    writeFileSync(join(work, 'small.yaml'), config);
    const small = join(work, 'small');
    papercraft(['run', join(work, 'cubes.obj'), '--config', join(work, 'small.yaml'), '--scale', '8', '--max-pages', '1000', '-q', '-o', small]);
    assert.ok(statSync(join(small, 'cubes', 'assembly.html')).size < Number(bound) * 1e6);
    const note = readJson(join(small, 'cubes', 'report.json')).notes.find((n) => n.startsWith('assembly.html'));
    assert.match(note, /pattern pages are left out/);
    await withViewer(join(small, 'cubes'), async ({ page }) => {
      assert.match(await page.locator('#notes').textContent(), /pattern pages are left out/);
      assert.equal(await page.locator('.page img').count(), 0);
      await expectLoadsAndSteps(page, pieces);
      const spot = await page.evaluate(() => window.viewer.pagePointOf('250'));
      await page.mouse.click(spot.x, spot.y);
      assert.deepEqual((await state(page)).selected3d, ['250']);
      await saveShot(page, 'pages_left_out');
    });
  },

  async awkward_name(work) {
    // Quotes, markup, an ampersand, UTF-8 and a Latin-1 byte (0xE9) in the file's name; a
    // batch's glob passes the bytes as they are (a command line argument from node is UTF-8).
    const name = Buffer.concat([Buffer.from('pawn "quoted" <b>&amp; caf\u00e9 ', 'utf8'), Buffer.from([0xe9])]);
    const bytes = (...parts) => Buffer.concat(parts.map((p) => (typeof p === 'string' ? Buffer.from(p) : p)));
    mkdirSync(join(work, 'in'));
    copyFileSync(join(source, 'examples', 'pawn.obj'), bytes(work, '/in/', name, '.obj'));
    writeFileSync(join(work, 'in', 'job.yaml'), 'inputs: ["*.obj"]\noutput: ../out\ntolerance: 2%\n');
    papercraft(['batch', join(work, 'in', 'job.yaml'), '-q']);
    const pieces = JSON.parse(readFileSync(bytes(work, '/out/', name, '/pieces.json'), 'utf8')).pieces;
    const html = readFileSync(bytes(work, '/out/', name, '/assembly.html'), 'utf8');
    assert.ok(!html.includes('<b>&amp;'), 'the name is escaped in the page');
    writeFileSync(join(work, 'awkward.html'), html);
    await withViewer(work, async ({ page }) => {
      const count = await page.locator('#piece-count').textContent();
      assert.equal(Number.parseInt(count, 10), pieces.length);
      const title = await page.locator('#title').textContent();
      assert.equal(title, 'pawn "quoted" <b>&amp; caf\u00e9 \\xE9: assembly');
      assert.equal(await page.title(), title);
    }, join(work, 'awkward.html'));
  },
};

const which = process.argv[2];
if (!(which in cases)) {
  console.error(`usage: viewer_test.mjs CASE (one of: ${Object.keys(cases).join(', ')})`);
  process.exit(2);
}
const work = mkdtempSync(join(tmpdir(), `papercraft-viewer-${which}-`));
try {
  await cases[which](work);
  console.log(`${which}: passed`);
} finally {
  rmSync(work, { recursive: true, force: true });
}
