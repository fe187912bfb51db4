// The equations panel: the model's equations of motion as momenta derives them (`momenta
// equations MODEL --all-symbols`), set by KaTeX as MathML (the browser's own math layout: no
// fonts to embed), long ones broken at their terms; the constraints' rows; the symbols' values.

import katex from 'katex';
import { element, formatNumber, table } from './data.js';

const LINE = 220; // LaTeX characters per displayed line, about 70 printed symbols

// The top-level terms of a LaTeX expression: split before ' + ' and ' - ' outside braces and
// \left…\right pairs (the printer writes a sum's terms so).
export function topLevelTerms(latex) {
  const terms = [];
  let depth = 0;
  let start = 0;
  for (let i = 0; i < latex.length; i++) {
    if (latex[i] === '{' || latex.startsWith('\\left', i)) depth++;
    else if (latex[i] === '}' || latex.startsWith('\\right', i)) depth--;
    else if (depth === 0 && i > start && (latex.startsWith(' + ', i) || latex.startsWith(' - ', i))) {
      terms.push(latex.slice(start, i));
      start = i + 1;
    }
  }
  terms.push(latex.slice(start));
  return terms;
}

// An equation's lines, each at most about LINE characters of LaTeX and each whole (broken only
// between top-level terms, so every line sets on its own).
export function equationLines(latex) {
  const eq = latex.indexOf(' = ');
  const [left, right] = eq < 0 ? [latex, ''] : [latex.slice(0, eq), latex.slice(eq + 1)];
  const lines = [];
  let line = '';
  for (const term of [...topLevelTerms(left), ...(right ? [right] : [])]) {
    if (line && line.length + term.length > LINE) {
      lines.push(line);
      line = '';
    }
    line += (line ? ' ' : '') + term;
  }
  lines.push(line);
  return lines;
}

// One equation, its continuation lines indented (the browser's MathML sets each line; it does
// not align the columns of a multi-line block).
function math(latex) {
  const holder = element('div', { class: 'equation' });
  for (const [k, line] of equationLines(latex).entries()) {
    const row = element('div', { class: k === 0 ? 'line' : 'line continued' });
    row.innerHTML = katex.renderToString(line, { output: 'mathml', throwOnError: false });
    holder.append(row);
  }
  return holder;
}

function inlineMath(latex) {
  const holder = element('span', {});
  holder.innerHTML = katex.renderToString(latex, { output: 'mathml', throwOnError: false });
  return holder;
}

export function equationsSection(equations) {
  const section = element('section', { id: 'equations' }, element('h2', {}, 'Equations of motion'));
  if (!equations || !equations.available) {
    section.append(element('p', { class: 'unavailable' }, `Not shown: ${equations ? equations.reason : 'not in this report'}`));
    return { section };
  }
  section.append(element('p', { class: 'note' },
    'M(q) q̈ + C(q, q̇) q̇ + g(q) = Q, derived in symbols from the model (momenta equations MODEL --all-symbols): ',
    'one equation per free coordinate, led by its own acceleration',
    equations.constraints.length ? ', with the constraint forces Gᵀλ on the right, then the constraints' : '', '.'));
  for (const e of equations.equations) section.append(math(e.latex));
  if (equations.constraints.length) {
    section.append(element('h3', {}, 'Constraints'));
    for (const c of equations.constraints) {
      section.append(element('p', { class: 'note' }, `${c.name} (${c.holonomic ? 'position' : 'velocity'})`), math(c.latex));
    }
  }
  if (equations.parameters.length) {
    const rows = equations.parameters.map((p) => [inlineMath(p.latex), formatNumber(p.value, 8), p.unit || '—']);
    const values = table(['symbol', 'value', 'unit'], rows);
    values.classList.add('symbols');
    section.append(element('h3', {}, 'Symbols'));
    // On a live page after a change: the equations hold for any values, these are the file's.
    if (equations.changed?.length) {
      section.append(element('p', { class: 'note stale' },
        `The values as the file gives them: the page's changes (${equations.changed.join(', ')}) are not substituted here; the equations above hold for any values.`));
    }
    section.append(values);
  }
  return { section };
}
