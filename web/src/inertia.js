// The mass-properties page: the part drawn from its parts (holes as dark wireframes), the centre
// of mass, the principal axes and the equivalent inertia ellipsoid; the table of parts and the
// tensors about the centre of mass and about the requested point.

import * as THREE from 'three';
import { element, formatNumber, shownValue, table } from './data.js';
import { chart } from './plots.js';
import { bodyColor, equivalentMesh, partMesh } from './shapes.js';
import { Viewer, boxCorners } from './viewer.js';

// A tensor's entries, round-off against its largest written 0.
function matrixTable(M) {
  const scale = Math.max(...M.map(Math.abs));
  return table(['', 'x', 'y', 'z'], ['x', 'y', 'z'].map((r, i) => [r, ...[0, 1, 2].map((j) => formatNumber(shownValue(M[3 * i + j], scale), 6))]));
}

export function inertiaPage(app, data) {
  app.append(element('h1', {}, data.name), element('p', {}, `Mass properties of ${data.file}, in the part's frame B (SI units; off-diagonals are minus the products of inertia).`));
  const view = element('div', { id: 'view', class: 'view' });
  app.append(element('section', {}, view));
  const extent = Math.max(1e-6, ...data.parts.flatMap((p) => [Math.hypot(...p.p), ...Object.values(p.sizes)]),
    ...(data.equivalent ? data.equivalent.semi_axes : [0]));
  const viewer = new Viewer(view, extent);
  // The box around every solid drawn (holes and the equivalent ellipsoid aside): what the camera
  // frames, and what the centre-of-mass dot and the principal axes are sized to.
  const solids = new THREE.Box3();
  data.parts.forEach((part, i) => {
    const mesh = partMesh(part, bodyColor(i), extent);
    if (!mesh) return;
    viewer.scene.add(mesh);
    if (!part.hole) solids.expandByObject(mesh);
  });
  solids.expandByPoint(new THREE.Vector3(...data.com));
  const radius = Math.max(0.5 * solids.getSize(new THREE.Vector3()).length(), 1e-6);
  if (data.equivalent) {
    const e = equivalentMesh(data.equivalent, 0xffd700, extent);
    e.material.opacity = 0.25;
    e.material.depthWrite = false;
    viewer.scene.add(e);
  }
  const com = new THREE.Mesh(new THREE.SphereGeometry(0.03 * radius, 16, 8), new THREE.MeshBasicMaterial({ color: 0x000000 }));
  com.position.set(...data.com);
  viewer.scene.add(com);
  const R = data.principal_axes;
  [0xd62728, 0x2ca02c, 0x1f77b4].forEach((color, k) => {
    viewer.scene.add(new THREE.ArrowHelper(new THREE.Vector3(R[k], R[3 + k], R[6 + k]), new THREE.Vector3(...data.com),
      0.6 * radius, color, 0.08 * radius, 0.04 * radius));
  });
  viewer.frame(boxCorners(solids));
  let frames = 0;
  const animate = () => { if (viewer.renderIfStale()) frames++; requestAnimationFrame(animate); };
  requestAnimationFrame(animate);
  app.append(element('p', { class: 'note' }, 'Black dot: centre of mass. Arrows: principal axes 1, 2, 3 (red, green, blue; moments ascending). Gold: the uniform ellipsoid with the same mass and inertia. Dark wireframes: holes.'));
  const facts = element('section', {}, element('h2', {}, 'The part'),
    element('dl', { class: 'facts' }, element('dt', {}, 'mass'), element('dd', {}, `${formatNumber(data.mass, 8)} kg`),
      element('dt', {}, 'centre of mass'), element('dd', {}, `[${data.com.map((x) => formatNumber(shownValue(x, extent), 8)).join(', ')}] m`),
      element('dt', {}, 'principal moments'), element('dd', {}, `${data.principal_moments.map((x) => formatNumber(shownValue(x, Math.max(...data.principal_moments)), 8)).join(', ')} kg·m²`)),
    element('h3', {}, 'Inertia about the centre of mass (kg·m²)'), matrixTable(data.inertia_com));
  if (data.about) facts.append(element('h3', {}, `Inertia about [${data.about.join(', ')}] m (kg·m²)`), matrixTable(data.inertia_about));
  facts.append(element('h3', {}, 'Parts'), table(['part', 'kind', 'line', 'mass (kg)', 'centre of mass (m)', ''],
    data.parts.map((p) => [p.name, p.kind, p.line, formatNumber(p.mass), `[${p.com.map((x) => formatNumber(shownValue(x, extent), 5)).join(', ')}]`, p.hole ? 'hole' : ''])));
  app.append(facts);
  if (data.balance) app.append(balanceSection(data.balance, viewer, extent));
  return { kind: 'inertia', framesDrawn: () => frames, balance: () => data.balance, ready: true };
}

// --- Balancing (momenta balance --report) ------------------------------------------------------

const RPM = (2 * Math.PI) / 60;
const degrees = (v) => (Math.atan2(v[1], v[0]) * 180) / Math.PI;
const amplitude = (v) => Math.hypot(v[0], v[1]);

// A point of the rotor's axis frame R (z along the axis from the axis point) in the part frame B.
function inPart(b, x, y, z) {
  const R = b.R_BR;
  return [0, 1, 2].map((i) => b.through[i] + R[3 * i] * x + R[3 * i + 1] * y + R[3 * i + 2] * z);
}

function rotating(v, unit) {
  return amplitude(v) === 0 ? `0 ${unit}` : `${formatNumber(amplitude(v), 6)} ${unit} at ${formatNumber(degrees(v), 4)}°`;
}

// The axis through the bearings, the bearing planes as rings and the correction masses as
// spheres at their radius and angle, in the 3-D view. Returns the points drawn, to be framed.
function drawBalance(b, viewer, extent) {
  const drawn = [];
  const planes = [...(b.bearings || []), ...b.corrections.map((c) => c.z), b.axial_com];
  const lo = Math.min(...planes) - 0.2 * extent;
  const hi = Math.max(...planes) + 0.2 * extent;
  const axis = new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(...inPart(b, 0, 0, lo)), new THREE.Vector3(...inPart(b, 0, 0, hi))]);
  drawn.push(inPart(b, 0, 0, lo), inPart(b, 0, 0, hi));
  viewer.scene.add(new THREE.Line(axis, new THREE.LineDashedMaterial({ color: 0x444444, dashSize: 0.05 * extent, gapSize: 0.03 * extent })).computeLineDistances());
  const ring = (z, color) => {
    const points = [];
    for (let k = 0; k <= 48; k++) {
      const a = (2 * Math.PI * k) / 48;
      points.push(new THREE.Vector3(...inPart(b, 0.35 * extent * Math.cos(a), 0.35 * extent * Math.sin(a), z)));
    }
    drawn.push(...points.map((p) => p.toArray()));
    viewer.scene.add(new THREE.Line(new THREE.BufferGeometry().setFromPoints(points), new THREE.LineBasicMaterial({ color })));
  };
  (b.bearings || []).forEach((z) => ring(z, 0x1f77b4));
  for (const c of b.corrections) {
    const r = b.radius || 0.3 * extent;
    const sign = b.remove ? -1 : 1;
    const a = Math.atan2(sign * c.mass_radius[1], sign * c.mass_radius[0]);
    const sphere = new THREE.Mesh(new THREE.SphereGeometry(0.04 * extent, 16, 8), new THREE.MeshBasicMaterial({ color: b.remove ? 0x555555 : 0xd62728 }));
    sphere.position.set(...inPart(b, r * Math.cos(a), r * Math.sin(a), c.z));
    viewer.scene.add(sphere);
    drawn.push(sphere.position.toArray());
    ring(c.z, 0xd62728);
  }
  return drawn;
}

function gradeTable(g, title) {
  const verdict = (ok) => (ok ? 'ok' : 'over');
  return element('div', {}, element('h3', {}, `${title}: ${g.pass ? 'PASS' : 'FAIL'}`),
    element('p', {}, `G ${formatNumber(g.grade, 4)} mm/s at ${formatNumber(g.omega / RPM, 6)} rev/min: U_per = ${formatNumber(g.permissible, 6)} kg·m${g.overhung ? ' (overhung rotor: U_per/2 allowed per plane)' : ''}.`),
    table(['plane', 'residual unbalance', 'allowed (kg·m)', ''], [
      ['A', rotating(g.plane_A, 'kg·m'), formatNumber(g.permissible_A, 6), verdict(amplitude(g.plane_A) <= g.permissible_A)],
      ['B', rotating(g.plane_B, 'kg·m'), formatNumber(g.permissible_B, 6), verdict(amplitude(g.plane_B) <= g.permissible_B)]]));
}

export function balanceSection(b, viewer, extent) {
  // The bearings, axis and correction masses join what the camera frames.
  viewer.frame([...boxCorners(viewer.framed.box), ...drawBalance(b, viewer, extent)]);
  const section = element('section', { id: 'balance' }, element('h2', {}, 'Balancing'),
    element('p', { class: 'note' }, 'Angles in the rotor, from x_R towards y_R; axial positions z along the axis. Dashed: the axis; blue rings: bearings; red: correction planes and masses (grey: mass to remove).'),
    element('dl', { class: 'facts' },
      element('dt', {}, 'eccentricity'), element('dd', {}, `${formatNumber(b.eccentricity, 6)} m (centre of mass at z = ${formatNumber(b.axial_com, 6)} m)`),
      element('dt', {}, 'static unbalance'), element('dd', {}, rotating(b.static_unbalance, 'kg·m')),
      element('dt', {}, 'couple unbalance'), element('dd', {}, rotating(b.couple_unbalance, 'kg·m²')),
      element('dt', {}, 'principal axis tilt'), element('dd', {}, `${formatNumber(b.principal_axis_tilt, 6)} rad`)));
  if (b.corrections.length) {
    section.append(element('h3', {}, `${b.corrections.length === 2 ? 'Two' : 'Single'}-plane correction (${b.remove ? 'remove' : 'add'})`),
      table(['plane z (m)', 'm·r (kg·m)', 'angle', b.radius ? `mass at r = ${formatNumber(b.radius, 4)} m` : ''],
        b.corrections.map((c) => {
          const v = b.remove ? c.mass_radius.map((x) => -x) : c.mass_radius;
          return [formatNumber(c.z, 6), formatNumber(amplitude(v), 6), `${formatNumber(degrees(v), 4)}°`,
            b.radius ? `${formatNumber((1000 * amplitude(v)) / b.radius, 6)} g` : ''];
        })));
  }
  if (b.grade) section.append(gradeTable(b.grade, 'Balance grade'));
  if (b.grade_after) section.append(gradeTable(b.grade_after, 'After the correction'));
  if (b.reactions.length > 1) {
    const rows = [...b.reactions].sort((p, q) => p.omega - q.omega);
    const holder = element('div', { class: 'plot' });
    section.append(element('div', { class: 'plot-grid' }, holder));
    const series = [{ name: '|A| (N)', data: rows.map((r) => amplitude(r.A)) },
      { name: '|B| (N)', data: rows.map((r) => amplitude(r.B)) }];
    if (rows[0].A_after) {
      series.push({ name: '|A| after (N)', data: rows.map((r) => amplitude(r.A_after)) },
        { name: '|B| after (N)', data: rows.map((r) => amplitude(r.B_after)) });
    }
    requestAnimationFrame(() => chart(holder, { title: 'Bearing forces against speed', xLabel: 'rev/min', yLabel: 'N',
      x: rows.map((r) => r.omega / RPM), series }));
  } else if (b.reactions.length === 1) {
    const r = b.reactions[0];
    section.append(element('p', {}, `At ${formatNumber(r.omega / RPM, 6)} rev/min the bearings push with A ${rotating(r.A, 'N')} and B ${rotating(r.B, 'N')}, turning with the rotor.`));
  }
  return section;
}
