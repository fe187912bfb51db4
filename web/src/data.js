// Reads the report's data: the JSON the library wrote into the page, with long arrays as
// "f64:<base64>" / "f32:<base64>" of little-endian IEEE values (src/report/page_data.hpp).

export function readData() {
  const element = document.getElementById('momenta-data');
  return JSON.parse(element.textContent);
}

export function decode(text) {
  if (typeof text !== 'string') return text;
  const kind = text.slice(0, 4);
  const bytes = base64Bytes(text, 4);
  if (kind === 'f64:') return new Float64Array(bytes.buffer);
  if (kind === 'f32:') return new Float32Array(bytes.buffer);
  throw new Error(`unknown array encoding ${kind}`);
}

// The live page's report data as the engine hands it over with its long arrays apart
// (reportDataParts): the JSON text, where `marker` followed by k stands for arrays[k], a typed
// array, in place of the base64 text a written page holds (decode passes it through).
export function dataWithArrays(json, arrays, marker) {
  return JSON.parse(json, (key, value) => {
    if (typeof value !== 'string' || !value.startsWith(marker)) return value;
    const array = arrays[Number(value.slice(marker.length))];
    if (!array) throw new Error(`report data: no array ${value.slice(marker.length)} of ${arrays.length}`);
    return array;
  });
}

// Base64 (RFC 4648, padded) from `start` of `text` to bytes, by table: atob and a byte-by-byte
// copy of its string took a live page's change 50 ms for the quarter car's 1.7 MB of arrays.
const kBase64Digit = (() => {
  const table = new Int8Array(128).fill(-1);
  const digits = 'ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/';
  for (let i = 0; i < digits.length; i++) table[digits.charCodeAt(i)] = i;
  return table;
})();
function base64Bytes(text, start) {
  const length = text.length - start;
  if (length % 4 !== 0) throw new Error('base64: the length is not a multiple of 4');
  const padding = length === 0 ? 0 : (text[text.length - 1] === '=') + (text[text.length - 2] === '=');
  const bytes = new Uint8Array((length / 4) * 3 - padding);
  const digit = (i) => {
    const code = text.charCodeAt(i);
    const value = code < 128 ? kBase64Digit[code] : -1;
    if (value < 0) throw new Error(`base64: '${text[i]}' at ${i - start} is not a digit`);
    return value;
  };
  let out = 0;
  const whole = padding ? length - 4 : length;
  for (let i = start; i < start + whole; i += 4) {
    const v = (digit(i) << 18) | (digit(i + 1) << 12) | (digit(i + 2) << 6) | digit(i + 3);
    bytes[out++] = v >> 16;
    bytes[out++] = (v >> 8) & 255;
    bytes[out++] = v & 255;
  }
  if (padding) {
    const i = start + whole;
    const v = (digit(i) << 18) | (digit(i + 1) << 12) | (padding === 1 ? digit(i + 2) << 6 : 0);
    bytes[out++] = v >> 16;
    if (padding === 1) bytes[out++] = (v >> 8) & 255;
  }
  return bytes;
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
