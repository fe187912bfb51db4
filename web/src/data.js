// Reads the report's data: the JSON the library wrote into the page, with long arrays as
// "f64:<base64>" / "f32:<base64>" of little-endian IEEE values (src/report/page_data.hpp).

export function readData() {
  const element = document.getElementById('momenta-data');
  return JSON.parse(element.textContent);
}

export function decode(text) {
  if (typeof text !== 'string') return text;
  const kind = text.slice(0, 4);
  const binary = atob(text.slice(4));
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  if (kind === 'f64:') return new Float64Array(bytes.buffer);
  if (kind === 'f32:') return new Float32Array(bytes.buffer);
  throw new Error(`unknown array encoding ${kind}`);
}

// x as text shows it: 0 where |x| ≤ 1e-12 of `scale`, the scale of the computation it comes from
// (the round-off of a symmetric part's products of inertia); the rule of the command line
// (momenta/common/number_text.hpp, kRoundOffRelative).
export function shownValue(x, scale) {
  return Math.abs(x) <= 1e-12 * Math.abs(scale) ? 0 : x;
}

export function formatNumber(x, digits = 6) {
  if (x === null || x === undefined) return '—';
  if (typeof x === 'string') return x;
  if (x === 0) return '0';
  const magnitude = Math.abs(x);
  if (magnitude >= 1e-3 && magnitude < 1e6) return Number(x.toPrecision(digits)).toString();
  return Number(x.toPrecision(digits)).toExponential();  // 1e+6, not 1.0000000e+6
}

export function element(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [key, value] of Object.entries(attributes)) {
    if (key === 'class') node.className = value;
    else if (key.startsWith('on')) node.addEventListener(key.slice(2), value);
    else node.setAttribute(key, value);
  }
  for (const child of children) {
    if (child === null || child === undefined) continue;
    node.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return node;
}

const SVG = 'http://www.w3.org/2000/svg';

// An SVG element with its attributes and children (the pages' own diagrams: sweep, heat map).
export function svg(tag, attributes = {}, ...children) {
  const node = document.createElementNS(SVG, tag);
  for (const [key, value] of Object.entries(attributes)) node.setAttribute(key, value);
  for (const child of children) node.append(child);
  return node;
}

export function table(headers, rows) {
  return element('table', {},
    element('thead', {}, element('tr', {}, ...headers.map((h) => element('th', {}, h)))),
    element('tbody', {}, ...rows.map((r) => element('tr', {}, ...r.map((c) => element('td', {}, c))))));
}
