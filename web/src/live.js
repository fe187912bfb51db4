// The live report (docs/report.md, "The live report"): the model file's numbers as sliders with
// their units. A change re-runs the model in the page's own engine (momenta compiled to
// WebAssembly, inlined in the page: window.createMomentaEngine) and the page redraws every panel
// from the new data, as `momenta report` would have written it for the changed file. The URL's
// hash holds the changed numbers (a link reproduces the page); a button writes the changed file.

import { element, formatNumber } from './data.js';

const kSteps = 1000;  // a slider's positions

// The engine the page inlines: its module's script defines window.createMomentaEngine, and its
// wasm is in the page gzipped, in base64 (cmake/embed_engine.mjs), unzipped here by the browser.
export async function loadEngine() {
  const text = document.getElementById('momenta-engine').textContent;
  const zipped = Uint8Array.from(atob(text), (c) => c.charCodeAt(0));
  const stream = new Blob([zipped]).stream().pipeThrough(new DecompressionStream('gzip'));
  const wasmBinary = new Uint8Array(await new Response(stream).arrayBuffer());
  return window.createMomentaEngine({ wasmBinary });
}

// The slider position of a value, and back, on the parameter's scale (log or linear).
function toPosition(p, value) {
  const f = p.scale === 'log' ? Math.log(value / p.min) / Math.log(p.max / p.min)
    : (value - p.min) / (p.max - p.min);
  return Math.round(Math.min(1, Math.max(0, f)) * kSteps);
}

function fromPosition(p, position) {
  const f = position / kSteps;
  const value = p.scale === 'log' ? p.min * (p.max / p.min) ** f : p.min + f * (p.max - p.min);
  return Number(value.toPrecision(4));  // a figure a person would type
}

// The overrides the URL's hash holds: #live=path=value&path=value.
export function overridesFromHash(hash, parameters) {
  const match = /(?:^#|&)live=([^#]*)/.exec(hash);
  if (!match) return {};
  const known = new Set(parameters.map((p) => p.path));
  const overrides = {};
  for (const pair of decodeURIComponent(match[1]).split('&')) {
    const [path, text] = pair.split('=');
    const value = Number(text);
    if (known.has(path) && text !== '' && Number.isFinite(value)) overrides[path] = value;
  }
  return overrides;
}

export function hashOf(overrides) {
  const pairs = Object.entries(overrides).map(([path, value]) => `${path}=${value}`);
  return pairs.length ? `#live=${encodeURIComponent(pairs.join('&'))}` : '';
}

// The panel: one row per parameter (its path, a slider, a field, its unit), the status of the
// last run, a reset and a download of the changed model file. `rerun(overrides)` is called with
// {path: value} of every number that differs from the file's; it returns a promise of the status
// text, or throws the engine's message (shown, the page left as it was).
export function liveSection(live, rerun, download) {
  const section = element('section', { id: 'live' }, element('h2', {}, 'Live model'));
  if (!live.available) {
    section.append(element('p', { class: 'note' }, `Not live: ${live.reason}.`));
    return { section, overrides: () => ({}), set: async () => {} };
  }
  section.append(element('p', { class: 'note' },
    `Change a number of ${live.file}: the page runs the model again in its own engine and redraws `
    + 'every panel. The equations keep their symbols; their values, and the equations with the '
    + 'numbers, follow where the change keeps the equations\' form.'));
  const overrides = {};
  const status = element('p', { class: 'live-status', role: 'status' }, '');
  const rows = new Map();
  let running = Promise.resolve();
  const apply = () => {
    running = running.then(async () => {
      status.classList.remove('error');
      status.textContent = 'running…';
      try {
        status.textContent = await rerun({ ...overrides });
        history.replaceState(null, '', hashOf(overrides) || location.pathname + location.search);
      } catch (e) {
        status.classList.add('error');
        status.textContent = String(e.message ?? e);
      }
    });
    return running;
  };
  const setValue = (p, value, from) => {
    const row = rows.get(p.path);
    if (from !== 'slider') row.slider.value = String(toPosition(p, value));
    if (from !== 'field') row.field.value = String(value);
    if (value === p.value) delete overrides[p.path];
    else overrides[p.path] = value;
    row.holder.classList.toggle('changed', value !== p.value);
  };
  const list = element('div', { class: 'live-parameters' });
  for (const p of live.parameters) {
    const slider = element('input', { type: 'range', min: '0', max: String(kSteps), step: '1',
      value: String(toPosition(p, p.value)), 'aria-label': p.path });
    const field = element('input', { type: 'number', value: String(p.value), step: 'any',
      'aria-label': `${p.path} (${p.unit})` });
    slider.addEventListener('input', () => setValue(p, fromPosition(p, Number(slider.value)), 'slider'));
    slider.addEventListener('change', () => apply());
    field.addEventListener('change', () => {
      const value = Number(field.value);
      if (field.value === '' || !Number.isFinite(value)) { field.value = String(overrides[p.path] ?? p.value); return; }
      setValue(p, value, 'field');
      apply();
    });
    const holder = element('label', { class: 'live-parameter', 'data-path': p.path },
      element('span', { class: 'live-path', title: `line ${p.line} of ${live.file}` }, p.path),
      slider, field, element('span', { class: 'live-unit' }, p.unit));
    rows.set(p.path, { slider, field, holder, parameter: p });
    list.append(holder);
  }
  const reset = element('button', { type: 'button', onclick: () => {
    for (const { parameter } of rows.values()) setValue(parameter, parameter.value);
    apply();
  } }, 'Reset to the file');
  const save = element('button', { type: 'button', onclick: () => download({ ...overrides }) },
    `Download the changed ${live.file}`);
  section.append(list, element('div', { class: 'live-actions' }, reset, save), status);
  return {
    section,
    overrides: () => ({ ...overrides }),
    // Sets numbers by path (as the hash or a test does) and runs once.
    set: (values) => {
      for (const [path, value] of Object.entries(values)) {
        const row = rows.get(path);
        if (!row) throw new Error(`no live parameter '${path}'`);
        setValue(row.parameter, value);
      }
      return apply();
    },
    status: () => ({ text: status.textContent, error: status.classList.contains('error') }),
    formatValue: (x) => formatNumber(x),
  };
}
