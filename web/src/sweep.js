// The page of a sweep (`momenta sweep --report`): the runs and failures, a scatter plot of any
// column against any other, and parallel coordinates of every column, a line per run. Drawn as
// SVG, so that what the page shows can be read back (the browser test counts its marks).

import { decode, element, formatNumber } from './data.js';

const SVG = 'http://www.w3.org/2000/svg';

function svg(tag, attributes = {}, ...children) {
  const node = document.createElementNS(SVG, tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  for (const child of children) node.append(child);
  return node;
}

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

// A colour from cool (low) to warm (high) for s in [0, 1].
function colour(s) {
  const hue = 240 - 240 * Math.min(1, Math.max(0, s));
  return `hsl(${hue.toFixed(0)}, 70%, 45%)`;
}

function scatterPlot(names, columns, ok, colourBy) {
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
    const [x0, x1] = extent(xs);
    const [y0, y1] = extent(ys);
    const [c0, c1] = extent(colourBy);
    const px = (x) => margin.left + ((x - x0) / (x1 - x0)) * (width - margin.left - margin.right);
    const py = (y) => height - margin.bottom - ((y - y0) / (y1 - y0)) * (height - margin.top - margin.bottom);
    const plot = svg('svg', { width, height, viewBox: `0 0 ${width} ${height}`, class: 'sweep-scatter' });
    plot.append(svg('rect', { x: margin.left, y: margin.top, width: width - margin.left - margin.right,
      height: height - margin.top - margin.bottom, fill: 'none', stroke: '#888' }));
    const label = (x, y, text, anchor = 'middle', extra = {}) =>
      svg('text', { x, y, 'text-anchor': anchor, 'font-size': 12, ...extra }, document.createTextNode(text));
    plot.append(label(margin.left, height - margin.bottom + 16, formatNumber(x0, 4), 'start'));
    plot.append(label(width - margin.right, height - margin.bottom + 16, formatNumber(x1, 4), 'end'));
    plot.append(label(margin.left - 6, height - margin.bottom, formatNumber(y0, 4), 'end'));
    plot.append(label(margin.left - 6, margin.top + 10, formatNumber(y1, 4), 'end'));
    plot.append(label((margin.left + width - margin.right) / 2, height - 18, names[xi], 'middle', { class: 'x-name' }));
    plot.append(label(16, (margin.top + height - margin.bottom) / 2, names[yi], 'middle',
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
    figure.replaceChildren(plot);
  };
  xSelect.addEventListener('change', draw);
  ySelect.addEventListener('change', draw);
  draw();
  return { section, state, set: (x, y) => { xSelect.value = String(x); ySelect.value = String(y); draw(); } };
}

function parallelCoordinates(names, columns, ok, colourBy) {
  const width = Math.max(640, 140 * names.length);
  const height = 420;
  const top = 40;
  const bottom = 40;
  const section = element('section', { id: 'sweep-parallel' }, element('h2', {}, 'Parallel coordinates'));
  const plot = svg('svg', { width, height, viewBox: `0 0 ${width} ${height}`, class: 'sweep-parallel' });
  const ax = (i) => 60 + (i * (width - 120)) / Math.max(1, names.length - 1);
  const extents = columns.values.map(extent);
  const [c0, c1] = extent(colourBy);
  let lines = 0;
  for (let r = 0; r < columns.runs.length; r++) {
    if (!ok[r]) continue;
    const points = [];
    for (let i = 0; i < names.length; i++) {
      const v = columns.values[i][r];
      if (!Number.isFinite(v)) continue;
      const [lo, hi] = extents[i];
      points.push(`${ax(i).toFixed(1)},${(height - bottom - ((v - lo) / (hi - lo)) * (height - top - bottom)).toFixed(1)}`);
    }
    plot.append(svg('polyline', { points: points.join(' '), fill: 'none', 'stroke-width': 1,
      'stroke-opacity': 0.6, stroke: colour((colourBy[r] - c0) / (c1 - c0)), 'data-run': columns.runs[r] }));
    lines++;
  }
  names.forEach((name, i) => {
    const [lo, hi] = extents[i];
    plot.append(svg('line', { x1: ax(i), x2: ax(i), y1: top, y2: height - bottom, stroke: '#333' }));
    plot.append(svg('text', { x: ax(i), y: top - 22, 'text-anchor': 'middle', 'font-size': 12, class: 'axis-name' }, document.createTextNode(name)));
    plot.append(svg('text', { x: ax(i), y: top - 8, 'text-anchor': 'middle', 'font-size': 11 }, document.createTextNode(formatNumber(hi, 4))));
    plot.append(svg('text', { x: ax(i), y: height - bottom + 16, 'text-anchor': 'middle', 'font-size': 11 }, document.createTextNode(formatNumber(lo, 4))));
  });
  section.append(element('div', { class: 'sweep-figure' }, plot));
  return { section, lines };
}

export function sweepPage(app, data) {
  const names = [...data.parameters, ...data.metrics];
  const values = data.values.map(decode);
  const ok = data.ok;
  const failures = ok.filter((b) => !b).length;
  const columns = { values, runs: data.runs, metricsCount: data.metrics.length };
  app.append(element('section', { id: 'sweep-summary' },
    element('h1', {}, data.title),
    element('p', {}, `${data.runs.length} runs of ${data.source}: ${data.runs.length - failures} ok, ${failures} failed; `,
      `${data.parameters.length} parameters, ${data.metrics.length} metric columns. Colour: ${data.metrics[0]}.`)));
  const colourBy = values[data.parameters.length];
  const scatter = scatterPlot(names, columns, ok, colourBy);
  app.append(scatter.section);
  const parallel = parallelCoordinates(names, columns, ok, colourBy);
  app.append(parallel.section);
  return {
    kind: 'sweep',
    names: () => names,
    runs: () => data.runs.length,
    failures: () => failures,
    scatterPoints: () => scatter.state.points,
    scatterAxes: () => [names[scatter.state.x], names[scatter.state.y]],
    setScatter: (x, y) => scatter.set(x, y),
    parallelLines: () => parallel.lines,
    column: (i) => Array.from(values[i]),
  };
}
