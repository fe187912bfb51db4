// Every recorded column, one uPlot chart per group (units on the axis, zoom by dragging,
// double-click to reset, hover read-out in the legend), their cursors linked with each other and
// with the 3-D view's time: clicking a plot moves the time there; playing moves a marker.

import uPlot from 'uplot';
import { decode, element } from './data.js';

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

export function chart(container, { title, xLabel, yLabel, x, series, logX = false, logY = false,
  timeline = null, sync = null, width = 560, height = 220 }) {
  const options = {
    title, width, height,
    scales: { x: { time: false, distr: logX ? 3 : 1 }, y: { distr: logY ? 3 : 1 } },
    axes: [{ label: xLabel }, { label: yLabel, size: 70 }],
    series: [{ label: xLabel }, ...series.map((s, i) => ({ label: s.name, stroke: COLORS[i % COLORS.length], width: 1.5, points: { show: false } }))],
    cursor: sync ? { sync: { key: sync } } : {},
    plugins: timeline ? [timeMarker(timeline)] : [],
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

export function plotsSection(data, timeline) {
  const section = element('section', { id: 'plots' }, element('h2', {}, 'Plots'));
  const note = data.plots.thinned
    ? `${data.plots.rows} rows, drawn as each of ${data.plots.points / 2} time buckets' minimum and maximum per column (every extreme shows).`
    : `${data.plots.rows} rows, every one drawn.`;
  section.append(element('p', { class: 'note' }, note, ' Drag to zoom, double-click to reset, click to move the 3-D view to that time.'));
  const grid = element('div', { class: 'plot-grid' });
  section.append(grid);
  const time = decode(data.plots.time);
  const plots = [];
  const registry = {};
  for (const group of data.plots.groups) {
    const holder = element('div', { class: 'plot' });
    grid.append(holder);
    const series = group.series.map((s) => {
      let values = decode(s.data);
      if (group.log) values = Array.from(values, (v) => (Math.abs(v) > 1e-17 ? Math.abs(v) : 1e-17));
      registry[s.name] = values;
      return { name: s.name, data: values };
    });
    plots.push(chart(holder, { title: group.title, xLabel: 't (s)', yLabel: group.unit || (group.log ? '|drift|' : ''),
      x: time, series, logY: group.log, timeline, sync: 'momenta' }));
  }
  const resize = () => {
    const width = Math.max(320, Math.min(640, grid.clientWidth / (grid.clientWidth > 1100 ? 2 : 1) - 16));
    plots.forEach((p) => p.setSize({ width, height: 220 }));
  };
  new ResizeObserver(resize).observe(grid);
  return { section, plots, registry, time };
}
