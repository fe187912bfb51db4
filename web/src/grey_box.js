// The page of a grey-box fit (`momenta identify FILE.yaml --report`): each measured channel with
// the fitted model's response and the start's, the residuals beside the noise, the estimates with
// their intervals, their correlations as a heat map, and what the data cannot determine.

import { LazyCharts, chart, niceCeiling } from './plots.js';
import { decode, element, formatNumber, table } from './data.js';
import { correlationSection, fitPageHooks } from './identification.js';

const MEASURED = '#bdbdbd';
const FITTED = '#d62728';
const START = '#4e79a7';

const shown = (x, digits) => (x === null ? 'not determined' : formatNumber(x, digits));

function summarySection(data) {
  const experiments = [...new Set(data.channels.map((c) => c.experiment))];
  const facts = [
    ['model', data.model_source],
    ['experiments', experiments.join(', ')],
    ['fit', data.termination],
    ['cost', [data.runs > 0 ? `${data.runs} runs, ${data.evaluations} evaluations of the dynamics` : null,
      data.linearizations > 0 ? `${data.linearizations} linearizations` : null,
      `${formatNumber(data.seconds, 3)} s`].filter((x) => x !== null).join(', ')],
  ];
  return element('section', { id: 'grey-box-summary' },
    element('h1', {}, `${data.title}: model numbers fitted to measured responses`),
    element('p', {}, element('span', { class: data.converged ? 'verdict pass' : 'verdict warn' },
      data.converged ? 'converged' : 'did not converge')),
    element('dl', { class: 'facts' }, ...facts.flatMap(([k, v]) => [element('dt', {}, k), element('dd', {}, v)])),
    // Logs shorter than the model's slowest time scale, as the command line warns of them.
    ...(data.warnings ?? []).map((w) => element('p', { class: 'warning' }, element('strong', {}, 'Warning: '), w)));
}

// Per channel: measured, fitted and at the start against time (a Bode test's against frequency,
// on a log scale); then the residual with ±2σ.
function channelsSection(data, charts, drawn) {
  const section = element('section', { id: 'channels' }, element('h2', {}, 'Measured and fitted responses'));
  section.append(element('p', { class: 'note' },
    'Grey (wide): the log; red: the model with the estimates; blue dashed: the model at the start. ',
    'Below each, the residual (measured − fitted) with ±2σ of the noise: a wrong model shows as structure in it.'));
  const grid = element('div', { class: 'plot-grid' });
  section.append(grid);
  data.channels.forEach((c) => {
    const name = `${c.experiment}: ${c.column}`;
    const x = Array.from(decode(c.time));
    const measured = Array.from(decode(c.measured));
    const fitted = Array.from(decode(c.fitted));
    const start = Array.from(decode(c.at_start));
    const residual = measured.map((m, i) => m - fitted[i]);
    const band = 2 * c.noise;
    const xLabel = `${c.abscissa} (${c.abscissa_unit})`;
    const logX = c.abscissa === 'frequency';  // a Bode test's, as Bode plots are drawn
    const xRange = logX ? [x[0], x[x.length - 1]] : null;  // the test's frequencies, not decades
    // The residual's axis symmetric about 0 out to a round number past the band and every
    // residual, so that it is labelled at both ends whatever its size.
    const reach = niceCeiling(Math.max(1.1 * band, ...residual.map(Math.abs)) || 1);
    const top = element('div', { class: 'plot channel-plot', 'data-channel': name });
    const bottom = element('div', { class: 'plot residual-plot', 'data-channel': name });
    grid.append(element('div', {}, top, bottom));
    charts.add(top, () => (drawn[name] = chart(top, { title: name, xLabel, logX, xRange, yLabel: `${c.channel} (${c.unit})`, x,
      series: [{ name: 'measured', data: measured, color: MEASURED, width: 4 },
        { name: 'fitted', data: fitted, color: FITTED, width: 1.5 },
        { name: 'at the start', data: start, color: START, width: 1, dash: [6, 4] }], shown: Infinity })));
    charts.add(bottom, () => (drawn[`${name} residual`] = chart(bottom, { title: `${name}: residual`, xLabel, logX, xRange, yRange: [-reach, reach],
      yLabel: `residual (${c.unit})`, x, height: 200,
      series: [{ name: 'measured − fitted', data: residual, color: '#4e79a7', width: 1 },
        { name: '+2σ', data: x.map(() => band), color: '#000', width: 1, dash: [5, 4] },
        { name: '−2σ', data: x.map(() => -band), color: '#000', width: 1, dash: [5, 4] }], shown: Infinity })));
  });
  const level = data.whiteness_level;
  const noise = table(['experiment', 'column → channel', 'noise σ', 'residual RMS', 'whiteness (Ljung–Box p)'],
    data.channels.map((c) => [c.experiment, `${c.column} → ${c.channel}`,
      `${formatNumber(c.noise, 4)} ${c.unit} (${c.noise_given ? 'given' : 'from the residuals'})`,
      `${formatNumber(c.residual_rms, 4)} ${c.unit}`,
      element('span', { class: c.whiteness_p >= level ? 'verdict pass' : 'verdict warn' },
        `p = ${formatNumber(c.whiteness_p, 2)}: ${c.whiteness_p >= level ? 'white' : 'correlated'}`)]));
  noise.id = 'channel-noise';
  section.append(noise);
  if (data.channels.some((c) => c.whiteness_p < level)) {
    section.append(element('p', { class: 'unavailable' },
      'A residual is correlated: the model\u2019s structure misses something the data has (friction? a flexible part? an input\u2019s delay?).'));
  }
  return section;
}

function estimatesSection(data) {
  const section = element('section', { id: 'estimates' }, element('h2', {}, 'Estimates'));
  section.append(element('p', { class: 'note' },
    'Each estimated number of the model file, by its path. The interval holds the true value 95 % of the time ',
    'if the model\u2019s structure is right and the noise is white',
    data.noise_estimated ? ` (Student\u2019s t, ${data.degrees_of_freedom} degrees of freedom: the noise was estimated).` : ' (every noise given).'));
  const end = (x, sign) => (x === null ? (sign < 0 ? '\u2212\u221e' : '\u221e') : formatNumber(x));
  section.append(table(['parameter', 'path', 'estimate', 'std. error', '95 % interval', 'start'],
    data.estimates.map((e) => [e.name, e.path, formatNumber(e.estimate), shown(e.standard_error, 3),
      e.standard_error === null ? 'not determined'
        : `[${end(e.lower, -1)}, ${end(e.upper, 1)}]` + (e.profiled ? ' \u1d56' : ''),
      formatNumber(e.start) + (e.at_bound ? ' (ended at its bound)' : '')])));
  if (data.interval_notes.length > 0) {
    section.append(element('p', { class: 'note' },
      '\u1d56 From the profile likelihood: where the cost, the other parameters refitted, has risen by q\u00b2 from its minimum.'));
    section.append(element('ul', { class: 'interval-notes' },
      ...data.interval_notes.map((note) => element('li', {}, note))));
  }
  return section;
}

function identifiabilitySection(data) {
  const x = data.identifiability;
  const section = element('section', { id: 'identifiability' }, element('h2', {}, 'What the data cannot tell'));
  section.append(element('p', {}, element('strong', {}, 'Identifiability: '),
    `singular values ${x.singular_values.map((v) => formatNumber(v, 3)).join(', ')} of the sensitivities with each column scaled by its parameter\u2019s size, `,
    `condition number ${shown(x.condition_number, 3)}: `,
    !x.identifiable ? element('span', { class: 'verdict warn' }, 'not identifiable from these experiments')
      : x.least_determined ? element('span', { class: 'verdict warn' }, `poorly determined (above ${formatNumber(x.poor)})`)
        : element('span', { class: 'verdict pass' }, 'every parameter is determined'), '.'));
  if (!x.identifiable) {
    section.append(element('ul', { class: 'undetermined' }, ...x.undetermined.map((u) => element('li', {}, u))));
    section.append(element('p', { class: 'advice' }, `\u2192 ${x.advice}`));
  } else if (x.least_determined) {
    section.append(element('p', {}, 'Least determined: ', element('span', { class: 'least-determined' }, x.least_determined)));
  }
  return section;
}

export function greyBoxPage(app, data) {
  const charts = new LazyCharts();
  const drawn = {};
  app.append(summarySection(data));
  app.append(channelsSection(data, charts, drawn));
  app.append(estimatesSection(data));
  app.append(correlationSection({ estimates: data.estimates, correlation: data.correlation }));
  app.append(identifiabilitySection(data));
  return {
    kind: 'grey-box',
    drawAllCharts: () => charts.drawAll(),
    estimates: () => data.estimates,
    warnings: () => Array.from(document.querySelectorAll('#grey-box-summary .warning'), (p) => p.textContent),
    ...fitPageHooks(drawn),
  };
}
