// The Campbell diagram (momenta report --campbell A B): each whirl frequency of the rotor against
// its spin speed, forward whirls in warm colours and backward in cool ones, the 1× line an
// unbalance excites, and the critical speeds where a forward whirl meets it.

import { LazyCharts, chart } from './plots.js';
import { element, formatNumber, table } from './data.js';

const RPM = 60 / (2 * Math.PI); // rev/min per rad/s
const HZ = 1 / (2 * Math.PI);   // Hz per rad/s
const FORWARD = ['#d62728', '#ff7f0e', '#8c564b', '#e377c2'];
const BACKWARD = ['#1f77b4', '#17becf', '#2ca02c', '#9467bd'];

export function campbellSection(campbell) {
  const section = element('section', { id: 'campbell' }, element('h2', {}, 'Campbell diagram'));
  if (!campbell.available) {
    section.append(element('p', { class: 'unavailable' }, `Not available: ${campbell.reason}`));
    return { section, charts: null };
  }
  section.append(element('p', {}, `Whirl frequencies of the rotor turning on ${campbell.rotor}, seen from ${campbell.frame}, `,
    `from ${formatNumber(campbell.speeds[0] * RPM, 5)} to ${formatNumber(campbell.speeds[campbell.speeds.length - 1] * RPM, 5)} rev/min. `,
    'An unbalance turns with the rotor and drives forward whirl at 1×: where a forward whirl meets that line is a critical speed.'));
  // One x axis for the whirls (at the diagram's speeds) and the critical speeds (markers).
  const critical = campbell.critical_speeds.map((c) => c.speed);
  const speeds = [...campbell.speeds, ...critical].sort((a, b) => a - b);
  const at = (values) => speeds.map((w) => {
    const k = campbell.speeds.indexOf(w);
    return k >= 0 && values[k] !== null ? values[k] * HZ : null;
  });
  let forward = 0; let backward = 0;
  const series = campbell.series.map((s) => ({
    name: `${s.name.replace('_', ' ')} (Hz)`,
    data: at(s.values),
    color: s.whirl === 'forward' ? FORWARD[forward++ % FORWARD.length] : s.whirl === 'backward' ? BACKWARD[backward++ % BACKWARD.length] : '#7f7f7f',
    spanGaps: true,
  }));
  series.push({ name: '1× (Hz)', data: speeds.map((w) => w * HZ), color: '#000', dash: [6, 4], width: 1 });
  series.push({ name: 'critical speeds', data: speeds.map((w) => (critical.includes(w) ? w * HZ : null)), color: '#000', width: 0, points: true });
  const holder = element('div', { class: 'plot campbell-plot' });
  section.append(holder);
  const charts = new LazyCharts();
  charts.add(holder, () => chart(holder, { title: 'Campbell diagram', xLabel: 'speed (rev/min)', yLabel: 'frequency (Hz)',
    x: speeds.map((w) => w * RPM), series, width: 760, height: 360, shown: Infinity }));
  section.append(campbell.critical_speeds.length
    ? table(['critical speed (rev/min)', 'rad/s', 'whirl'], campbell.critical_speeds.map((c) =>
      [formatNumber(c.speed * RPM, 8), formatNumber(c.speed, 8), c.whirl]))
    : element('p', {}, 'No critical speed in this range: no forward whirl crosses the 1× line.'));
  if (campbell.unstable_speeds.length) {
    section.append(element('p', { class: 'unavailable' }, `Unstable at ${campbell.unstable_speeds.length} of the speeds (no whirl frequency drawn there).`));
  }
  return { section, charts };
}
