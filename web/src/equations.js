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

function mathml(latex) {
  return katex.renderToString(latex, { output: 'mathml', throwOnError: false });
}

// An equation's lines set into `holder`, continuation lines indented (the browser's MathML sets
// each line; it does not align the columns of a multi-line block).
function setLines(holder, latex) {
  for (const [k, line] of equationLines(latex).entries()) {
    const row = element('div', { class: k === 0 ? 'line' : 'line continued' });
    row.innerHTML = mathml(line);
    holder.append(row);
  }
}

function math(latex) {
  const holder = element('div', { class: 'equation' });
  setLines(holder, latex);
  return holder;
}

// An equation in symbols longer than this many LaTeX characters (some 90 lines of LINE) is
// folded: set when the reader opens it. The flyball governor's longest is 142 040 characters and
// 64 000 MathML elements; laying out three such took Chromium 4 s of its page's 9 s opening.
const kFoldedLatex = 20000;

// The braced group that opens at latex[open] ('{'), with its braces; '' if it is not closed.
function bracedGroup(latex, open) {
  let depth = 0;
  for (let i = open; i < latex.length; i++) {
    if (latex[i] === '{') depth++;
    else if (latex[i] === '}' && --depth === 0) return latex.slice(open, i + 1);
  }
  return '';
}

// The acceleration an equation is led by — its first \ddot{…} with the subscript after it — as
// LaTeX; '' if it has none.
function leadingAcceleration(latex) {
  const start = latex.indexOf('\\ddot{');
  if (start < 0) return '';
  const argument = bracedGroup(latex, start + 5);
  if (!argument) return '';
  const end = start + 5 + argument.length;
  const subscript = latex.startsWith('_{', end) ? bracedGroup(latex, end + 1) : '';
  return latex.slice(start, end) + (subscript ? `_${subscript}` : '');
}

// An equation in symbols: set, or folded where it is longer than kFoldedLatex — a summary naming
// its acceleration and its length, the lines set the first time it is opened.
function symbolicEquation(latex) {
  if (latex.length <= kFoldedLatex) return math(latex);
  const lead = leadingAcceleration(latex);
  const summary = element('summary', {}, lead ? 'The equation led by ' : 'An equation ',
    lead ? inlineMath(lead) : null, `: ${latex.length.toLocaleString('en')} characters of LaTeX, `
    + 'set when opened (momenta equations MODEL --all-symbols prints it)');
  const holder = element('details', { class: 'equation folded' }, summary);
  holder.addEventListener('toggle', () => {
    if (holder.open && !holder.querySelector('.line')) setLines(holder, latex);
  });
  return holder;
}

function inlineMath(latex) {
  const holder = element('span', {});
  holder.innerHTML = mathml(latex);
  return holder;
}

// A coefficient as LaTeX: four significant figures, powers of ten beyond 1e5 and below 1e-3.
export function numberLatex(x) {
  const magnitude = Math.abs(x);
  if (magnitude >= 1e-3 && magnitude < 1e5) return Number(x.toPrecision(4)).toString();
  const [mantissa, exponent] = x.toExponential(3).split('e');
  const shown = Number(mantissa).toString();
  return `${shown === '1' ? '' : `${shown} \\times `}10^{${Number(exponent)}}`;
}

// A term's coefficient at the parameters' `values`: Σ factor × Π value[p]^e.
export function coefficientAt(c, values) {
  let sum = 0;
  for (const [factor, powers] of c) {
    let product = factor;
    for (let k = 0; k < powers.length; k += 2) product *= values[powers[k]] ** powers[k + 1];
    sum += product;
  }
  return sum;
}

// One side of an equation with numbers: its terms' coefficients at `values`, a term whose
// coefficient is 0 left out, a coefficient ±1 not written, a constant as its number; "0" when
// nothing is left.
function sideLatex(terms, values) {
  let text = '';
  for (const term of terms) {
    const c = coefficientAt(term.c, values);
    if (c === 0) continue;
    const size = numberLatex(Math.abs(c));
    const body = term.latex === '1' ? size : size === '1' ? term.latex : `${size}\\,${term.latex}`;
    text += text === '' ? (c < 0 ? `-${body}` : body) : (c < 0 ? ` - ${body}` : ` + ${body}`);
  }
  return text || '0';
}

// An equation with its parameters' `values` put in (EquationTerm: equations_section.cpp).
export function equationWithNumbers(terms, values) {
  return `${sideLatex(terms.filter((t) => !t.right), values)} = ${sideLatex(terms.filter((t) => t.right), values)}`;
}

// `head` false: the section without its head in symbols (title, note, equations), for a live
// page that keeps the one it shows (main.js, equationsPanel).
export function equationsSection(equations, { head = true } = {}) {
  const section = element('section', { id: 'equations' }, element('h2', {}, 'Equations of motion'));
  if (!equations || !equations.available) {
    section.append(element('p', { class: 'unavailable' }, `Not shown: ${equations ? equations.reason : 'not in this report'}`));
    return { section };
  }
  // The head, in symbols (class in-symbols): the same whatever a live page changes, which keeps
  // it across a redraw (main.js, equationsPanel); `symbolsOf` says which equations it shows.
  if (head) {
    section.symbolsOf = equations.equations;
    section.firstElementChild.classList.add('in-symbols');
    section.append(element('p', { class: 'note in-symbols' },
      'M(q) q̈ + C(q, q̇) q̇ + g(q) = Q, derived in symbols from the model (momenta equations MODEL --all-symbols): ',
      'one equation per free coordinate, led by its own acceleration',
      equations.constraints.length ? ', with the constraint forces Gᵀλ on the right, then the constraints' : '', '.'));
    for (const e of equations.equations) {
      const shown = symbolicEquation(e.latex);
      shown.classList.add('in-symbols');
      section.append(shown);
    }
  } else {
    section.firstElementChild.remove();
  }
  // The page's numbers where its changes keep the equations' form, else the file's.
  const numbers = equations.numbers;
  const pageValues = numbers?.formChanges.length === 0;
  // A value within 1e-12 of the file's is the file's (the engine's libm differs from the
  // native build's in the last bit of sin and cos: a rotated part's inertia).
  const values = equations.parameters.map((p, k) => {
    const v = pageValues ? numbers.values[k] : p.value;
    return Math.abs(v - p.value) <= 1e-12 * Math.abs(p.value) ? p.value : v;
  });
  if (equations.equations.some((e) => e.terms)) {
    section.append(element('h3', {}, 'With the numbers'));
    section.append(element('p', { class: 'note' },
      `The equations above with the symbols' values ${pageValues ? 'the page\'s changes give' : 'the file gives'} (four figures, SI units)`,
      equations.equations.some((e) => !e.terms)
        ? '; an equation with a parameter inside a function (√(L² + …), sin(q − rest)) or of more than 40 terms is not written again.' : '.'));
    const holder = element('div', { class: 'with-numbers' });
    for (const e of equations.equations) if (e.terms) holder.append(math(equationWithNumbers(e.terms, values)));
    section.append(holder);
  }
  if (equations.constraints.length) {
    section.append(element('h3', {}, 'Constraints'));
    for (const c of equations.constraints) {
      section.append(element('p', { class: 'note' }, `${c.name} (${c.holonomic ? 'position' : 'velocity'})`), math(c.latex));
    }
  }
  if (equations.parameters.length) {
    const rows = equations.parameters.map((p, k) => [inlineMath(p.latex),
      formatNumber(values[k], 8) + (values[k] !== p.value ? ` (file: ${formatNumber(p.value, 8)})` : ''),
      p.unit || '—']);
    const symbols = table(['symbol', 'value', 'unit'], rows);
    symbols.classList.add('symbols');
    equations.parameters.forEach((p, k) => {
      if (values[k] !== p.value) symbols.tBodies[0].rows[k].classList.add('changed');
    });
    section.append(element('h3', {}, 'Symbols'));
    // On a live page after a change: the changed model's values, where the equations keep their
    // form; where they do not, the file's, and why.
    if (equations.changed?.length && pageValues && numbers.zeroed.length) {
      section.append(element('p', { class: 'note' },
        `The values with the page's changes (${equations.changed.join(', ')}): ${numbers.zeroed.join(', ')} `
        + `${numbers.zeroed.length > 1 ? 'are' : 'is'} 0 — the terms above that hold ${numbers.zeroed.length > 1 ? 'them' : 'it'} `
        + 'are 0, and the equations with the numbers leave them out.'));
    } else if (equations.changed?.length && pageValues) {
      section.append(element('p', { class: 'note' },
        `The values with the page's changes (${equations.changed.join(', ')}): the equations keep their form.`));
    } else if (equations.changed?.length) {
      section.append(element('p', { class: 'note stale' },
        `The values as the file gives them: the page's changes (${equations.changed.join(', ')}) change the equations' form`,
        numbers ? ` (${numbers.formChanges.join('; ')})` : '',
        '. The equations above are the file\'s; momenta equations on the downloaded file derives the new ones.'));
    }
    section.append(symbols);
  }
  return { section };
}
