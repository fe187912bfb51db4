// The report's in-page engine (wasm/) against the command line: every bundled example run in
// both, the rows compared (docs/report.md, "The live report"). Run by ctest (wasm.engine) with
//   MOMENTA_WASM_ENGINE  the built module (build/wasm-engine/wasm/momenta_engine.js)
//   MOMENTA_CLI          the native momenta executable
//   MOMENTA_SOURCE_DIR   the checkout (its examples/)
//
// What "the same numbers" means here, and why:
//  - Same columns, same number of rows, always.
//  - Bit for bit where both builds do the same arithmetic: the models whose steps call no C
//    library transcendental function (the two libraries, glibc and emscripten's musl, differ in
//    the last bit of sin, exp, atan2, ...; the integrators' step control uses
//    math::portable_pow for that reason). kBitIdentical lists them; a change that breaks one is
//    a change in what the page shows.
//    (Zero's sign aside: the CSV keeps it, and no figure depends on it.)
//  - Elsewhere, on rows at the same time, every value within 1e-12 of its scale: the largest
//    magnitude of its column, or of its vector's columns (H_x, H_y, H_z; a quaternion's four),
//    which frames mix; a column that is zero in exact arithmetic (a planar model's H_x: its scale
//    below 1e-9 of the table's) within 1e-12 of the table's largest. The audit columns are
//    round-off themselves and are left out.
//  - Rows at times that differ — an event's instant located from states that differ in their
//    last bits, or an adaptive step chosen from them — are compared by their times: within
//    1e-12 of the run's duration. The four-bar falling onto its stop is the exception named:
//    its 27 impacts each amplify the last bits of the one before, and its instants part by up
//    to 4.2e-9 of the duration by the end (measured); its bound is 1e-8.
//  - bdf (SUNDIALS's CVODE, the same release 6.4.1 in both) decides its Newton iterations and
//    its steps on the last bits of the model's sin and cos and of pow, so on a model that calls
//    them its run parts from the native one by the integrator's own error, not by round-off
//    (the flyball governor at rtol 1e-7: 2e-5 of a rate's scale, 4.6e-4 of the coupler's
//    tension, measured). kSameAccuracy names those: each is checked to be as accurate as the
//    native run — its distance from a native run at rtol 1e-12 (bdf, the same rows) within twice
//    the native run's own largest distance from it, column by column on the scales above. A
//    bdf model without them (the stiff spring–damper) is bit for bit.

import { test } from 'node:test';
import assert from 'node:assert/strict';
import { createRequire } from 'node:module';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, readdirSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import path from 'node:path';
import { dataWithArrays } from '../../web/src/data.js';

const require = createRequire(import.meta.url);
const source = process.env.MOMENTA_SOURCE_DIR;
const cli = process.env.MOMENTA_CLI;
// The module's script and its wasm beside it (the page inlines both; Node.js is handed the wasm).
const createMomentaEngine = require(process.env.MOMENTA_WASM_ENGINE);
const engine = await createMomentaEngine({
  wasmBinary: readFileSync(process.env.MOMENTA_WASM_ENGINE.replace(/\.js$/, '.wasm')),
});
const scratch = mkdtempSync(path.join(tmpdir(), 'momenta-wasm-'));

const kBitIdentical = new Set([
  'belt_stick_slip', 'block_on_incline', 'bouncing_ball', 'cart_pendulum', 'cart_pendulum_lqr',
  'cart_pendulum_servo', 'compound_pendulum', 'cruise_control', 'cruise_control_pi',
  'double_pendulum', 'eccentric_impact', 'falling_rod', 'newtons_cradle', 'pendulum',
  'quarter_car', 'rotating_shaft_bent_rod', 'satellite_attitude', 'satellite_attitude_pd',
  'skidding_ball', 'sleeping_top', 'stiff_spring_damper', 'struck_rod', 'unbalanced_rotor',
  'constraints/geared_pair',
]);
const kSameAccuracy = new Set(['flyball_governor']);
const kTimeBound = { 'constraints/four_bar_on_a_stop': 1e-8 };

function examples() {
  const names = [];
  for (const folder of ['', 'constraints/']) {
    for (const file of readdirSync(path.join(source, 'examples', folder)).sort()) {
      if (file.endsWith('.yaml')) names.push(folder + file.replace(/\.yaml$/, ''));
    }
  }
  return names;
}

function nativeRun(modelPath, options = []) {
  const csv = path.join(scratch, 'native.csv');
  execFileSync(cli, ['simulate', modelPath, '-o', csv, '--force', '--quiet', ...options], { stdio: 'pipe' });
  const lines = readFileSync(csv, 'utf8').trim().split('\n');
  return { columns: lines[0].split(','), rows: lines.slice(1).map((l) => l.split(',').map(Number)) };
}

function pageRun(modelPath, overrides = []) {
  return engine.simulate(readFileSync(modelPath, 'utf8'), path.basename(modelPath), overrides);
}

// Each column's scale, as the file comment says: its largest magnitude, or its vector's; and
// which columns are compared (not the audit's).
function scales(native) {
  const compared = native.columns.map((column) => !column.startsWith('audit.'));
  const columnScale = native.columns.map((_, c) => Math.max(...native.rows.map((v) => Math.abs(v[c]))));
  const vector = (column) => column.replace(/([._])[xyz]$/, '$1*').replace(/\.q[wxyz]$/, '.q*');
  const vectorScale = new Map();
  native.columns.forEach((column, c) => {
    vectorScale.set(vector(column), Math.max(vectorScale.get(vector(column)) ?? 0, columnScale[c]));
  });
  const scale = native.columns.map((column) => vectorScale.get(vector(column)));
  const tableScale = Math.max(...scale.filter((_, c) => c > 0 && compared[c]));
  return { compared, scale, tableScale };
}

// The page's bdf run as accurate as the native one (the file comment): against a native run at
// rtol 1e-12 with the same rows, each column's largest distance in the page within twice the
// native run's largest over every column (both on the columns' scales).
function compareAccuracy(name, modelPath, native, page) {
  const reference = nativeRun(modelPath, ['--rtol', '1e-12', '--atol', '1e-14']);
  assert.deepEqual(reference.rows.map((r) => r[0]), native.rows.map((r) => r[0]), `${name}: reference rows`);
  const { compared, scale, tableScale } = scales(native);
  const n = native.columns.length;
  const distance = (value, r, c) => Math.abs(value - reference.rows[r][c]) /
    (scale[c] > 1e-9 * tableScale ? scale[c] : tableScale);
  let nativeLargest = 0;
  native.rows.forEach((row, r) => row.forEach((v, c) => {
    if (c > 0 && compared[c]) nativeLargest = Math.max(nativeLargest, distance(v, r, c));
  }));
  assert.ok(nativeLargest > 0 && nativeLargest < 1e-3, `${name}: the native run ${nativeLargest} from the reference`);
  for (let c = 1; c < n; ++c) {
    if (!compared[c]) continue;
    let largest = 0;
    for (let r = 0; r < native.rows.length; ++r) largest = Math.max(largest, distance(page.rows[r * n + c], r, c));
    assert.ok(largest <= 2 * nativeLargest, `${name}: ${native.columns[c]} ${largest} of its scale from ` +
      `the rtol 1e-12 run in the page, beyond twice the native run's ${nativeLargest}`);
  }
}

// The rows of the page's run compared with the native one's, as the file comment says.
function compare(name, native, page) {
  assert.deepEqual(page.columns, native.columns, `${name}: columns`);
  const n = native.columns.length;
  assert.equal(page.rows.length / n, native.rows.length, `${name}: rows`);
  const row = (r) => page.rows.subarray(r * n, (r + 1) * n);
  if (kBitIdentical.has(name)) {
    for (let r = 0; r < native.rows.length; ++r) {
      const p = row(r);
      for (let c = 0; c < n; ++c) {
        if (p[c] !== native.rows[r][c] && !(Number.isNaN(p[c]) && Number.isNaN(native.rows[r][c]))) {
          assert.fail(`${name}: row ${r + 1} ${native.columns[c]}: ${p[c]} in the page, ` +
                      `${native.rows[r][c]} native (expected the same bits)`);
        }
      }
    }
    return;
  }
  const { compared, scale, tableScale } = scales(native);
  const duration = native.rows.at(-1)[0];
  const timeBound = (kTimeBound[name] ?? 1e-12) * duration;
  for (let r = 0; r < native.rows.length; ++r) {
    const p = row(r);
    const t = native.rows[r][0];
    if (p[0] !== t) {
      assert.ok(Math.abs(p[0] - t) <= timeBound,
                `${name}: row ${r + 1} at t = ${p[0]} s in the page, ${t} s native`);
      continue;
    }
    for (let c = 1; c < n; ++c) {
      if (!compared[c]) continue;
      const bound = 1e-12 * (scale[c] > 1e-9 * tableScale ? scale[c] : tableScale);
      const difference = Math.abs(p[c] - native.rows[r][c]);
      if (!(difference <= bound)) {
        assert.fail(`${name}: row ${r + 1} (t = ${t} s) ${native.columns[c]}: ${p[c]} in the ` +
                    `page, ${native.rows[r][c]} native, |difference| ${difference} > ${bound}`);
      }
    }
  }
}

for (const name of examples()) {
  test(`${name}: the page's run is the command line's`, () => {
    const modelPath = path.join(source, 'examples', `${name}.yaml`);
    const native = nativeRun(modelPath);
    const page = pageRun(modelPath);
    if (kSameAccuracy.has(name)) {
      assert.deepEqual(page.columns, native.columns, `${name}: columns`);
      assert.equal(page.rows.length / native.columns.length, native.rows.length, `${name}: rows`);
      compareAccuracy(name, modelPath, native, page);
      return;
    }
    compare(name, native, page);
  });
}

test('a number changed by its path is the file changed at that path', () => {
  // The quarter car's suspension spring at 90 000 N/m instead of 130 000: the page's run with the
  // override against the command line's on the file the page would write (textWith).
  const modelPath = path.join(source, 'examples', 'quarter_car.yaml');
  const text = readFileSync(modelPath, 'utf8');
  const overrides = [{ path: 'forces.suspension.stiffness', value: 90000 }];
  assert.equal(engine.numberAt(text, 'quarter_car.yaml', 'forces.suspension.stiffness'), 130000);
  const edited = engine.textWith(text, 'quarter_car.yaml', overrides);
  assert.match(edited, /stiffness: 90000/);
  assert.equal(edited.split('\n').length, text.split('\n').length, 'every other line kept');
  const editedPath = path.join(scratch, 'quarter_car.yaml');
  writeFileSync(editedPath, edited);
  const native = nativeRun(editedPath);
  const page = pageRun(modelPath, overrides);
  compare('quarter_car', native, page);
  const nominal = pageRun(modelPath);
  assert.ok(page.rows.some((value, i) => value !== nominal.rows[i]), 'the override changed the run');
});

test('bad input is refused with the file, the line and the key', () => {
  const modelPath = path.join(source, 'examples', 'double_pendulum.yaml');
  assert.throws(() => pageRun(modelPath, [{ path: 'bodies.mass1.mass', value: -1 }]),
                /^Error: double_pendulum\.yaml:\d+:\d+: bodies\[0\]\.mass: must be positive, got -1/);
  assert.throws(() => pageRun(modelPath, [{ path: 'bodies.mas1.mass', value: 1 }]),
                /did you mean 'mass1'/);
  assert.throws(() => engine.simulate('bodies: [', 'broken.yaml', []), /^Error: broken\.yaml:/);
});

test('the page says which integrator and tolerances it used', () => {
  const run = pageRun(path.join(source, 'examples', 'quarter_car.yaml'));
  assert.equal(run.integrator, 'dopri5');
  assert.equal(run.relativeTolerance, 1e-8);
  assert.equal(run.absoluteTolerance, 1e-10);
  assert.match(run.summary, /integrator {3}dopri5 \(order 5, adaptive\)/);
});

// The data of `momenta report` (what its page embeds) against the engine's reportData for the
// same file — the summary, the scene, the frames, the plots, the linear analysis, the free-body
// diagrams and the feedback loops — less what is not the model's (the wall time, the file's path
// as given) and the equations, which the engine leaves to the native page (it has no symbolic
// layer). Text (names, units, SVG) equal; numbers as the rows above: where the data is the run's
// own rows (frames, plotted columns) of a bit-identical run, the same bits. What is computed from
// them with the C library's functions or Eigen's vectorized kernels — Euler angles (atan2), the
// linear analysis (eigenvectors, frequencies) — within 1e-12 of its scale: a number's own
// magnitude, an array's largest (a Bode phase near 0 beside its −180°); an array kept in single precision (f32: drawing only)
// within two of its ulps at that scale, for a value that rounds the other way.
function nativeReportData(modelPath) {
  const html = path.join(scratch, 'report.html');
  execFileSync(cli, ['report', modelPath, '-o', html, '--force', '--quiet'], { stdio: 'pipe' });
  const page = readFileSync(html, 'utf8');
  const match = page.match(/<script type="application\/json" id="momenta-data">([\s\S]*?)<\/script>/);
  assert.ok(match, 'the report embeds its data');
  return JSON.parse(match[1]);  // its '<\/' is JSON's own escape of '/'
}

function decoded(text) {
  const bytes = Buffer.from(text.slice(4), 'base64');
  const buffer = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength);
  return text.startsWith('f64:') ? new Float64Array(buffer) : new Float32Array(buffer);
}

// Every difference between the native data and the engine's beyond the bounds above, by path.
function differences(native, page, where = '', found = []) {
  if (found.length >= 10) return found;
  const encoded = (x) => typeof x === 'string' && /^f(32|64):/.test(x);
  const numbers = (x) => Array.isArray(x) && x.length > 0 && x.every((v) => typeof v === 'number');
  if ((encoded(native) && encoded(page)) || (numbers(native) && numbers(page))) {
    const single = encoded(native) && native.startsWith('f32:');
    const a = encoded(native) ? decoded(native) : native, b = encoded(page) ? decoded(page) : page;
    if (a.length !== b.length || (encoded(native) && native.slice(0, 4) !== page.slice(0, 4))) {
      found.push(`${where}: arrays of ${a.length} and ${b.length}`);
      return found;
    }
    let scale = 0;
    for (const x of a) scale = Math.max(scale, Math.abs(x));
    const bound = single ? 2 * 2 ** -23 * scale : 1e-12 * scale;
    const k = a.findIndex((x, i) => !(Math.abs(x - b[i]) <= bound));
    if (k >= 0) found.push(`${where}[${k}]: ${a[k]} native, ${b[k]} in the engine`);
  } else if (typeof native === 'number' && typeof page === 'number') {
    if (!(Math.abs(native - page) <= 1e-12 * Math.max(Math.abs(native), Math.abs(page)))) {
      found.push(`${where}: ${native} native, ${page} in the engine`);
    }
  } else if (native && page && typeof native === 'object' && typeof page === 'object') {
    const keys = new Set([...Object.keys(native), ...Object.keys(page)]);
    for (const key of keys) differences(native[key], page[key], `${where}.${key}`, found);
  } else if (native !== page) {
    found.push(`${where}: ${JSON.stringify(native)?.slice(0, 80)} native, ` +
               `${JSON.stringify(page)?.slice(0, 80)} in the engine`);
  }
  return found;
}

function withoutRunSpecifics(data) {
  const copy = structuredClone(data);
  delete copy.summary.wall_seconds;
  delete copy.summary.file;
  delete copy.equations;
  delete copy.live;  // the page's controls (the native page's alone)
  return copy;
}

for (const name of ['double_pendulum', 'quarter_car', 'cart_pendulum_lqr', 'sleeping_top',
                    'bouncing_ball', 'satellite_attitude_pd', 'constraints/geared_pair']) {
  test(`${name}: the engine's report data is the command line's`, () => {
    assert.ok(kBitIdentical.has(name));
    const modelPath = path.join(source, 'examples', `${name}.yaml`);
    const native = nativeReportData(modelPath);
    const page = JSON.parse(engine.reportData(readFileSync(modelPath, 'utf8'),
                                              path.basename(modelPath), []));
    assert.equal(page.equations.available, false);
    assert.deepEqual(differences(withoutRunSpecifics(native), withoutRunSpecifics(page)), []);
    // The run's own rows: the same bits.
    assert.equal(page.frames.time, native.frames.time);
    assert.equal(page.plots.time, native.plots.time);
  });
}

// The live page takes the report data with its long arrays apart (reportDataParts): revived as
// the page revives it (web/src/data.js), it is reportData's data, each base64 array the same
// bytes as the typed array standing in its place (float32 ones rounded alike), all else equal.
test('the report data with its arrays apart is reportData\'s, bit for bit', () => {
  const marker = '@array-test-';
  const same = (whole, apart, where) => {
    if (typeof whole === 'string' && /^f(32|64):/.test(whole)) {
      assert.ok(ArrayBuffer.isView(apart), `${where}: a typed array`);
      assert.equal(apart instanceof Float32Array ? 'f32:' : 'f64:', whole.slice(0, 4), where);
      assert.equal(Buffer.from(apart.buffer, apart.byteOffset, apart.byteLength).toString('base64'),
                   whole.slice(4), where);
      return 1;
    }
    if (whole && typeof whole === 'object') {
      assert.deepEqual(Object.keys(apart), Object.keys(whole), where);
      return Object.keys(whole).reduce((n, key) => n + same(whole[key], apart[key], `${where}.${key}`), 0);
    }
    assert.equal(apart, whole, where);
    return 0;
  };
  for (const name of ['quarter_car', 'heavy_top', 'cart_pendulum_lqr', 'constraints/four_bar_on_a_stop']) {
    const modelPath = path.join(source, 'examples', `${name}.yaml`);
    const text = readFileSync(modelPath, 'utf8');
    const file = path.basename(modelPath);
    const whole = JSON.parse(engine.reportData(text, file, []));
    const parts = engine.reportDataParts(text, file, [], marker, 'all');
    const apart = dataWithArrays(parts.json, parts.arrays, marker);
    delete whole.summary.wall_seconds;
    delete apart.summary.wall_seconds;
    const arrays = same(whole, apart, name);
    assert.equal(arrays, parts.arrays.length, `${name}: every array set apart stands in the data once`);
    assert.ok(arrays >= 5, `${name}: ${arrays} arrays`);
    assert.ok(!/"f(32|64):/.test(parts.json), `${name}: no base64 left in the text`);
    // The live page's two redraws: the run's panels, then the analysis', from one run; together
    // the same data, bit for bit (the summary's audit allowance included: its fastest rate is
    // the linear panel's).
    const motionParts = engine.reportDataParts(text, file, [], marker, 'motion');
    const analysisParts = engine.reportDataParts(text, file, [], marker, 'analysis');
    const motion = dataWithArrays(motionParts.json, motionParts.arrays, marker);
    const analysis = dataWithArrays(analysisParts.json, analysisParts.arrays, marker);
    assert.deepEqual(Object.keys(motion), ['kind', 'summary', 'scene', 'frames', 'plots', 'loops'], name);
    assert.deepEqual(Object.keys(analysis), ['kind', 'linear', 'equations', 'campbell', 'diagrams'], name);
    const together = Object.fromEntries(Object.keys(whole).map((key) => [key, key in motion ? motion[key] : analysis[key]]));
    delete together.summary.wall_seconds;
    assert.equal(same(whole, together, `${name} in two`), arrays, `${name}: the two hold every array`);
  }
  const text = readFileSync(path.join(source, 'examples', 'pendulum.yaml'), 'utf8');
  assert.throws(() => engine.reportDataParts(text, 'pendulum.yaml', [], '', 'all'), /an empty marker/);
  assert.throws(() => engine.reportDataParts(text, 'pendulum.yaml', [], 'a"b', 'all'), /a character JSON escapes/);
  assert.throws(() => engine.reportDataParts(text, 'pendulum.yaml', [], marker, 'plots'), /panels 'plots': expected all, motion or analysis/);
  assert.throws(() => dataWithArrays('{"x": "@array-test-3"}', [], marker), /no array 3 of 0/);
});

// What the live page offers (src/report/live_section.cpp), read from the page the command line
// writes: the heavy top's tilt by its Euler angles in degrees over ±180°, its spin in rad/s,
// its mass on a logarithmic slider; and each path leads back to the file's number.
test('the live page offers the heavy top\'s tilt in degrees and its spin in rad/s', () => {
  const modelPath = path.join(source, 'examples', 'heavy_top.yaml');
  const live = nativeReportData(modelPath).live;
  assert.equal(live.available, true);
  const byPath = Object.fromEntries(live.parameters.map((p) => [p.path, p]));
  const tilt = byPath['joints.tip.q0.euler.angles_deg.1'];
  assert.deepEqual([tilt.value, tilt.unit, tilt.min, tilt.max], [20, 'deg', -160, 200]);
  assert.deepEqual([byPath['joints.tip.v0.2'].value, byPath['joints.tip.v0.2'].unit], [300, 'rad/s']);
  assert.deepEqual([byPath['bodies.top.mass'].unit, byPath['bodies.top.mass'].scale], ['kg', 'log']);
  const text = readFileSync(modelPath, 'utf8');
  for (const p of live.parameters) assert.equal(engine.numberAt(text, 'heavy_top.yaml', p.path), p.value, p.path);
  assert.equal(live.text, text);
});

test('the live page offers no quaternion component and every number with its unit', () => {
  const live = nativeReportData(path.join(source, 'examples', 'skidding_ball.yaml')).live;
  const paths = live.parameters.map((p) => p.path);
  assert.ok(paths.includes('joints.free.q0.2') && paths.includes('joints.free.v0.3'));
  assert.ok(!paths.includes('joints.free.q0.3'), 'a free joint\'s quaternion qw offered');
  for (const p of live.parameters) assert.ok(p.unit && p.unit !== '1', `${p.path}: unit '${p.unit}'`);
});

// A file's `live:` section chooses the numbers, their order and their sliders' ranges; without
// it the page offers every number it has a rule for — here the quarter car's kerb height in m
// (the unit of the joint its signal prescribes), and not the mass of the road, which moves only
// as its prescribed joint moves it.
test('the quarter car\'s live section chooses its controls; without it the page offers the kerb and no road mass', () => {
  const modelPath = path.join(source, 'examples', 'quarter_car.yaml');
  const listed = nativeReportData(modelPath).live.parameters;
  assert.deepEqual(listed.map((p) => [p.path, p.unit, p.min, p.max, p.scale]), [
    ['forces.suspension.stiffness', 'N/m', 10000, 1000000, 'log'],
    ['forces.suspension.damping', 'N·s/m', 500, 50000, 'log'],
    ['forces.tyre.stiffness', 'N/m', 100000, 10000000, 'log'],
    ['bodies.body.mass', 'kg', 37.5, 3750, 'log'],
    ['bodies.wheel.mass', 'kg', 2, 200, 'log'],
    ['inputs.road.final', 'm', 0.01, 0.2, 'log'],
    ['simulation.duration', 's', 0.2, 20, 'log'],
  ]);
  const text = readFileSync(modelPath, 'utf8');
  const unlisted = path.join(scratch, 'quarter_car.yaml');
  writeFileSync(unlisted, text.slice(0, text.indexOf('\n# What the report\'s live page offers')));
  const chosen = Object.fromEntries(nativeReportData(unlisted).live.parameters.map((p) => [p.path, p]));
  assert.deepEqual([chosen['inputs.road.final'].unit, chosen['inputs.road.start'].unit], ['m', 's']);
  assert.equal(chosen['bodies.road_surface.mass'], undefined, 'the prescribed road\'s mass offered');
  assert.equal(chosen['bodies.body.mass'].unit, 'kg');
});

// A PID's gains in the unit of what it drives per what it measures: the cruise control's kp in
// N per m/s and ki in N per m (its file's comments), the satellite's kp in N·m/rad and kd in
// N·m·s/rad, its constant reference in rad; every bundled example's controls with a unit.
test('the live page offers controller gains in their units, and every example\'s numbers with theirs', () => {
  const units = (name) => Object.fromEntries(nativeReportData(path.join(source, 'examples', `${name}.yaml`))
    .live.parameters.map((p) => [p.path, p.unit]));
  const cruise = units('cruise_control_pi');
  assert.deepEqual([cruise['controllers.cruise.kp'], cruise['controllers.cruise.ki']], ['N·s/m', 'N/m']);
  const satellite = units('satellite_attitude_pd');
  assert.deepEqual([satellite['controllers.attitude_pd.kp'], satellite['controllers.attitude_pd.kd'],
    satellite['controllers.attitude_pd.reference'], satellite['bodies.satellite.inertia.2']],
  ['N·m/rad', 'N·m·s/rad', 'rad', 'kg·m²']);
  for (const file of readdirSync(path.join(source, 'examples')).filter((f) => f.endsWith('.yaml'))) {
    const live = nativeReportData(path.join(source, 'examples', file)).live;
    if (!live || !live.available) continue;
    for (const p of live.parameters) assert.ok(p.unit && p.unit !== '1', `${file}: ${p.path}: unit '${p.unit}'`);
  }
});

// The equations' numbers after a change (report::equation_numbers, model/parameter_source):
// for every bundled example with equations and live numbers, each of its first two numbers
// moved (a quarter up; one that is 0 to half its range's top), the engine's values of the
// report's symbols against `momenta equations --all-symbols --json` of the file the page writes.
// Where the engine says the form is kept, the command line's equations of the changed file are
// those of the file as written, letter for letter, with the same symbols, and every symbol's
// value is the engine's to 1e-12; where it says a symbol is 0, the changed file's derivation has
// no such symbol and the others' values are the engine's; where it says the form changes, the
// equations or the symbols differ.
test('every example: the equations\' values after a change are a fresh derivation\'s', () => {
  let kept = 0;
  let changed = 0;
  let refused = 0;
  let zeroedCount = 0;
  // Changes beside each example's first two numbers: a damper removed (its symbol 0: the terms
  // leave the equations, which hold with the 0), and three that change the form — gravity off
  // (its direction, a number no symbol stands for, is gone), gravity turned sideways, a bob
  // moved above its pivot (a length the other way along its axis).
  const formChanges = {
    quarter_car: [{ path: 'forces.suspension.damping', value: 0 }],
    pendulum: [{ path: 'gravity.2', value: 0 }, { path: 'gravity.0', value: 3 }],
    double_pendulum: [{ path: 'bodies.mass1.position.2', value: 1 }],
  };
  for (const name of examples()) {
    const modelPath = path.join(source, 'examples', `${name}.yaml`);
    const data = nativeReportData(modelPath);
    if (!data.equations?.available || !data.live?.available) continue;
    const text = readFileSync(modelPath, 'utf8');
    const derived = (file) => JSON.parse(execFileSync(cli, ['equations', file, '--all-symbols', '--json'],
      { stdio: 'pipe', maxBuffer: 1 << 28 }).toString());
    const base = derived(modelPath);
    const moves = data.live.parameters.slice(0, 2)
      .map((p) => ({ path: p.path, value: p.value === 0 ? p.max / 2 : p.value * 1.25 }));
    for (const { path: numberPath, value } of [...moves, ...(formChanges[name] ?? [])]) {
      const overrides = [{ path: numberPath, value }];
      const where = `${name}: ${numberPath} = ${value}`;
      let numbers;
      try {
        numbers = engine.equationNumbers(text, path.basename(modelPath), overrides,
          data.equations.parameters, data.equations.form);
      } catch (error) {
        // A change the model refuses (a principal moment past the triangle inequality): the
        // page says so and keeps what it showed — the live tests' concern, not this one's.
        assert.match(error.message, new RegExp(`^${path.basename(modelPath)}:\\d+:\\d+: `), where);
        refused++;
        continue;
      }
      const editedPath = path.join(scratch, path.basename(modelPath));
      writeFileSync(editedPath, engine.textWith(text, path.basename(modelPath), overrides));
      const fresh = derived(editedPath);
      const sameLatex = JSON.stringify(fresh.equations_latex) === JSON.stringify(base.equations_latex);
      const sameSymbols = JSON.stringify(Object.keys(fresh.parameters).sort())
        === JSON.stringify(Object.keys(base.parameters).sort());
      if (numbers.formChanges.length === 0) {
        // A symbol that is 0 now is none in the derivation of the changed file: its terms are
        // gone there, and every other symbol is the engine's value.
        const zeroed = new Set(numbers.zeroed);
        if (zeroed.size === 0) {
          kept++;
          assert.ok(sameLatex && sameSymbols, `${where}: the engine keeps the form, the command line does not`);
        } else {
          zeroedCount++;
          assert.ok(!sameLatex && numbers.zeroed.every((n) => !(n in fresh.parameters)), `${where}: ${numbers.zeroed} still in the derivation`);
        }
        data.equations.parameters.forEach((q, k) => {
          const expected = zeroed.has(q.name) ? 0 : fresh.parameters[q.name];
          assert.ok(Math.abs(numbers.values[k] - expected) <= 1e-12 * Math.abs(expected),
            `${where}: ${q.name} is ${numbers.values[k]} in the page, ${expected} derived`);
        });
      } else {
        changed++;
        assert.ok(!sameLatex || !sameSymbols, `${where}: the engine says the form changes (${numbers.formChanges}), the command line's equations are the file's`);
      }
    }
  }
  assert.ok(kept >= 60, `${kept} changes kept the form`);
  assert.ok(changed >= 3, `${changed} changes changed the form`);
  assert.ok(zeroedCount >= 1, `${zeroedCount} changes made a symbol 0`);
  console.log(`equation numbers: ${kept} changes kept the form, ${zeroedCount} made a symbol 0, ${changed} changed it, ${refused} refused`);
});
