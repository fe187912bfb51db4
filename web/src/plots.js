// Every recorded column, one uPlot chart per group (units on the axis, zoom by dragging,
// double-click to reset, hover read-out in the legend), their cursors linked with each other and
// with the 3-D view's time: clicking a plot moves the time there; playing moves a marker.
// A chart is drawn when it comes near the window (a software-rendered browser pays for every
// line of every canvas), and a group of many columns starts with its first few shown: the
// others are a click on their legend entry away. The reader chooses the plots shown (a box per
// group above them); a group the report marks hidden (a ball joint's quaternion components, its
// Euler angles plotted instead) starts unticked.

import uPlot from 'uplot';
import { decode, element, shownValue } from './data.js';

const SHOWN_AT_FIRST = 8;

const COLORS = ['#4e79a7', '#f28e2b', '#59a14f', '#e15759', '#76b7b2', '#edc948', '#b07aa1',
  '#ff9da7', '#9c755f', '#bab0ac'];

// The time marker: a line over the plot moved by CSS, so playing does not redraw the series.
function timeMarker(timeline) {
  return {
    hooks: {
      init: (u) => {
        const marker = document.createElement('div');
        marker.className = 'time-marker';
        u.over.append(marker);
        const place = () => { marker.style.left = `${u.valToPos(timeline.time, 'x')}px`; };
        timeline.onChange(place);
        u.placeMarker = place;
      },
      ready: (u) => u.placeMarker(),
      setSize: (u) => u.placeMarker(),
      setScale: (u) => u.placeMarker && u.placeMarker(),
    },
  };
}

// What a stop or contact did at an instant, in words (a tick's tooltip).
function stopText(s) {
  const held = s.contact ? 'body' : 'joint';
  const what = {
    impact: 'impact', rest: `holds the ${held}`, release: `lets the ${held} go`, stick: 'sticks', slip: 'slips',
  }[s.kind] ?? s.kind;
  const head = `${s.contact ? `contact ${s.contact}` : `${s.joint} ${s.stop} stop`}: ${what}`
    + `${s.kind === 'rest' && s.friction ? `, ${s.friction}` : ''} at t = ${s.time.toPrecision(6)} s`;
  if (s.kind === 'release') return head;
  if (s.kind === 'stick' && s.in_impact) {
    return `${head}, in the impact: its slip of ${s.rate_before.toPrecision(4)} m/s would have turned to run with its friction`;
  }
  if (s.kind === 'slip' && s.in_impact) {
    return `${head}, in the impact: a friction impulse of ${s.friction_needed.toPrecision(4)} N·s needed, beyond μs P_n = ${s.friction_limit.toPrecision(4)} N·s`;
  }
  if (s.kind === 'slip' && s.friction_needed <= s.friction_limit * (1 + 1e-9)) {
    return `${head}, its friction reached μs N = ${s.friction_limit.toPrecision(4)} N`;
  }
  if (s.kind === 'stick' || s.kind === 'slip') {
    return `${head}, friction ${s.friction_needed.toPrecision(4)} N ${s.kind === 'stick' ? 'within' : 'beyond'} μs N = ${s.friction_limit.toPrecision(4)} N`;
  }
  return `${head}, ${s.contact ? 'normal speed' : 'rate'} ${s.rate_before.toPrecision(4)} → ${s.rate_after.toPrecision(4)} ${s.rate_unit}, impulse ${s.impulse.toPrecision(4)} ${s.impulse_unit}, ${s.energy_lost.toPrecision(3)} J lost`;
}

// What happened at an instant — a stop's impact, rest or release, a contact's stick or slip, an
// event — as a short tick on the time axis of every time plot, its text the tooltip; placed by
// CSS like the time marker.
export function timeMarks(summary) {
  const stops = (summary.stops ?? []).map((s) => ({ time: s.time, kind: s.kind, text: stopText(s) }));
  const events = (summary.events ?? []).map((e) => ({
    time: e.time, kind: 'event', text: `event ${e.name} (${e.condition}) at t = ${e.time.toPrecision(6)} s: ${e.action}`,
  }));
  return [...stops, ...events].sort((a, b) => a.time - b.time);
}

function markTicks(marks) {
  return {
    hooks: {
      init: (u) => {
        u.marks = marks.map((m) => {
          const tick = document.createElement('div');
          tick.className = `time-mark ${m.kind}`;
          tick.title = m.text;
          tick.dataset.time = m.time;
          u.over.append(tick);
          return tick;
        });
      },
      ready: (u) => placeTicks(u, marks),
      setSize: (u) => placeTicks(u, marks),
      setScale: (u, key) => { if (key === 'x' && u.marks) placeTicks(u, marks); },
    },
  };
}

function placeTicks(u, marks) {
  const { min, max } = u.scales.x;
  marks.forEach((m, i) => {
    const tick = u.marks[i];
    tick.style.display = m.time >= min && m.time <= max ? '' : 'none';
    tick.style.left = `${u.valToPos(m.time, 'x')}px`;
  });
}

// A logarithmic axis ticked and labelled at its decades only (0.01, 0.1, 1, …, and 10⁻¹² beyond
// 10⁻³ or from 10⁵): uPlot's own labels round values below 10⁻³ to 0.
const isDecade = (v) => v > 0 && Math.abs(Math.log10(v) - Math.round(Math.log10(v))) < 1e-9;
const SUPERSCRIPT = { '-': '⁻', 0: '⁰', 1: '¹', 2: '²', 3: '³', 4: '⁴', 5: '⁵', 6: '⁶', 7: '⁷', 8: '⁸', 9: '⁹' };
const decadeLabel = (v) => (v >= 1e-3 && v < 1e5 ? uPlot.fmtNum(v)
  : `10${String(Math.round(Math.log10(v))).replace(/./g, (c) => SUPERSCRIPT[c])}`);
const decades = (u, splits) => splits.map((v) => (v !== null && isDecade(v) ? v : null));
const logAxis = {
  filter: decades,
  grid: { filter: decades },
  ticks: { filter: decades },
  values: (u, splits) => splits.map((v) => (v !== null && isDecade(v) ? decadeLabel(v) : '')),
};

// A linear axis's labels: uPlot's own where they are readable, powers of ten where the values
// are below 10⁻³ or from 10⁷ on (rounding noise of 10⁻¹⁴ would read as 0 otherwise).
function linearLabels(u, splits, axis, space, increment) {
  const scale = Math.max(0, ...splits.filter((v) => v !== null).map(Math.abs));
  if (scale > 0 && (scale < 1e-3 || scale >= 1e7)) {
    const digits = Math.min(6, Math.max(0, Math.floor(Math.log10(scale)) - Math.floor(Math.log10(increment))));
    return splits.map((v) => (v === null ? '' : v === 0 ? '0' : v.toExponential(digits)));
  }
  return splits.map((v) => (v === null ? '' : uPlot.fmtNum(v)));
}

// A number's nice ceiling: the smallest of 1, 2, 2.5, 5 × 10ⁿ at or above it (x > 0).
export function niceCeiling(x) {
  const decade = 10 ** Math.floor(Math.log10(x));
  return [1, 2, 2.5, 5, 10].map((m) => m * decade).find((v) => v >= x * (1 - 1e-12));
}

// xRange / yRange: [min, max] fixed (a log axis otherwise rounds out to whole decades).
export function chart(container, { title, xLabel, yLabel, x, series, logX = false, logY = false,
  timeline = null, sync = null, width = 560, height = 220, shown = SHOWN_AT_FIRST, marks = [],
  xRange = null, yRange = null }) {
  const fixed = (range) => (range ? { range: () => range } : {});
  const options = {
    title, width, height,
    scales: { x: { time: false, distr: logX ? 3 : 1, ...fixed(xRange) }, y: { distr: logY ? 3 : 1, ...fixed(yRange) } },
    axes: [{ label: xLabel, ...(logX ? logAxis : { values: linearLabels }) },
      { label: yLabel, size: 82, ...(logY ? logAxis : { values: linearLabels }) }],
    series: [{ label: xLabel }, ...series.map((s, i) => ({ label: s.name, stroke: s.color ?? COLORS[i % COLORS.length],
      width: s.width ?? 1.5, dash: s.dash, spanGaps: s.spanGaps ?? false,
      points: s.points ? { show: true, size: 9, fill: s.color } : { show: false }, show: i < shown }))],
    cursor: sync ? { sync: { key: sync } } : {},
    plugins: [...(timeline ? [timeMarker(timeline)] : []), ...(marks.length ? [markTicks(marks)] : [])],
  };
  const plot = new uPlot(options, [x, ...series.map((s) => s.data)], container);
  if (timeline) {
    plot.over.addEventListener('click', () => {
      const left = plot.cursor.left;
      if (left !== undefined && left >= 0) timeline.set(plot.posToVal(left, 'x'), 'plot');
    });
  }
  return plot;
}

// Charts drawn when their holder comes within 300 px of the window, or all at once on request
// (the tests' screenshots).
export class LazyCharts {
  constructor() {
    this.charts = [];
    this.pending = new Map();
    this.observer = new IntersectionObserver((entries) => {
      for (const entry of entries) if (entry.isIntersecting) this.draw(entry.target);
    }, { rootMargin: '300px' });
  }

  add(holder, make) {
    this.pending.set(holder, make);
    this.observer.observe(holder);
  }

  draw(holder) {
    const make = this.pending.get(holder);
    if (!make) return;
    this.pending.delete(holder);
    this.observer.unobserve(holder);
    this.charts.push(make());
  }

  drawAll() {
    for (const holder of [...this.pending.keys()]) this.draw(holder);
    return this.charts.length;
  }
}

export function plotsSection(data, timeline) {
  const section = element('section', { id: 'plots' }, element('h2', {}, 'Plots'));
  const note = data.plots.thinned
    ? `${data.plots.rows} rows, drawn as each of ${data.plots.points / 2} time buckets' minimum and maximum per column (every extreme shows).`
    : `${data.plots.rows} rows, every one drawn.`;
  const marks = timeMarks(data.summary);
  const marked = marks.length
    ? ` Ticks on the time axis mark the stops' and contacts' impacts, rests and releases (orange, grey, blue), where friction sticks or slips (purple, brown) and the events (green): hover over one to read it.`
    : '';
  section.append(element('p', { class: 'note' }, note, ' Drag to zoom, double-click to reset, click to move the 3-D view to that time.', marked));
  const chooser = element('fieldset', { class: 'plot-chooser' }, element('legend', {}, 'Plots shown'));
  const grid = element('div', { class: 'plot-grid' });
  section.append(chooser, grid);
  const time = decode(data.plots.time);
  const charts = new LazyCharts();
  const registry = {};
  const drawnRegistry = {};
  const width = () => Math.max(320, Math.min(640, grid.clientWidth / (grid.clientWidth > 1100 ? 2 : 1) - 16));
  for (const group of data.plots.groups) {
    const holder = element('div', { class: 'plot' });
    grid.append(holder);
    holder.hidden = Boolean(group.hidden);
    const box = element('input', { type: 'checkbox', onchange: () => { holder.hidden = !box.checked; } });
    box.checked = !group.hidden;
    chooser.append(element('label', {}, box, ` ${group.title}`));
    const series = group.series.map((s) => {
      let values = decode(s.data);
      if (group.log) values = Array.from(values, (v) => (Math.abs(v) > 1e-17 ? Math.abs(v) : 1e-17));
      registry[s.name] = values;
      // Drawn with round-off as 0 (the page keeps the exact values for read-back).
      const scale = group.round_off_scale;
      const drawn = scale > 0 ? Array.from(values, (v) => shownValue(v, scale)) : values;
      drawnRegistry[s.name] = drawn;
      return { name: s.name, data: drawn };
    });
    if (series.length > SHOWN_AT_FIRST) {
      holder.append(element('p', { class: 'note' }, `${series.length} columns, the first ${SHOWN_AT_FIRST} shown: click a legend entry to show or hide one.`));
    }
    charts.add(holder, () => chart(holder, { title: group.title, xLabel: 't (s)', yLabel: group.unit || (group.log ? '|drift|' : ''),
      x: time, series, logY: group.log, timeline, sync: 'momenta', width: width(), marks }));
  }
  new ResizeObserver(() => charts.charts.forEach((p) => p.setSize({ width: width(), height: 220 }))).observe(grid);
  return { section, charts, registry, drawnRegistry, time };
}
