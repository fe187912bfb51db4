// The motion of a run in the 3-D view: bodies posed at any time by interpolating the recorded
// poses (linear in position, slerp in rotation; exact at the recorded times), body frames, joint
// axes, massless links, springs as coils and dampers as dashpots, and on request each body's ω
// and H, a body's trajectory, applied loads and joint and constraint reactions as arrows scaled
// with a legend.
// Mode shapes animate in the same view.

import * as THREE from 'three';
import { decode, element, formatNumber } from './data.js';
import { bodyColor, equivalentMesh, partMesh } from './shapes.js';
import { Viewer, makeArrow, setArrow } from './viewer.js';

// Pose arithmetic in float64 (JavaScript numbers): q = [x, y, z, w].
function rotate(q, v) {
  const [x, y, z, w] = q;
  const tx = 2 * (y * v[2] - z * v[1]);
  const ty = 2 * (z * v[0] - x * v[2]);
  const tz = 2 * (x * v[1] - y * v[0]);
  return [v[0] + w * tx + (y * tz - z * ty), v[1] + w * ty + (z * tx - x * tz),
    v[2] + w * tz + (x * ty - y * tx)];
}

function slerp(a, b, t) {
  if (t === 0) return a.slice();
  let dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
  const sign = dot < 0 ? -1 : 1;
  dot *= sign;
  if (dot > 0.9995) {
    const q = a.map((x, i) => x + t * (sign * b[i] - x));
    const n = Math.hypot(...q);
    return q.map((x) => x / n);
  }
  const theta = Math.acos(dot);
  const s = Math.sin(theta);
  const wa = Math.sin((1 - t) * theta) / s;
  const wb = (sign * Math.sin(t * theta)) / s;
  return a.map((x, i) => wa * x + wb * b[i]);
}

export class Motion {
  constructor(container, data, timeline) {
    this.data = data;
    this.scene = data.scene;
    this.timeline = timeline;
    const frames = data.frames;
    this.time = decode(frames.time);
    this.position = decode(frames.position);
    this.quaternion = decode(frames.quaternion);
    this.omega = decode(frames.omega);
    this.bodies = this.scene.bodies;
    this.nb = this.bodies.length;
    // Everything is drawn at the scale of the motion: the radius of the sphere around every body
    // (its centre of mass, joint points and size) over the run, so that arrows, axes and point
    // masses read at the scale the camera frames.
    [this.sweptPoints, this.skeleton] = this.motionPoints();
    this.length = this.radiusOf(this.sweptPoints);
    const g = this.scene.gravity;
    const up = Math.hypot(...g) > 0 ? g.map((x) => -x) : [0, 0, 1];
    this.viewer = new Viewer(container, this.length, up);
    this.mode = null;
    this.buildBodies();
    this.buildJoints();
    this.buildElements();
    this.buildVectors(frames);
    this.show(timeline.time);
    this.viewer.frame(this.sweptPoints, this.skeleton);
    this.buildPlanes();
    timeline.onChange((t) => { if (!this.mode) this.show(t); });
  }

  // Points the bodies sweep, at up to 60 kept frames: each body's centre of mass ± its size
  // along each world axis (1.75 radii of gyration: a slender rod's half length, a sphere's radius
  // and a third), and the joint points J' on it (a massless rod's ends). Returns those and the
  // skeleton alone (centres of mass and joint points).
  motionPoints() {
    const points = [];
    const skeleton = [];
    const step = Math.max(1, Math.floor(this.time.length / 60));
    const anchors = this.bodies.map((body) => [body.com,
      ...this.scene.joints.filter((j) => j.child === body.name).map((j) => j.origin)]);
    const sizes = this.bodies.map((body) => {
      const I = body.inertia;
      return body.mass > 0 ? 1.75 * Math.sqrt(Math.max(0, I[0] + I[4] + I[8]) / (2 * body.mass)) : 0;
    });
    for (let k = 0; k < this.time.length; k += step) {
      for (let b = 0; b < this.nb; b++) {
        for (const a of anchors[b]) skeleton.push(this.bodyPoint(b, a, this.time[k]));
        const c = this.bodyPoint(b, this.bodies[b].com, this.time[k]);
        for (let axis = 0; axis < 3; axis++) {
          for (const sign of [-1, 1]) points.push(c.map((x, i) => (i === axis ? x + sign * sizes[b] : x)));
        }
      }
    }
    // A run that blew up leaves rows of huge or non-finite values: not to be framed (the view's
    // geometry is float32, which overflows near 3e38).
    const bound = Math.min(1e30, 1e9 * this.scene.length);
    const sane = (p) => p.every((x) => Math.abs(x) < bound);
    return [[...skeleton, ...points].filter(sane), skeleton.filter(sane)];
  }

  // Half the diagonal of the points' box (at least 1e-3 of the model's characteristic length).
  radiusOf(points) {
    const lo = [Infinity, Infinity, Infinity];
    const hi = [-Infinity, -Infinity, -Infinity];
    for (const p of points) for (let i = 0; i < 3; i++) { lo[i] = Math.min(lo[i], p[i]); hi[i] = Math.max(hi[i], p[i]); }
    const radius = 0.5 * Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]);
    return Number.isFinite(radius) ? Math.max(radius, 1e-3 * this.scene.length) : this.scene.length;
  }

  // The kept frames around time t: [lo, hi] with time[lo] ≤ t ≤ time[hi] (equal at the ends).
  bracket(t) {
    const times = this.time;
    let lo = 0;
    let hi = times.length - 1;
    if (t <= times[0]) return [0, 0];
    if (t >= times[hi]) return [hi, hi];
    while (hi - lo > 1) {
      const mid = (lo + hi) >> 1;
      if (times[mid] <= t) lo = mid; else hi = mid;
    }
    return [lo, hi];
  }

  // The body's pose at time t: [position, quaternion] (float64).
  pose(b, t) {
    const times = this.time;
    const [lo, hi] = this.bracket(t);
    const p0 = this.position.subarray(3 * (lo * this.nb + b), 3 * (lo * this.nb + b) + 3);
    const q0 = Array.from(this.quaternion.subarray(4 * (lo * this.nb + b), 4 * (lo * this.nb + b) + 4));
    if (lo === hi || t === times[lo]) return [Array.from(p0), q0];
    const a = (t - times[lo]) / (times[hi] - times[lo]);
    const p1 = this.position.subarray(3 * (hi * this.nb + b), 3 * (hi * this.nb + b) + 3);
    const q1 = Array.from(this.quaternion.subarray(4 * (hi * this.nb + b), 4 * (hi * this.nb + b) + 4));
    return [[0, 1, 2].map((i) => p0[i] * (1 - a) + p1[i] * a), slerp(q0, q1, a)];
  }

  // p_WoP_W of the point p_BoP_B of body b at time t.
  bodyPoint(b, point, t) {
    const [p, q] = this.pose(b, t);
    const r = rotate(q, point);
    return [p[0] + r[0], p[1] + r[1], p[2] + r[2]];
  }

  // The last kept frame at or before t.
  frameIndex(t) { return this.bracket(t)[0]; }

  buildBodies() {
    this.groups = this.bodies.map((body, b) => {
      const group = new THREE.Group();
      group.matrixAutoUpdate = true;
      const color = bodyColor(b);
      if (body.parts.length) {
        for (const part of body.parts) {
          const mesh = partMesh(part, color, this.length);
          if (mesh) group.add(mesh);
        }
      } else if (body.equivalent) {
        group.add(equivalentMesh(body.equivalent, color, this.length));
      }
      const axes = new THREE.AxesHelper(0.25 * this.length);
      axes.userData.kind = 'frame';
      group.add(axes);
      this.viewer.scene.add(group);
      return group;
    });
  }

  buildJoints() {
    // Each joint's axis, drawn at J' on the child; and a link from the parent's joint point to
    // the child's joint point, so massless rods show.
    this.jointArrows = this.scene.joints.map((joint) => {
      const child = this.bodies.findIndex((b) => b.name === joint.child);
      let arrow = null;
      if (joint.axis) {
        arrow = new THREE.ArrowHelper(new THREE.Vector3(...joint.axis), new THREE.Vector3(...joint.origin),
          0.35 * this.length, 0x333333, 0.06 * this.length, 0.03 * this.length);
        arrow.userData.kind = 'axis';
        this.groups[child].add(arrow);
      }
      return { joint, child, parent: this.bodies.findIndex((b) => b.name === joint.parent) };
    });
    // A ball joint turns about no one axis: a dashed vertical through its point instead (along
    // the view's up, against gravity), the line a top's nutation θ is measured from.
    // Drawn through the bodies (no depth test): a top's own cone would hide it.
    const dashes = new THREE.LineDashedMaterial({ color: 0x333333, dashSize: 0.05 * this.length, gapSize: 0.03 * this.length,
      depthTest: false, transparent: true, opacity: 0.8 });
    this.verticals = this.jointArrows.filter((j) => j.joint.type === 'spherical').map((j) => {
      const top = this.viewer.up.clone().multiplyScalar(1.5 * this.length);
      const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(), top]), dashes);
      line.computeLineDistances();
      line.renderOrder = 1;
      this.viewer.scene.add(line);
      return { line, joint: j };
    });
    const material = new THREE.LineBasicMaterial({ color: 0x555555 });
    this.links = [];
    for (const body of this.bodies.keys()) {
      // From the body's own joint point through its centre of mass to each child joint point.
      const geometry = new THREE.BufferGeometry();
      geometry.setAttribute('position', new THREE.BufferAttribute(new Float32Array(3 * 8), 3));
      const line = new THREE.Line(geometry, material);
      line.frustumCulled = false;
      this.viewer.scene.add(line);
      this.links.push(line);
    }
  }

  buildElements() {
    const coil = [];
    const turns = 10;
    for (let i = 0; i <= 400; i++) {
      const s = i / 400;
      const a = 2 * Math.PI * turns * s;
      const taper = s < 0.05 || s > 0.95 ? 0 : 1;
      coil.push(new THREE.Vector3(taper * Math.cos(a), taper * Math.sin(a), s));
    }
    // A linear spring-damper: a coil where it has stiffness, a dashpot (housing and rod) inside
    // it where it has damping; drawn from a to b in a frame scaled to their distance.
    const coilMaterial = new THREE.LineBasicMaterial({ color: 0x8c564b });
    const dashpotMaterial = new THREE.MeshStandardMaterial({ color: 0x7f7f7f, roughness: 0.5 });
    const housing = new THREE.CylinderGeometry(0.45, 0.45, 0.55, 16).rotateX(Math.PI / 2).translate(0, 0, 0.325);
    const rod = new THREE.CylinderGeometry(0.12, 0.12, 0.45, 8).rotateX(Math.PI / 2).translate(0, 0, 0.725);
    this.springs = this.scene.elements.filter((e) => e.type === 'spring').map((e) => {
      const object = new THREE.Group();
      if (e.stiffness > 0 || !(e.damping > 0)) {
        const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(coil), coilMaterial);
        line.frustumCulled = false;
        object.add(line);
      }
      if (e.damping > 0) object.add(new THREE.Mesh(housing, dashpotMaterial), new THREE.Mesh(rod, dashpotMaterial));
      this.viewer.scene.add(object);
      return { e, object, a: this.bodies.findIndex((b) => b.name === e.a), b: this.bodies.findIndex((b) => b.name === e.b) };
    });
  }

  buildVectors(frames) {
    const maxOf = (array) => { let m = 0; for (let i = 0; i < array.length; i += 3) m = Math.max(m, Math.hypot(array[i], array[i + 1], array[i + 2])); return m; };
    const scaleFor = (maximum) => (maximum > 0 ? (0.6 * this.length) / maximum : 1);
    // The display rule (house style §11): ω that turns no body by a nanoradian over the whole run
    // is round-off (7.7e-34 rad/s at rest), and so is H below that ω times the bodies' inertia:
    // neither has an arrow or a scale then.
    const span = Math.max(this.time[this.time.length - 1] - this.time[0], 1e-300);
    const omegaMax = maxOf(this.omega);
    this.omegaShown = omegaMax * span > 1e-9;
    this.omegaScale = scaleFor(omegaMax);
    // H of each body about its centre of mass: R I_Bcm Rᵀ ω, in W.
    let hmax = 0;
    for (let k = 0; k < this.time.length; k++) {
      for (let b = 0; b < this.nb; b++) hmax = Math.max(hmax, this.momentumLengthAt(k, b));
    }
    const inertia = Math.max(0, ...this.bodies.map((b) => (b.inertia[0] + b.inertia[4] + b.inertia[8]) / 3));
    this.hShown = hmax * span > 1e-9 * inertia;
    this.hScale = scaleFor(hmax);
    this.omegaArrows = this.bodies.map(() => makeArrow(0xd62728));
    this.hArrows = this.bodies.map(() => makeArrow(0x1f77b4));
    [...this.omegaArrows, ...this.hArrows].forEach((a) => this.viewer.scene.add(a));
    this.loads = frames.loads ? { names: frames.loads.names, vector: decode(frames.loads.vector) } : null;
    // Reactions: each joint's on its child at J', then each constraint's on its body (on its line
    // of action), per frame.
    this.reactions = frames.reactions ? { names: frames.reactions.names || this.scene.joints.map((j) => j.name), force: decode(frames.reactions.force), point: decode(frames.reactions.point) } : null;
    this.loadScale = this.loads ? scaleFor(maxOf(this.loads.vector)) : 1;
    this.reactionScale = this.reactions ? scaleFor(maxOf(this.reactions.force)) : 1;
    this.loadArrows = this.loads ? this.loads.names.map(() => makeArrow(0x2ca02c)) : [];
    this.reactionArrows = this.reactions ? this.reactions.names.map(() => makeArrow(0x9467bd)) : [];
    [...this.loadArrows, ...this.reactionArrows].forEach((a) => this.viewer.scene.add(a));
    this.loadElements = this.scene.elements.filter((e) => e.type === 'force');
    // A body's trajectory: its centre of mass at every kept frame, shown up to the current time.
    this.trace = new THREE.Line(new THREE.BufferGeometry(), new THREE.LineBasicMaterial({ color: 0xff7f0e }));
    this.trace.frustumCulled = false;
    this.trace.visible = false;
    this.viewer.scene.add(this.trace);
    this.toggles = { frames: true, axes: true, omega: false, H: false, loads: false, reactions: false, trace: -1 };
  }

  // |H| of body b at frame k, without building H (buildVectors scans every frame; the live page
  // does it at each change): a rotation keeps lengths, so |H| = |I_Bcm ω_B|, ω_B = Rᵀ ω.
  momentumLengthAt(k, b) {
    const i = k * this.nb + b;
    const q = this.quaternion;
    const x = -q[4 * i], y = -q[4 * i + 1], z = -q[4 * i + 2], w = q[4 * i + 3];
    const v0 = this.omega[3 * i], v1 = this.omega[3 * i + 1], v2 = this.omega[3 * i + 2];
    const tx = 2 * (y * v2 - z * v1), ty = 2 * (z * v0 - x * v2), tz = 2 * (x * v1 - y * v0);
    const b0 = v0 + w * tx + (y * tz - z * ty);
    const b1 = v1 + w * ty + (z * tx - x * tz);
    const b2 = v2 + w * tz + (x * ty - y * tx);
    const I = this.bodies[b].inertia;
    const h0 = I[0] * b0 + I[1] * b1 + I[2] * b2;
    const h1 = I[3] * b0 + I[4] * b1 + I[5] * b2;
    const h2 = I[6] * b0 + I[7] * b1 + I[8] * b2;
    return Math.sqrt(h0 * h0 + h1 * h1 + h2 * h2);
  }

  momentumAt(k, b) {
    const q = Array.from(this.quaternion.subarray(4 * (k * this.nb + b), 4 * (k * this.nb + b) + 4));
    const w = [this.omega[3 * (k * this.nb + b)], this.omega[3 * (k * this.nb + b) + 1], this.omega[3 * (k * this.nb + b) + 2]];
    const qi = [-q[0], -q[1], -q[2], q[3]];
    const wB = rotate(qi, w);
    const I = this.bodies[b].inertia;
    const hB = [0, 1, 2].map((r) => I[3 * r] * wB[0] + I[3 * r + 1] * wB[1] + I[3 * r + 2] * wB[2]);
    return rotate(q, hB);
  }

  setTrace(b) {
    this.toggles.trace = b;
    this.trace.visible = b >= 0;
    this.viewer.invalidate();
    if (b < 0) return;
    const points = [];
    for (let k = 0; k < this.time.length; k++) points.push(new THREE.Vector3(...this.bodyPoint(b, this.bodies[b].com, this.time[k])));
    this.trace.geometry.dispose();
    this.trace.geometry = new THREE.BufferGeometry().setFromPoints(points);
    this.show(this.timeline.time);
  }

  // Moves every body, link, spring and marker to the poses `poseOf` gives; the view is drawn anew.
  placeBodies(poseOf) {
    this.viewer.invalidate();
    const poses = this.bodies.map((_, b) => poseOf(b));
    poses.forEach(([p, q], b) => {
      this.groups[b].position.set(p[0], p[1], p[2]);
      this.groups[b].quaternion.set(q[0], q[1], q[2], q[3]);
      this.groups[b].traverse((o) => {
        if (o.userData.kind === 'frame') o.visible = this.toggles.frames;
        if (o.userData.kind === 'axis') o.visible = this.toggles.axes;
      });
    });
    const world = (b, point) => {
      if (b < 0) return point;
      const r = rotate(poses[b][1], point);
      return [poses[b][0][0] + r[0], poses[b][0][1] + r[1], poses[b][0][2] + r[2]];
    };
    // Links: parent joint point → centre of mass → each child's joint point.
    this.bodies.forEach((body, b) => {
      const own = this.jointArrows.find((j) => j.child === b);
      const path = [];
      if (own) path.push(world(b, own.joint.origin));
      path.push(world(b, body.com));
      for (const j of this.jointArrows.filter((x) => x.parent === b)) {
        path.push(world(b, body.com), world(j.child, j.joint.origin));
      }
      const attribute = this.links[b].geometry.getAttribute('position');
      for (let i = 0; i < 8; i++) {
        const p = path[Math.min(i, path.length - 1)];
        attribute.setXYZ(i, p[0], p[1], p[2]);
      }
      attribute.needsUpdate = true;
    });
    for (const v of this.verticals) {
      v.line.position.set(...world(v.joint.child, v.joint.joint.origin));
      v.line.visible = this.toggles.axes;
    }
    for (const s of this.springs) {
      const a = world(s.a, s.e.pa);
      const b = world(s.b, s.e.pb);
      const d = new THREE.Vector3(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
      const length = Math.max(d.length(), 1e-9);
      s.object.position.set(...a);
      s.object.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), d.clone().normalize());
      s.object.scale.set(0.06 * this.length, 0.06 * this.length, length);
    }
    return world;
  }

  show(t) {
    const world = this.placeBodies((b) => this.pose(b, t));
    const k = this.frameIndex(t);
    this.bodies.forEach((body, b) => {
      const c = world(b, body.com);
      const w = this.omega.subarray(3 * (k * this.nb + b), 3 * (k * this.nb + b) + 3);
      setArrow(this.omegaArrows[b], c, w, this.omegaScale, this.toggles.omega && this.omegaShown);
      setArrow(this.hArrows[b], c, this.momentumAt(k, b), this.hScale, this.toggles.H && this.hShown);
    });
    if (this.loads) {
      this.loadElements.forEach((e, i) => {
        const b = this.bodies.findIndex((x) => x.name === e.body);
        const F = this.loads.vector.subarray(3 * (k * this.loadElements.length + i), 3 * (k * this.loadElements.length + i) + 3);
        setArrow(this.loadArrows[i], world(b, e.point), F, this.loadScale, this.toggles.loads);
      });
    }
    if (this.reactions) {
      const nj = this.reactionArrows.length;
      this.reactionArrows.forEach((_, j) => {
        const at = this.reactions.point.subarray(3 * (k * nj + j), 3 * (k * nj + j) + 3);
        const F = this.reactions.force.subarray(3 * (k * nj + j), 3 * (k * nj + j) + 3);
        setArrow(this.reactionArrows[j], at, F, this.reactionScale, this.toggles.reactions);
      });
    }
    if (this.trace.visible) this.trace.geometry.setDrawRange(0, k + 1);
  }

  // A mode shape: the body poses over one period, played at the mode's frequency times the speed.
  playMode(mode) {
    this.mode = mode ? { mode, position: decode(mode.position), quaternion: decode(mode.quaternion), start: performance.now() } : null;
    if (!mode) this.show(this.timeline.time);
  }

  animateMode(now) {
    const m = this.mode;
    const phases = m.position.length / (3 * this.nb);
    const frequency = m.mode.damped_frequency > 0 ? m.mode.damped_frequency : m.mode.natural_frequency;
    const period = frequency > 0 ? (2 * Math.PI) / frequency : 2;
    const cycle = (((now - m.start) / 1000) * this.timeline.speed / period) % 1;
    const k = Math.floor(cycle * phases) % phases;
    this.placeBodies((b) => [Array.from(m.position.subarray(3 * (k * this.nb + b), 3 * (k * this.nb + b) + 3)),
      Array.from(m.quaternion.subarray(4 * (k * this.nb + b), 4 * (k * this.nb + b) + 4))]);
  }

  // Draws the view if anything it shows has changed (every frame while a mode animates); true
  // when it drew.
  render(now) {
    if (this.mode) this.animateMode(now);
    return this.viewer.renderIfStale();
  }

  // The ground planes the contacts touch (a floor, a ramp): a translucent square on each, centred
  // where the motion's middle projects onto it, three times the motion's size across, with its
  // outline. A plane a body rests on is then seen under it.
  buildPlanes() {
    const box = new THREE.Box3();
    this.sweptPoints.forEach((p) => box.expandByPoint(new THREE.Vector3(...p)));
    const middle = box.getCenter(new THREE.Vector3());
    const size = 3 * Math.max(box.getSize(new THREE.Vector3()).length(), this.length);
    const square = new THREE.PlaneGeometry(size, size);
    const material = new THREE.MeshStandardMaterial({ color: 0xc8b27d, transparent: true, opacity: 0.45, side: THREE.DoubleSide, depthWrite: false });
    const outline = new THREE.LineBasicMaterial({ color: 0x8c7a4f });
    this.planes = (this.scene.planes ?? []).map((plane) => {
      const normal = new THREE.Vector3(...plane.normal).normalize();
      const point = new THREE.Vector3(...plane.point);
      const center = middle.clone().addScaledVector(normal, normal.dot(point) - normal.dot(middle));
      const mesh = new THREE.Mesh(square, material);
      mesh.add(new THREE.LineSegments(new THREE.EdgesGeometry(square), outline));
      mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, 0, 1), normal);
      mesh.position.copy(center);
      this.viewer.scene.add(mesh);
      return { name: plane.name, mesh, normal, size };
    });
    this.viewer.invalidate();
  }

  // The planes drawn (for the test hook): each one's name, centre, unit normal and side (m).
  planesDrawn() {
    return this.planes.map((p) => ({
      name: p.name, center: p.mesh.position.toArray(), normal: new THREE.Vector3(0, 0, 1).applyQuaternion(p.mesh.quaternion).toArray(), size: p.size,
    }));
  }

  // What the reaction arrows show now (for the test hook): each one's name, whether it is drawn,
  // its origin and unit direction in W.
  reactionArrowsDrawn() {
    return this.reactionArrows.map((a, j) => ({
      name: this.reactions.names[j],
      visible: a.visible,
      origin: a.position.toArray(),
      direction: new THREE.Vector3(0, 1, 0).applyQuaternion(a.quaternion).toArray(),
    }));
  }

  setToggle(key, on) {
    this.toggles[key] = on;
    this.show(this.timeline.time);
  }

  // The toggles and the legend of arrow scales.
  controls() {
    const check = (label, key, on) => {
      const box = element('input', { type: 'checkbox' });
      box.checked = on;
      box.addEventListener('change', () => { this.toggles[key] = box.checked; this.show(this.timeline.time); });
      return element('label', {}, box, ` ${label}`);
    };
    const trace = element('select', { 'aria-label': 'trace' }, element('option', { value: -1 }, 'none'),
      ...this.bodies.map((b, i) => element('option', { value: i }, b.name)));
    trace.addEventListener('change', () => this.setTrace(Number(trace.value)));
    const legend = element('div', { class: 'legend' },
      element('span', { style: 'color:#d62728' }, this.omegaShown ? `ω: 1 m = ${formatNumber(1 / this.omegaScale, 3)} rad/s` : 'ω: 0 (no body turns)'), ' · ',
      element('span', { style: 'color:#1f77b4' }, this.hShown ? `H: 1 m = ${formatNumber(1 / this.hScale, 3)} kg·m²/s` : 'H: 0'),
      this.loads ? element('span', { style: 'color:#2ca02c' }, ` · loads: 1 m = ${formatNumber(1 / this.loadScale, 3)} N`) : null,
      this.reactions ? element('span', { style: 'color:#9467bd' }, ` · reactions: 1 m = ${formatNumber(1 / this.reactionScale, 3)} N`) : null);
    const notes = this.bodies.some((b) => !b.parts.length && b.equivalent)
      ? element('div', { class: 'note' }, 'Translucent ellipsoids: bodies given by mass and inertia, drawn as the uniform ellipsoid with the same inertia.')
      : null;
    return element('div', { class: 'toggles' },
      check('body frames', 'frames', true), check('joint axes', 'axes', true),
      check('ω (angular velocity)', 'omega', false), check('H (angular momentum about the centre of mass)', 'H', false),
      this.loads ? check('applied forces', 'loads', false) : null,
      this.reactions ? check(this.reactions.names.length > this.scene.joints.length ? 'joint and constraint reactions' : 'joint reactions', 'reactions', false) : null,
      element('label', {}, 'trace ', trace), legend, notes);
  }
}
