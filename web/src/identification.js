// The page of an identification (`momenta identify --report`): what was measured against what
// the estimate gives, the residuals beside the noise found, the estimates with their intervals,
// their correlations as a heat map, and what the data cannot tell.

import { LazyCharts, chart } from './plots.js';
import { decode, element, formatNumber, svg, table } from './data.js';

const MEASURED = '#bdbdbd';
const FITTED = '#d62728';

function summarySection(data) {
  const facts = [
    ['model', data.model_source],
    ['data', `${data.data_source}: ${data.samples} samples`],
    ['identifiable', `${data.estimates.length} base parameters of the ${data.num_parameters} inertial parameters`],
    ['degrees of freedom', String(data.degrees_of_freedom)],
  ];
  return element('section', { id: 'identification-summary' },
    element('h1', {}, `${data.title}: inertial parameters from measured efforts`),
    element('dl', { class: 'facts' }, ...facts.flatMap(([k, v]) => [element('dt', {}, k), element('dd', {}, v)])));
}

// Per effort: measured and fitted against time, then the residual with ±2σ of the noise found.
function effortsSection(data, charts, drawn) {
  const section = element('section', { id: 'efforts' }, element('h2', {}, 'Efforts: measured and fitted'));
  const hasTime = data.time !== null;
  const x = hasTime ? Array.from(decode(data.time)) : Array.from({ length: data.samples }, (_, i) => i);
  const xLabel = hasTime ? 'time (s)' : 'sample';
  section.append(element('p', { class: 'note' },
    'Grey (wide): the measured effort; red: the effort the estimate gives at the same motion. ',
    'Below each, the residual (measured − fitted) with ±2σ of the noise the fit found: a wrong model shows as structure in it.'));
  const grid = element('div', { class: 'plot-grid' });
  section.append(grid);
  data.efforts.forEach((effort, k) => {
    const measured = Array.from(decode(effort.measured));
    const fitted = Array.from(decode(effort.fitted));
    const residual = measured.map((m, i) => m - fitted[i]);
    const band = 2 * effort.noise;
    const label = `${effort.name} (${effort.unit})`;
    const top = element('div', { class: 'plot effort-plot', 'data-effort': effort.name });
    const bottom = element('div', { class: 'plot residual-plot', 'data-effort': effort.name });
    grid.append(element('div', {}, top, bottom));
    charts.add(top, () => (drawn[`${effort.name}`] = chart(top, { title: effort.name, xLabel, yLabel: label, x,
      series: [{ name: 'measured', data: measured, color: MEASURED, width: 4 },
        { name: 'fitted', data: fitted, color: FITTED, width: 1.5 }], shown: Infinity })));
    charts.add(bottom, () => (drawn[`${effort.name} residual`] = chart(bottom, { title: `${effort.name}: residual`, xLabel,
      yLabel: `residual (${effort.unit})`, x, height: 200,
      series: [{ name: 'measured − fitted', data: residual, color: '#4e79a7', width: 1 },
        { name: '+2σ', data: x.map(() => band), color: '#000', width: 1, dash: [5, 4] },
        { name: '−2σ', data: x.map(() => -band), color: '#000', width: 1, dash: [5, 4] }], shown: Infinity })));
  });
  const white = data.whiteness;
  const noise = table(['effort', 'noise σ (from the residuals)', 'residual RMS', `whiteness (Ljung–Box p, ${white.lags} lags)`],
    data.efforts.map((e, k) => [e.name, `${formatNumber(e.noise, 4)} ${e.unit}`, `${formatNumber(e.residual_rms, 4)} ${e.unit}`,
      element('span', { class: white.p[k] >= white.level ? 'verdict pass' : 'verdict warn' },
        `p = ${formatNumber(white.p[k], 2)}: ${white.p[k] >= white.level ? 'white' : 'correlated'}`)]));
  noise.id = 'effort-noise';
  section.append(noise);
  if (white.p.some((p) => p < white.level)) {
    section.append(element('p', { class: 'unavailable' },
      'A residual is correlated: the model\u2019s structure misses something the data has (joint friction? a flexible link? a wrong length?).'));
  }
  return section;
}

function estimatesSection(data) {
  const section = element('section', { id: 'estimates' }, element('h2', {}, 'Estimates'));
  section.append(element('p', { class: 'note' },
    'Each base parameter is a combination of the bodies\u2019 inertial parameters (ten per body: mass m, first moment h = m c, ',
    'the inertia about the body\u2019s origin) that the joint efforts decide. The interval holds the true value 95 % of the time ',
    'if the model\u2019s structure is right and the noise is white.'));
  section.append(table(['base parameter', 'unit', 'estimate', 'std. error', '95 % interval', 'model', 'model in interval'],
    data.estimates.map((e) => [e.name, e.unit, formatNumber(e.estimate), formatNumber(e.standard_error, 3),
      `[${formatNumber(e.lower)}, ${formatNumber(e.upper)}]`, formatNumber(e.model),
      e.lower <= e.model && e.model <= e.upper ? 'yes' : 'no'])));
  return section;
}

// Blue −1, white 0, red +1.
export function correlationColour(rho) {
  const t = Math.max(-1, Math.min(1, rho));
  const mix = (a, b) => Math.round(255 + (b - 255) * Math.abs(t));
  return t >= 0 ? `rgb(${mix(255, 214)},${mix(255, 39)},${mix(255, 40)})` : `rgb(${mix(255, 31)},${mix(255, 119)},${mix(255, 180)})`;
}

export function correlationSection(data) {
  const section = element('section', { id: 'correlation' }, element('h2', {}, 'Correlations of the estimates'));
  const n = data.estimates.length;
  const cell = 56;
  const labelWidth = 8 + 7.2 * Math.max(...data.estimates.map((e, i) => `${i + 1}  ${e.name}`.length));
  const width = labelWidth + n * cell + 110;
  const height = 30 + n * cell + 10;
  const map = svg('svg', { class: 'heat-map', width, height, viewBox: `0 0 ${width} ${height}` });
  data.estimates.forEach((e, i) => {
    map.append(svg('text', { x: labelWidth - 8, y: 30 + i * cell + cell / 2 + 4, 'text-anchor': 'end', class: 'row-name' }, `${i + 1}  ${e.name}`));
    map.append(svg('text', { x: labelWidth + i * cell + cell / 2, y: 20, 'text-anchor': 'middle', class: 'column-name' }, String(i + 1)));
    data.estimates.forEach((_, j) => {
      const rho = data.correlation[i][j];
      const x = labelWidth + j * cell;
      const y = 30 + i * cell;
      map.append(svg('rect', { x, y, width: cell - 2, height: cell - 2, fill: correlationColour(rho), class: 'cell', 'data-row': i, 'data-column': j },
        svg('title', {}, `ρ(${e.name}, ${data.estimates[j].name}) = ${rho.toFixed(4)}`)));
      map.append(svg('text', { x: x + (cell - 2) / 2, y: y + cell / 2 + 3, 'text-anchor': 'middle', class: 'cell-value', fill: Math.abs(rho) > 0.6 ? '#fff' : '#222' }, rho.toFixed(2)));
    });
  });
  // The colour scale.
  const barX = labelWidth + n * cell + 30;
  for (let k = 0; k < 20; k++) {
    const rho = 1 - (2 * k) / 19;
    map.append(svg('rect', { x: barX, y: 30 + (k * (n * cell - 2)) / 20, width: 16, height: (n * cell - 2) / 20 + 0.5, fill: correlationColour(rho) }));
  }
  map.append(svg('text', { x: barX + 22, y: 38, class: 'scale-label' }, '+1'));
  map.append(svg('text', { x: barX + 22, y: 30 + (n * cell) / 2 + 4, class: 'scale-label' }, '0'));
  map.append(svg('text', { x: barX + 22, y: 30 + n * cell - 4, class: 'scale-label' }, '−1'));
  section.append(map);
  section.append(element('p', { class: 'note' },
    'ρ near ±1: the data barely separates the two parameters (they move together in the fit); add motion that excites one without the other.'));
  return section;
}

function identifiabilitySection(data) {
  const section = element('section', { id: 'identifiability' }, element('h2', {}, 'What the data cannot tell'));
  const list = (items) => (items.length ? items.join(', ') : 'none');
  const x = data.excitation;
  section.append(element('p', {}, element('strong', {}, 'Excitation: '),
    `condition number ${formatNumber(x.condition_number, 3)} of the regressor with each column scaled by the model\u2019s own size of its parameter `,
    `(singular values ${x.singular_values.map((v) => formatNumber(v, 2)).join(', ')}): `,
    x.condition_number > x.poor
      ? element('span', { class: 'verdict warn' }, `poorly excited (above ${x.poor})`)
      : element('span', { class: 'verdict pass' }, `every base parameter excited (below ${x.poor})`),
    '. Least determined by this data: ',
    element('span', { class: 'least-determined' }, x.least_determined), '.'));
  section.append(element('p', {}, element('strong', {}, 'Never felt by the joints: '), list(data.never_felt),
    ' — no data of joint efforts can tell these.'));
  section.append(element('p', {}, element('strong', {}, 'Regrouped: '), list(data.regrouped),
    ' — told only in the combinations above; the model\u2019s values are kept for them.'));
  section.append(element('h3', {}, 'Can a body have these estimates?'));
  section.append(table(['body', 'physical consistency'], data.bodies.map((b) => [b.name,
    element('span', { class: b.consistent ? 'verdict pass' : 'verdict warn' }, b.verdict)])));
  return section;
}

// What a test reads back from a fit's page (this one and grey_box.js's): a drawn chart's title,
// each series' name and values and its axes; the heat map's cells; the estimates table's rows.
export function fitPageHooks(drawn) {
  return {
    plotted: (name) => {
      const plot = drawn[name];
      if (!plot) return null;
      return { title: plot.root.querySelector('.u-title')?.textContent,
        series: plot.series.slice(1).map((s, i) => ({ name: s.label, values: Array.from(plot.data[i + 1]) })),
        x: Array.from(plot.data[0]), axes: plot.axes.map((a) => a.label), logX: plot.scales.x.distr === 3 };
    },
    heatMap: () => Array.from(document.querySelectorAll('#correlation rect.cell')).map((r) => ({
      row: Number(r.dataset.row), column: Number(r.dataset.column), fill: r.getAttribute('fill'),
      text: r.nextSibling.textContent })),
    tableRows: () => Array.from(document.querySelectorAll('#estimates tbody tr')).map((tr) => Array.from(tr.children).map((td) => td.textContent)),
  };
}

export function identificationPage(app, data) {
  const charts = new LazyCharts();
  const drawn = {};
  app.append(summarySection(data));
  app.append(effortsSection(data, charts, drawn));
  app.append(estimatesSection(data));
  app.append(correlationSection(data));
  app.append(identifiabilitySection(data));
  return {
    kind: 'identification',
    drawAllCharts: () => charts.drawAll(),
    estimates: () => data.estimates,
    ...fitPageHooks(drawn),
  };
}
