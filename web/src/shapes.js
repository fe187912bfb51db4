// What a body looks like: each part drawn as its own solid in its part frame (docs/inertia-format.md:
// origin at the centroid, symmetry axis along z, thin shapes in the xy-plane, the cone's origin
// at its apex), meshes as their triangles, explicit inertias as the equivalent uniform ellipsoid.

import * as THREE from 'three';
import { decode } from './data.js';

const PALETTE = [0x4e79a7, 0xf28e2b, 0x59a14f, 0xe15759, 0x76b7b2, 0xedc948, 0xb07aa1, 0xff9da7,
  0x9c755f, 0xbab0ac];

export function bodyColor(index) { return PALETTE[index % PALETTE.length]; }

// Three's cylinders, cones and lathes are along y: turn them onto z.
function alongZ(geometry) { geometry.rotateX(Math.PI / 2); return geometry; }

function ellipsoid(semi) {
  const g = new THREE.SphereGeometry(1, 32, 16);
  g.scale(Math.max(semi[0], 1e-9), Math.max(semi[1], 1e-9), Math.max(semi[2], 1e-9));
  return g;
}

function geometryOf(part, length) {
  const s = part.sizes;
  const thin = 0.01 * length;
  switch (part.kind) {
    case 'point_mass': return new THREE.SphereGeometry(0.04 * length, 24, 12);
    case 'slender_rod': return alongZ(new THREE.CylinderGeometry(thin, thin, s.length, 16));
    case 'thin_ring': return new THREE.TorusGeometry(s.radius, thin, 12, 64);
    case 'thin_disk': return alongZ(new THREE.CylinderGeometry(s.radius, s.radius, thin, 48));
    case 'annulus': return new THREE.RingGeometry(s.inner_radius, s.outer_radius, 48);
    case 'cylinder': return alongZ(new THREE.CylinderGeometry(s.radius, s.radius, s.length, 48));
    case 'capsule': return alongZ(new THREE.CapsuleGeometry(s.radius, s.length, 12, 32));
    case 'hollow_cylinder': {
      const h = s.length / 2;
      const profile = [[s.inner_radius, -h], [s.outer_radius, -h], [s.outer_radius, h],
        [s.inner_radius, h], [s.inner_radius, -h]].map(([x, y]) => new THREE.Vector2(x, y));
      return alongZ(new THREE.LatheGeometry(profile, 48));
    }
    case 'cylindrical_shell':
      return alongZ(new THREE.CylinderGeometry(s.radius, s.radius, s.length, 48, 1, true));
    case 'sphere': return new THREE.SphereGeometry(s.radius, 32, 16);
    case 'hollow_sphere': return new THREE.SphereGeometry(s.outer_radius, 32, 16);
    case 'spherical_shell': return new THREE.SphereGeometry(s.radius, 32, 16);
    case 'box': return new THREE.BoxGeometry(s['size.x'], s['size.y'], s['size.z']);
    case 'thin_plate': return new THREE.PlaneGeometry(s.width, s.height);
    case 'cone': {
      const g = new THREE.ConeGeometry(s.radius, s.height, 48);
      g.rotateX(-Math.PI / 2); // apex from +y to −z
      g.translate(0, 0, s.height / 2); // apex at the origin, base at z = height
      return g;
    }
    case 'ellipsoid': return ellipsoid([s['semi_axes.x'], s['semi_axes.y'], s['semi_axes.z']]);
    case 'mesh': {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.BufferAttribute(new Float32Array(decode(part.mesh.vertices)), 3));
      g.setIndex(Array.from(decode(part.mesh.triangles)));
      g.computeVertexNormals();
      return g;
    }
    default: return null;
  }
}

function placed(object, R, p) {
  const m = new THREE.Matrix4().set(R[0], R[1], R[2], p[0], R[3], R[4], R[5], p[1], R[6], R[7], R[8], p[2],
    0, 0, 0, 1);
  object.applyMatrix4(m);
  return object;
}

// An equivalent ellipsoid, translucent: it stands for a body known only by its inertia.
export function equivalentMesh(equivalent, color, length) {
  const semi = equivalent.semi_axes;
  const tiny = Math.max(...semi) < 1e-9;
  const geometry = tiny ? new THREE.SphereGeometry(0.04 * length, 24, 12) : ellipsoid(semi);
  const material = new THREE.MeshStandardMaterial({ color, transparent: true, opacity: 0.45,
    roughness: 0.6 });
  const mesh = new THREE.Mesh(geometry, material);
  return placed(mesh, equivalent.R, equivalent.center);
}

export function partMesh(part, color, length) {
  if (part.kind === 'inertia') return equivalentMesh(part.equivalent, color, length);
  const geometry = geometryOf(part, length);
  if (!geometry) return null;
  const thinKinds = ['annulus', 'thin_plate', 'cylindrical_shell', 'hollow_cylinder'];
  const material = part.hole
    ? new THREE.MeshBasicMaterial({ color: 0x222222, wireframe: true, transparent: true, opacity: 0.6 })
    : new THREE.MeshStandardMaterial({ color, roughness: 0.55, metalness: 0.05,
      side: thinKinds.includes(part.kind) ? THREE.DoubleSide : THREE.FrontSide });
  const mesh = new THREE.Mesh(geometry, material);
  mesh.userData.hole = part.hole;
  return placed(mesh, part.R, part.p);
}
