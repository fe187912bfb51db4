// The summary panel: the model, the run, and the conservation audit with its verdict.

import { element, formatNumber, table } from './data.js';

export function summarySection(data) {
  const s = data.summary;
  const section = element('section', { id: 'summary' });
  if (s.stop_reason) {
    section.append(element('div', { class: 'stopped', role: 'alert' },
      element('strong', {}, `The run stopped at t = ${formatNumber(s.t_end)} s: `), s.stop_reason,
      ' The report shows the rows recorded up to then.'));
  }
  // A model without a description (a URDF or MJCF file, say) has no paragraph: append(null)
  // would print the word "null".
  section.append(element('h1', {}, s.model));
  if (s.description) section.append(element('p', { class: 'description' }, s.description));
  const facts = [
    ['file', s.file], ['bodies', s.bodies], ['joints', s.joints], ['degrees of freedom', s.dof === s.speeds ? s.dof : `${s.dof} (of ${s.speeds} joint speeds, after prescribed motion and constraints)`],
    ['integrator', `${s.integrator} (order ${s.order}${s.adaptive ? ', adaptive' : ''})`],
    [s.adaptive ? 'largest step' : 'step', `${formatNumber(s.step)} s`],
    ['simulated', `${formatNumber(s.t_end)} s of ${formatNumber(s.duration)} s, ${s.steps} steps, ${s.rows} rows`],
    ['wall time', `${formatNumber(s.wall_seconds, 3)} s`],
  ];
  section.append(element('dl', { class: 'facts' }, ...facts.flatMap(([k, v]) => [element('dt', {}, k), element('dd', {}, String(v))])));
  if (s.stops?.length) section.append(stopsTable(s.stops));
  const verdict = element('span', { class: `verdict ${s.verdict}` }, s.verdict === 'none' ? 'nothing conserved to audit' : s.verdict);
  section.append(element('h3', {}, 'Conservation audit ', verdict));
  if (s.audit.length) {
    section.append(table(['quantity', 'initial', 'max drift', 'final drift', 'allowed', 'verdict'],
      s.audit.map((a) => [a.name, formatNumber(a.initial), formatNumber(a.max_drift, 3), formatNumber(a.final_drift, 3),
        formatNumber(a.allowed, 2), a.verdict])));
    if (s.verdict_reason) section.append(element('p', { class: 'note verdict-reason' }, `Not vouched for: ${s.verdict_reason}.`));
    section.append(element('p', { class: 'note' }, 'Drifts are relative (the quaternion norm error absolute). Allowed: what the integrator\'s order and step imply over the run, at most 0.1 (docs/report.md).'));
  }
  return section;
}

// A stop's or contact's entry in words: a rest with when its bounces end and how friction holds,
// a stick or slip with the friction it needed against the cone's μs N.
function stopWhat(e) {
  if (e.kind === 'stick' && e.in_impact) {
    return `stick in the impact (its slip of ${formatNumber(e.rate_before, 4)} m/s would have turned to run with its friction)`;
  }
  if (e.kind === 'slip' && e.in_impact) {
    return `slip in the impact (friction impulse ${formatNumber(e.friction_needed, 4)} N·s > μs P_n = ${formatNumber(e.friction_limit, 4)} N·s)`;
  }
  if (e.kind === 'slip' && e.friction_needed <= e.friction_limit * (1 + 1e-9)) {
    return `slip (friction reached μs N = ${formatNumber(e.friction_limit, 4)} N)`;
  }
  if (e.kind === 'stick' || e.kind === 'slip') {
    return `${e.kind} (friction ${formatNumber(e.friction_needed, 4)} N ${e.kind === 'stick' ? '≤' : '>'} μs N = ${formatNumber(e.friction_limit, 4)} N)`;
  }
  if (e.kind !== 'rest') return e.kind;
  const notes = [];
  // Bounces that end later than the time says (a rebound's round-off tail says nothing).
  const restTime = formatNumber(e.rest_time, 12);
  if (e.rest_time > e.time && restTime !== formatNumber(e.time, 12)) {
    notes.push(`its bounces end at ${restTime} s`);
  }
  if (e.friction) notes.push(e.friction);
  return notes.length ? `rest (${notes.join('; ')})` : 'rest';
}

// Every impact, rest and release of the joints' stops and the contacts, in time order (open when
// there are few); a contact is named in the 'stop' column, its rates its normal speed.
function stopsTable(stops) {
  // Counted as the run's summary counts them: a rest that strikes (an impulse) is an impact too.
  const impacts = stops.filter((e) => e.kind === 'impact' || (e.kind === 'rest' && e.impulse !== 0)).length;
  const lost = stops.reduce((sum, e) => sum + e.energy_lost, 0);
  const details = element('details', { class: 'stops' },
    element('summary', {}, `Stops and contacts: ${stops.length} entr${stops.length === 1 ? 'y' : 'ies'}, ${impacts} impact${impacts === 1 ? '' : 's'}, ${formatNumber(lost, 4)} J lost`),
    table(['time (s)', 'joint', 'stop', 'what', 'rate before', 'rate after', 'impulse', 'energy lost (J)'],
      stops.map((e) => [formatNumber(e.time, 12), e.contact ? '' : e.joint, e.contact ? `contact ${e.contact}` : e.stop,
        stopWhat(e),
        `${formatNumber(e.rate_before, 6)} ${e.rate_unit}`, `${formatNumber(e.rate_after, 6)} ${e.rate_unit}`,
        `${formatNumber(e.impulse, 6)} ${e.impulse_unit}`, formatNumber(e.energy_lost, 4)])));
  if (stops.length <= 10) details.open = true;
  return details;
}
