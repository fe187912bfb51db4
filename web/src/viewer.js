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

export class Viewer {
  constructor(container, length, up = [0, 0, 1]) {
    this.length = length;
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color(0xf7f7f5);
    this.camera = new THREE.PerspectiveCamera(40, 1, length * 1e-3, length * 1e3);
    this.camera.up.set(...up);
    this.container = container;
    this.renderer = makeRenderer();
    // Without WebGL (a locked-down browser, a remote desktop) the view says so and everything
    // else on the page — the plots, the linear analysis, the numbers — works as before.
    const surface = this.renderer ? this.renderer.domElement
      : element('div', { class: 'unavailable no-webgl' }, 'The 3-D view needs WebGL, which this browser could not '
        + 'provide (it may be turned off, or the graphics driver blocked). Every other panel works without it.');
    container.append(surface);
    this.controls = new OrbitControls(this.camera, surface);
    this.controls.enableDamping = false;
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x888888, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.4);
    sun.position.set(3, -2, 5);
    this.scene.add(sun);
    // The ground grid in the world's xy-plane (z up), and the world axes (x red, y green, z blue).
    const grid = new THREE.GridHelper(length * 8, 16, 0xbbbbbb, 0xdddddd);
    grid.rotateX(Math.PI / 2);
    this.scene.add(grid);
    this.scene.add(new THREE.AxesHelper(length * 0.6));
    this.resize();
    new ResizeObserver(() => this.resize()).observe(container);
  }

  // Looks at the box around the points, from a three-quarter view.
  frame(points) {
    const box = new THREE.Box3();
    for (const p of points) box.expandByPoint(new THREE.Vector3(...p));
    const center = box.getCenter(new THREE.Vector3());
    const size = Math.max(box.getSize(new THREE.Vector3()).length(), this.length);
    this.controls.target.copy(center);
    this.camera.position.set(center.x + 0.6 * size, center.y - 1.0 * size, center.z + 0.45 * size);
    this.controls.update();
  }

  resize() {
    const width = this.container.clientWidth || 640;
    const height = this.container.clientHeight || 420;
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
    if (this.renderer) this.renderer.setSize(width, height, false);
  }

  render() { if (this.renderer) this.renderer.render(this.scene, this.camera); }
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
