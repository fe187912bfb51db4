// Free-body diagrams: each body's free-body and kinetic diagrams (drawn by the library as SVG) at
// a few instants of the run, one picture at a time, chosen by body and time. The time list
// follows the timeline: moving it selects the nearest instant that has diagrams.

import { element, formatNumber } from './data.js';

export function diagramsSection(diagrams, timeline) {
  const section = element('section', { id: 'diagrams' }, element('h2', {}, 'Free-body diagrams'));
  if (!diagrams || diagrams.bodies.length === 0) {
    section.append(element('p', { class: 'unavailable' }, 'Not available: the model has no moving body.'));
    return { section, show: () => {} };
  }
  section.append(element('p', {},
    'Each body isolated with every force and couple on it (gravity, joint and constraint reactions, springs, loads), ',
    'beside its kinetic diagram (m a_G and Ī α + ω × H_G). The residuals of ΣF = m a_G and ΣM_G = Ḣ_G are under each picture. ',
    diagrams.omitted > 0 ? `(${diagrams.omitted} more bodies have diagrams through momenta diagram.)` : ''));
  const bodySelect = element('select', { id: 'diagram-body' },
    ...diagrams.bodies.map((b, i) => element('option', { value: String(i) }, b.name)));
  const timeSelect = element('select', { id: 'diagram-time' },
    ...diagrams.times.map((t, i) => element('option', { value: String(i) }, `t = ${formatNumber(t, 6)} s`)));
  const picture = element('div', { class: 'diagram', id: 'diagram-picture' });
  section.append(element('div', { class: 'controls' },
    element('label', {}, 'body ', bodySelect), ' ', element('label', {}, 'time ', timeSelect)), picture);

  const show = () => {
    const body = diagrams.bodies[Number(bodySelect.value)];
    const k = Number(timeSelect.value);
    const svg = body.svg[k];
    // The SVG is the library's own output (names escaped there); a missing one says why.
    if (svg) picture.innerHTML = svg;
    else picture.replaceChildren(element('p', { class: 'unavailable' }, `No diagram at this time: ${body.residuals[k]}`));
  };
  bodySelect.addEventListener('change', show);
  timeSelect.addEventListener('change', show);
  // Moving the timeline picks the nearest instant with diagrams.
  timeline?.onChange?.((t) => {
    let best = 0;
    diagrams.times.forEach((s, i) => { if (Math.abs(s - t) < Math.abs(diagrams.times[best] - t)) best = i; });
    if (String(best) !== timeSelect.value) { timeSelect.value = String(best); show(); }
  });
  show();
  const select = (body, k) => {
    bodySelect.value = String(diagrams.bodies.findIndex((b) => b.name === body));
    timeSelect.value = String(k);
    show();
  };
  return { section, show, select };
}
