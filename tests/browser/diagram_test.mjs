// Free-body diagrams seen as a person sees them: `momenta diagram -o FILE.svg` opened in headless
// Chromium, and the report's diagram section. What the browser lays out is read back — each
// arrow's and label's box on the page — and screenshots are kept.
//
//   MOMENTA_CLI=… MOMENTA_SOURCE_DIR=… MOMENTA_ARTIFACTS=… node --test diagram_test.mjs
//
// Checks: every load of `momenta diagram --json` with a force is an arrow (a couple a curved or
// double arrow) of its kind, whose magnitude attribute equals the JSON's to 1e-12; every arrow
// and label lies within the picture; no two labels of a panel overlap; each label names its
// load and shows its magnitude; the residual lines are there and are round-off; the report's
// section shows each body's picture and follows its time selector.

import fs from 'node:fs';
import path from 'node:path';
import assert from 'node:assert/strict';
import { test, after, before } from 'node:test';
import { examples, launchBrowser, openReport, run } from './pages.mjs';

const artifacts = process.env.MOMENTA_ARTIFACTS;
const work = fs.mkdtempSync(path.join(process.env.TMPDIR || '/tmp', 'momenta-diagram-'));
fs.mkdirSync(artifacts, { recursive: true });

let browser;
before(async () => { browser = await launchBrowser(); });
after(async () => { await browser?.close(); fs.rmSync(work, { recursive: true, force: true }); });

// What the browser laid out: the picture's size, and each arrow's box, kind, name, value and label.
async function layout(page) {
  return page.evaluate(() => {
    const svg = document.querySelector('svg');
    const box = (e) => { const b = e.getBBox(); return { x: b.x, y: b.y, w: b.width, h: b.height }; };
    const arrows = [...svg.querySelectorAll('g.force, g.couple')].map((g) => ({
      type: g.getAttribute('class'),
      kind: g.dataset.kind,
      name: g.dataset.name,
      value: Number(g.dataset.value),
      box: box(g),
      label: g.querySelector('text').textContent,
      labelBox: box(g.querySelector('text')),
      // Which panel: the left (free-body) or the right (kinetic) half.
      panel: box(g).x + box(g).w / 2 < svg.viewBox.baseVal.width / 2 ? 'free-body' : 'kinetic',
    }));
    const residuals = [...svg.querySelectorAll('text.residual')].map((t) => t.textContent);
    return { width: svg.viewBox.baseVal.width, height: svg.viewBox.baseVal.height, arrows, residuals };
  });
}

function within(box, width, height) {
  return box.x >= -0.5 && box.y >= -0.5 && box.x + box.w <= width + 0.5 && box.y + box.h <= height + 0.5;
}

function overlap(a, b) {
  const dx = Math.min(a.x + a.w, b.x + b.w) - Math.max(a.x, b.x);
  const dy = Math.min(a.y + a.h, b.y + b.h) - Math.max(a.y, b.y);
  return dx > 1 && dy > 1;  // more than a pixel each way
}

const cases = [
  { name: 'pendulum', model: 'pendulum.yaml', body: 'bob', time: '0.5', planar: true },
  { name: 'heavy-top', model: 'heavy_top.yaml', body: 'top', time: '0.3', planar: false },
  { name: 'bent-rod', model: 'rotating_shaft_bent_rod.yaml', body: 'rod', time: '0.1', planar: true },
  { name: 'bent-rod-shaft', model: 'rotating_shaft_bent_rod.yaml', body: 'shaft', time: '0.1', planar: true },
  { name: 'quarter-car-body', model: 'quarter_car.yaml', body: 'body', time: '0.37', planar: true },
  { name: 'four-bar-coupler', model: 'constraints/four_bar.yaml', body: 'coupler', time: '0.2', planar: true },
];

for (const c of cases) {
  test(`the ${c.name} diagram shows every load within the picture`, async () => {
    const file = path.join(work, `${c.name}.svg`);
    const result = JSON.parse(run('diagram', path.join(examples, c.model), '--body', c.body, '--time', c.time,
      '-o', file, '--json'));
    assert.equal(result.plane_normal !== null, c.planar, 'planar or not');
    const page = await browser.newPage();
    await page.setViewport({ width: 1100, height: 900 });
    await page.goto(`file://${file}`, { waitUntil: 'load' });
    const shown = await layout(page);
    await page.screenshot({ path: path.join(artifacts, `diagram-${c.name}.png`), fullPage: true });
    await page.close();

    const norm = (v) => Math.hypot(...v);
    const forces = result.loads.map((l) => norm(l.force));
    const couples = result.loads.map((l) => norm(l.couple));
    const largestForce = Math.max(...forces, norm(result.kinetic.m_a_G));
    const largestCouple = Math.max(...couples, norm(result.kinetic.I_alpha), norm(result.kinetic.omega_cross_H));
    // Every load with a force (a couple) beyond round-off is drawn once as such, with its value.
    for (const [k, load] of result.loads.entries()) {
      for (const [type, size, largest] of [['force', forces[k], largestForce], ['couple', couples[k], largestCouple]]) {
        if (size <= 1e-9 * largest) continue;
        const drawn = shown.arrows.filter((a) => a.panel === 'free-body' && a.type === type && a.name === load.name &&
          Math.abs(a.value - size) <= 1e-12 * size);
        assert.equal(drawn.length, 1, `${type} of ${load.name} (${size}) drawn once`);
        assert.equal(drawn[0].kind, load.kind);
        const digits = Number(drawn[0].label.match(/([-\d.e+]+) N/)[1]);
        assert.ok(Math.abs(digits - size) <= 5e-4 * size, `label ${drawn[0].label} shows ${size}`);
      }
    }
    // The kinetic side: m a_G when there is one.
    if (norm(result.kinetic.m_a_G) > 1e-9 * largestForce) {
      assert.equal(shown.arrows.filter((a) => a.panel === 'kinetic' && a.name === 'm a_G').length, 1);
    }
    // Inside the picture, labels apart.
    for (const a of shown.arrows) {
      assert.ok(within(a.box, shown.width, shown.height), `${a.name} inside: ${JSON.stringify(a.box)}`);
      assert.ok(within(a.labelBox, shown.width, shown.height), `label ${a.label} inside`);
      assert.ok(a.label.startsWith(a.kind === 'gravity' ? 'W' : a.name.split(' ')[0].replace('omega', 'ω').replace('I_G', 'Ī')),
        `label ${a.label} names ${a.name}`);
    }
    for (const panel of ['free-body', 'kinetic']) {
      const labels = shown.arrows.filter((a) => a.panel === panel);
      for (let i = 0; i < labels.length; ++i) {
        for (let j = i + 1; j < labels.length; ++j) {
          assert.ok(!overlap(labels[i].labelBox, labels[j].labelBox), `labels ${labels[i].label} and ${labels[j].label} overlap`);
        }
      }
    }
    // The table of loads: no two cells of a row overlap, each inside the picture.
    const cells = await (async () => {
      const again = await browser.newPage();
      await again.goto(`file://${file}`, { waitUntil: 'load' });
      const boxes = await again.evaluate(() => [...document.querySelectorAll('text.table')].map((t) => {
        const b = t.getBBox();
        return { x: b.x, y: b.y, w: b.width, h: b.height, text: t.textContent };
      }));
      await again.close();
      return boxes;
    })();
    assert.ok(cells.length >= 4 * (result.loads.length + 1), `${cells.length} table cells`);
    // A body whose file gives its shape is outlined by that shape's silhouette: the heavy top's
    // cone at 0.3 s, its base circle seen obliquely, is a hull of many points (the box with its
    // inertia has at most 11: G, the two loads' points and its 8 corners).
    if (c.name === 'heavy-top') {
      const outline = fs.readFileSync(file, 'utf8').match(/<path class="body" d="([^"]*)"/)[1];
      const corners = outline.split(/[MLZ]/).filter((s) => s.trim()).length;
      assert.ok(corners > 12, `the top's outline has ${corners} corners: ${outline}`);
    }
    for (let i = 0; i < cells.length; ++i) {
      assert.ok(within(cells[i], shown.width, shown.height), `cell ${cells[i].text} inside`);
      for (let j = i + 1; j < cells.length; ++j) {
        assert.ok(!overlap(cells[i], cells[j]), `cells ${cells[i].text} and ${cells[j].text} overlap`);
      }
    }
    // The balance: two residual lines, round-off against the largest load.
    assert.equal(shown.residuals.length, 2);
    assert.ok(norm(result.residual.force) <= 1e-12 * largestForce, `ΣF − m a_G = ${result.residual.force}`);
    assert.ok(norm(result.residual.moment) <= 1e-12 * Math.max(largestCouple, largestForce), `ΣM_G − Ḣ_G = ${result.residual.moment}`);
  });
}

// The impulse–momentum diagram (`momenta diagram … --between … --restitution …`): three panels,
// momenta before + impulses = momenta after, each arrow in its panel with its value, inside the
// picture, labels apart; the residual lines round-off.
const impacts = [
  { name: 'eccentric-impact-rod', model: 'eccentric_impact.yaml', body: 'rod',
    blow: ['--between', 'sphere', 'rod:0,0,-1.1', '--normal', '1,0,0', '--restitution', '0.6'] },
  { name: 'eccentric-impact-sphere', model: 'eccentric_impact.yaml', body: 'sphere',
    blow: ['--between', 'sphere', 'rod:0,0,-1.1', '--normal', '1,0,0', '--restitution', '0.6'] },
  { name: 'struck-rod-tip', model: 'struck_rod.yaml', body: 'rod',
    blow: ['--at', 'rod:0,0,-1.2', '--impulse', '4,0,0'] },
];

for (const c of impacts) {
  test(`the ${c.name} impulse–momentum diagram shows momenta and impulses in their panels`, async () => {
    const file = path.join(work, `${c.name}.svg`);
    const result = JSON.parse(run('diagram', path.join(examples, c.model), '--body', c.body, ...c.blow,
      '-o', file, '--json'));
    const page = await browser.newPage();
    await page.setViewport({ width: 1600, height: 900 });
    await page.goto(`file://${file}`, { waitUntil: 'load' });
    const shown = await page.evaluate(() => {
      const svg = document.querySelector('svg');
      const box = (e) => { const b = e.getBBox(); return { x: b.x, y: b.y, w: b.width, h: b.height }; };
      const arrows = [...svg.querySelectorAll('g.force, g.couple')].map((g) => ({
        type: g.getAttribute('class'), kind: g.dataset.kind, name: g.dataset.name,
        value: Number(g.dataset.value), panel: g.closest('g.panel').dataset.panel,
        box: box(g), label: g.querySelector('text').textContent, labelBox: box(g.querySelector('text')),
      }));
      const headings = [...svg.querySelectorAll('text')].map((t) => t.textContent);
      const residuals = [...svg.querySelectorAll('text.residual')].map((t) => t.textContent);
      return { width: svg.viewBox.baseVal.width, height: svg.viewBox.baseVal.height, arrows, headings, residuals };
    });
    await page.screenshot({ path: path.join(artifacts, `impulse-${c.name}.png`), fullPage: true });
    await page.close();

    const norm = (v) => Math.hypot(...v);
    for (const heading of ['momenta just before', 'impulses on the body', 'momenta just after', '+', '=']) {
      assert.ok(shown.headings.includes(heading), `heading ${heading}`);
    }
    const largest = Math.max(norm(result.before.linear), norm(result.after.linear),
      ...result.impulses.map((p) => norm(p.impulse)));
    // Each side's momentum where it moves, drawn in its panel with its value (N·s).
    for (const [side, index] of [['before', '₁'], ['after', '₂']]) {
      const size = norm(result[side].linear);
      const drawn = shown.arrows.filter((a) => a.panel === side && a.type === 'force');
      if (size <= 1e-9 * largest) {
        assert.equal(drawn.length, 0, `no momentum ${side}`);
        continue;
      }
      assert.equal(drawn.length, 1, `m v̄ ${side}`);
      assert.ok(Math.abs(drawn[0].value - size) <= 1e-12 * size);
      assert.ok(drawn[0].label.startsWith(`m v̄${index} `), drawn[0].label);
    }
    // Every impulse beyond round-off, in the middle panel with its value and kind.
    for (const p of result.impulses) {
      const size = norm(p.impulse);
      const drawn = shown.arrows.filter((a) => a.panel === 'impulses' && a.type === 'force' && a.name === p.name);
      if (size <= 1e-9 * largest) {
        assert.equal(drawn.length, 0, `${p.name} (round-off) not drawn`);
        continue;
      }
      assert.equal(drawn.length, 1, `${p.name} drawn once`);
      assert.equal(drawn[0].kind, p.kind);
      assert.ok(Math.abs(drawn[0].value - size) <= 1e-12 * size);
      const digits = Number(drawn[0].label.match(/([-\d.e+]+) N·s/)[1]);
      assert.ok(Math.abs(digits - size) <= 5e-4 * size, `label ${drawn[0].label} shows ${size}`);
    }
    for (const a of shown.arrows) {
      assert.ok(within(a.box, shown.width, shown.height), `${a.name} inside: ${JSON.stringify(a.box)}`);
      assert.ok(within(a.labelBox, shown.width, shown.height), `label ${a.label} inside`);
    }
    for (const panel of ['before', 'impulses', 'after']) {
      const labels = shown.arrows.filter((a) => a.panel === panel);
      for (let i = 0; i < labels.length; ++i) {
        for (let j = i + 1; j < labels.length; ++j) {
          assert.ok(!overlap(labels[i].labelBox, labels[j].labelBox), `labels ${labels[i].label} and ${labels[j].label} overlap`);
        }
      }
    }
    assert.equal(shown.residuals.length, 2);
    assert.ok(norm(result.residual.linear) <= 1e-12 * largest, `linear residual ${result.residual.linear}`);
    assert.ok(norm(result.residual.angular) <= 1e-12 * 2 * largest, `angular residual ${result.residual.angular}`);
  });
}

test('the report shows each body\'s diagrams and follows its time selector', async () => {
  const file = path.join(work, 'bent-rod.html');
  run('report', path.join(examples, 'rotating_shaft_bent_rod.yaml'), '-o', file, '-q');
  const { page, problems } = await openReport(browser, file);
  const diagrams = await page.evaluate(() => window.momentaReport.diagrams());
  assert.deepEqual(diagrams.bodies, ['shaft', 'rod']);
  assert.equal(diagrams.times.length, 5);
  assert.equal(diagrams.times[0], 0);
  assert.equal(diagrams.times[4], 1);
  for (const [body, k] of [['rod', 0], ['rod', 4], ['shaft', 2]]) {
    await page.evaluate((b, i) => window.momentaReport.showDiagram(b, i), body, k);
    const title = await page.$eval('#diagram-picture svg text', (t) => t.textContent);
    assert.ok(title.includes(`body ${body} at t = `), title);
    const couples = await page.$$eval('#diagram-picture svg g.couple', (gs) => gs.map((g) => g.dataset.name));
    // The weld's couple (m L²/12) ω² sin β cos β on the rod; on the shaft too, with the bearing's.
    assert.ok(couples.includes('weld'), couples.join(','));
  }
  const section = await page.$('#diagrams');
  await section.screenshot({ path: path.join(artifacts, 'report-diagrams.png') });
  assert.deepEqual(problems, []);
  await page.close();
});
