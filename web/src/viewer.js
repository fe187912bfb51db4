// The 3-D view: a three.js scene with orbit, pan and zoom, the ground grid and world axes.
// Shared by the simulation and mass-properties pages.

import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { element } from './data.js';

// No multisampling: software rasterizers (headless browsers, machines without a GPU) pay for it
// on every pixel, and a report must animate smoothly there too. three.js needs WebGL 2; null
// when the browser has none (asked first, so three.js logs no error for an expected absence).
function makeRenderer() {
  const canvas = document.createElement('canvas');
  const attributes = { antialias: false, preserveDrawingBuffer: true };
  const context = canvas.getContext('webgl2', attributes);
  if (!context) return null;
  const renderer = new THREE.WebGLRenderer({ canvas, context, ...attributes });
  renderer.setPixelRatio(Math.min(window.devicePixelRatio || 1, 2));
  return renderer;
}

// What a scene holds on the graphics card: its geometries, materials and their textures.
function disposeScene(scene) {
  scene.traverse((object) => {
    object.geometry?.dispose();
    for (const material of [object.material ?? []].flat()) {
      for (const value of Object.values(material)) if (value?.isTexture) value.dispose();
      material.dispose();
    }
  });
}

// One renderer for the page's life. The live page redraws by building its panels anew; a new
// WebGL context each time, its shaders compiled again, cost a change 200–250 ms of a software
// rasterizer's time (losing the old context alone 150 ms). A released view hands its renderer
// on with its scene, which the next view frees once it has drawn with the same shaders (freed
// first, the shaders would go with the materials that use them).
// The reader's own view goes with it: where they turned, panned or zoomed the camera, the next
// view looks from there (`view`; null when the camera is still where the page framed it).
let spare = null;
function takeRenderer() {
  if (!spare) return { renderer: makeRenderer(), leftover: null, view: null };
  const taken = spare;
  spare = null;
  return taken;
}

// The eight corners of a THREE.Box3, as [x, y, z] arrays.
export function boxCorners(box) {
  return [0, 1].flatMap((i) => [0, 1].flatMap((j) => [0, 1].map((k) => [
    i ? box.max.x : box.min.x, j ? box.max.y : box.min.y, k ? box.max.z : box.min.z])));
}

export class Viewer {
  constructor(container, length, up = [0, 0, 1]) {
    this.length = length;
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xf7f7f5);
    this.camera = new THREE.PerspectiveCamera(40, 1, length * 1e-3, length * 1e3);
    this.camera.up.set(...up);
    this.container = container;
    const { renderer, leftover, view } = takeRenderer();
    this.renderer = renderer;
    this.leftover = leftover;
    this.keptView = view;
    // Without WebGL (a locked-down browser, a remote desktop) the view says so and everything
    // else on the page — the plots, the linear analysis, the numbers — works as before.
    const surface = this.renderer ? this.renderer.domElement
      : element('div', { class: 'unavailable no-webgl' }, 'The 3-D view needs WebGL, which this browser could not '
        + 'provide (it may be turned off, or the graphics driver blocked). Every other panel works without it.');
    container.append(surface);
    this.controls = new OrbitControls(this.camera, surface);
    this.controls.enableDamping = false;
    // Drawn on demand: only after something the view shows has changed (the time, the camera, a
    // toggle, the size), not on every animation frame — an open report that is not playing keeps
    // no core busy (a software rasterizer's frame at 1280 × 900 costs tens of milliseconds).
    this.stale = true;
    this.controls.addEventListener('change', () => this.invalidate());
    // The reader moved the camera (a drag or the wheel): the live page's next view keeps it.
    this.moved = false;
    this.controls.addEventListener('start', () => { this.moved = true; });
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x888888, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.4);
    sun.position.set(3, -2, 5);
    this.scene.add(sun);
    // The ground grid, perpendicular to `up` (frame() places and sizes it), and the world axes
    // (x red, y green, z blue).
    this.up = new THREE.Vector3(...up).normalize();
    this.grid = new THREE.GridHelper(1, 10, 0xbbbbbb, 0xdddddd);
    this.grid.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), this.up);
    this.scene.add(this.grid);
    this.scene.add(new THREE.AxesHelper(length * 0.3));
    this.resize();
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
  }

  // Lets the view go: its canvas leaves the page and its renderer waits for the next view (the
  // live page's redraw); its scene is freed when that view has drawn. The view draws no more.
  release() {
    this.resizeObserver.disconnect();
    this.controls.dispose();
    if (this.leftover) disposeScene(this.leftover);
    if (this.renderer) {
      this.renderer.domElement.remove();
      if (spare) {  // a renderer no view took: let it go whole
        disposeScene(spare.leftover);
        spare.renderer.dispose();
        spare.renderer.forceContextLoss();
      }
      spare = { renderer: this.renderer, leftover: this.scene,
        view: this.moved ? { position: this.camera.position.clone(), target: this.controls.target.clone() } : null };
    } else {
      disposeScene(this.scene);
    }
    this.renderer = null;
    this.leftover = null;
  }

  // Looks at the box around the points so that its bounding sphere fills the view with a margin:
  // face on to the plane of motion when the box is flat (a planar mechanism: its thinnest
  // direction is under a fifth of its largest), from a three-quarter view otherwise — or, where
  // the reader moved the camera of the view this one replaces, from where they left it. The
  // ground grid goes under the box (at the world's origin when the box is above it), a few times
  // its size, in 1-2-5 steps.
  // `skeleton`: the points that say whether the motion is planar (centres of mass and joint
  // points, without the bodies' sizes); `points` besides: everything to keep in view.
  frame(points, skeleton = points) {
    const boxOf = (list) => {
      const b = new THREE.Box3();
      for (const p of list) b.expandByPoint(new THREE.Vector3(...p));
      return b;
    };
    const box = boxOf(points);
    const center = box.getCenter(new THREE.Vector3());
    const radius = Math.max(0.5 * box.getSize(new THREE.Vector3()).length(), 1e-3 * this.length);
    if (this.keptView) {
      this.camera.position.copy(this.keptView.position);
      this.controls.target.copy(this.keptView.target);
      this.fitDepth(this.camera.position.distanceTo(center), radius);
      this.keptView = null;
      this.moved = true;
    } else {
      this.placeCamera(box, center, radius, boxOf(skeleton));
    }
    this.controls.update();
    this.placeGrid(box, radius);
    this.framed = { box, radius };
    this.invalidate();
  }

  // The camera's depth range for a sphere of `radius` whose centre is `distance` away.
  fitDepth(distance, radius) {
    this.camera.near = Math.max(distance - 1.5 * radius, distance * 1e-3);
    this.camera.far = distance + 20 * radius;
    this.camera.updateProjectionMatrix();
  }

  // The page's own framing of `box` (frame(), above); `skeleton`, the box of the points that say
  // whether the motion is planar.
  placeCamera(box, center, radius, skeleton) {
    const flat = skeleton.getSize(new THREE.Vector3());
    // Of the thin directions, the thinnest; where the motion runs along a line (two thin
    // directions: a wheel rolling, a block sliding) the one across `up`, so that it is seen from
    // the side as the textbook draws it, not from above (which of the two is thinner is then
    // round-off).
    const largest = Math.max(flat.x, flat.y, flat.z);
    const thin = [0, 1, 2].filter((k) => flat.getComponent(k) < 0.2 * largest);
    const level = thin.filter((k) => Math.abs(this.up.getComponent(k)) < 0.9);
    const candidates = thin.length >= 2 && level.length > 0 ? level : [0, 1, 2];
    const thinnest = candidates.reduce((a, k) => (flat.getComponent(k) < flat.getComponent(a) ? k : a));
    const threeQuarter = this.threeQuarterDirection();
    let direction = threeQuarter;
    if (flat.getComponent(thinnest) < 0.2 * Math.max(flat.x, flat.y, flat.z)) {
      // Along the plane's normal, turned 20° about the up direction (or a side) to show depth.
      const normal = new THREE.Vector3().setComponent(thinnest, 1);
      const side = Math.abs(normal.dot(this.up)) > 0.9 ? new THREE.Vector3(1, 0, 0) : this.up;
      direction = normal.applyAxisAngle(side, (20 * Math.PI) / 180);
      if (direction.dot(threeQuarter) < 0) direction.negate();
      direction.add(this.up.clone().multiplyScalar(0.15));  // from a little above, after the turn
    }
    direction.normalize();
    // First the sphere fits the narrower of the vertical and horizontal fields of view, with 15 %
    // to spare; then the camera moves in or out until the box's projection spans 75 % of the
    // canvas in its larger direction (a long, thin motion — a car driving off — would fill little
    // of the sphere's view). Never closer than the sphere's surface.
    const vertical = THREE.MathUtils.degToRad(this.camera.fov) / 2;
    const horizontal = Math.atan(Math.tan(vertical) * this.camera.aspect);
    let distance = (1.15 * radius) / Math.sin(Math.min(vertical, horizontal));
    const place = () => {
      this.camera.position.copy(center).addScaledVector(direction, distance);
      this.camera.lookAt(center);
      this.fitDepth(distance, radius);
    };
    this.controls.target.copy(center);
    place();
    for (let pass = 0; pass < 3; pass++) {
      const { width, height } = this.coverage(box);
      const filled = Math.max(width, height);
      if (!(filled > 0)) break;
      distance = Math.max(distance * (filled / 0.75), 1.2 * radius);
      place();
    }
  }

  // From the front right and a little above, whichever way is up: (0.6, −1, 0.45) with z up.
  threeQuarterDirection() {
    const reference = Math.abs(this.up.z) > 0.9 ? new THREE.Vector3(1, 0, 0) : new THREE.Vector3(0, 0, 1);
    const right = reference.clone().addScaledVector(this.up, -reference.dot(this.up)).normalize();
    const front = new THREE.Vector3().crossVectors(this.up, right);  // z up: right = x, front = y
    return right.multiplyScalar(0.6).addScaledVector(front, -1.0).addScaledVector(this.up, 0.45);
  }

  placeGrid(box, radius) {
    const lowest = Math.min(...boxCorners(box).map((c) => new THREE.Vector3(...c).dot(this.up)));
    const height = Math.min(0, lowest - 0.05 * radius);
    const span = 6 * radius;
    const decade = 10 ** Math.floor(Math.log10(span / 10));
    const spacing = [1, 2, 5, 10].map((m) => m * decade).find((s) => span / s <= 12);
    const cells = Math.max(2, 2 * Math.ceil(span / spacing / 2));
    this.grid.scale.setScalar(cells * spacing);
    this.grid.geometry.dispose();
    this.grid.geometry = new THREE.GridHelper(1, cells, 0xbbbbbb, 0xdddddd).geometry;
    const center = box.getCenter(new THREE.Vector3());
    const along = center.dot(this.up);
    this.grid.position.copy(center).addScaledVector(this.up, height - along);
    this.gridSpacing = spacing;
  }

  // The fraction of the canvas's width and height that the box's projection covers (each corner
  // projected; > 1 where it spills over), and whether any corner is before the near plane.
  coverage(box) {
    this.camera.updateMatrixWorld();
    const projected = boxCorners(box).map((c) => new THREE.Vector3(...c).project(this.camera));
    const xs = projected.map((p) => p.x);
    const ys = projected.map((p) => p.y);
    return {
      width: (Math.max(...xs) - Math.min(...xs)) / 2,
      height: (Math.max(...ys) - Math.min(...ys)) / 2,
      clipped: projected.some((p) => p.z < -1 || p.z > 1),
    };
  }

  resize() {
    const width = this.container.clientWidth || 640;
    const height = this.container.clientHeight || 420;
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    if (this.renderer) this.renderer.setSize(width, height, false);
    this.invalidate();
  }

  // Says that what the view shows has changed: the next renderIfStale() draws it.
  invalidate() { this.stale = true; }

  // Draws the scene if it changed since it was last drawn; true when it drew.
  renderIfStale() {
    if (!this.stale || !this.renderer) return false;
    this.renderer.render(this.scene, this.camera);
    this.stale = false;
    if (this.leftover) {
      disposeScene(this.leftover);
      this.leftover = null;
    }
    return true;
  }
}

// An arrow from `origin` along `vector`, reused frame to frame.
export function makeArrow(color) {
  const arrow = new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1), new THREE.Vector3(), 1, color);
  arrow.visible = false;
  return arrow;
}

export function setArrow(arrow, origin, vector, scale, visible) {
  const length = Math.hypot(vector[0], vector[1], vector[2]) * scale;
  arrow.visible = visible && length > 1e-12;
  if (!arrow.visible) return;
  arrow.position.set(origin[0], origin[1], origin[2]);
  arrow.setDirection(new THREE.Vector3(vector[0], vector[1], vector[2]).normalize());
  arrow.setLength(length, 0.2 * length, 0.1 * length);
}
