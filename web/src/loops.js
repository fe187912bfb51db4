// The feedback loops of a model with controllers: each drawn by the library as a block diagram
// (SVG: reference, summing junction, law, hold, actuator, mechanism, sensor), beside the motion.

import { element } from './data.js';

export function loopsSection(loops) {
  const section = element('section', { id: 'loops' }, element('h2', {}, 'Feedback loops'));
  section.append(element('p', {},
    'Each controller of the model closes a loop around the mechanism: its reference, error and control effort ',
    'are plotted under "Loop …" below.'));
  for (const loop of loops) {
    const picture = element('div', { class: 'diagram loop', 'data-controller': loop.name });
    // The SVG is the library's own output (names escaped there).
    picture.innerHTML = loop.svg;
    section.append(picture);
  }
  return section;
}
