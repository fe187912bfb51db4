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

// The panels of a simulation page, in the page's order. A live page redraws the run's own
// (kMotionPanels) from the engine's first data and the analysis' from its second.
const kPanels = ['summary', 'motion', 'loops', 'plots', 'equations', 'linear', 'campbell', 'diagrams'];
const kMotionPanels = ['summary', 'motion', 'loops', 'plots'];
const kAnalysisPanels = kPanels.filter((name) => !kMotionPanels.includes(name));

// The 3-D view with its clock: every animation frame advances the clock, and the view is drawn
// only when what it shows changed. `dispose` stops the clock and lets the view go (its renderer
// serves the live page's next one).
function motionPanel(data, place) {
  const time = decode(data.frames.time);
  const timeline = new Timeline(time[0], time[time.length - 1]);
  const view = element('div', { id: 'view', class: 'view' });
  const section = place(element('section', { id: 'motion' }, element('h2', {}, 'Motion'), view, timeline.controls()));
  const motion = new Motion(view, data, timeline);
  section.append(motion.controls());
  const panel = { section, motion, timeline, frames: 0, disposed: false };
  panel.draw = (now) => { if (motion.render(now)) panel.frames++; };
  const loop = (now) => {
    if (panel.disposed) return;
    timeline.tick(now);
    panel.draw(now);
    requestAnimationFrame(loop);
  };
  requestAnimationFrame(loop);
  panel.dispose = () => {
    panel.disposed = true;
    motion.viewer.release();
  };
  return panel;
}

// The equations. A live page's equations in symbols are the file's whatever the reader changes
// (the engine has no symbolic layer), so the head of their section — its title, note and
// equations, class `in-symbols` — stays in the page across a redraw instead of being laid out
// anew (a free body's 13 700 MathML nodes took 270 ms of each change): `old`'s section keeps its
// head and takes the new values and equations with the numbers below it.
function equationsPanel(data, place, old) {
  const kept = old?.section;
  if (!(data.equations?.available && kept?.symbolsOf === data.equations.equations)) {
    return { section: place(equationsSection(data.equations).section) };
  }
  const fresh = equationsSection(data.equations, { head: false }).section;
  for (const child of [...kept.children]) if (!child.classList.contains('in-symbols')) child.remove();
  kept.append(...fresh.children);
  return { section: place(kept) };
}

// Builds the panel `name` from the data and puts its section in the page (`place`): {section,
// what the page's hook reads}. `built` holds the panels before it (the clock and the 3-D view
// those after it follow); `old`, the panel it replaces.
function buildPanel(name, data, built, place, old) {
  const placed = (panel) => { place(panel.section); return panel; };
  switch (name) {
    case 'summary': return { section: place(summarySection(data)) };
    case 'motion': return motionPanel(data, place);
    case 'loops': return data.loops?.length ? { section: place(loopsSection(data.loops)) } : {};
    case 'plots': return placed(plotsSection(data, built.motion.timeline));
    case 'equations': return equationsPanel(data, place, old);
    case 'linear': return placed(linearSection(data, built.motion.motion));
    case 'campbell': return data.campbell ? placed(campbellSection(data.campbell)) : {};
    case 'diagrams': return placed(diagramsSection(data.diagrams, built.motion.timeline));
    default: throw new Error(`no panel '${name}'`);
  }
}

// A simulation page in `app`, or — given the page it replaces (`from`) — the same page with the
// panels `keep` names kept as they are and the others built again from `data` in their place.
function simulationPage(app, data, { from = null, keep = [] } = {}) {
  const panels = {};
  let last = null;
  // Puts a section after the one before it (a section already there stays: moving it would lay
  // it out again).
  const place = (section) => {
    if ((last ? last.nextElementSibling : app.firstElementChild) !== section) {
      if (last) last.after(section); else app.prepend(section);
    }
    last = section;
    return section;
  };
  for (const name of kPanels) {
    const old = from?.panels[name];
    if (keep.includes(name)) {
      panels[name] = old;
      if (old.section) last = old.section;
      continue;
    }
    // The old panel lets go first (its renderer is the new view's); its section leaves once the
    // new one is in place, unless the new one is it (the equations' kept head).
    old?.dispose?.();
    panels[name] = buildPanel(name, data, panels, place, old);
    if (old?.section !== panels[name].section) old?.section?.remove();
  }
  const { motion: { motion, timeline }, plots, linear, campbell, diagrams } = panels;
  const draw = (now) => panels.motion.draw(now);
  return {
    kind: 'simulation',
    data,
    panels,
    setTime: (t) => { motion.playMode(null); timeline.set(t); draw(performance.now()); },
    time: () => timeline.time,
    frameTimes: () => Array.from(motion.time),
    bodyNames: () => data.scene.bodies.map((b) => b.name),
    bodyPoint: (name, point, t) => motion.bodyPoint(data.scene.bodies.findIndex((b) => b.name === name), point, t ?? timeline.time),
    series: () => Object.keys(plots.registry),
    seriesValues: (name) => Array.from(plots.registry[name] || []),
    plottedValues: (name) => Array.from(plots.drawnRegistry[name] || []),
    plotTime: () => Array.from(plots.time),
    drawAllCharts: () => plots.charts.drawAll() + (linear.charts?.drawAll() ?? 0) + (campbell.charts?.drawAll() ?? 0),
    campbell: () => data.campbell,
    linear: () => data.linear,
    // What the equations panel shows: each set equation's text as the browser lays it out (in
    // symbols, and with the numbers), the symbols' table as it reads.
    equations: () => ({
      data: data.equations,
      shown: Array.from(document.querySelectorAll('#equations > .equation:not(.folded)')).map((e) => {
        const lines = Array.from(e.querySelectorAll('math'));
        return { text: lines.map((m) => m.textContent).join(' '), lines: lines.length,
          width: Math.max(...lines.map((m) => m.getBoundingClientRect().width)) };
      }),
      // Equations too long to set on opening: each summary's text and the lines set once opened.
      folded: Array.from(document.querySelectorAll('#equations > .equation.folded')).map((e) => ({
        summary: e.querySelector('summary').textContent, open: e.open,
        lines: e.querySelectorAll('.line').length, elements: e.getElementsByTagName('*').length })),
      elements: document.querySelector('#equations')?.getElementsByTagName('*').length ?? 0,
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
    framesDrawn: () => panels.motion.frames,
    // The canvas fraction the box of every body over the run covers, as the camera frames it.
    framing: () => motion.viewer.coverage(motion.viewer.framed.box),
    camera: () => ({ position: motion.viewer.camera.position.toArray(), target: motion.viewer.controls.target.toArray() }),
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

// Runs `work` when the page is idle (at once where the browser cannot say).
const whenIdle = (work) => (window.requestIdleCallback ? requestIdleCallback(work, { timeout: 3000 }) : setTimeout(work, 0));

// A simulation page with its engine (docs/report.md, "The live report"): the live panel on top,
// the run's panels below it, drawn again from the engine's data after each change. The hook the
// tests use is the current run's, with `live` besides.
function livePage(app, data) {
  const engine = loadEngine();
  const run = element('div', { id: 'run' });
  let current = null;
  // A redraw keeps the reader's place: the time shown (where the new run reaches it) and the
  // window's scroll (the new panels are as tall as the old). `keep`: the panels left as they are
  // (a first redraw's, marked stale until the next redraws them).
  const show = (pageData, { keep = [], stale = false } = {}) => {
    const time = current?.time();
    const scroll = window.scrollY;
    current = simulationPage(run, pageData, { from: current, keep });
    for (const name of kPanels) {
      const section = current.panels[name].section;
      if (!section) continue;
      const old = stale && keep.includes(name);
      section.classList.toggle('stale', old);
      section.inert = old;
      if (old) section.setAttribute('aria-busy', 'true'); else section.removeAttribute('aria-busy');
    }
    if (time !== undefined && time <= pageData.summary.t_end) current.setTime(time);
    window.scrollTo(0, scroll);
  };
  const { text, file } = data.live;
  // {path: value} as the engine takes overrides: [{path, value}].
  const listOf = (values) => Object.entries(values).map(([path, value]) => ({ path, value }));
  let lastMilliseconds = null;
  let firstMilliseconds = null;
  // What stands for an array in the engine's data: random, so that no name or text of the
  // model's file can be taken for one.
  const arrayMarker = `@array-${Array.from(crypto.getRandomValues(new Uint32Array(2)), (x) => x.toString(16)).join('')}-`;
  const nextFrame = () => new Promise((done) => requestAnimationFrame(() => setTimeout(done, 0)));
  // A change runs the model once and redraws in two steps: first the run's own panels — the
  // summary and its audit, the 3-D view, the loops, the plots — (the engine's "motion" data),
  // then, once the browser has shown them, the analysis — the equations' values, the linear
  // analysis, the Campbell and free-body diagrams — (its "analysis" data, from the same run).
  const rerun = async (overrides) => {
    const started = performance.now();
    const list = listOf(overrides);
    const ready = await engine;
    const panelData = (panels) => {
      const parts = ready.reportDataParts(text, file, list, arrayMarker, panels);
      return dataWithArrays(parts.json, parts.arrays, arrayMarker);
    };
    const motion = panelData('motion');
    show({ ...current.data, ...motion }, { keep: kAnalysisPanels, stale: true });
    await nextFrame();
    firstMilliseconds = performance.now() - started;
    const next = { ...motion, ...panelData('analysis') };
    // The native page's equations (the engine has no symbolic layer), told which numbers the
    // page has changed and, where the engine finds that they keep their form, their symbols'
    // values in the changed model (report::equation_numbers).
    next.equations = data.equations && { ...data.equations, changed: list.map(({ path, value }) => {
      const unit = data.live.parameters.find((p) => p.path === path)?.unit;
      return `${path} = ${value}${unit ? ` ${unit}` : ''}`;
    }) };
    if (data.equations?.available) {
      try {
        next.equations.numbers = ready.equationNumbers(text, file, list,
          data.equations.parameters, data.equations.form);
      } catch (error) {
        // The run stands; the equations keep the file's values and say why.
        next.equations.numbers = { values: [], zeroed: [], formChanges: [`the page could not give the symbols values: ${error.message}`] };
      }
    }
    next.live = data.live;
    show(next, { keep: kMotionPanels });
    lastMilliseconds = performance.now() - started;
    const s = next.summary;
    return `${list.length ? `${list.length} number${list.length > 1 ? 's' : ''} changed` : 'the file as written'}: `
      + `re-simulated ${s.t_end} s with ${s.integrator}; the run's panels redrawn in ${Math.round(firstMilliseconds)} ms, `
      + `the analysis in ${Math.round(lastMilliseconds)} ms, in this page.`;
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
  // The browser compiles WebAssembly a function at its first call: the engine's first report
  // data took 300 of the quarter car's first change's 500 ms. A page opened without changes
  // makes the file's own once it is idle, so that the reader's first change runs compiled code
  // (its result is the page's already; the engine keeps it, as it keeps the file read).
  if (!Object.keys(fromHash).length && data.live.available) {
    engine.then((module) => whenIdle(() => {
      try {
        module.reportDataParts(text, file, [], arrayMarker, 'all');
        if (data.equations?.available) module.equationNumbers(text, file, [], data.equations.parameters, data.equations.form);
      } catch {
        // The reader's change says what is wrong.
      }
    }));
  }
  const liveHook = {
    parameters: () => data.live.parameters ?? [],
    overrides: () => live.overrides(),
    set: (values) => live.set(values),
    status: () => live.status(),
    lastMilliseconds: () => lastMilliseconds,
    // From the change to the frame after the run's own panels were redrawn (the analysis after).
    firstMilliseconds: () => firstMilliseconds,
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
