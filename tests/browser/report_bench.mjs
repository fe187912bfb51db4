// How fast the report opens and plays in the Debian Chromium (software WebGL, as on a machine
// without a GPU): for each page, the file's size, the median and range over `MOMENTA_OPENS`
// opens (default 7) of the time to interactive (request → hook ready → the main thread answers
// after the first 3-D frame), and the frames per second while playing.
//
//   cmake --build build --target bench_report     (or: MOMENTA_CLI=… MOMENTA_SOURCE_DIR=… node report_bench.mjs)
//
// Targets (issue 10): interactive within 2 s; ≥ 30 frames/s for 20 bodies; the 10 s double
// pendulum ≤ 3 MB. Issue 29: the MJCF humanoid interactive within 2 s. Prints a table and writes it as JSON to MOMENTA_BENCH_OUT when set.

import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { chainModel, examples, framesPerSecond, launchBrowser, openReport, run } from './pages.mjs';

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

const median = (values) => { const s = [...values].sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };

const browser = await launchBrowser();
const results = [];
try {
  // The browser's own start (its processes, the software GL's first programs) is not a page's.
  const warm = path.join(work, 'warm.html');
  run('report', path.join(examples, 'pendulum.yaml'), '--duration', '1', '-o', warm, '-q');
  (await openReport(browser, warm)).page.close();
  for (const [name, model, extra] of pages) {
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
if (process.env.MOMENTA_BENCH_OUT) fs.writeFileSync(process.env.MOMENTA_BENCH_OUT, JSON.stringify(results, null, 2));
