// How fast the report opens and plays in the Debian Chromium (software WebGL, as on a machine
// without a GPU): for each page, the file's size, the median and range over `MOMENTA_OPENS`
// opens (default 7) of the time to interactive (request → hook ready → the main thread answers
// after the first 3-D frame), and the frames per second while playing.
//
//   cmake --build build --target bench_report     (or: MOMENTA_CLI=… MOMENTA_SOURCE_DIR=… node report_bench.mjs)
//
// Targets (issue 10): interactive within 2 s; ≥ 30 frames/s for 20 bodies; the 10 s double
// pendulum ≤ 3 MB. Issue 29: the MJCF humanoid interactive within 2 s. Prints a table and writes it as JSON to MOMENTA_BENCH_OUT when set.
//
// The live pages (issue 57; a build with the in-page engine): for each, the median over
// `MOMENTA_OPENS` changes of its first number (a tenth up, then back, in turn) of the engine's
// run alone (`live.simulateMilliseconds`), of the change to the frame after the run's own panels
// (summary, 3-D view, loops, plots) were redrawn (`live.firstMilliseconds`, the page's own
// clock), and of the whole change — the page's run, its report data, the equations' numbers and
// every panel redrawn, the analysis' after the run's, to the next frame — beside the native
// run's wall time (`momenta simulate`'s summary, median of as many runs). Aims: the double
// pendulum's 10 s at rtol 1e-10 ≤ 150 ms in the page; a change to the redrawn page ≤ 100 ms up
// to 10 degrees of freedom. MOMENTA_BENCH_LIVE_ONLY=1 measures the live pages alone.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { spawnSync } from 'node:child_process';
import { chainModel, examples, framesPerSecond, launchBrowser, momenta, openReport, run } from './pages.mjs';

const opens = Number(process.env.MOMENTA_OPENS || 7);
const work = fs.mkdtempSync(path.join(os.tmpdir(), 'momenta-report-bench-'));
const pages = [
  ['double pendulum, 10 s', path.join(examples, 'double_pendulum.yaml'), ['--duration', '10']],
  ['quarter car', path.join(examples, 'quarter_car.yaml'), []],
  ['heavy top', path.join(examples, 'heavy_top.yaml'), []],
  ['chain of 20', chainModel(work), []],
  // Issue 29: a humanoid-size MJCF tree (26 bodies, 37 with its joint chains), floating.
  ['MJCF humanoid, 2 s', path.join(examples, '..', 'tests', 'data', 'models', 'mjcf', 'humanoid.xml'), ['--duration', '2']],
];

// The live pages: the double pendulum as the aim states it (10 s, dopri5 at rtol 1e-10), and
// three bundled examples as they are.
function doublePendulumAtTolerance(directory) {
  const text = fs.readFileSync(path.join(examples, 'double_pendulum.yaml'), 'utf8')
    .replace(/^simulation:\n(?:[ \t].*(?:\n|$))*/m,
      'simulation:\n  duration: 10.0\n  integrator: dopri5\n  rtol: 1.0e-10\n  atol: 1.0e-12\n');
  if (!text.includes('rtol: 1.0e-10')) throw new Error('double_pendulum.yaml: no simulation section to change');
  const model = path.join(directory, 'double_pendulum.yaml');
  fs.writeFileSync(model, text);
  return model;
}
const livePages = [
  ['double pendulum, rtol 1e-10', doublePendulumAtTolerance(work)],
  ['quarter car', path.join(examples, 'quarter_car.yaml')],
  ['heavy top', path.join(examples, 'heavy_top.yaml')],
  ['tennis racket (free body)', path.join(examples, 'free_body_tennis_racket.yaml')],
];

const median = (values) => { const s = [...values].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };

// The native run's wall time, as `momenta simulate` prints it in its summary (stderr), in ms.
function nativeMilliseconds(model) {
  const result = spawnSync(momenta, ['simulate', model, '-o', path.join(work, 'native.csv'), '--force'], { encoding: 'utf8' });
  const wall = /wall time\s+([0-9.e+-]+) s/.exec(result.stderr);
  if (result.status !== 0 || !wall) throw new Error(`momenta simulate ${model}: ${result.stderr}`);
  return 1000 * Number(wall[1]);
}

const browser = await launchBrowser();
const results = [];
const liveResults = [];
try {
  // The browser's own start (its processes, the software GL's first programs) is not a page's.
  const warm = path.join(work, 'warm.html');
  run('report', path.join(examples, 'pendulum.yaml'), '--duration', '1', '-o', warm, '-q');
  (await openReport(browser, warm)).page.close();
  for (const [name, model, extra] of process.env.MOMENTA_BENCH_LIVE_ONLY ? [] : pages) {
    const file = path.join(work, `${name.replace(/\W+/g, '_')}.html`);
    run('report', model, '-o', file, '-q', ...extra);
    const times = [];
    let fps = 0;
    for (let k = 0; k < opens; k++) {
      const { page, problems, interactiveMs } = await openReport(browser, file);
      if (problems.length) throw new Error(`${name}: ${problems.join('; ')}`);
      times.push(interactiveMs);
      if (k === opens - 1) fps = await framesPerSecond(page, 3);
      await page.close();
    }
    results.push({ page: name, bytes: fs.statSync(file).size, interactive_ms_median: median(times),
      interactive_ms_min: Math.min(...times), interactive_ms_max: Math.max(...times), frames_per_second: fps });
  }
  for (const [name, model] of livePages) {
    if (!fs.existsSync(model)) continue;
    const file = path.join(work, `live_${name.replace(/\W+/g, '_')}.html`);
    run('report', model, '-o', file, '-q');
    const { page, problems } = await openReport(browser, file);
    if (problems.length) throw new Error(`${name}: ${problems.join('; ')}`);
    const live = await page.evaluate(async () => {
      const hook = window.momentaReport.live;
      await hook.ready();
      return hook.parameters().length ? hook.parameters()[0] : null;
    });
    if (!live) { await page.close(); continue; }
    const simulate = [], change = [], first = [];
    for (let k = 0; k < opens; k++) {
      const value = k % 2 === 0 ? live.value * 1.1 : live.value;
      const values = { [live.path]: value };
      simulate.push(await page.evaluate((v) => window.momentaReport.live.simulateMilliseconds(v), values));
      change.push(await page.evaluate(async (v) => {
        const started = performance.now();
        await window.momentaReport.live.set(v);
        await new Promise((done) => requestAnimationFrame(() => setTimeout(done, 0)));
        return performance.now() - started;
      }, values));
      first.push(await page.evaluate(() => window.momentaReport.live.firstMilliseconds()));
      if ((await page.evaluate(() => window.momentaReport.live.status())).error) throw new Error(`${name}: the change failed`);
    }
    const dof = await page.evaluate(() => window.momentaReport.summary().dof);
    await page.close();
    const native = [];
    for (let k = 0; k < opens; k++) native.push(nativeMilliseconds(model));
    liveResults.push({ page: name, dof, bytes: fs.statSync(file).size, simulate_ms_median: median(simulate),
      first_redraw_ms_median: median(first), first_redraw_ms_min: Math.min(...first), first_redraw_ms_max: Math.max(...first), change_ms_median: median(change),
      change_ms_min: Math.min(...change), change_ms_max: Math.max(...change), native_ms_median: median(native) });
  }
} finally {
  await browser.close();
  fs.rmSync(work, { recursive: true, force: true });
}

console.log(`Chromium, software WebGL; ${opens} opens per page; ${os.cpus().length} cores`);
console.log('page                      size (MB)   interactive: median (min–max) ms   frames/s');
for (const r of results) {
  console.log(`${r.page.padEnd(24)}  ${(r.bytes / 1048576).toFixed(2).padStart(9)}   ${String(r.interactive_ms_median).padStart(10)} (${r.interactive_ms_min}–${r.interactive_ms_max})`.padEnd(70)
    + `${r.frames_per_second.toFixed(1).padStart(8)}`);
}
if (liveResults.length) {
  console.log(`\nlive pages: medians of ${opens} changes of the first number (a tenth up, then back)`);
  console.log('page                              size (MB)   engine run ms   run\'s panels redrawn, median (min–max) ms   whole change, median (min–max) ms   native run ms   engine/native');
  const range = (median, min, max) => `${median.toFixed(0)} (${min.toFixed(0)}–${max.toFixed(0)})`;
  for (const r of liveResults) {
    console.log(`${`${r.page}, ${r.dof} dof`.padEnd(32)}  ${(r.bytes / 1048576).toFixed(2).padStart(9)}   ${r.simulate_ms_median.toFixed(1).padStart(13)}   `
      + `${range(r.first_redraw_ms_median, r.first_redraw_ms_min, r.first_redraw_ms_max).padStart(40)}   ${range(r.change_ms_median, r.change_ms_min, r.change_ms_max).padStart(33)}   `
      + `${r.native_ms_median.toFixed(1).padStart(13)}   ${(r.simulate_ms_median / r.native_ms_median).toFixed(2).padStart(13)}`);
  }
}
if (process.env.MOMENTA_BENCH_OUT) fs.writeFileSync(process.env.MOMENTA_BENCH_OUT, JSON.stringify({ pages: results, live: liveResults }, null, 2));
