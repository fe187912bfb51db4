// The mass-properties page: the part drawn from its parts (holes as dark wireframes), the centre
// of mass, the principal axes and the equivalent inertia ellipsoid; the table of parts and the
// tensors about the centre of mass and about the requested point.

import * as THREE from 'three';
import { element, formatNumber, table } from './data.js';
import { bodyColor, equivalentMesh, partMesh } from './shapes.js';
import { Viewer } from './viewer.js';

function matrixTable(M) {
  return table(['', 'x', 'y', 'z'], ['x', 'y', 'z'].map((r, i) => [r, ...[0, 1, 2].map((j) => formatNumber(M[3 * i + j], 6))]));
}

export function inertiaPage(app, data) {
  app.append(element('h1', {}, data.name), element('p', {}, `Mass properties of ${data.file}, in the part's frame B (SI units; off-diagonals are minus the products of inertia).`));
  const view = element('div', { id: 'view', class: 'view' });
  app.append(element('section', {}, view));
  const extent = Math.max(1e-6, ...data.parts.flatMap((p) => [Math.hypot(...p.p), ...Object.values(p.sizes)]),
    ...(data.equivalent ? data.equivalent.semi_axes : [0]));
  const viewer = new Viewer(view, extent);
  data.parts.forEach((part, i) => {
    const mesh = partMesh(part, bodyColor(i), extent);
    if (mesh) viewer.scene.add(mesh);
  });
  if (data.equivalent) {
    const e = equivalentMesh(data.equivalent, 0xffd700, extent);
    e.material.opacity = 0.25;
    e.material.depthWrite = false;
    viewer.scene.add(e);
  }
  const com = new THREE.Mesh(new THREE.SphereGeometry(0.03 * extent, 16, 8), new THREE.MeshBasicMaterial({ color: 0x000000 }));
  com.position.set(...data.com);
  viewer.scene.add(com);
  const R = data.principal_axes;
  [0xd62728, 0x2ca02c, 0x1f77b4].forEach((color, k) => {
    viewer.scene.add(new THREE.ArrowHelper(new THREE.Vector3(R[k], R[3 + k], R[6 + k]), new THREE.Vector3(...data.com),
      0.8 * extent, color, 0.1 * extent, 0.05 * extent));
  });
  viewer.frame([data.com, ...data.parts.map((p) => p.p)].map((p) => p.map((x) => x)));
  let frames = 0;
  const animate = () => { viewer.render(); frames++; requestAnimationFrame(animate); };
  requestAnimationFrame(animate);
  app.append(element('p', { class: 'note' }, 'Black dot: centre of mass. Arrows: principal axes 1, 2, 3 (red, green, blue; moments ascending). Gold: the uniform ellipsoid with the same mass and inertia. Dark wireframes: holes.'));
  const facts = element('section', {}, element('h2', {}, 'The part'),
    element('dl', { class: 'facts' }, element('dt', {}, 'mass'), element('dd', {}, `${formatNumber(data.mass, 8)} kg`),
      element('dt', {}, 'centre of mass'), element('dd', {}, `[${data.com.map((x) => formatNumber(x, 8)).join(', ')}] m`),
      element('dt', {}, 'principal moments'), element('dd', {}, `${data.principal_moments.map((x) => formatNumber(x, 8)).join(', ')} kg·m²`)),
    element('h3', {}, 'Inertia about the centre of mass (kg·m²)'), matrixTable(data.inertia_com));
  if (data.about) facts.append(element('h3', {}, `Inertia about [${data.about.join(', ')}] m (kg·m²)`), matrixTable(data.inertia_about));
  facts.append(element('h3', {}, 'Parts'), table(['part', 'kind', 'line', 'mass (kg)', 'centre of mass (m)', ''],
    data.parts.map((p) => [p.name, p.kind, p.line, formatNumber(p.mass), `[${p.com.map((x) => formatNumber(x, 5)).join(', ')}]`, p.hole ? 'hole' : ''])));
  app.append(facts);
  return { kind: 'inertia', framesDrawn: () => frames, ready: true };
}
