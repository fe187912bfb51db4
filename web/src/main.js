// momenta's HTML report: reads the data the library embedded in the page and builds the panels.
// A small test hook (window.momentaReport) lets the browser tests read back what the page shows.

import 'uplot/dist/uPlot.min.css';
import './style.css';
import { dataWithArrays, decode, element, readData } from './data.js';
import { campbellSection } from './campbell.js';
import { diagramsSection } from './diagrams.js';
import { equationsSection } from './equations.js';
import { greyBoxPage } from './grey_box.js';
import { identificationPage } from './identification.js';
import { inertiaPage } from './inertia.js';
import { linearSection } from './linear.js';
import { liveSection, loadEngine, overridesFromHash } from './live.js';
import { loopsSection } from './loops.js';
import { Motion } from './motion.js';
import { plotsSection } from './plots.js';
import { summarySection } from './summary.js';
import { sweepPage } from './sweep.js';
import { Timeline } from './timeline.js';

// `keptEquations`: the live page keeps the equations' head it shows; the page builds the rest.
function simulationPage(app, data, { keptEquations = false } = {}) {
  app.append(summarySection(data));
  const time = decode(data.frames.time);
  const timeline = new Timeline(time[0], time[time.length - 1]);
  const view = element('div', { id: 'view', class: 'view' });
  app.append(element('section', { id: 'motion' }, element('h2', {}, 'Motion'), view, timeline.controls()));
  const motion = new Motion(view, data, timeline);
  app.querySelector('#motion').append(motion.controls());
  if (data.loops?.length) app.append(loopsSection(data.loops));
  const plots = plotsSection(data, timeline);
  app.append(plots.section);
  app.append(equationsSection(data.equations, { head: !keptEquations }).section);
  const linear = linearSection(data, motion);
  app.append(linear.section);
  const campbell = data.campbell ? campbellSection(data.campbell) : null;
  if (campbell) app.append(campbell.section);
  const diagrams = diagramsSection(data.diagrams, timeline);
  app.append(diagrams.section);
  // Every animation frame advances the clock; the view is drawn only when what it shows changed.
  let frames = 0;
  let disposed = false;
  const draw = (now) => { if (motion.render(now)) frames++; };
  const loop = (now) => {
    if (disposed) return;
    timeline.tick(now);
    draw(now);
    requestAnimationFrame(loop);
  };
  requestAnimationFrame(loop);
  return {
    kind: 'simulation',
    // Stops the clock and lets the view go (its renderer serves the live page's next one).
    dispose: () => {
      disposed = true;
      motion.viewer.release();
    },
    setTime: (t) => { motion.playMode(null); timeline.set(t); draw(performance.now()); },
    time: () => timeline.time,
    frameTimes: () => Array.from(motion.time),
    bodyNames: () => data.scene.bodies.map((b) => b.name),
    bodyPoint: (name, point, t) => motion.bodyPoint(data.scene.bodies.findIndex((b) => b.name === name), point, t ?? timeline.time),
    series: () => Object.keys(plots.registry),
    seriesValues: (name) => Array.from(plots.registry[name] || []),
    plottedValues: (name) => Array.from(plots.drawnRegistry[name] || []),
    plotTime: () => Array.from(plots.time),
    drawAllCharts: () => plots.charts.drawAll() + (linear.charts?.drawAll() ?? 0) + (campbell?.charts?.drawAll() ?? 0),
    campbell: () => data.campbell,
    linear: () => data.linear,
    // What the equations panel shows: each set equation's text as the browser lays it out (in
    // symbols, and with the numbers), the symbols' table as it reads.
    equations: () => ({
      data: data.equations,
      shown: Array.from(document.querySelectorAll('#equations > .equation')).map((e) => {
        const lines = Array.from(e.querySelectorAll('math'));
        return { text: lines.map((m) => m.textContent).join(' '), lines: lines.length,
          width: Math.max(...lines.map((m) => m.getBoundingClientRect().width)) };
      }),
      withNumbers: Array.from(document.querySelectorAll('#equations .with-numbers .equation'))
        .map((e) => Array.from(e.querySelectorAll('math')).map((m) => m.textContent).join(' ')),
      symbols: Array.from(document.querySelectorAll('#equations table.symbols tbody tr')).map((r) => ({
        cells: Array.from(r.cells).map((c) => c.textContent), changed: r.classList.contains('changed') })),
      notes: Array.from(document.querySelectorAll('#equations .note')).map((n) => n.textContent),
      errors: document.querySelectorAll('#equations .katex-error, #equations merror').length,
      panelWidth: document.querySelector('#equations')?.getBoundingClientRect().width ?? 0,
    }),
    play: (on) => { timeline.playing = on; },
    playMode: (i) => motion.playMode(data.linear.modes[i]),
    framesDrawn: () => frames,
    // The canvas fraction the box of every body over the run covers, as the camera frames it.
    framing: () => motion.viewer.coverage(motion.viewer.framed.box),
    gridHeight: () => motion.viewer.grid.position.dot(motion.viewer.up),
    sweptLowest: () => Math.min(...motion.sweptPoints.map((p) => p[0] * motion.viewer.up.x + p[1] * motion.viewer.up.y + p[2] * motion.viewer.up.z)),
    showReactions: (on) => motion.setToggle('reactions', on),
    reactionArrows: () => motion.reactionArrowsDrawn(),
    planes: () => motion.planesDrawn(),
    summary: () => data.summary,
    diagrams: () => data.diagrams && { times: data.diagrams.times, bodies: data.diagrams.bodies.map((b) => b.name) },
    showDiagram: (body, k) => diagrams.select(body, k),
    // The feedback loops drawn: per controller, the words its diagram shows and its size on screen.
    loops: () => Array.from(document.querySelectorAll('#loops .loop')).map((d) => {
      const svg = d.querySelector('svg');
      const box = svg.getBoundingClientRect();
      return { name: d.dataset.controller, texts: Array.from(svg.querySelectorAll('text')).map((t) => t.textContent),
        blocks: svg.querySelectorAll('rect.block').length, junctions: svg.querySelectorAll('circle.junction').length,
        width: box.width, height: box.height };
    }),
    // Each plot's title as drawn (after drawAllCharts), with its data's series and unit, and
    // whether the reader sees it (its box in the chooser ticked).
    plotGroups: () => data.plots.groups.map((g, i) => {
      const holder = document.querySelectorAll('#plots .plot')[i];
      return { title: holder?.querySelector('.u-title')?.textContent, unit: g.unit, series: g.series.map((s) => s.name),
        shown: Boolean(holder) && !holder.hidden && getComputedStyle(holder).display !== 'none' };
    }),
  };
}

// The live page's equations in symbols are the file's whatever the reader changes (the engine
// has no symbolic layer), so their section's head — its title, note and equations — stays in the
// page across a redraw instead of being laid out anew (a free body's 13 700 MathML nodes took
// 270 ms of each change). The section `run` shows, when it holds these equations.
function keptEquations(run, equations) {
  const section = [...run.children].find((c) => c.id === 'equations');
  return equations?.available && section?.symbolsOf === equations.equations ? section : null;
}

// Puts the new page's sections that come before its equations in front of `kept`, gives `kept`
// in place of what follows its head what `fresh` (the new equations section, built without a
// head) holds — the values, the equations with the numbers — and lets `fresh` go. Nothing of
// `kept`'s head leaves the page.
function adoptEquations(kept, fresh) {
  const before = [];
  for (let e = kept.nextElementSibling; e && e !== fresh; e = e.nextElementSibling) before.push(e);
  kept.before(...before);
  for (const child of [...kept.children]) if (!child.classList.contains('in-symbols')) child.remove();
  kept.append(...fresh.children);
  fresh.remove();
}

// A simulation page with its engine (docs/report.md, "The live report"): the live panel on top,
// the run's panels below it, drawn again from the engine's data after each change. The hook the
// tests use is the current run's, with `live` besides.
function livePage(app, data) {
  const engine = loadEngine();
  const run = element('div', { id: 'run' });
  let current = null;
  // A redraw keeps the reader's place: the time shown (where the new run reaches it) and the
  // window's scroll (the new panels are as tall as the old).
  const show = (pageData) => {
    const time = current?.time();
    const scroll = window.scrollY;
    current?.dispose();
    const kept = keptEquations(run, pageData.equations);
    for (const child of [...run.children]) if (child !== kept) child.remove();
    current = simulationPage(run, pageData, { keptEquations: Boolean(kept) });
    if (kept) adoptEquations(kept, [...run.children].find((c) => c.id === 'equations' && c !== kept));
    if (time !== undefined && time <= pageData.summary.t_end) current.setTime(time);
    window.scrollTo(0, scroll);
  };
  const { text, file } = data.live;
  // {path: value} as the engine takes overrides: [{path, value}].
  const listOf = (values) => Object.entries(values).map(([path, value]) => ({ path, value }));
  let lastMilliseconds = null;
  // What stands for an array in the engine's data: random, so that no name or text of the
  // model's file can be taken for one.
  const arrayMarker = `@array-${Array.from(crypto.getRandomValues(new Uint32Array(2)), (x) => x.toString(16)).join('')}-`;
  const rerun = async (overrides) => {
    const started = performance.now();
    const list = listOf(overrides);
    const parts = (await engine).reportDataParts(text, file, list, arrayMarker);
    const next = dataWithArrays(parts.json, parts.arrays, arrayMarker);
    // The native page's equations (the engine has no symbolic layer), told which numbers the
    // page has changed and, where the engine finds that they keep their form, their symbols'
    // values in the changed model (report::equation_numbers).
    next.equations = data.equations && { ...data.equations, changed: list.map(({ path, value }) => {
      const unit = data.live.parameters.find((p) => p.path === path)?.unit;
      return `${path} = ${value}${unit ? ` ${unit}` : ''}`;
    }) };
    if (data.equations?.available) {
      try {
        next.equations.numbers = (await engine).equationNumbers(text, file, list,
          data.equations.parameters, data.equations.form);
      } catch (error) {
        // The run stands; the equations keep the file's values and say why.
        next.equations.numbers = { values: [], zeroed: [], formChanges: [`the page could not give the symbols values: ${error.message}`] };
      }
    }
    next.live = data.live;
    show(next);
    lastMilliseconds = performance.now() - started;
    const s = next.summary;
    return `${list.length ? `${list.length} number${list.length > 1 ? 's' : ''} changed` : 'the file as written'}: `
      + `re-simulated ${s.t_end} s with ${s.integrator} in ${Math.round(lastMilliseconds)} ms in this page.`;
  };
  const download = async (overrides) => {
    const list = listOf(overrides);
    const changed = (await engine).textWith(text, file, list);
    const link = element('a', { href: URL.createObjectURL(new Blob([changed], { type: 'text/yaml' })), download: file });
    link.click();
    URL.revokeObjectURL(link.href);
  };
  const live = liveSection(data.live, rerun, download);
  app.append(live.section, run);
  show(data);
  const fromHash = data.live.available ? overridesFromHash(location.hash, data.live.parameters) : {};
  const ready = Object.keys(fromHash).length ? live.set(fromHash) : engine;
  const liveHook = {
    parameters: () => data.live.parameters ?? [],
    overrides: () => live.overrides(),
    set: (values) => live.set(values),
    status: () => live.status(),
    lastMilliseconds: () => lastMilliseconds,
    ready: () => ready.then(() => true),
    textWith: async (values) => (await engine).textWith(text, file, listOf(values)),
    // The engine's run alone, without the report's data or the redraw (the benchmark's figure).
    simulateMilliseconds: async (values) => {
      const ready = await engine;
      const started = performance.now();
      ready.simulate(text, file, listOf(values));
      return performance.now() - started;
    },
  };
  // What start() sets (ready, loadMilliseconds) is the page's own; everything else the current
  // run's hook.
  const hook = new Proxy({}, {
    get: (own, key) => (key === 'live' ? liveHook : key in own ? own[key] : current[key]),
    set: (own, key, value) => { own[key] = value; return true; },
  });
  return hook;
}

function start() {
  const app = document.getElementById('app');
  const started = performance.now();
  const data = readData();
  const pages = { inertia: inertiaPage, sweep: sweepPage, identification: identificationPage, 'grey-box': greyBoxPage };
  const live = data.kind === 'simulation' && data.live && typeof window.createMomentaEngine === 'function'
    && document.getElementById('momenta-engine') !== null;
  const hook = live ? livePage(app, data) : (pages[data.kind] ?? simulationPage)(app, data);
  hook.loadMilliseconds = performance.now() - started;
  hook.ready = true;
  window.momentaReport = hook;
}

start();
