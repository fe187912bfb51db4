#pragma once
// Spatial-algebra kernels on plain double[6] arrays for the innermost loops (private to
// src/dynamics). Chains of these stay in registers; the Eigen forms in math/spatial.hpp mix
// packet and scalar accesses on the same 6-vectors, which stalls on store forwarding.

#include "momenta/math/spatial.hpp"

namespace momenta::dynamics::detail {

// out = ᴮX_A m (motion from parent A to child B, X = X_AB).
inline void motion_inverse(const Transform& X, const double* m, double* out) {
  const Mat3& R = X.R;
  const Vec3& p = X.p;
  const double px = p[1] * m[2] - p[2] * m[1];
  const double py = p[2] * m[0] - p[0] * m[2];
  const double pz = p[0] * m[1] - p[1] * m[0];
  const double vx = m[3] - px, vy = m[4] - py, vz = m[5] - pz;
  out[0] = R(0, 0) * m[0] + R(1, 0) * m[1] + R(2, 0) * m[2];
  out[1] = R(0, 1) * m[0] + R(1, 1) * m[1] + R(2, 1) * m[2];
  out[2] = R(0, 2) * m[0] + R(1, 2) * m[1] + R(2, 2) * m[2];
  out[3] = R(0, 0) * vx + R(1, 0) * vy + R(2, 0) * vz;
  out[4] = R(0, 1) * vx + R(1, 1) * vy + R(2, 1) * vz;
  out[5] = R(0, 2) * vx + R(1, 2) * vy + R(2, 2) * vz;
}

// out += ᴬX_B* f (force from child B to parent A, X = X_AB).
inline void add_force(const Transform& X, const double* f, double* out) {
  const Mat3& R = X.R;
  const Vec3& p = X.p;
  const double fx = R(0, 0) * f[3] + R(0, 1) * f[4] + R(0, 2) * f[5];
  const double fy = R(1, 0) * f[3] + R(1, 1) * f[4] + R(1, 2) * f[5];
  const double fz = R(2, 0) * f[3] + R(2, 1) * f[4] + R(2, 2) * f[5];
  out[0] += R(0, 0) * f[0] + R(0, 1) * f[1] + R(0, 2) * f[2] + p[1] * fz - p[2] * fy;
  out[1] += R(1, 0) * f[0] + R(1, 1) * f[1] + R(1, 2) * f[2] + p[2] * fx - p[0] * fz;
  out[2] += R(2, 0) * f[0] + R(2, 1) * f[1] + R(2, 2) * f[2] + p[0] * fy - p[1] * fx;
  out[3] += fx;
  out[4] += fy;
  out[5] += fz;
}

// out = I v for a rigid-body spatial inertia.
inline void inertia_times(const SpatialInertia& I, const double* v, double* out) {
  const Mat3& J = I.I_O;
  const Vec3& h = I.h;
  out[0] = J(0, 0) * v[0] + J(0, 1) * v[1] + J(0, 2) * v[2] + h[1] * v[5] - h[2] * v[4];
  out[1] = J(1, 0) * v[0] + J(1, 1) * v[1] + J(1, 2) * v[2] + h[2] * v[3] - h[0] * v[5];
  out[2] = J(2, 0) * v[0] + J(2, 1) * v[1] + J(2, 2) * v[2] + h[0] * v[4] - h[1] * v[3];
  out[3] = I.mass * v[3] - (h[1] * v[2] - h[2] * v[1]);
  out[4] = I.mass * v[4] - (h[2] * v[0] - h[0] * v[2]);
  out[5] = I.mass * v[5] - (h[0] * v[1] - h[1] * v[0]);
}

// out += v ×* f.
inline void add_cross_force(const double* v, const double* f, double* out) {
  out[0] += v[1] * f[2] - v[2] * f[1] + v[4] * f[5] - v[5] * f[4];
  out[1] += v[2] * f[0] - v[0] * f[2] + v[5] * f[3] - v[3] * f[5];
  out[2] += v[0] * f[1] - v[1] * f[0] + v[3] * f[4] - v[4] * f[3];
  out[3] += v[1] * f[5] - v[2] * f[4];
  out[4] += v[2] * f[3] - v[0] * f[5];
  out[5] += v[0] * f[4] - v[1] * f[3];
}

// out += v ×m (s e_k) for a unit basis vector e_k (k < 3: rotation, else translation).
inline void add_cross_motion_basis(const double* v, int k, double s, double* out) {
  // ω × e_k and v × e_k are the components of ω (v) permuted with signs.
  const int i = (k + 1) % 3;
  const int j = (k + 2) % 3;
  if (k < 3) {
    // [ω × e_k; v × e_k]: (ω × e_k)_i = ω_j, (ω × e_k)_j = −ω_i.
    out[i] += s * v[j];
    out[j] -= s * v[i];
    out[3 + i] += s * v[3 + j];
    out[3 + j] -= s * v[3 + i];
  } else {
    // [0; ω × e_{k−3}].
    const int kk = k - 3;
    const int ii = (kk + 1) % 3;
    const int jj = (kk + 2) % 3;
    out[3 + ii] += s * v[jj];
    out[3 + jj] -= s * v[ii];
  }
}

// out += v ×m m.
inline void add_cross_motion(const double* v, const double* m, double* out) {
  out[0] += v[1] * m[2] - v[2] * m[1];
  out[1] += v[2] * m[0] - v[0] * m[2];
  out[2] += v[0] * m[1] - v[1] * m[0];
  out[3] += v[1] * m[5] - v[2] * m[4] + v[4] * m[2] - v[5] * m[1];
  out[4] += v[2] * m[3] - v[0] * m[5] + v[5] * m[0] - v[3] * m[2];
  out[5] += v[0] * m[4] - v[1] * m[3] + v[3] * m[1] - v[4] * m[0];
}

}  // namespace momenta::dynamics::detail
