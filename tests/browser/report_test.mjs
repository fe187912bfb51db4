// The HTML report tested as a person uses it: each page opened from disk in headless Chromium
// (the Debian package, driven by puppeteer-core), and what it shows read back through the page's
// test hook (window.momentaReport) and from its pixels. Screenshots of every panel are kept.
//
//   MOMENTA_CLI=… MOMENTA_SOURCE_DIR=… MOMENTA_ARTIFACTS=… node --test report_test.mjs
//   (CTest's browser.report sets them; CHROMIUM names the browser, default /usr/bin/chromium)
//
// Checks, per page: no console error and no request beyond the file; the 3-D canvas is not
// blank and changes between two times; body positions equal the CSV of `momenta simulate` to
// 1e-9 m; the plots hold every recorded column; the poles equal `linearize --json` and the Bode
// data `response --bode` to 1e-9; the 10 s double pendulum's file is ≤ 3 MB; every bundled
// example's whole motion is framed and its page live (below). How fast a page
// becomes interactive and how many frames a second it draws are measured by report_bench.mjs,
// not here: a timed test fails on a busy machine.

import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';
import assert from 'node:assert/strict';
import { test, after, before } from 'node:test';
import {
  browserName, canvasDigest, chainModel, examples, kLoadLimitMs, launchBrowser, momenta, openReport, run,
} from './pages.mjs';

const sourceDir = process.env.MOMENTA_SOURCE_DIR;
const artifacts = process.env.MOMENTA_ARTIFACTS;
const work = fs.mkdtempSync(path.join(process.env.TMPDIR || '/tmp', 'momenta-report-'));
fs.mkdirSync(artifacts, { recursive: true });

function csv(text) {
  const lines = text.trim().split('\n');
  const header = lines[0].split(',');
  const rows = lines.slice(1).map((l) => l.split(',').map(Number));
  return { header, rows, column: (name) => rows.map((r) => r[header.indexOf(name)]) };
}

let browser;
before(async () => { browser = await launchBrowser(); });
after(async () => { await browser?.close(); fs.rmSync(work, { recursive: true, force: true }); });

const open = (file) => openReport(browser, file);

// The 3-D view has drawn its first frame (shaders compiled) once the hook's frame count moves.
async function firstFrame(page) {
  await page.waitForFunction(() => window.momentaReport.framesDrawn() > 0, { timeout: kLoadLimitMs, polling: 20 });
}

async function screenshots(page, name) {
  // Charts are drawn as they come near the window; a screenshot of the whole page wants them all.
  await page.evaluate(() => window.momentaReport.drawAllCharts());
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => done())));
  await page.screenshot({ path: path.join(artifacts, `${name}-page.png`), fullPage: true });
  for (const id of ['summary', 'motion', 'plots', 'equations', 'linear', 'campbell']) {
    const handle = await page.$(`#${id}`);
    if (handle) await handle.screenshot({ path: path.join(artifacts, `${name}-${id}.png`) });
  }
}

async function checkSimulationPage(name, model, extra = []) {
  const file = path.join(work, `${name}.html`);
  run('report', model, '-o', file, '-q', ...extra);
  const size = fs.statSync(file).size;
  const { page, problems } = await open(file);
  await firstFrame(page);
  const hook = await page.evaluate(() => ({ times: window.momentaReport.frameTimes(), series: window.momentaReport.series(),
    bodies: window.momentaReport.bodyNames(), load: window.momentaReport.loadMilliseconds }));
  // The canvas is drawn, and differs between the first and a later time.
  await page.evaluate((t) => window.momentaReport.setTime(t), hook.times[0]);
  const first = await canvasDigest(page);
  await page.evaluate((t) => window.momentaReport.setTime(t), hook.times[Math.floor(hook.times.length / 3)]);
  const later = await canvasDigest(page);
  assert.ok(first.colours > 20, `${name}: the 3-D canvas looks blank (${first.colours} colours)`);
  assert.notEqual(first.hash, later.hash, `${name}: the 3-D view did not change with time`);
  await screenshots(page, name);
  assert.deepEqual(problems, []);
  return { page, file, size, hook };
}

const measured = {};

// Every bundled example's 3-D view frames its whole motion: the box of every body (centre of
// mass, joint points, size) over the run projects onto 30–90 % of the canvas in its larger
// direction (the framing aims at 75 %), no corner before the near plane or beyond the far one,
// and the ground grid lies under the lowest point the bodies reach. The motion panel of each is
// kept as a screenshot. Checked in Chromium only, on the page the live test below opens for
// each example (one report and one page an example): the framing is the page's own arithmetic
// (three.js's projection, the same in every browser).
async function checkFraming(page, name) {
  await firstFrame(page);
  const seen = await page.evaluate(() => ({ coverage: window.momentaReport.framing(),
    grid: window.momentaReport.gridHeight(), lowest: window.momentaReport.sweptLowest() }));
  const larger = Math.max(seen.coverage.width, seen.coverage.height);
  assert.ok(larger >= 0.3 && larger <= 0.9, `${name}: the motion spans ${larger.toFixed(2)} of the canvas`);
  assert.ok(seen.coverage.width <= 0.9 && seen.coverage.height <= 0.9, `${name}: the motion spills over`);
  assert.equal(seen.coverage.clipped, false, `${name}: the motion is clipped by the near or far plane`);
  assert.ok(seen.grid <= seen.lowest, `${name}: the grid at ${seen.grid} cuts the motion (lowest ${seen.lowest})`);
  const motion = await page.$('#motion');
  await motion.screenshot({ path: path.join(artifacts, `framing-${name}.png`) });
}

test('double pendulum: positions equal the CSV, every column plotted, poles and Bode match', async () => {
  const model = path.join(examples, 'double_pendulum.yaml');
  const r = await checkSimulationPage('double_pendulum', model, ['--duration', '10']);
  // The report within 3 MiB; a live one (a build with the in-page engine) carries the engine
  // besides: its wasm gzipped and its script, counted apart (docs/report.md, "The live report").
  const html = fs.readFileSync(r.file, 'utf8');
  const engineStart = html.indexOf('<script type="application/gzip;base64" id="momenta-engine">');
  const engineBytes = engineStart < 0 ? 0
    : Buffer.byteLength(html.slice(engineStart, html.lastIndexOf('<script>')));
  measured.double_pendulum = { bytes: r.size, engine_bytes: engineBytes };
  assert.ok(r.size - engineBytes <= 3 * 1024 * 1024, `the 10 s report is ${r.size - engineBytes} bytes without its engine`);
  const table = csv(run('simulate', model, '--duration', '10', '--reactions', '-q'));
  // The page's position of the tip (mass2's point [0, 0, −1]) at kept frame times equals the CSV.
  const rowsByTime = new Map(table.rows.map((row, i) => [row[0], i]));
  const picks = [0, 1, 7, Math.floor(r.hook.times.length / 2), r.hook.times.length - 1];
  for (const k of picks) {
    const t = r.hook.times[k];
    const i = rowsByTime.get(t);
    assert.ok(i !== undefined, `frame time ${t} is a CSV row`);
    const tip = await r.page.evaluate((time) => window.momentaReport.bodyPoint('mass2', [0, 0, -1], time), t);
    ['tip.x', 'tip.y', 'tip.z'].forEach((c, j) => {
      assert.ok(Math.abs(tip[j] - table.rows[i][table.header.indexOf(c)]) <= 1e-9, `${c} at t = ${t}: ${tip[j]}`);
    });
  }
  // Every column but time is a plotted series, with its values (every row: no thinning below 2000 rows
  // does not apply here, so check the envelope holds the column's extremes).
  assert.deepEqual([...r.hook.series].sort(), table.header.slice(1).sort());
  const theta = await r.page.evaluate(() => window.momentaReport.seriesValues('upper.angle'));
  const column = table.column('upper.angle');
  assert.equal(Math.max(...theta), Math.max(...column));
  assert.equal(Math.min(...theta), Math.min(...column));
  // The upper joint's out-of-plane reaction moment is round-off (4e-14 N·m against forces of
  // 100 N on 1 m rods): the page keeps it and plots 0; the in-plane angle is plotted as it is.
  const moment = await r.page.evaluate(() => ({ kept: window.momentaReport.seriesValues('upper.reaction.My'),
    drawn: window.momentaReport.plottedValues('upper.reaction.My') }));
  assert.ok(moment.kept.some((v) => v !== 0), 'the computed round-off is kept');
  assert.ok(moment.drawn.every((v) => v === 0), 'round-off plotted as 0');
  assert.deepEqual(await r.page.evaluate(() => window.momentaReport.plottedValues('upper.angle')), theta);
  // The 3-D view is drawn on demand: not once while the page stands still (half a second: ~30
  // animation frames), once when the time moves, frame after frame while it plays.
  const frames = await r.page.evaluate(async () => {
    const wait = (ms) => new Promise((done) => setTimeout(done, ms));
    const hook = window.momentaReport;
    const counts = [hook.framesDrawn()];
    await wait(500);
    counts.push(hook.framesDrawn());
    hook.setTime(1.5);
    await wait(100);
    counts.push(hook.framesDrawn());
    hook.play(true);
    await wait(500);
    hook.play(false);
    counts.push(hook.framesDrawn());
    return counts;
  });
  assert.equal(frames[1], frames[0], `frames drawn while the page stood still: ${frames}`);
  assert.equal(frames[2], frames[1] + 1, `frames drawn for one change of time: ${frames}`);
  assert.ok(frames[3] >= frames[2] + 2, `frames drawn in 0.5 s of play: ${frames}`);
  await r.page.close();
});

// The equations panel shows the equations `momenta equations MODEL --all-symbols` prints, set as
// MathML by the browser (no KaTeX error), each as wide as the panel at most (long ones broken at
// their terms), the constraints' rows, and a table of the symbols with their values and units.
test('equations panel: the CLI\'s equations set as mathematics, broken to fit, with the symbols\' values', async () => {
  for (const [name, count, rows] of [['double_pendulum', 2, 0], ['constraints/chaplygin_sleigh', 3, 1]]) {
    const model = path.join(examples, `${name}.yaml`);
    const file = path.join(work, `equations-${path.basename(name)}.html`);
    run('report', model, '-o', file, '-q', '--duration', '1');
    const { page, problems } = await open(file);
    const seen = await page.evaluate(() => window.momentaReport.equations());
    assert.equal(seen.data.available, true, name);
    assert.equal(seen.shown.length, count + rows, `${name}: ${seen.shown.length} equations set`);
    assert.equal(seen.errors, 0, `${name}: KaTeX could not set an equation`);
    for (const m of seen.shown) {
      assert.ok(m.width > 50 && m.width <= seen.panelWidth + 1, `${name}: an equation ${m.width} px wide in ${seen.panelWidth}`);
    }
    // The page's text of each equation is the CLI's (joined where the CLI breaks lines).
    const printed = run('equations', model, '--all-symbols').replace(/\n {4}/g, ' ').split('\n');
    for (const e of seen.data.equations) assert.ok(printed.includes(e.text), `${name}: ${e.text}`);
    // Every symbol's value is the model's: the double pendulum's masses 1 kg, lengths 1 m, g.
    const units = Object.fromEntries(seen.data.parameters.map((p) => [p.name, [p.value, p.unit]]));
    if (name === 'double_pendulum') {
      assert.deepEqual(units.m_mass2, [1, 'kg']);
      assert.deepEqual(units.L_lower, [1, 'm']);
      assert.deepEqual(units.g, [9.81, 'm/s²']);
    }
    // Also with the numbers: one line per equation with a term list (the double pendulum's and
    // the sleigh's have them all), its coefficients the symbols' values put in.
    assert.equal(seen.withNumbers.length, seen.data.equations.filter((e) => e.terms).length, name);
    assert.equal(seen.withNumbers.length, count, `${name}: every equation written with its numbers`);
    // The panel in view first: charts drawn as they come near the window move what is below them.
    const handle = await page.$('#equations');
    await handle.evaluate((e) => e.scrollIntoView());
    await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
    await handle.screenshot({ path: path.join(artifacts, `equations-${path.basename(name)}.png`) });
    assert.deepEqual(problems, [], name);
    await page.close();
  }
});

// The flyball governor's equations in symbols are 5 108, 43 232 and twice 142 040 characters of
// LaTeX; set at once they were 150 000 MathML elements and 4 of the page's 9 s to open. The
// three beyond kFoldedLatex (20 000) are folded, named by the acceleration they lead with, and
// set when the reader opens one.
test('equations panel: an equation too long to read at a glance is folded, and set when opened', async () => {
  const model = path.join(examples, 'flyball_governor.yaml');
  const file = path.join(work, 'equations-folded.html');
  run('report', model, '-o', file, '-q', '--duration', '1');
  const { page, problems } = await open(file);
  let seen = await page.evaluate(() => window.momentaReport.equations());
  assert.deepEqual(seen.data.equations.map((e) => e.latex.length), [5108, 43232, 142040, 142040]);
  assert.equal(seen.shown.length, 1, 'the spin\'s equation set');
  assert.deepEqual(seen.folded.map((f) => [f.open, f.lines]), [[false, 0], [false, 0], [false, 0]]);
  // A summary's text holds its MathML's LaTeX annotation: the acceleration it names.
  ['\\ddot{s}', '\\ddot{q}_{\\mathrm{arm1}}', '\\ddot{q}_{\\mathrm{arm2}}'].forEach((lead, k) => {
    assert.ok(seen.folded[k].summary.startsWith('The equation led by') && seen.folded[k].summary.includes(lead),
      seen.folded[k].summary);
  });
  assert.ok(seen.folded[2].summary.includes('142,040 characters'), seen.folded[2].summary);
  assert.ok(seen.elements < 5000, `the panel holds ${seen.elements} elements folded`);
  const handle = await page.$('#equations');
  await handle.evaluate((e) => e.scrollIntoView());
  await handle.screenshot({ path: path.join(artifacts, 'equations-folded.png') });
  // Opened as a reader opens it: a click on its summary.
  await page.click('#equations details.folded summary');
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  seen = await page.evaluate(() => window.momentaReport.equations());
  assert.deepEqual(seen.folded.map((f) => f.open), [true, false, false]);
  assert.ok(seen.folded[0].lines > 1 && seen.folded[0].elements > 10000, JSON.stringify(seen.folded[0]));
  assert.equal(seen.errors, 0, 'KaTeX could not set the opened equation');
  await page.screenshot({ path: path.join(artifacts, 'equations-folded-opened.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

test('quarter car: Bode and poles equal linearize --json and response --bode', async () => {
  const model = path.join(examples, 'quarter_car.yaml');
  const r = await checkSimulationPage('quarter_car', model);
  measured.quarter_car = { bytes: r.size };
  const linear = await r.page.evaluate(() => window.momentaReport.linear());
  assert.equal(linear.available, true);
  const reference = JSON.parse(run('linearize', model, '--json'));
  assert.equal(linear.poles.length, reference.eigenvalues.length);
  const sorted = (list) => [...list].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  sorted(linear.poles).forEach(([re, im], i) => {
    const [r0, i0] = sorted(reference.eigenvalues)[i];
    assert.ok(Math.abs(re - r0) <= 1e-9 * Math.hypot(r0, i0) && Math.abs(im - i0) <= 1e-9 * Math.hypot(r0, i0), `pole ${i}`);
  });
  const pair = linear.pairs[0];
  const w = pair.frequency;
  const bode = csv(run('response', model, '--input', pair.input, '--output', pair.output, '--bode', String(w[0]),
    String(w[w.length - 1]), '--points', String(w.length), '--csv', '-'));
  const magnitude = bode.column(bode.header.find((h) => h.startsWith('magnitude_db')));
  const phase = bode.column(bode.header.find((h) => h.startsWith('phase')));
  w.forEach((_, i) => {
    assert.ok(Math.abs(pair.magnitude_db[i] - magnitude[i]) <= 1e-9 * (1 + Math.abs(magnitude[i])), `|G| at ${i}`);
    assert.ok(Math.abs(pair.phase_deg[i] - phase[i]) <= 1e-9 * (1 + Math.abs(phase[i])), `phase at ${i}`);
  });
  // A mode shape animates in the 3-D view.
  await r.page.evaluate(() => window.momentaReport.playMode(0));
  const a = await canvasDigest(r.page);
  await new Promise((done) => setTimeout(done, 150));
  const b = await canvasDigest(r.page);
  assert.notEqual(a.hash, b.hash, 'the mode shape does not move');
  await r.page.close();
});

test('heavy top: reports its spin, a rigid body drawn as its cone, nutating about its precession', async () => {
  const model = path.join(examples, 'heavy_top.yaml');
  const r = await checkSimulationPage('heavy_top', model);
  measured.heavy_top = { bytes: r.size };
  const summary = await r.page.evaluate(() => window.momentaReport.summary());
  assert.equal(summary.verdict, 'pass');
  // The linear panel by default (auto): the steady precession the top is in, its nutation ±iω_n
  // as `modes --about steady` gives it (the slow root's) — not the top at rest.
  const linear = await r.page.evaluate(() => window.momentaReport.linear());
  assert.equal(linear.available, true);
  assert.match(linear.about, /steady precession of the symmetric top 'top'/);
  const modes = JSON.parse(run('modes', model, '--about', 'steady', '--json'));
  const nutation = linear.poles.map(([, im]) => im).filter((im) => im > 0);
  assert.equal(nutation.length, 1);
  assert.ok(Math.abs(nutation[0] - modes.slow_nutation) <= 1e-12 * modes.slow_nutation, `nutation ${nutation[0]}`);
  assert.ok(linear.poles.every(([re]) => re === 0));
  const shown = await r.page.evaluate(() => document.getElementById('linear').innerText);
  assert.match(shown, /steady precession/);
  // Its mode animates: the cone tilts about the line of nodes.
  await r.page.evaluate(() => window.momentaReport.playMode(0));
  const frames = [];
  for (let k = 0; k < 3; k += 1) {
    await new Promise((done) => setTimeout(done, 97));
    frames.push((await canvasDigest(r.page)).hash);
  }
  assert.ok(new Set(frames).size > 1, 'the nutation mode did not move the cone');
  await (await r.page.$('#motion')).screenshot({ path: path.join(artifacts, 'heavy_top-nutation.png') });

  // Its turning plotted as the notes' Euler angles (ZXZ): in the slow steady precession θ stays
  // 20° and φ grows at Ω, the root of A cos θ Ω² − C ω3 Ω + m g l = 0 (the example's closed
  // form), ψ at ω3 − Ω cos θ (ω3 = φ̇ cos θ + ψ̇) — straight lines, not sawtooths. RK4 at 0.1 ms
  // (h ω3 = 0.03) drifts from them by 1.1e-6 rad in φ and ψ over the 5 s (a rate 2e-7 rad/s off:
  // its phase error), θ by 9e-9 rad (measured from the CSV); 1e-5 and 1e-7 rad allowed, while
  // a lost turn is 2π and a wrong sequence or axis leaves no straight line at all. The
  // quaternion's components start hidden: a tick in the chooser shows them.
  const groups = await r.page.evaluate(() => window.momentaReport.plotGroups());
  assert.equal(groups[0].title, 'top\'s precession φ and nutation θ (ZXZ Euler angles, rad)');
  assert.deepEqual(groups[0].series, ['tip.precession φ', 'tip.nutation θ']);
  assert.equal(groups[1].title, 'top\'s spin ψ (ZXZ Euler angle, rad)');
  assert.deepEqual(groups[1].series, ['tip.spin ψ']);
  assert.ok(groups[0].shown && groups[1].shown);
  const quaternion = groups.findIndex((g) => g.series.includes('tip.qw'));
  assert.equal(groups[quaternion].shown, false, 'the quaternion components start hidden');
  const [A, C, mgl, w3, th] = [6.375e-3, 7.5e-4, 9.81 * 0.075, 300, (20 * Math.PI) / 180];
  const omega = (C * w3 - Math.sqrt((C * w3) ** 2 - 4 * A * Math.cos(th) * mgl)) / (2 * A * Math.cos(th));
  const euler = await r.page.evaluate(() => ({ t: window.momentaReport.plotTime(),
    phi: window.momentaReport.seriesValues('tip.precession φ'), theta: window.momentaReport.seriesValues('tip.nutation θ'),
    psi: window.momentaReport.seriesValues('tip.spin ψ') }));
  assert.ok(euler.t.at(-1) >= 4.999, `plotted to ${euler.t.at(-1)} s`);
  euler.t.forEach((t, k) => {
    assert.ok(Math.abs(euler.theta[k] - th) <= 1e-7, `θ(${t}) = ${euler.theta[k]}`);
    assert.ok(Math.abs(euler.phi[k] - euler.phi[0] - omega * t) <= 1e-5, `φ(${t}) = ${euler.phi[k]}`);
    assert.ok(Math.abs(euler.psi[k] - euler.psi[0] - (w3 - omega * Math.cos(th)) * t) <= 1e-5, `ψ(${t}) = ${euler.psi[k]}`);
  });
  await r.page.click(`#plots .plot-chooser label:nth-of-type(${quaternion + 1}) input`);
  const after = await r.page.evaluate(() => window.momentaReport.plotGroups());
  assert.equal(after[quaternion].shown, true, 'ticking its box shows the quaternion plot');
  await r.page.evaluate(() => window.momentaReport.drawAllCharts());
  await (await r.page.$('#plots')).screenshot({ path: path.join(artifacts, 'heavy_top-euler-plots.png') });
  await r.page.close();

  // Asleep (upright, spinning at 300 rad/s about its axis): θ = 0, where only φ + ψ has a value;
  // ψ is held and φ carries the turn, 300 t — no jumps between the two.
  const sleeping = path.join(work, 'sleeping_top.html');
  run('report', path.join(examples, 'sleeping_top.yaml'), '-o', sleeping, '-q');
  const asleep = await open(sleeping);
  const upright = await asleep.page.evaluate(() => ({ t: window.momentaReport.plotTime(),
    phi: window.momentaReport.seriesValues('tip.precession φ'), theta: window.momentaReport.seriesValues('tip.nutation θ'),
    psi: window.momentaReport.seriesValues('tip.spin ψ') }));
  upright.t.forEach((t, k) => {
    assert.ok(Math.abs(upright.phi[k] - 300 * t) <= 1e-6 && upright.theta[k] === 0 && upright.psi[k] === 0,
      `at ${t} s: φ ${upright.phi[k]}, θ ${upright.theta[k]}, ψ ${upright.psi[k]}`);
  });
  assert.deepEqual(asleep.problems, []);
  await asleep.page.close();
});

// The bouncing ball (a joint's stop, e = 0.8): every impact a tick on the time axis of every time
// plot, at its time — the first at t₁ = √(2h/g), where the height plot reaches the floor — its
// tooltip what happened; the summary lists every stop entry with units, rest at the Zeno limit.
test('bouncing ball: its impacts ticked on the time axis and listed in the summary', async () => {
  const r = await checkSimulationPage('bouncing_ball', path.join(examples, 'bouncing_ball.yaml'));
  const summary = await r.page.evaluate(() => window.momentaReport.summary());
  const stops = summary.stops;
  assert.ok(stops.length > 50, `${stops.length} stop entries`);
  const t1 = Math.sqrt(2 * 1.0 / 9.81);
  assert.ok(Math.abs(stops[0].time - t1) < 1e-9, `first impact at ${stops[0].time}`);
  assert.equal(stops[0].rate_unit, 'm/s');
  await r.page.evaluate(() => window.momentaReport.drawAllCharts());
  const ticks = await r.page.evaluate(() => {
    const plot = document.querySelector('#plots .plot');
    const over = plot.querySelector('.u-over');
    const shown = [...plot.querySelectorAll('.time-mark')].filter((t) => t.style.display !== 'none');
    return { count: shown.length, width: over.clientWidth,
      first: { left: parseFloat(shown[0].style.left), title: shown[0].title, time: Number(shown[0].dataset.time) },
      last: { left: parseFloat(shown.at(-1).style.left), kind: shown.at(-1).className } };
  });
  assert.equal(ticks.count, stops.length);
  assert.match(ticks.first.title, /^drop lower stop: impact at t = 0\.451524 s, rate -4\.429 → 3\.544 m\/s, impulse 0\.7973 N·s, 0\.353 J lost$/);
  // Placed at its time on the axis (the plot spans the run, 0 to 5 s): to within a pixel.
  const expected = (ticks.first.time / 5.0) * ticks.width;
  assert.ok(Math.abs(ticks.first.left - expected) <= 1.0, `first tick at ${ticks.first.left}px, expected ${expected}`);
  assert.match(ticks.last.kind, /rest/);
  // 93 entries: the list starts closed (open where there are at most 10); opened, as a reader would.
  const listed = await r.page.evaluate(() => {
    const details = document.querySelector('#summary details.stops');
    const closed = !details.open;
    details.open = true;
    return { closed, text: details.innerText };
  });
  assert.ok(listed.closed);
  // Counted as `momenta simulate` counts them ("93 in all (93 impacts"): the last rest strikes too.
  const impacts = stops.filter((e) => e.kind === 'impact' || (e.kind === 'rest' && e.impulse !== 0)).length;
  assert.equal(stops.filter((e) => e.kind === 'impact').length, stops.length - 1);  // the last: rest
  assert.equal(impacts, stops.length);
  assert.match(listed.text, new RegExp(`Stops and contacts: ${stops.length} entries, ${impacts} impacts`));
  assert.match(listed.text, /its bounces end at 4\.0637\d* s/);
  assert.match(listed.text, /\t-4\.42945 m\/s\t3\.54356 m\/s\t0\.7973 N·s\t/);
  await (await r.page.$('#summary')).screenshot({ path: path.join(artifacts, 'bouncing_ball-stops.png') });
  await (await r.page.$('#plots .plot')).screenshot({ path: path.join(artifacts, 'bouncing_ball-ticks.png') });
  await r.page.close();
});

// Newton's cradle (contacts between balls, e = 1): its eight impacts, in pairs at one instant, each
// a tick and a row of the summary's list — open, as there are few — named by its contact, the
// rates the normal speed in m/s.
test('newtons cradle: its contacts ticked and listed', async () => {
  const r = await checkSimulationPage('newtons_cradle', path.join(examples, 'newtons_cradle.yaml'));
  const summary = await r.page.evaluate(() => window.momentaReport.summary());
  const stops = summary.stops;
  assert.equal(stops.length, 8);
  assert.deepEqual(stops.slice(0, 2).map((s) => s.contact), ['touch12', 'touch23']);
  assert.equal(stops[0].time, stops[1].time);
  assert.equal(stops[0].rate_unit, 'm/s');
  assert.equal(stops[0].impulse_unit, 'N·s');
  await r.page.evaluate(() => window.momentaReport.drawAllCharts());
  const first = await r.page.evaluate(() => {
    const shown = [...document.querySelectorAll('#plots .plot:first-child .time-mark')].filter((t) => t.style.display !== 'none');
    return { count: shown.length, title: shown[0].title };
  });
  assert.equal(first.count, 8);
  assert.match(first.title, /^contact touch12: impact at t = 0\.360248 s, normal speed -1\.096 → 1\.096 m\/s, impulse 0\.1096 N·s, 0\.00 J lost$/);
  const listed = await r.page.evaluate(() => {
    const details = document.querySelector('#summary details.stops');
    return { open: details.open, text: details.innerText };
  });
  assert.ok(listed.open);
  assert.match(listed.text, /Stops and contacts: 8 entries, 8 impacts/);
  assert.match(listed.text, /0\.360247555493\t\tcontact touch12\timpact\t-1\.09586 m\/s\t1\.09586 m\/s\t0\.109586 N·s\t/);
  await (await r.page.$('#summary')).screenshot({ path: path.join(artifacts, 'newtons_cradle-contacts.png') });
  await (await r.page.$('#plots .plot')).screenshot({ path: path.join(artifacts, 'newtons_cradle-ticks.png') });
  await r.page.close();
});

// The display rule in the 3-D view: a car on a road never turns, so ω and H have no arrow and
// no scale (the legend said "ω: 1 m = 7.69e-34 rad/s" of round-off before); a swinging rod's
// have both (a point mass's H about its centre of mass is 0: no arrow either).
test('a body that never turns: no ω or H arrow and no scale in the legend', async () => {
  const legendOf = async (name, model) => {
    const file = path.join(work, `${name}-legend.html`);
    run('report', model, '-o', file, '-q', '--duration', '2');
    const { page, problems } = await open(file);
    await firstFrame(page);
    const text = await page.$eval('#motion .legend', (e) => e.textContent);
    await page.close();
    assert.deepEqual(problems, []);
    return text;
  };
  const car = await legendOf('cruise_control', path.join(examples, 'cruise_control.yaml'));
  assert.ok(car.includes('ω: 0 (no body turns)') && car.includes('H: 0'), car);
  assert.ok(!car.includes('rad/s') && !car.includes('kg·m²/s'), car);
  const rod = await legendOf('compound_pendulum', path.join(examples, 'compound_pendulum.yaml'));
  assert.match(rod, /ω: 1 m = [0-9.e+-]+ rad\/s · H: 1 m = [0-9.e+-]+ kg·m²\/s/);
  const bob = await legendOf('pendulum', path.join(examples, 'pendulum.yaml'));
  assert.match(bob, /ω: 1 m = [0-9.e+-]+ rad\/s · H: 0/);
});

// The audit cannot pass vacuously: the double pendulum under RK4 at h = 0.05 s (|λ|h = 0.29 for
// its fastest mode, 5.79 1/s) would be allowed 10 ω T (ω h)^4 = 2 — more than the whole energy —
// and passed its 6 % drift; the allowance is capped at 0.1 and the panel says why it cannot judge.
test('a step too coarse for the fastest mode: the audit says so instead of passing', async () => {
  const file = path.join(work, 'coarse.html');
  run('report', path.join(examples, 'double_pendulum.yaml'), '--integrator', 'rk4', '--dt', '0.05', '-o', file, '-q');
  const { page, problems } = await open(file);
  const summary = await page.evaluate(() => window.momentaReport.summary());
  assert.equal(summary.verdict, 'warn');
  assert.match(summary.verdict_reason, /the step is too large for the fastest mode to vouch for accuracy: \|λ\|h = 0\.29/);
  for (const a of summary.audit) assert.ok(a.allowed <= 0.1, JSON.stringify(a));
  const shown = await page.$eval('#summary .verdict-reason', (e) => e.textContent);
  assert.ok(shown.startsWith('Not vouched for: the step is too large'), shown);
  await page.screenshot({ path: path.join(artifacts, 'coarse-summary.png') });
  await page.close();
  assert.deepEqual(problems, []);
});

test('four-bar: the closure\'s force drawn in 3-D beside the joints\' reactions', async () => {
  const model = path.join(examples, 'constraints', 'four_bar.yaml');
  const file = path.join(work, 'four_bar.html');
  run('report', model, '-o', file, '-q');
  const table = csv(run('simulate', model, '--reactions', '-q'));
  const { page, problems } = await open(file);
  await firstFrame(page);
  const times = await page.evaluate(() => window.momentaReport.frameTimes());
  const t = times[Math.floor(times.length / 2)];
  await page.evaluate((time) => { window.momentaReport.showReactions(true); window.momentaReport.setTime(time); }, t);
  const arrows = await page.evaluate(() => window.momentaReport.reactionArrows());
  // The joints' (in the model's order), then the constraint's.
  assert.deepEqual(arrows.slice(0, 3).map((a) => a.name).sort(), ['coupler_pin', 'crank_pin', 'rocker_pin']);
  assert.equal(arrows[3].name, 'closure');
  // The closure's arrow: drawn along the force the CSV records on the rocker (W), at that row.
  const row = table.column('time').findIndex((x) => Math.abs(x - t) < 1e-12);
  assert.ok(row >= 0, `no CSV row at t = ${t}`);
  const F = ['Fx', 'Fy', 'Fz'].map((c) => table.column(`closure.reaction.${c}`)[row]);
  const size = Math.hypot(...F);
  const closure = arrows[3];
  assert.ok(closure.visible && size > 1e-3, `closure arrow ${JSON.stringify(closure)}, |F| = ${size}`);
  closure.direction.forEach((d, i) => assert.ok(Math.abs(d - F[i] / size) < 1e-5, `direction ${closure.direction} vs ${F}`));
  const label = await page.evaluate(() => [...document.querySelectorAll('#motion label')].map((l) => l.textContent).join('|'));
  assert.match(label, /joint and constraint reactions/);
  await page.$('#motion').then((h) => h.screenshot({ path: path.join(artifacts, 'four-bar-reactions-motion.png') }));
  assert.deepEqual(problems, []);
  await page.close();
});

// A contact's force (examples/bouncing_sphere.yaml): none while the ball flies; once it rests, the
// floor's push drawn upwards where the ball touches the floor, as the CSV's floor.normal says.
test('bouncing sphere: the floor\'s force drawn where it touches, once it holds the ball', async () => {
  const model = path.join(examples, 'bouncing_sphere.yaml');
  const file = path.join(work, 'bouncing_sphere.html');
  run('report', model, '-o', file, '-q');
  const { page, problems } = await open(file);
  await firstFrame(page);
  const times = await page.evaluate(() => window.momentaReport.frameTimes());
  const floorAt = async (time) => {
    await page.evaluate((t) => { window.momentaReport.showReactions(true); window.momentaReport.setTime(t); }, time);
    return (await page.evaluate(() => window.momentaReport.reactionArrows())).find((a) => a.name === 'floor');
  };
  const flying = await floorAt(times.find((t) => t > 0.2));  // before the first impact, 0.4515 s
  assert.ok(flying && !flying.visible, `in flight: ${JSON.stringify(flying)}`);
  const resting = await floorAt(times.at(-1));  // at rest from 4.0637 s, pushed up with m g
  assert.ok(resting.visible, JSON.stringify(resting));
  resting.direction.forEach((d, i) => assert.ok(Math.abs(d - [0, 0, 1][i]) < 1e-6, `direction ${resting.direction}`));
  await page.$('#motion').then((h) => h.screenshot({ path: path.join(artifacts, 'bouncing_sphere-floor-force.png') }));
  assert.deepEqual(problems, []);
  await page.close();
});

test('crate on a ramp: friction drawn against the slide, then holding it; the stick ticked and listed', async () => {
  const r = await checkSimulationPage('block_on_incline', path.join(examples, 'block_on_incline.yaml'));
  const summary = await r.page.evaluate(() => window.momentaReport.summary());
  assert.deepEqual(summary.stops.map((s) => [s.kind, s.friction]), [['rest', 'sliding'], ['stick', 'sticking']]);
  await r.page.evaluate(() => window.momentaReport.drawAllCharts());
  const tick = await r.page.evaluate(() => [...document.querySelectorAll('#plots .plot:first-child .time-mark.stick')].map((t) => t.title));
  assert.deepEqual(tick, ['contact ramp: sticks at t = 0.327767 s, friction 9.810 N within μs N = 11.89 N']);
  const listed = await r.page.evaluate(() => document.querySelector('#summary details.stops').innerText);
  assert.match(listed, /0\.327766596246\t\tcontact ramp\tstick \(friction 9\.81 N ≤ μs N = 11\.89 N\)/);
  assert.match(listed, /\tcontact ramp\trest \(sliding\)\t/);
  // The ramp's force N n + F t₁ on the crate (m = 2 kg): sliding up, kinetic friction μk N down the
  // ramp tilts it back from the normal (−sin 30°, 0, cos 30°); stuck, it holds the weight, straight up.
  const times = await r.page.evaluate(() => window.momentaReport.frameTimes());
  const rampAt = async (time) => {
    await r.page.evaluate((t) => { window.momentaReport.showReactions(true); window.momentaReport.setTime(t); }, time);
    return (await r.page.evaluate(() => window.momentaReport.reactionArrows())).find((a) => a.name === 'ramp');
  };
  // The ramp drawn: a plane through the origin with its normal, under the crate.
  const planes = await r.page.evaluate(() => window.momentaReport.planes());
  assert.equal(planes.length, 1);
  assert.equal(planes[0].name, 'ramp');
  const s = 0.5, c = Math.sqrt(3) / 2, sliding = [-s - 0.5 * c, 0, c - 0.5 * s];
  planes[0].normal.forEach((d, i) => assert.ok(Math.abs(d - [-s, 0, c][i]) < 1e-6, `ramp normal ${planes[0].normal}`));
  assert.ok(Math.abs(-s * planes[0].center[0] + c * planes[0].center[2]) < 1e-6, `ramp centre ${planes[0].center}`);
  const norm = Math.hypot(...sliding);
  const up = await rampAt(times.find((t) => t > 0.1));
  assert.ok(up.visible, JSON.stringify(up));
  up.direction.forEach((d, i) => assert.ok(Math.abs(d - sliding[i] / norm) < 1e-6, `sliding: ${up.direction}`));
  await (await r.page.$('#motion')).screenshot({ path: path.join(artifacts, 'block_on_incline-sliding.png') });
  const held = await rampAt(times.at(-1));
  held.direction.forEach((d, i) => assert.ok(Math.abs(d - [0, 0, 1][i]) < 1e-6, `stuck: ${held.direction}`));
  await (await r.page.$('#motion')).screenshot({ path: path.join(artifacts, 'block_on_incline-stuck.png') });
  await (await r.page.$('#summary')).screenshot({ path: path.join(artifacts, 'block_on_incline-stops.png') });
  await r.page.close();
});

test('rotor on bearings: modes about the steady motion and the Campbell diagram with its critical speeds', async () => {
  const model = path.join(examples, 'rotor_on_bearings.yaml');
  const r = await checkSimulationPage('rotor', model, ['--about', 'steady', '--campbell', '500', '5000', '--duration', '0.1']);
  // The linear panel: the reduced model's poles, as `modes --about steady` gives them.
  const linear = await r.page.evaluate(() => window.momentaReport.linear());
  assert.equal(linear.available, true);
  assert.match(linear.about, /steady motion: spin\.angle turning/);
  const modes = JSON.parse(run('modes', model, '--about', 'steady', '--json'));
  assert.equal(linear.states.length, modes.state_names.length);
  const sorted = (list) => [...list].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  const reference = sorted(modes.modes.map((m) => m.eigenvalue));
  sorted(linear.poles).forEach(([re, im], i) => {
    const [r0, i0] = reference[i];
    assert.ok(Math.abs(re - r0) <= 1e-9 * (1 + Math.hypot(r0, i0)) && Math.abs(im - i0) <= 1e-9 * (1 + Math.hypot(r0, i0)), `pole ${i}`);
  });
  // The Campbell panel: the critical speeds of `momenta campbell`, shown to 8 digits, and a chart.
  const expected = JSON.parse(run('campbell', model, '--speed-range', '500', '5000', '--json'));
  const campbell = await r.page.evaluate(() => window.momentaReport.campbell());
  assert.equal(campbell.available, true);
  assert.deepEqual(campbell.critical_speeds.map((c) => c.speed), expected.critical_speeds.map((c) => c.speed_rad_s));
  const shown = await r.page.evaluate(() => document.getElementById('campbell').innerText);
  assert.match(shown, /1934\.2044/);
  assert.match(shown, /2835\.0381/);
  const legend = await r.page.evaluate(() => [...document.querySelectorAll('#campbell .u-legend .u-label')].map((e) => e.textContent));
  for (const name of ['backward 1 (Hz)', 'backward 2 (Hz)', 'forward 1 (Hz)', 'forward 2 (Hz)', '1× (Hz)', 'critical speeds']) {
    assert.ok(legend.includes(name), `legend lacks ${name}: ${legend}`);
  }
  await r.page.close();
});

test('rolling coin: the steady circle\'s modes seen from its turning frame', async () => {
  const model = path.join(examples, 'constraints', 'rolling_coin.yaml');
  const r = await checkSimulationPage('rolling-coin-steady', model, ['--about', 'steady', '--duration', '1']);
  // The linear panel: the wobble, the displaced circle's ±iΩ and the symmetry's zeros, as
  // `modes --about steady` gives them.
  const linear = await r.page.evaluate(() => window.momentaReport.linear());
  assert.equal(linear.available, true);
  assert.match(linear.about, /steady rolling motion \(precession 2\.16958 rad\/s/);
  const modes = JSON.parse(run('modes', model, '--about', 'steady', '--json'));
  assert.deepEqual(linear.states, modes.state_names);
  const imaginary = linear.poles.map(([, im]) => im).filter((im) => im > 1e-3).sort((a, b) => a - b);
  assert.equal(imaginary.length, 2);
  assert.ok(Math.abs(imaginary[0] - modes.circle_shift[0][1]) < 1e-9, `circle ${imaginary[0]}`);
  assert.ok(Math.abs(imaginary[1] - modes.eigenvalues[0][1]) < 1e-9, `wobble ${imaginary[1]}`);
  const shown = await r.page.evaluate(() => document.getElementById('linear').innerText);
  assert.match(shown, /15\.14/);
  await r.page.close();
});

test('feedback loops: each controller drawn as its block diagram, reference, error and effort plotted', async () => {
  const expected = {
    cruise_control_pi: { words: ['PI cruise', 'kp = 800, ki = 40', 'engine (N)', 'Σ', 'x.position_rate', 'target_speed'],
      blocks: 2, junctions: 1, plots: { 'Loop cruise: reference, measured and error': [['cruise.reference', 'x.position_rate', 'cruise.error'], 'm/s'],
        'Loop cruise: control effort': [['cruise.engine'], 'N'], 'Loop cruise: controller states': [['cruise.integral'], 'N'] } },
    satellite_attitude_pd: { words: ['PD attitude_pd', 'hold (ZOH)', 'T = 0.1 s', 'thrust (N·m)', 'sensor', 'r = 0.1'],
      blocks: 4, junctions: 1, plots: { 'Loop attitude_pd: control effort': [['attitude_pd.thrust'], 'N·m'],
        'Loop attitude_pd: reference, measured and error': [['attitude_pd.reference', 'attitude.angle', 'attitude_pd.error'], 'rad'] } },
    cart_pendulum_lqr: { words: ['state feedback balance', 'u = K e, K 1×4', 'force (N)', 'x_ref'],
      blocks: 2, junctions: 1, plots: { 'Loop balance: control effort': [['balance.force'], 'N'] } },
    // A commanded joint: the controller's output is the cart's acceleration.
    cart_pendulum_servo: { words: ['state feedback balance', 'cart_drive (m/s²)'],
      blocks: 2, junctions: 1, plots: { 'Loop balance: control effort': [['balance.cart_drive'], 'm/s²'] } },
  };
  for (const [name, want] of Object.entries(expected)) {
    const file = path.join(work, `${name}.html`);
    run('report', path.join(examples, `${name}.yaml`), '-o', file, '-q');
    const { page, problems } = await open(file);
    await page.evaluate(() => window.momentaReport.drawAllCharts());
    const [loop] = await page.evaluate(() => window.momentaReport.loops());
    const text = loop.texts.join(' | ');
    for (const word of want.words) assert.ok(loop.texts.some((t) => t.includes(word)), `${name}: '${word}' in ${text}`);
    assert.equal(loop.blocks, want.blocks, `${name}: ${text}`);
    assert.equal(loop.junctions, want.junctions);
    // The diagram is drawn at a readable size and fits the page's width.
    assert.ok(loop.width > 500 && loop.width <= 1280 && loop.height > 150, JSON.stringify(loop));
    const groups = await page.evaluate(() => window.momentaReport.plotGroups());
    for (const [title, [series, unit]] of Object.entries(want.plots)) {
      const group = groups.find((g) => g.title === title);
      assert.ok(group, `${name}: a plot '${title}' among ${groups.map((g) => g.title).join('; ')}`);
      assert.deepEqual(group.series, series);
      assert.equal(group.unit, unit, `${name}: ${title}'s axis`);
    }
    await (await page.$('#loops')).screenshot({ path: path.join(artifacts, `loop-${name}.png`) });
    await page.screenshot({ path: path.join(artifacts, `loop-${name}-page.png`), fullPage: true });
    assert.deepEqual(problems, []);
    await page.close();
  }
});

test('a run that blows up still gives a report, with the reason at the top', async () => {
  const model = path.join(sourceDir, 'tests', 'data', 'models', 'stiff_spring.yaml');
  const file = path.join(work, 'blowup.html');
  const result = spawnSync(momenta, ['report', model, '--duration', '100', '--dt', '0.01', '-o', file, '-q']);
  assert.equal(result.status, 1);
  const { page, problems } = await open(file);
  const banner = await page.$eval('.stopped', (e) => e.textContent);
  assert.match(banner, /non-finite/);
  await page.screenshot({ path: path.join(artifacts, 'blowup-page.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

test('without WebGL the 3-D view says why and every other panel works', async () => {
  const file = path.join(work, 'no_webgl.html');
  run('report', path.join(examples, 'quarter_car.yaml'), '-o', file, '-q');
  const { page, problems } = await openReport(browser, file, {
    beforeLoad: () => {
      const real = HTMLCanvasElement.prototype.getContext;
      HTMLCanvasElement.prototype.getContext = function getContext(kind, ...rest) {
        return /webgl/.test(kind) ? null : real.call(this, kind, ...rest);
      };
    },
  });
  const notice = await page.$eval('#view .no-webgl', (e) => e.textContent);
  assert.match(notice, /needs WebGL/);
  const shown = await page.evaluate(() => ({ series: window.momentaReport.series().length,
    charts: window.momentaReport.drawAllCharts(), poles: window.momentaReport.linear().poles.length,
    point: window.momentaReport.bodyPoint('body', [0, 0, 0], 0.5) }));
  assert.ok(shown.series > 0 && shown.charts > 0 && shown.poles > 0, JSON.stringify(shown));
  assert.ok(shown.point.every(Number.isFinite));
  await page.screenshot({ path: path.join(artifacts, 'no_webgl-page.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

test('an existing report is never overwritten without --force', () => {
  const file = path.join(work, 'keep.html');
  fs.writeFileSync(file, 'keep me');
  const result = spawnSync(momenta, ['report', path.join(examples, 'pendulum.yaml'), '-o', file, '-q'], { encoding: 'utf8' });
  assert.equal(result.status, 1);
  assert.match(result.stderr, /--force/);
  assert.equal(fs.readFileSync(file, 'utf8'), 'keep me');
});

test('20 bodies: every link drawn and moving while the page plays', async () => {
  const model = chainModel(work);
  const r = await checkSimulationPage('chain20', model);
  assert.equal(r.hook.bodies.length, 20);
  const before = await canvasDigest(r.page);
  const drawn = await r.page.evaluate(async () => {
    const start = window.momentaReport.framesDrawn();
    window.momentaReport.play(true);
    await new Promise((done) => setTimeout(done, 500));
    window.momentaReport.play(false);
    return window.momentaReport.framesDrawn() - start;
  });
  const after = await canvasDigest(r.page);
  assert.ok(drawn > 1, `${drawn} frames drawn in 0.5 s of play`);
  assert.notEqual(before.hash, after.hash, 'the chain did not move while playing');
  measured.chain20 = { bytes: r.size };
  await r.page.close();
});

// A robot file's page: its links among the bodies, no stray word where a description it does not
// have would be, and the arm spanning 30–90 % of the canvas, as the bundled examples are framed.
async function expectLinksDrawnAndFramed(r, links) {
  for (const link of links) assert.ok(r.hook.bodies.includes(link), link);
  const text = await r.page.evaluate(() => document.body.innerText);
  assert.ok(!/\b(null|undefined|NaN)\b/.test(text), text.slice(0, 300));
  const seen = await r.page.evaluate(() => window.momentaReport.framing());
  const larger = Math.max(seen.width, seen.height);
  assert.ok(larger >= 0.3 && larger <= 0.9, `the arm spans ${larger.toFixed(2)} of the canvas`);
}

// An MJCF model (tests/data/models/mjcf/arm7.xml): its bodies drawn from their geoms — capsules,
// cylinders, a box and an ellipsoid — and the arm framed as the bundled examples are.
test('MJCF arm: every link drawn from its geoms and framed', async () => {
  const model = path.join(sourceDir, 'tests', 'data', 'models', 'mjcf', 'arm7.xml');
  const r = await checkSimulationPage('arm7_mjcf', model, ['--duration', '2']);
  await expectLinksDrawnAndFramed(r, ['base', 'link1', 'link4', 'link7']);
  await r.page.close();
});

// A URDF whose links are meshes (tests/data/models/urdf/packages/mesh_arm): STL and COLLADA
// found on the package path, weighed at 2700 kg/m³, each link drawn from its visual mesh (the
// hexagonal upper arm, the scaled-cube forearm, the hand in millimetres) and the arm framed.
test('URDF mesh arm: links drawn from their meshes and framed', async () => {
  const model = path.join(sourceDir, 'tests', 'data', 'models', 'urdf', 'packages', 'mesh_arm', 'urdf', 'mesh_arm.urdf');
  const packages = path.join(sourceDir, 'tests', 'data', 'models', 'urdf', 'packages');
  const r = await checkSimulationPage('mesh_arm_urdf', model, ['--duration', '2', '--package-path', packages, '--link-density', '2700']);
  await expectLinksDrawnAndFramed(r, ['base', 'upper_arm', 'forearm', 'hand', 'payload']);
  const parts = await r.page.evaluate(() => JSON.parse(document.getElementById('momenta-data').textContent)
    .scene.bodies.map((b) => (b.parts || []).map((p) => p.kind).join(',')));
  assert.equal(parts.filter((k) => k === 'mesh').length, 4, parts.join(' | '));
  await r.page.close();
});

test('mass properties page of a mesh and of a part file with a hole', async () => {
  for (const [name, args] of [['mesh_part', [path.join(examples, 'parts', 'meshes', 'l_bracket.obj'), '--density', '2700', '--scale', '0.001']],
    ['bracket_part', [path.join(examples, 'parts', 'bracket.yaml'), '--about', '0', '0', '0']],
    ['flanged_shaft_part', [path.join(examples, 'parts', 'flanged_shaft.yaml')]]]) {
    const file = path.join(work, `${name}.html`);
    const expected = JSON.parse(run('inertia', ...args, '--json'));
    run('inertia', ...args, '--report', file);
    const { page, problems } = await open(file);
    await firstFrame(page);
    const shown = await page.evaluate(() => document.body.innerText);
    assert.match(shown, /centre of mass/);
    const digest = await canvasDigest(page);
    assert.ok(digest.colours > 20, `${name}: blank view`);
    const mass = await page.evaluate(() => JSON.parse(document.getElementById('momenta-data').textContent).mass);
    assert.equal(mass, expected.mass);
    // Round-off is not shown as a value: the flanged shaft's centre of mass is computed as
    // [1.3e-20, 0, 0.11067] (--json keeps that) and shown as [0, 0, 0.11066742] m, and no
    // figure on the page is a round-off residue of 1e-15 or below.
    if (name === 'flanged_shaft_part') {
      assert.ok(expected.com[0] !== 0, 'the JSON keeps the computed value');
      assert.match(shown, /centre of mass\s*\[0, 0, 0\.11066742\d*\] m/);
    }
    assert.doesNotMatch(shown, /e-(1[5-9]|[2-9]\d)\b/, `${name}: round-off shown as a value`);
    await page.screenshot({ path: path.join(artifacts, `${name}-page.png`), fullPage: true });
    assert.deepEqual(problems, []);
    await page.close();
  }
});

test('balancing page: the rotor with its axis, bearings and correction masses, the verdicts', async () => {
  const file = path.join(work, 'balance.html');
  const args = [path.join(examples, 'parts', 'two_disk_shaft.yaml'), '--bearings', '0', '1', '--speed', '3000',
    '--speed-range', '0', '3000', '--planes', '0.25', '0.75', '--radius', '0.15', '--grade', '2.5'];
  const expected = JSON.parse(run('balance', ...args, '--json'));
  run('balance', ...args, '--report', file);
  const { page, problems } = await open(file);
  await firstFrame(page);
  const shown = await page.evaluate(() => document.getElementById('balance').innerText);
  // The correction gives back the file's 12 g and 8 g; the grade fails before and passes after.
  assert.match(shown, /12 g/);
  assert.match(shown, /8 g/);
  assert.match(shown, /Balance grade: FAIL/);
  assert.match(shown, /After the correction: PASS/);
  const balance = await page.evaluate(() => window.momentaReport.balance());
  assert.deepEqual(balance.static_unbalance, [expected.unbalance.static_unbalance.x, expected.unbalance.static_unbalance.y]);
  assert.equal(balance.reactions.length, expected.reactions.length);
  const digest = await canvasDigest(page);
  assert.ok(digest.colours > 20, 'blank view');
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  await page.screenshot({ path: path.join(artifacts, 'balance-page.png'), fullPage: true });
  assert.deepEqual(problems, []);
  await page.close();
});

test('sweep page: a scatter plot and parallel coordinates of every run, the numbers of its CSV', async () => {
  const results = path.join(work, 'ride.csv');
  const file = path.join(work, 'ride.html');
  run('sweep', path.join(examples, 'sweeps', 'quarter_car_ride.yaml'), '-o', results, '--report', file, '-q', '--no-timing');
  const table = csv(fs.readFileSync(results, 'utf8'));
  const { page, problems } = await open(file);
  const hook = await page.evaluate(() => ({
    names: window.momentaReport.names(), runs: window.momentaReport.runs(),
    points: window.momentaReport.scatterPoints(), lines: window.momentaReport.parallelLines(),
    axes: window.momentaReport.scatterAxes(), ks: window.momentaReport.column(0),
    units: window.momentaReport.units(),
  }));
  // Each column's unit, from where its number sits in the model and what the metric measures.
  assert.deepEqual(hook.units, ['N/m', 'N·s/m', 'm', '%', 's', 'N', 'm']);
  const labelled = hook.names.map((n, i) => `${n} (${hook.units[i]})`);
  // Every parameter and metric column of the file, every run a point and a line.
  assert.deepEqual(hook.names, table.header.slice(1, table.header.indexOf('status')));
  assert.equal(hook.runs, 48);
  assert.equal(hook.points, 48);
  assert.equal(hook.lines, 48);
  assert.deepEqual(hook.ks, table.column('ks'));
  assert.deepEqual(hook.axes, ['ks', 'max(body_y)']);
  // What is drawn: 48 circles and 48 polylines, the axis names shown.
  const drawn = await page.evaluate(() => ({
    circles: document.querySelectorAll('#sweep-scatter circle').length,
    polylines: document.querySelectorAll('#sweep-parallel polyline').length,
    axisNames: Array.from(document.querySelectorAll('#sweep-parallel .axis-name')).map((t) => t.textContent),
    axisUnits: Array.from(document.querySelectorAll('#sweep-parallel .axis-unit')).map((t) => t.textContent),
    summary: document.getElementById('sweep-summary').innerText,
  }));
  assert.equal(drawn.circles, 48);
  assert.equal(drawn.polylines, 48);
  assert.deepEqual(drawn.axisNames, hook.names);
  assert.deepEqual(drawn.axisUnits, ['(N/m)', '(N·s/m, log)', '(m)', '(%)', '(s)', '(N)', '(m)']);
  const scatterNames = await page.evaluate(() => Array.from(document.querySelectorAll('#sweep-scatter .x-name, #sweep-scatter .y-name')).map((t) => t.textContent));
  assert.deepEqual(scatterNames, ['ks (N/m)', 'max(body_y) (m)']);
  assert.match(drawn.summary, /48 runs .*: 48 ok, 0 failed/);
  // Another pair chosen on the page: the points follow, each where its run's values put it.
  await page.select('#sweep-x', '1');
  await page.select('#sweep-y', '5');
  const chosen = await page.evaluate(() => ({
    axes: window.momentaReport.scatterAxes(),
    first: (() => { const c = document.querySelector('#sweep-scatter circle[data-run="0"] title'); return c.textContent; })(),
  }));
  assert.deepEqual(chosen.axes, ['b', 'peak_suspension_force']);
  // b runs 2000 to 20000 N·s/m in log steps: a log axis ticked at 2, 5, 10, 20 thousand; the
  // force's axis linear, at 1-2-5 steps; the colour scale has its legend.
  const scales = await page.evaluate(() => window.momentaReport.scatterScales());
  assert.equal(scales.x.log, true);
  assert.deepEqual(scales.x.ticks, [2000, 5000, 10000, 20000]);
  assert.equal(scales.y.log, false);
  const steps = scales.y.ticks.slice(1).map((t, i) => t - scales.y.ticks[i]);
  assert.ok(steps.length >= 2 && steps.every((s) => Math.abs(s - steps[0]) <= 1e-9 * steps[0]), `${scales.y.ticks}`);
  const mantissa = steps[0] / 10 ** Math.floor(Math.log10(steps[0]));
  assert.ok([1, 2, 5].some((m) => Math.abs(mantissa - m) < 1e-9), `tick step ${steps[0]}`);
  const legend = await page.$eval('#sweep-scatter .colour-legend .legend-name', (e) => e.textContent);
  assert.equal(legend, `colour: ${labelled[2]}`);
  assert.equal(chosen.first, `run 0: b (N·s/m) = ${table.column('b')[0]}, peak_suspension_force (N) = ${table.column('peak_suspension_force')[0]}`);
  await page.select('#sweep-y', '2');
  await page.screenshot({ path: path.join(artifacts, 'sweep-page.png'), fullPage: true });
  assert.deepEqual(problems, []);
  await page.close();
});

test('identification page: measured and fitted efforts, residuals, estimates and their correlations, the numbers of the command line', async () => {
  const file = path.join(work, 'arm.html');
  const model = path.join(examples, 'identification', 'two_link_arm.yaml');
  const log = path.join(examples, 'identification', 'two_link_arm_log.csv');
  const printed = JSON.parse(run('identify', model, '--data', log, '--report', file, '--json'));
  const data = csv(fs.readFileSync(log, 'utf8'));
  const { page, problems } = await open(file);
  assert.equal(await page.evaluate(() => window.momentaReport.kind), 'identification');
  await page.evaluate(() => window.momentaReport.drawAllCharts());
  const shown = await page.evaluate(() => ({
    estimates: window.momentaReport.estimates(), rows: window.momentaReport.tableRows(),
    shoulder: window.momentaReport.plotted('shoulder.effort'),
    residual: window.momentaReport.plotted('elbow.effort residual'),
    cells: window.momentaReport.heatMap(),
    consistency: Array.from(document.querySelectorAll('#identifiability tbody tr')).map((tr) => tr.innerText),
  }));
  // The estimates are the command line's, bit for bit, each row named as `identify` names it.
  assert.deepEqual(shown.estimates.map((e) => e.estimate), printed.base_parameters.map((p) => p.estimate));
  assert.deepEqual(shown.rows.map((r) => r[0]), printed.base_parameters.map((p) => p.name));
  assert.equal(shown.rows[2][1], 'kg·m²');
  // The measured effort is the log's column, against its time; the fitted one beside it, within
  // the noise (σ = 0.02 N·m: 5σ); both axes name their quantity and unit.
  assert.deepEqual(shown.shoulder.x, data.column('time'));
  assert.deepEqual(shown.shoulder.series[0].values, data.column('shoulder.effort'));
  assert.deepEqual(shown.shoulder.axes, ['time (s)', 'shoulder.effort (N·m)']);
  const gap = Math.max(...shown.shoulder.series[1].values.map((f, i) => Math.abs(f - shown.shoulder.series[0].values[i])));
  assert.ok(gap < 0.1, `fitted ${gap} N·m from measured`);
  // The residual's band is ±2σ of the noise found.
  assert.equal(shown.residual.series[1].values[0], 2 * printed.noise['elbow.effort']);
  assert.deepEqual(shown.residual.axes, ['time (s)', 'residual (N·m)']);
  // The heat map: 6 × 6 cells, ones on the diagonal in full red, each cell's number the matrix's.
  assert.equal(shown.cells.length, 36);
  for (const c of shown.cells) {
    assert.equal(c.text, printed.correlation[c.row][c.column].toFixed(2));
    if (c.row === c.column) assert.equal(c.fill, 'rgb(214,39,40)');
  }
  assert.deepEqual(shown.consistency.map((t) => t.replace(/\s+/g, ' ').trim()), ['upper consistent', 'lower consistent']);
  // The excitation and the residuals' whiteness, as the command line words them.
  const words = await page.evaluate(() => ({
    least: document.querySelector('#identifiability .least-determined').textContent,
    white: Array.from(document.querySelectorAll('#effort-noise tbody tr')).map((tr) => tr.lastChild.textContent),
  }));
  assert.equal(words.least, printed.excitation.least_determined_text);
  assert.deepEqual(words.white.map((w) => w.endsWith(': white')), [true, true]);
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  await page.screenshot({ path: path.join(artifacts, 'identification-page.png'), fullPage: true });
  assert.deepEqual(problems, []);
  await page.close();
});

test('grey-box page: the log, the fitted and the starting model, residuals, estimates and their correlations, the numbers of the command line', async () => {
  const file = path.join(work, 'quarter_car_fit.html');
  const identification = path.join(examples, 'identification', 'quarter_car_identify.yaml');
  const log = path.join(examples, 'identification', 'quarter_car_log.csv');
  const printed = JSON.parse(run('identify', identification, '--report', file, '--json'));
  const data = csv(fs.readFileSync(log, 'utf8'));
  const { page, problems } = await open(file);
  assert.equal(await page.evaluate(() => window.momentaReport.kind), 'grey-box');
  await page.evaluate(() => window.momentaReport.drawAllCharts());
  const shown = await page.evaluate(() => ({
    estimates: window.momentaReport.estimates(), rows: window.momentaReport.tableRows(),
    body: window.momentaReport.plotted('kerb: body_travel'),
    residual: window.momentaReport.plotted('kerb: body_travel residual'),
    cells: window.momentaReport.heatMap(),
    verdict: document.querySelector('#identifiability .verdict').textContent,
    white: Array.from(document.querySelectorAll('#channel-noise tbody tr')).map((tr) => tr.lastChild.textContent),
  }));
  // The estimates are the command line's, bit for bit, named and placed by their paths.
  assert.deepEqual(shown.estimates.map((e) => e.estimate), printed.parameters.map((p) => p.estimate));
  assert.deepEqual(shown.rows.map((r) => r.slice(0, 2)), [['ks', 'forces.suspension.stiffness'], ['b', 'forces.suspension.damping']]);
  // The measured series is the log's column against its time; the fitted model within 5σ of it
  // (σ = 0.5 mm); the start visibly elsewhere; both axes say quantity and unit.
  assert.deepEqual(shown.body.x, data.column('time'));
  assert.deepEqual(shown.body.series[0].values, data.column('body_travel'));
  assert.deepEqual(shown.body.series.map((s) => s.name), ['measured', 'fitted', 'at the start']);
  assert.deepEqual(shown.body.axes, ['time (s)', 'body_y (m)']);
  const gap = (k) => Math.max(...shown.body.series[k].values.map((f, i) => Math.abs(f - shown.body.series[0].values[i])));
  assert.ok(gap(1) < 5 * 0.0005, `fitted ${gap(1)} m from measured`);
  assert.ok(gap(2) > 10 * 0.0005, `the start only ${gap(2)} m from measured`);
  assert.equal(shown.residual.series[1].values[0], 2 * printed.channels[0].noise);
  assert.deepEqual(shown.residual.axes, ['time (s)', 'residual (m)']);
  // 2 × 2 correlations, the diagonal full red, each number the matrix's.
  assert.equal(shown.cells.length, 4);
  for (const c of shown.cells) {
    assert.equal(c.text, printed.correlation[c.row][c.column].toFixed(2));
    if (c.row === c.column) assert.equal(c.fill, 'rgb(214,39,40)');
  }
  assert.equal(shown.verdict, 'every parameter is determined');
  assert.deepEqual(shown.white.map((w) => w.endsWith(': white')), [true]);
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  await page.screenshot({ path: path.join(artifacts, 'grey-box-page.png'), fullPage: true });
  assert.deepEqual(problems, []);
  await page.close();
});

// A log shorter than its model's slowest time scale: the bundled drive's first 4 s (its time
// constant m/b is tens of seconds) with m and b free. The page warns of it at the top, in the
// command line's words; the full log's page warns of nothing.
test('grey-box page: a log shorter than the model\'s time scale is warned of as the command line words it', async () => {
  const rows = fs.readFileSync(path.join(examples, 'identification', 'cruise_control_log.csv'), 'utf8').split('\n');
  fs.writeFileSync(path.join(work, 'short_drive.csv'), `${rows.slice(0, 10).join('\n')}\n`);
  const fit = path.join(work, 'short_drive_identify.yaml');
  fs.writeFileSync(fit, `model: ${path.join(examples, 'cruise_control.yaml')}
parameters:
  - {name: m, path: bodies.car.mass, guess: 1500, lower: 100}
  - {name: b, path: joints.road.damping, guess: 20}
experiments:
  - {name: drive, data: short_drive.csv, inputs: [{column: force, signal: u}], outputs: [{column: speed, channel: speed}]}
`);
  const file = path.join(work, 'short_drive.html');
  const printed = JSON.parse(run('identify', fit, '--report', file, '--json'));
  assert.equal(printed.warnings.length, 1);
  assert.match(printed.warnings[0], /^experiment 'drive' \(.*short_drive\.csv\): the log lasts 4 s, shorter than the model's slowest time scale/);
  const { page, problems } = await open(file);
  assert.deepEqual(await page.evaluate(() => window.momentaReport.warnings()), [`Warning: ${printed.warnings[0]}`]);
  await (await page.$('#grey-box-summary')).screenshot({ path: path.join(artifacts, 'grey-box-short-log.png') });
  assert.deepEqual(problems, []);
  await page.close();
  const full = path.join(work, 'cruise_fit.html');
  run('identify', path.join(examples, 'identification', 'cruise_control_identify.yaml'), '--report', full);
  const other = await open(full);
  assert.deepEqual(await other.page.evaluate(() => window.momentaReport.warnings()), []);
  await other.page.close();
});

test('grey-box page: a Bode test drawn against frequency on a log scale, magnitude in dB and phase in degrees', async () => {
  const file = path.join(work, 'shaker_fit.html');
  const identification = path.join(examples, 'identification', 'quarter_car_shaker_identify.yaml');
  const bode = csv(fs.readFileSync(path.join(examples, 'identification', 'quarter_car_shaker_bode.csv'), 'utf8'));
  const printed = JSON.parse(run('identify', identification, '--report', file, '--json'));
  const { page, problems } = await open(file);
  await page.evaluate(() => window.momentaReport.drawAllCharts());
  const shown = await page.evaluate(() => ({
    magnitude: window.momentaReport.plotted('shaker: magnitude_db'),
    phase: window.momentaReport.plotted('shaker: phase'),
    residual: window.momentaReport.plotted('shaker: phase residual'),
    cost: Array.from(document.querySelectorAll('#grey-box-summary dd')).map((d) => d.textContent)[3],
  }));
  assert.deepEqual(shown.magnitude.x, bode.column('frequency'));
  assert.deepEqual(shown.magnitude.axes, ['frequency (Hz)', 'magnitude (dB)']);
  assert.deepEqual(shown.phase.axes, ['frequency (Hz)', 'phase (deg)']);
  assert.deepEqual(shown.residual.axes, ['frequency (Hz)', 'residual (deg)']);
  assert.ok(shown.magnitude.logX && shown.phase.logX && shown.residual.logX);
  assert.deepEqual(shown.phase.series[0].values, bode.column('phase'));
  // The measured magnitude is the log's |G| in dB; the fit within 5σ (0.2 dB, 1°) of the data.
  bode.column('magnitude').forEach((m, i) => assert.ok(Math.abs(shown.magnitude.series[0].values[i] - 20 * Math.log10(m)) < 1e-12));
  const gap = (plot) => Math.max(...plot.series[1].values.map((f, i) => Math.abs(f - plot.series[0].values[i])));
  assert.ok(gap(shown.magnitude) < 5 * 0.2, `magnitude ${gap(shown.magnitude)} dB off`);
  assert.ok(gap(shown.phase) < 5 * 1.0, `phase ${gap(shown.phase)}° off`);
  assert.ok(shown.cost.startsWith(`${printed.linearizations} linearizations`), shown.cost);
  await page.evaluate(() => document.querySelector('#channels').scrollIntoView());
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => requestAnimationFrame(done))));
  await page.screenshot({ path: path.join(artifacts, 'grey-box-bode.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

test('grey-box page: intervals from the profile likelihood are marked and explained as the command line words them', async () => {
  const file = path.join(work, 'short_drive_fit.html');
  const identification = path.join(examples, 'identification', 'cruise_control_short_identify.yaml');
  const printed = JSON.parse(run('identify', identification, '--report', file, '--json'));
  const { page, problems } = await open(file);
  const shown = await page.evaluate(() => ({
    rows: window.momentaReport.tableRows(),
    notes: Array.from(document.querySelectorAll('#estimates .interval-notes li')).map((li) => li.textContent),
    visible: document.querySelector('#estimates .interval-notes').getBoundingClientRect().height > 0,
  }));
  // The interval column holds the profile's ends, marked ᵖ; under the table, each note as printed.
  const interval = (p) => shown.rows.find((r) => r[0] === p.name)[4];
  for (const p of printed.parameters) {
    assert.equal(p.interval_from, 'profile likelihood');
    assert.ok(interval(p).endsWith(' \u1d56'), interval(p));
    assert.ok(!interval(p).includes(String(p.fisher_interval_95[0])), 'Fisher\u2019s end shown as the interval');
  }
  assert.deepEqual(shown.notes, printed.interval_notes);
  assert.ok(shown.visible);
  await page.evaluate(() => document.querySelector('#estimates').scrollIntoView());
  await page.screenshot({ path: path.join(artifacts, 'grey-box-profile.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

after(() => fs.writeFileSync(path.join(artifacts, 'measured.json'), JSON.stringify(measured, null, 2)));

// A live page opened with its engine ready, or null — the test skipped — where the build has no
// in-page engine (MOMENTA_WASM_ENGINE off).
async function openLive(t, file) {
  const opened = await open(file);
  if (!(await opened.page.evaluate(() => typeof window.createMomentaEngine === 'function'))) {
    await opened.page.close();
    t.skip('this build has no in-page engine');
    return null;
  }
  await opened.page.evaluate(() => window.momentaReport.live.ready());
  return opened;
}

// The live report (docs/report.md, "The live report"): on the quarter car, the suspension spring
// changed by script as a reader moves its slider. The page runs the changed model in its engine
// and redraws; what it shows then is checked against the command line on the file the page
// writes (textWith, the download), and the poles against the quarter car's characteristic
// polynomial (Franklin's eq. 2.12: det(M s² + B s + K) = 0 with the new ks). The URL's hash holds
// the change: the page opened with it comes up changed. A value the model refuses is said, and the
// page stays as it was. Skipped where the build has no engine (MOMENTA_WASM_ENGINE off).
test('live quarter car: a changed spring re-simulates in the page, as the CLI runs the changed file', async (t) => {
  const model = path.join(examples, 'quarter_car.yaml');
  const file = path.join(work, 'quarter_car-live.html');
  run('report', model, '-o', file, '-q', '--force');
  const live = await openLive(t, file);
  if (!live) return;
  const { page, problems } = live;
  const parameters = await page.evaluate(() => window.momentaReport.live.parameters());
  const ks = parameters.find((p) => p.path === 'forces.suspension.stiffness');
  assert.deepEqual([ks.value, ks.unit, ks.scale], [130000, 'N/m', 'log']);
  assert.ok(parameters.some((p) => p.path === 'bodies.body.mass' && p.unit === 'kg'));
  await (await page.$('#live')).screenshot({ path: path.join(artifacts, 'live-quarter_car-controls.png') });
  await screenshots(page, 'live-quarter_car-before');
  const numbersBefore = (await page.evaluate(() => window.momentaReport.equations())).withNumbers[0].replace(/\s+/g, '');
  for (const figure of ['1.13×106', '1.3×105']) assert.ok(numbersBefore.includes(figure), `${figure} in ${numbersBefore}`);
  const posesBefore = await page.evaluate(() => window.momentaReport.bodyPoint('body', [0, 0, 0], 0.5));
  await page.evaluate(() => window.momentaReport.setTime(0.75));
  const panels = () => page.evaluate(() => [...document.querySelector('#run').children].map((c) => c.id).join(','));
  const panelsBefore = await panels();
  // The equations in symbols are the file's whatever the page changes: the redraw keeps their
  // nodes in the page (not laid out anew), and gives the section the new values below them.
  await page.evaluate(() => { window.equationBefore = document.querySelector('#equations > .equation'); });

  // The reader turns the camera (a drag on the 3-D view): the redrawn view keeps it.
  const framed = await page.evaluate(() => window.momentaReport.camera());
  await page.$eval('#view', (view) => view.scrollIntoView({ block: 'center' }));
  const canvas = await (await page.$('#view canvas')).boundingBox();
  await page.mouse.move(canvas.x + canvas.width / 2, canvas.y + canvas.height / 2);
  await page.mouse.down();
  await page.mouse.move(canvas.x + canvas.width / 2 + 120, canvas.y + canvas.height / 2 + 40, { steps: 5 });
  await page.mouse.up();
  const turned = await page.evaluate(() => window.momentaReport.camera());
  assert.ok(Math.hypot(...turned.position.map((x, i) => x - framed.position[i])) > 0.05 * Math.hypot(...framed.position.map((x, i) => x - framed.target[i])),
    `the drag turned the camera: ${JSON.stringify([framed, turned])}`);
  // The change redraws the run's panels first, the analysis' after them: between the two, the
  // analysis panels are dimmed and inert (read back as the page marks them: which are stale).
  const staleSeen = await page.evaluate(async () => {
    const seen = new Set();
    const record = () => seen.add([...document.querySelectorAll('#run > section')]
      .filter((s) => s.classList.contains('stale') && s.inert).map((s) => s.id).join(','));
    const observer = new MutationObserver(record);
    observer.observe(document.querySelector('#run'), { subtree: true, childList: true, attributes: true, attributeFilter: ['class'] });
    await window.momentaReport.live.set({ 'forces.suspension.stiffness': 90000 });
    observer.disconnect();
    record();
    return [...seen];
  });
  assert.ok(staleSeen.includes('equations,linear,diagrams'), `stale between the redraws: ${JSON.stringify(staleSeen)}`);
  assert.equal(staleSeen.at(-1), '', 'nothing stale once the change is drawn');
  const [first, last] = await page.evaluate(() => [window.momentaReport.live.firstMilliseconds(), window.momentaReport.live.lastMilliseconds()]);
  assert.ok(first > 0 && first <= last, `first redraw ${first} ms, whole change ${last} ms`);
  assert.equal(await page.evaluate(() => window.momentaReport.time()), 0.75, 'the redraw keeps the time shown');
  // (OrbitControls.update() places the camera again from its spherical coordinates: the last bits.)
  const kept = await page.evaluate(() => window.momentaReport.camera());
  const reach = Math.hypot(...turned.position.map((x, i) => x - turned.target[i]));
  for (const key of ['position', 'target']) {
    kept[key].forEach((x, i) => assert.ok(Math.abs(x - turned[key][i]) <= 1e-12 * reach,
      `the redraw keeps the reader's camera: ${key} ${JSON.stringify(kept[key])} against ${JSON.stringify(turned[key])}`));
  }
  const status = await page.evaluate(() => window.momentaReport.live.status());
  assert.equal(status.error, false, status.text);
  assert.match(status.text, /1 number changed: re-simulated 2 s with dopri5; the run's panels redrawn in \d+ ms, the analysis in \d+ ms, in this page/);
  assert.match(await page.evaluate(() => location.hash), /live=forces.suspension.stiffness%3D90000/);
  // The equations keep their form; their symbols' values and the equations with the numbers are
  // the changed model's: the wheel's row of Franklin's eq. 2.12, m1 ẍ + b (ẋ − ẏ) + ks (x − y) +
  // kw (x − r) = 0, expanded — 20 ẍ + 9800 ẋ − 9800 ẏ + (ks + kw) x − ks y − kw r, with ks + kw
  // = 1.09×10⁶ and ks = 90000 now (1.13×10⁶ and 1.3×10⁵ before).
  const equations = await page.evaluate(() => window.momentaReport.equations());
  const ksRow = equations.symbols.find((r) => r.cells[0].startsWith('ksuspension'));  // then its TeX annotation
  assert.deepEqual([ksRow?.cells[1], ksRow?.changed], ['90000 (file: 130000)', true], JSON.stringify(equations.symbols));
  assert.ok(equations.symbols.filter((r) => r.changed).length === 1, 'one value changed');
  const wheel = equations.withNumbers[0].replace(/\s+/g, '');
  for (const figure of ['20', '9800', '1.09×106', '90000', '106']) assert.ok(wheel.includes(figure), `${figure} in ${wheel}`);
  assert.ok(!wheel.includes('1.13×106') && !wheel.includes('1.3×105'), wheel);
  assert.ok(equations.notes.some((n) => n.includes("The values with the page's changes (forces.suspension.stiffness = 90000 N/m): the equations keep their form.")),
    equations.notes.join(' | '));
  assert.equal(await page.evaluate(() => document.querySelectorAll('#equations .stale').length), 0);
  assert.equal(await panels(), panelsBefore, 'the panels in their order, one of each');
  assert.ok(await page.evaluate(() => window.equationBefore === document.querySelector('#equations > .equation')),
    'the equations in symbols are the same nodes');
  assert.deepEqual(await page.evaluate(() => [...document.querySelectorAll('#equations h3')].map((h) => h.textContent)),
    ['With the numbers', 'Symbols']);
  await firstFrame(page);
  await screenshots(page, 'live-quarter_car-after');
  const posesAfter = await page.evaluate(() => window.momentaReport.bodyPoint('body', [0, 0, 0], 0.5));
  assert.notDeepEqual(posesAfter, posesBefore, 'the body moves otherwise with a softer spring');

  // The file the page writes, run by the command line: the same poles, the same run.
  const edited = path.join(work, 'quarter_car_ks90000.yaml');
  fs.writeFileSync(edited, await page.evaluate(() => window.momentaReport.live.textWith({ 'forces.suspension.stiffness': 90000 })));
  const linear = await page.evaluate(() => window.momentaReport.linear());
  const reference = JSON.parse(run('linearize', edited, '--json'));
  const sorted = (list) => [...list].sort((a, b) => a[0] - b[0] || a[1] - b[1]);
  assert.equal(linear.poles.length, 4);
  sorted(linear.poles).forEach(([re, im], i) => {
    const [r0, i0] = sorted(reference.eigenvalues)[i];
    assert.ok(Math.hypot(re - r0, im - i0) <= 1e-9 * Math.hypot(r0, i0), `pole ${i}: ${re}+${im}j against ${r0}+${i0}j`);
    // Franklin: det [[m1 s² + b s + ks + kw, −(b s + ks)], [−(b s + ks), m2 s² + b s + ks]] = 0.
    const [m1, m2, kw, b, k] = [20, 375, 1e6, 9800, 90000];
    const mul = ([a, c], [d, e]) => [a * d - c * e, a * e + c * d];
    const s = [re, im], s2 = mul(s, s);
    const coupling = [b * re + k, b * im];
    const d1 = [m1 * s2[0] + b * re + k + kw, m1 * s2[1] + b * im];
    const d2 = [m2 * s2[0] + b * re + k, m2 * s2[1] + b * im];
    const det = [mul(d1, d2)[0] - mul(coupling, coupling)[0], mul(d1, d2)[1] - mul(coupling, coupling)[1]];
    const size = Math.hypot(...d1) * Math.hypot(...d2) + Math.hypot(...coupling) ** 2;
    assert.ok(Math.hypot(...det) <= 1e-12 * size, `pole ${i} is not a root of Franklin's polynomial: ${Math.hypot(...det) / size}`);
  });
  // The body's travel at the end, as the 3-D view places it, against the command line's row.
  const native = csv(run('simulate', edited, '-q'));
  const travel = native.column('body_travel.position');
  const end = native.column('time').at(-1);
  const [z0, z1] = await page.evaluate((t) => [0, t].map((s) => window.momentaReport.bodyPoint('body', [0, 0, 0], s)[2]), end);
  assert.ok(Math.abs((z1 - z0) - (travel.at(-1) - travel[0])) <= 1e-12 * Math.max(1, Math.abs(z0)),
            `the body's travel ${z1 - z0} m in the page, ${travel.at(-1) - travel[0]} m by the command line`);

  // The hash reproduces the page; a value the model refuses is said, the page kept.
  await page.goto(`file://${file}#live=${encodeURIComponent('forces.suspension.stiffness=90000')}`);
  await page.reload();
  await page.waitForFunction(() => window.momentaReport?.ready, { polling: 20 });
  await page.evaluate(() => window.momentaReport.live.ready());
  assert.deepEqual(await page.evaluate(() => window.momentaReport.live.overrides()), { 'forces.suspension.stiffness': 90000 });
  const reopened = await page.evaluate(() => window.momentaReport.linear().poles);
  assert.deepEqual(sorted(reopened), sorted(linear.poles));
  await page.evaluate(() => window.momentaReport.live.set({ 'bodies.body.mass': -5 }));
  const refused = await page.evaluate(() => window.momentaReport.live.status());
  assert.equal(refused.error, true);
  assert.match(refused.text, /^quarter_car\.yaml:\d+:\d+: bodies\[\d\]\.mass: must not be negative, got -5$/);
  assert.deepEqual(sorted(await page.evaluate(() => window.momentaReport.linear().poles)), sorted(linear.poles));
  await (await page.$('#live')).screenshot({ path: path.join(artifacts, 'live-quarter_car-refused.png') });
  // The damper taken out: its symbol is 0, its terms leave the equations with the numbers (they
  // still hold: the terms above are 0), and the panel says so.
  await page.evaluate(() => window.momentaReport.live.set({ 'bodies.body.mass': 375, 'forces.suspension.damping': 0 }));
  const undampedStatus = await page.evaluate(() => window.momentaReport.live.status());
  assert.equal(undampedStatus.error, false, undampedStatus.text);
  const undamped = await page.evaluate(() => window.momentaReport.equations());
  assert.ok(undamped.notes.some((n) => n.includes('c_suspension is 0 — the terms above that hold it are 0, and the equations with the numbers leave them out.')),
    undamped.notes.join(' | '));
  assert.ok(undamped.notes.some((n) => n.startsWith("The equations above with the symbols' values the page's changes give")), undamped.notes.join(' | '));
  assert.equal(undamped.symbols.filter((r) => r.changed).length, 2, 'ks and c changed');
  const undampedWheel = undamped.withNumbers[0].replace(/\s+/g, '');
  assert.ok(!undampedWheel.includes('9800') && undampedWheel.includes('1.09×106'), undampedWheel);
  await page.evaluate(() => window.momentaReport.drawAllCharts());  // the layout settled above it
  await page.evaluate(() => new Promise((done) => requestAnimationFrame(() => done())));
  await (await page.$('#equations')).screenshot({ path: path.join(artifacts, 'live-quarter_car-undamped-equations.png') });
  assert.deepEqual(problems, []);
  await page.close();
});

// Every bundled example's page is live: opened, one of its numbers moved as a reader moves its
// slider (its first mass the page offers, else its first number but the run's duration and
// gravity: up a quarter on a logarithmic slider, a tenth of the range on a linear one), and what
// the page then plots read
// back and checked against `momenta report` on the file the page writes (textWith): the same
// times, and every plotted column within 1e-9 of its plot's scale (the engine's run is the command line's
// to 1e-12, tests/wasm/engine_test.mjs; the page plots what it computed) — the flyball governor's
// bdf run within 2e-3 (it parts from the native run by the integrator's own error, as far as the
// native run is from a tighter one: 4.6e-4 of the coupler's tension, measured). A page that
// offers no number, or whose change is refused, fails. A mass first: it moves no part of the
// geometry (an input's start moves the four-bar's crank 36° from where its other joints' q0
// assemble it, and the page then says the model cannot be assembled — rightly, and not what
// this test is about); not gravity: the bouncing sphere's at 7.848 m/s² ends its bounces in
// 38 269 impacts 55 µs apart, whose rows part from the command line's where an impact's instant
// lands by a last bit (a step's row more or less).
//
// The same page is the one whose framing is checked (checkFraming, above, in Chromium). Where the
// build has no engine the pages are still opened and framed, and the live part is skipped.
test('every bundled example: framed whole; its page live, a moved number re-simulated as the CLI runs the changed file', async (t) => {
  const models = [
    ...fs.readdirSync(examples).filter((f) => f.endsWith('.yaml')).map((f) => path.join(examples, f)),
    ...['constraints', 'kinematics'].flatMap((dir) => fs.readdirSync(path.join(examples, dir))
      .filter((f) => f.endsWith('.yaml')).map((f) => path.join(examples, dir, f))),
  ];
  const decode = (text) => {
    const bytes = Buffer.from(text.slice(4), 'base64');
    const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
    return Array.from(text.startsWith('f64:') ? new Float64Array(buffer) : new Float32Array(buffer));
  };
  const reportData = (html) => JSON.parse(fs.readFileSync(html, 'utf8')
    .match(/<script type="application\/json" id="momenta-data">([\s\S]*?)<\/script>/)[1]);
  assert.ok(models.length >= 20, `${models.length} examples`);
  const moved = [];
  let engineless = false;
  for (const model of models) {
    const name = path.basename(model, '.yaml');
    const file = path.join(work, `live-${name}.html`);
    run('report', model, '-o', file, '-q', '--force');
    const { page, problems } = await open(file);
    if (browserName !== 'firefox') await checkFraming(page, name);
    if (!(await page.evaluate(() => typeof window.createMomentaEngine === 'function'))) {
      engineless = true;
      assert.deepEqual(problems, [], name);
      await page.close();
      continue;
    }
    await page.evaluate(() => window.momentaReport.live.ready());
    const parameters = await page.evaluate(() => window.momentaReport.live.parameters());
    const chosen = parameters.find((p) => p.path.startsWith('bodies.') && p.path.endsWith('.mass'))
      ?? parameters.find((p) => p.path !== 'simulation.duration' && !p.path.startsWith('gravity.')) ?? parameters[0];
    assert.ok(chosen, `${name}: the page offers no number`);
    const value = chosen.scale === 'log' ? chosen.value * 1.25 : chosen.value + 0.1 * (chosen.max - chosen.min);
    await page.evaluate((p, v) => window.momentaReport.live.set({ [p]: v }), chosen.path, value);
    const status = await page.evaluate(() => window.momentaReport.live.status());
    assert.equal(status.error, false, `${name}: ${chosen.path} = ${value}: ${status.text}`);
    moved.push(`${name}: ${chosen.path} ${chosen.value} → ${value} ${chosen.unit}`);

    const edited = path.join(work, `live-${name}-edited.yaml`);
    fs.writeFileSync(edited, await page.evaluate((p, v) => window.momentaReport.live.textWith({ [p]: v }), chosen.path, value));
    const nativeHtml = path.join(work, `live-${name}-native.html`);
    run('report', edited, '-o', nativeHtml, '-q', '--force');
    const native = reportData(nativeHtml);
    const time = decode(native.plots.time);
    const pageTime = await page.evaluate(() => window.momentaReport.plotTime());
    assert.equal(pageTime.length, time.length, `${name}: plotted times`);
    // An impact's instant within 1e-12 of the duration; the four-bar falling onto its stop's
    // within 1e-8 (its 27 impacts each amplify the last bits of the one before, as the engine's
    // test measured).
    const timeBound = (name === 'four_bar_on_a_stop' ? 1e-8 : 1e-12) * time.at(-1);
    pageTime.forEach((v, i) => assert.ok(Math.abs(v - time[i]) <= timeBound, `${name}: time ${i}: ${v} against ${time[i]}`));
    const bound = name === 'flyball_governor' ? 2e-3 : 1e-9;
    // A column's scale is its plot's largest value; a plot zero in exact arithmetic (a planar
    // model's reaction moment out of its plane, round-off) takes every plot's largest, as the
    // engine's test does.
    const groups = native.plots.groups.filter((group) => !group.log);  // not the audit's drift
    const groupScale = groups.map((group) => Math.max(...group.series.flatMap((series) => decode(series.data).map(Math.abs))));
    const tableScale = Math.max(...groupScale);
    for (const [g, group] of groups.entries()) {
      const scale = groupScale[g] > 1e-9 * tableScale ? groupScale[g] : tableScale;
      for (const series of group.series) {
        const expected = decode(series.data);
        const shown = await page.evaluate((n) => window.momentaReport.seriesValues(n), series.name);
        // The plots keep each stretch's extremes (src/report/plots.cpp); which of two nearly equal
        // rows is a stretch's extreme is a last bit's choice, so a value may be its neighbour's.
        const near = (v, i) => Math.min(...[i - 1, i, i + 1].filter((k) => k >= 0 && k < expected.length)
          .map((k) => Math.abs(v - expected[k])));
        // Rows at instants that part (the four-bar on its stop) are compared by their times alone.
        const worst = Math.max(0, ...shown.map((v, i) => (Math.abs(pageTime[i] - time[i]) <= 1e-12 * time.at(-1) ? near(v, i) : 0)));
        assert.ok(shown.length === expected.length && worst <= bound * scale,
                  `${name}: ${series.name}: ${worst} of ${scale} from the command line's`);
      }
    }
    assert.deepEqual(problems, [], name);
    await page.close();
  }
  if (engineless) {
    t.skip('this build has no in-page engine: every example framed, none moved');
    return;
  }
  fs.writeFileSync(path.join(artifacts, 'live-every-example.txt'), `${moved.join('\n')}\n`);
});

// The live heavy top: its spin doubled (ω3 = 600 rad/s) with its transverse rate set to the slow
// root of the steady-precession condition A cos θ Ω² − C ω3 Ω + m g l = 0 (Goldstein §5.7; the
// example's header), as a reader would with two fields. The page's 3-D view then shows the
// symmetry axis at θ = 20° from the vertical throughout and precessing at that Ω: read back from
// the axis' direction at every frame (ZXZ: axis = (sin φ sin θ, −cos φ sin θ, cos θ)).
test('live heavy top: doubling the spin halves the precession, as the steady-precession formula says', async (t) => {
  const file = path.join(work, 'heavy_top-live.html');
  run('report', path.join(examples, 'heavy_top.yaml'), '-o', file, '-q', '--force');
  const live = await openLive(t, file);
  if (!live) return;
  const { page, problems } = live;
  const [m, g, r, h] = [1, 9.81, 0.05, 0.1];
  const [A, C, l] = [0.6 * m * h * h + 0.15 * m * r * r, 0.3 * m * r * r, 0.75 * h];
  const theta = 20 * Math.PI / 180;
  const slowRoot = (w3) => (C * w3 - Math.sqrt((C * w3) ** 2 - 4 * A * Math.cos(theta) * m * g * l)) / (2 * A * Math.cos(theta));
  const precession = async () => page.evaluate((tilt) => {
    const hook = window.momentaReport;
    const times = hook.frameTimes().filter((_, i) => i % 10 === 0);
    let phi = 0, previous = null, worstTilt = 0;
    for (const time of times) {
      const [x, y, z] = hook.bodyPoint('top', [0, 0, 1], time).map((v, k) => v - hook.bodyPoint('top', [0, 0, 0], time)[k]);
      worstTilt = Math.max(worstTilt, Math.abs(Math.acos(z / Math.hypot(x, y, z)) - tilt));
      const angle = Math.atan2(x, -y);
      if (previous !== null) phi += Math.atan2(Math.sin(angle - previous), Math.cos(angle - previous));
      previous = angle;
    }
    return { rate: phi / (times.at(-1) - times[0]), worstTilt };
  }, theta);
  const before = await precession();
  assert.ok(Math.abs(before.rate - slowRoot(300)) <= 1e-6 * slowRoot(300), `Ω ${before.rate} against ${slowRoot(300)}`);
  const w3 = 600;
  await page.evaluate((values) => window.momentaReport.live.set(values),
    { 'joints.tip.v0.1': slowRoot(w3) * Math.sin(theta), 'joints.tip.v0.2': w3 });
  const status = await page.evaluate(() => window.momentaReport.live.status());
  assert.equal(status.error, false, status.text);
  const after = await precession();
  assert.ok(Math.abs(after.rate - slowRoot(w3)) <= 1e-6 * slowRoot(w3), `Ω ${after.rate} against ${slowRoot(w3)}`);
  assert.ok(after.worstTilt <= 1e-6, `θ strays ${after.worstTilt} rad from 20°`);
  assert.ok(Math.abs(after.rate / before.rate - 0.5) < 0.05, 'about half: the gyroscopic approximation m g l/(C ω3)');
  await firstFrame(page);
  await (await page.$('#motion')).screenshot({ path: path.join(artifacts, 'live-heavy_top-spin600.png') });
  assert.deepEqual(problems, []);
  await page.close();
});
