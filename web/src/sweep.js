// The page of a sweep (`momenta sweep --report`): the runs and failures, a scatter plot of any
// column against any other, and parallel coordinates of every column, a line per run. Drawn as
// SVG, so that what the page shows can be read back (the browser test counts its marks).

import { decode, element, formatNumber, svg } from './data.js';

function extent(values) {
  let low = Infinity;
  let high = -Infinity;
  for (const v of values) {
    if (!Number.isFinite(v)) continue;
    low = Math.min(low, v);
    high = Math.max(high, v);
  }
  if (low === high) return [low - 1, high + 1];
  return [low, high];
}

// Whether a column reads better on a log axis: positive values over at least a decade that are
// geometrically spaced (a sweep's `spacing: log`: equal ratios between its distinct values), or
// spread over two decades or more however they fall.
function isLogSpaced(values) {
  const finite = values.filter(Number.isFinite);
  if (!finite.length || finite.some((v) => v <= 0)) return false;
  const [lo, hi] = extent(finite);
  if (hi / lo >= 100) return true;
  if (hi / lo < 10) return false;
  const distinct = [...new Set(finite)].sort((a, b) => a - b);
  if (distinct.length < 3) return false;
  const steps = distinct.slice(1).map((v, i) => Math.log(v / distinct[i]));
  return steps.every((s) => Math.abs(s - steps[0]) <= 1e-6 * steps[0]);
}

// Ticks at 1-2-5 steps (about `count` of them) within [lo, hi].
function linearTicks(lo, hi, count = 5) {
  const rough = (hi - lo) / count;
  const decade = 10 ** Math.floor(Math.log10(rough));
  const step = [1, 2, 5, 10].map((m) => m * decade).find((s) => s >= rough) ?? 10 * decade;
  const ticks = [];
  const first = Math.ceil(lo / step);
  for (let k = first; (k * step) <= hi + 1e-9 * step && ticks.length < 50; k++) ticks.push(k === 0 ? 0 : k * step);
  return ticks;
}

// Ticks at 1, 2, 5 times each power of ten within [lo, hi] (the powers alone over many decades).
function logTicks(lo, hi) {
  const ticks = [];
  const multiples = Math.log10(hi / lo) > 4 ? [1] : [1, 2, 5];
  for (let e = Math.floor(Math.log10(lo)); e <= Math.ceil(Math.log10(hi)); e++) {
    for (const m of multiples) {
      const t = m * 10 ** e;
      if (t >= lo * (1 - 1e-12) && t <= hi * (1 + 1e-12)) ticks.push(t);
    }
  }
  return ticks;
}

// A column's scale: where a value falls in [0, 1] along its axis, and the axis's ticks.
function scaleOf(values) {
  const log = isLogSpaced(values);
  const [lo, hi] = extent(values.filter((v) => Number.isFinite(v) && (!log || v > 0)));
  const at = log ? (v) => Math.log(v / lo) / Math.log(hi / lo) : (v) => (v - lo) / (hi - lo);
  return { log, lo, hi, at, ticks: log ? logTicks(lo, hi) : linearTicks(lo, hi) };
}

// A colour from cool (low) to warm (high) for s in [0, 1].
function colour(s) {
  const hue = 240 - 240 * Math.min(1, Math.max(0, s));
  return `hsl(${hue.toFixed(0)}, 70%, 45%)`;
}

// The colour scale: a bar from the lowest to the highest value of the colouring column, its
// name and ticks.
function colourLegend(name, lo, hi) {
  const width = 640;
  const legend = svg('svg', { width, height: 54, viewBox: `0 0 ${width} 54`, class: 'colour-legend' });
  const gradient = svg('linearGradient', { id: 'sweep-colours', x1: '0', x2: '1', y1: '0', y2: '0' });
  for (let k = 0; k <= 10; k++) gradient.append(svg('stop', { offset: `${10 * k}%`, 'stop-color': colour(k / 10) }));
  legend.append(svg('defs', {}, gradient));
  const left = 80;
  const right = width - 20;
  legend.append(svg('rect', { x: left, y: 18, width: right - left, height: 10, fill: 'url(#sweep-colours)' }));
  legend.append(svg('text', { x: left, y: 12, 'font-size': 12, class: 'legend-name' }, document.createTextNode(`colour: ${name}`)));
  for (const t of linearTicks(lo, hi)) {
    const x = left + ((t - lo) / (hi - lo)) * (right - left);
    legend.append(svg('text', { x: x.toFixed(1), y: 44, 'text-anchor': 'middle', 'font-size': 11 }, document.createTextNode(formatNumber(t, 4))));
  }
  return legend;
}

function scatterPlot(names, columns, ok, colourBy, colourName) {
  const width = 640;
  const height = 420;
  const margin = { left: 80, right: 20, top: 20, bottom: 60 };
  const section = element('section', { id: 'sweep-scatter' }, element('h2', {}, 'Scatter'));
  const pick = (id, chosen) => {
    const select = element('select', { id });
    names.forEach((name, i) => {
      const option = element('option', { value: String(i) }, name);
      if (i === chosen) option.selected = true;
      select.append(option);
    });
    return select;
  };
  const xSelect = pick('sweep-x', 0);
  const ySelect = pick('sweep-y', names.length > 1 ? names.length - columns.metricsCount : 0);
  section.append(element('p', {}, 'x: ', xSelect, '  y: ', ySelect));
  const figure = element('div', { class: 'sweep-figure' });
  section.append(figure);
  const state = { points: 0, x: 0, y: 0 };

  const draw = () => {
    const xi = Number(xSelect.value);
    const yi = Number(ySelect.value);
    state.x = xi;
    state.y = yi;
    const xs = columns.values[xi];
    const ys = columns.values[yi];
    const xScale = scaleOf(Array.from(xs));
    const yScale = scaleOf(Array.from(ys));
    state.scales = { x: xScale, y: yScale };
    const [c0, c1] = extent(colourBy);
    const px = (x) => margin.left + xScale.at(x) * (width - margin.left - margin.right);
    const py = (y) => height - margin.bottom - yScale.at(y) * (height - margin.top - margin.bottom);
    const plot = svg('svg', { width, height, viewBox: `0 0 ${width} ${height}`, class: 'sweep-scatter' });
    plot.append(svg('rect', { x: margin.left, y: margin.top, width: width - margin.left - margin.right,
      height: height - margin.top - margin.bottom, fill: 'none', stroke: '#888' }));
    const label = (x, y, text, anchor = 'middle', extra = {}) =>
      svg('text', { x, y, 'text-anchor': anchor, 'font-size': 12, ...extra }, document.createTextNode(text));
    // Ticks, gridlines and their numbers; "(log)" after the name of a log axis.
    for (const t of xScale.ticks) {
      const x = px(t).toFixed(1);
      plot.append(svg('line', { x1: x, x2: x, y1: margin.top, y2: height - margin.bottom, stroke: '#e4e4e4', class: 'x-tick' }));
      plot.append(label(x, height - margin.bottom + 16, formatNumber(t, 4)));
    }
    for (const t of yScale.ticks) {
      const y = py(t).toFixed(1);
      plot.append(svg('line', { x1: margin.left, x2: width - margin.right, y1: y, y2: y, stroke: '#e4e4e4', class: 'y-tick' }));
      plot.append(label(margin.left - 6, Number(y) + 4, formatNumber(t, 4), 'end'));
    }
    const axisName = (i, scale) => `${names[i]}${scale.log ? ' (log)' : ''}`;
    plot.append(label((margin.left + width - margin.right) / 2, height - 18, axisName(xi, xScale), 'middle', { class: 'x-name' }));
    plot.append(label(16, (margin.top + height - margin.bottom) / 2, axisName(yi, yScale), 'middle',
      { class: 'y-name', transform: `rotate(-90 16 ${(margin.top + height - margin.bottom) / 2})` }));
    let points = 0;
    for (let r = 0; r < xs.length; r++) {
      if (!ok[r] || !Number.isFinite(xs[r]) || !Number.isFinite(ys[r])) continue;
      const title = svg('title', {}, document.createTextNode(`run ${columns.runs[r]}: ${names[xi]} = ${xs[r]}, ${names[yi]} = ${ys[r]}`));
      plot.append(svg('circle', { cx: px(xs[r]).toFixed(2), cy: py(ys[r]).toFixed(2), r: 4,
        fill: colour((colourBy[r] - c0) / (c1 - c0)), 'data-run': columns.runs[r] }, title));
      points++;
    }
    state.points = points;
    figure.replaceChildren(plot, colourLegend(colourName, c0, c1));
  };
  xSelect.addEventListener('change', draw);
  ySelect.addEventListener('change', draw);
  draw();
  return { section, state, set: (x, y) => { xSelect.value = String(x); ySelect.value = String(y); draw(); } };
}

function parallelCoordinates(names, units, columns, ok, colourBy) {
  const width = Math.max(640, 170 * names.length);
  const height = 420;
  const top = 40;
  const bottom = 40;
  const section = element('section', { id: 'sweep-parallel' }, element('h2', {}, 'Parallel coordinates'));
  const plot = svg('svg', { width, height, viewBox: `0 0 ${width} ${height}`, class: 'sweep-parallel' });
  const ax = (i) => 60 + (i * (width - 120)) / Math.max(1, names.length - 1);
  const scales = columns.values.map((v) => scaleOf(Array.from(v)));
  const [c0, c1] = extent(colourBy);
  let lines = 0;
  for (let r = 0; r < columns.runs.length; r++) {
    if (!ok[r]) continue;
    const points = [];
    for (let i = 0; i < names.length; i++) {
      const v = columns.values[i][r];
      if (!Number.isFinite(v)) continue;
      points.push(`${ax(i).toFixed(1)},${(height - bottom - scales[i].at(v) * (height - top - bottom)).toFixed(1)}`);
    }
    plot.append(svg('polyline', { points: points.join(' '), fill: 'none', 'stroke-width': 1,
      'stroke-opacity': 0.6, stroke: colour((colourBy[r] - c0) / (c1 - c0)), 'data-run': columns.runs[r] }));
    lines++;
  }
  names.forEach((name, i) => {
    const scale = scales[i];
    plot.append(svg('line', { x1: ax(i), x2: ax(i), y1: top, y2: height - bottom, stroke: '#333' }));
    plot.append(svg('text', { x: ax(i), y: top - 22, 'text-anchor': 'middle', 'font-size': 12, class: 'axis-name' }, document.createTextNode(name)));
    // Under the name: its unit, and "log" for a log axis.
    const under = [units[i], scale.log ? 'log' : ''].filter((t) => t).join(', ');
    if (under) plot.append(svg('text', { x: ax(i), y: top - 8, 'text-anchor': 'middle', 'font-size': 10, class: 'axis-unit' }, document.createTextNode(`(${under})`)));
    for (const t of scale.ticks) {
      const y = (height - bottom - scale.at(t) * (height - top - bottom)).toFixed(1);
      plot.append(svg('line', { x1: ax(i) - 4, x2: ax(i), y1: y, y2: y, stroke: '#333' }));
      plot.append(svg('text', { x: ax(i) - 6, y: Number(y) + 4, 'text-anchor': 'end', 'font-size': 10 }, document.createTextNode(formatNumber(t, 4))));
    }
  });
  section.append(element('div', { class: 'sweep-figure' }, plot));
  return { section, lines };
}

// A column's name with its unit, as axes, legends and tooltips show it: "m2 (kg)", "zeta (1)".
export function withUnit(name, unit) {
  return unit ? `${name} (${unit})` : name;
}

export function sweepPage(app, data) {
  const names = [...data.parameters, ...data.metrics];
  const units = [...(data.parameter_units ?? data.parameters.map(() => '')), ...(data.metric_units ?? data.metrics.map(() => ''))];
  const labels = names.map((name, i) => withUnit(name, units[i]));
  const values = data.values.map(decode);
  const ok = data.ok;
  const failures = ok.filter((b) => !b).length;
  const columns = { values, runs: data.runs, metricsCount: data.metrics.length };
  app.append(element('section', { id: 'sweep-summary' },
    element('h1', {}, data.title),
    element('p', {}, `${data.runs.length} runs of ${data.source}: ${data.runs.length - failures} ok, ${failures} failed; `,
      `${data.parameters.length} parameters, ${data.metrics.length} metric columns. Colour: ${labels[data.parameters.length]}.`)));
  const colourBy = values[data.parameters.length];
  const scatter = scatterPlot(labels, columns, ok, colourBy, labels[data.parameters.length]);
  app.append(scatter.section);
  const parallel = parallelCoordinates(names, units, columns, ok, colourBy);
  app.append(parallel.section);
  return {
    kind: 'sweep',
    names: () => names,
    units: () => units,
    runs: () => data.runs.length,
    failures: () => failures,
    scatterPoints: () => scatter.state.points,
    scatterAxes: () => [names[scatter.state.x], names[scatter.state.y]],
    scatterScales: () => ({ x: { log: scatter.state.scales.x.log, ticks: scatter.state.scales.x.ticks },
      y: { log: scatter.state.scales.y.log, ticks: scatter.state.scales.y.ticks } }),
    setScatter: (x, y) => scatter.set(x, y),
    parallelLines: () => parallel.lines,
    column: (i) => Array.from(values[i]),
  };
}
