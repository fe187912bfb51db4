// The linear analysis: poles and zeros on the s-plane, Bode magnitude and phase of each
// input–output pair, step responses, and the modes (ωn, ζ) with their shapes animated in the
// 3-D view.

import { LazyCharts, chart } from './plots.js';
import { decode, element, formatNumber, table } from './data.js';

function poleZeroMap(poles, zeros) {
  const size = 320;
  const all = [...poles, ...zeros];
  const reach = Math.max(1e-9, ...all.map(([re, im]) => Math.max(Math.abs(re), Math.abs(im)))) * 1.15;
  const at = (v) => size / 2 + (v / reach) * (size / 2 - 12);
  const ns = 'http://www.w3.org/2000/svg';
  const svg = document.createElementNS(ns, 'svg');
  svg.setAttribute('width', size);
  svg.setAttribute('height', size);
  svg.setAttribute('class', 'pole-zero');
  const add = (tag, attributes) => {
    const node = document.createElementNS(ns, tag);
    for (const [k, v] of Object.entries(attributes)) node.setAttribute(k, v);
    svg.append(node);
    return node;
  };
  add('line', { x1: 0, y1: size / 2, x2: size, y2: size / 2, stroke: '#999' });
  add('line', { x1: size / 2, y1: 0, x2: size / 2, y2: size, stroke: '#999' });
  const label = add('text', { x: 6, y: 14, 'font-size': 11, fill: '#555' });
  label.textContent = `±${formatNumber(reach, 3)} 1/s`;
  for (const [re, im] of poles) {
    const x = at(re); const y = at(-im); const d = 5;
    add('path', { d: `M${x - d},${y - d}L${x + d},${y + d}M${x - d},${y + d}L${x + d},${y - d}`, stroke: '#d62728', 'stroke-width': 2, class: 'pole' });
  }
  for (const [re, im] of zeros) add('circle', { cx: at(re), cy: at(-im), r: 5, fill: 'none', stroke: '#1f77b4', 'stroke-width': 2, class: 'zero' });
  return svg;
}

export function linearSection(data, motion) {
  const linear = data.linear;
  const section = element('section', { id: 'linear' }, element('h2', {}, 'Linear analysis'));
  if (!linear.available) {
    section.append(element('p', { class: 'unavailable' }, `Not available: ${linear.reason}`));
    return { section, charts: null };
  }
  section.append(element('p', {}, `Linearized about ${linear.about}: ${linear.states.length} states, inputs `,
    linear.inputs.length ? linear.inputs.join(', ') : 'none (the model has no signals)', '; outputs ',
    linear.outputs.join(', ') || 'none', '.'));
  const zeros = linear.pairs.flatMap((p) => p.zeros);
  const row = element('div', { class: 'row' });
  row.append(element('figure', {}, poleZeroMap(linear.poles, zeros),
    element('figcaption', {}, '× poles (eigenvalues of A), ○ zeros of the pairs below')));
  const modes = element('div', { class: 'modes' }, element('h3', {}, 'Modes'));
  const stop = element('button', { class: 'stop-mode' }, 'back to the run');
  stop.addEventListener('click', () => motion && motion.playMode(null));
  modes.append(table(['λ (1/s)', 'ωn (rad/s)', 'ζ', 'shape'], linear.modes.map((m, i) => {
    const button = element('button', { class: 'animate-mode', 'data-mode': i }, 'animate');
    button.addEventListener('click', () => { if (motion) { motion.playMode(m); document.getElementById('view').scrollIntoView(); } });
    const [re, im] = m.eigenvalue;
    return [`${formatNumber(re, 5)} ${im >= 0 ? '+' : '−'} ${formatNumber(Math.abs(im), 5)}j`, formatNumber(m.natural_frequency, 5),
      formatNumber(m.damping_ratio, 4), button];
  })), stop);
  row.append(modes);
  section.append(row);
  const bode = element('div', { class: 'plot-grid' });
  section.append(bode);
  const charts = new LazyCharts();
  for (const pair of linear.pairs) {
    const title = `${pair.output} / ${pair.input}`;
    const w = pair.frequency;
    const m = element('div', { class: 'plot' });
    const p = element('div', { class: 'plot' });
    bode.append(m, p);
    charts.add(m, () => chart(m, { title: `Bode magnitude ${title}`, xLabel: 'ω (rad/s)', yLabel: 'dB', x: w,
      series: [{ name: 'magnitude (dB)', data: pair.magnitude_db.map((v) => (Number.isFinite(v) ? v : null)) }], logX: true }));
    charts.add(p, () => chart(p, { title: `Bode phase ${title}`, xLabel: 'ω (rad/s)', yLabel: 'deg', x: w,
      series: [{ name: 'phase (°)', data: pair.phase_deg }], logX: true }));
  }
  // One chart per output: the outputs of a model have different units (metres, newtons).
  for (const step of linear.steps) {
    const time = decode(step.time);
    for (const output of step.outputs) {
      const holder = element('div', { class: 'plot' });
      bode.append(holder);
      charts.add(holder, () => chart(holder, { title: `Step response of ${output.name} to ${step.input}`, xLabel: 't (s)',
        yLabel: output.name, x: time, series: [{ name: output.name, data: decode(output.data) }] }));
    }
  }
  return { section, charts };
}
