#pragma once
// The spatial-algebra kernels: every transform, cross product and inertia product of
// math/spatial.hpp and of the dynamics algorithms is one of these functions, written once.
//
// They work on plain `double*` six-vectors (rotation first, Featherstone 2008 ch. 2) and write
// their result through an output pointer, so a chain of them in an algorithm's inner loop stays
// in registers. (Eigen's fixed 6-vectors mix packet and scalar accesses on the same vector, and
// a packed load of what scalar stores just wrote stalls on store forwarding.) The Eigen-typed
// forms in math/spatial.hpp (`Transform::act_motion`, `cross_force`, `SpatialInertia * V`, ...)
// call these.
//
// A transform X_AB is given as R = R_AB and p = p_AoBo_A; "motion" maps a motion vector in B
// (about Bo) into A (about Ao), Featherstone's ᴬX_B; "force" does the same for a force, ᴬX_B*.
// Output pointers may not alias inputs unless stated.

#include "momenta/math/types.hpp"

namespace momenta::kernel {

/// out = ᴬX_B m: motion from B to A.
inline void motion(const Mat3& R, const Vec3& p, const double* m, double* out) {
  const double w0 = R(0, 0) * m[0] + R(0, 1) * m[1] + R(0, 2) * m[2];
  const double w1 = R(1, 0) * m[0] + R(1, 1) * m[1] + R(1, 2) * m[2];
  const double w2 = R(2, 0) * m[0] + R(2, 1) * m[1] + R(2, 2) * m[2];
  const double v0 = R(0, 0) * m[3] + R(0, 1) * m[4] + R(0, 2) * m[5];
  const double v1 = R(1, 0) * m[3] + R(1, 1) * m[4] + R(1, 2) * m[5];
  const double v2 = R(2, 0) * m[3] + R(2, 1) * m[4] + R(2, 2) * m[5];
  out[0] = w0;
  out[1] = w1;
  out[2] = w2;
  out[3] = v0 + p[1] * w2 - p[2] * w1;
  out[4] = v1 + p[2] * w0 - p[0] * w2;
  out[5] = v2 + p[0] * w1 - p[1] * w0;
}

/// out = ᴮX_A m: motion from A back to B.
inline void motion_inverse(const Mat3& R, const Vec3& p, const double* m, double* out) {
  const double vx = m[3] - (p[1] * m[2] - p[2] * m[1]);
  const double vy = m[4] - (p[2] * m[0] - p[0] * m[2]);
  const double vz = m[5] - (p[0] * m[1] - p[1] * m[0]);
  const double w0 = R(0, 0) * m[0] + R(1, 0) * m[1] + R(2, 0) * m[2];
  const double w1 = R(0, 1) * m[0] + R(1, 1) * m[1] + R(2, 1) * m[2];
  const double w2 = R(0, 2) * m[0] + R(1, 2) * m[1] + R(2, 2) * m[2];
  out[0] = w0;
  out[1] = w1;
  out[2] = w2;
  out[3] = R(0, 0) * vx + R(1, 0) * vy + R(2, 0) * vz;
  out[4] = R(0, 1) * vx + R(1, 1) * vy + R(2, 1) * vz;
  out[5] = R(0, 2) * vx + R(1, 2) * vy + R(2, 2) * vz;
}

/// out = ᴬX_B* f: force from B to A. `out` may alias `f`.
inline void force(const Mat3& R, const Vec3& p, const double* f, double* out) {
  const double fx = R(0, 0) * f[3] + R(0, 1) * f[4] + R(0, 2) * f[5];
  const double fy = R(1, 0) * f[3] + R(1, 1) * f[4] + R(1, 2) * f[5];
  const double fz = R(2, 0) * f[3] + R(2, 1) * f[4] + R(2, 2) * f[5];
  const double n0 = R(0, 0) * f[0] + R(0, 1) * f[1] + R(0, 2) * f[2] + p[1] * fz - p[2] * fy;
  const double n1 = R(1, 0) * f[0] + R(1, 1) * f[1] + R(1, 2) * f[2] + p[2] * fx - p[0] * fz;
  const double n2 = R(2, 0) * f[0] + R(2, 1) * f[1] + R(2, 2) * f[2] + p[0] * fy - p[1] * fx;
  out[0] = n0;
  out[1] = n1;
  out[2] = n2;
  out[3] = fx;
  out[4] = fy;
  out[5] = fz;
}

/// out = ᴮX_A* f: force from A back to B.
inline void force_inverse(const Mat3& R, const Vec3& p, const double* f, double* out) {
  const double nx = f[0] - (p[1] * f[5] - p[2] * f[4]);
  const double ny = f[1] - (p[2] * f[3] - p[0] * f[5]);
  const double nz = f[2] - (p[0] * f[4] - p[1] * f[3]);
  const double f0 = R(0, 0) * f[3] + R(1, 0) * f[4] + R(2, 0) * f[5];
  const double f1 = R(0, 1) * f[3] + R(1, 1) * f[4] + R(2, 1) * f[5];
  const double f2 = R(0, 2) * f[3] + R(1, 2) * f[4] + R(2, 2) * f[5];
  out[0] = R(0, 0) * nx + R(1, 0) * ny + R(2, 0) * nz;
  out[1] = R(0, 1) * nx + R(1, 1) * ny + R(2, 1) * nz;
  out[2] = R(0, 2) * nx + R(1, 2) * ny + R(2, 2) * nz;
  out[3] = f0;
  out[4] = f1;
  out[5] = f2;
}

// --- Transforms whose rotation turns about coordinate axis K only (a revolute joint's) -------
// R = Rot_K(θ) given by c = cos θ, s = sin θ: with (K, I, J) cyclic, R e_I = c e_I + s e_J and
// R e_J = −s e_I + c e_J. Half the products of the general forms above.

/// out = ᴮX_A m for X_AB = (Rot_K(θ), p).
template <int K>
inline void motion_inverse_about_axis(double c, double s, const Vec3& p, const double* m,
                                      double* out) {
  constexpr int I = (K + 1) % 3, J = (K + 2) % 3;
  const double v0 = m[3] - (p[1] * m[2] - p[2] * m[1]);
  const double v1 = m[4] - (p[2] * m[0] - p[0] * m[2]);
  const double v2 = m[5] - (p[0] * m[1] - p[1] * m[0]);
  const double v[3] = {v0, v1, v2};
  out[I] = c * m[I] + s * m[J];
  out[J] = c * m[J] - s * m[I];
  out[K] = m[K];
  out[3 + I] = c * v[I] + s * v[J];
  out[3 + J] = c * v[J] - s * v[I];
  out[3 + K] = v[K];
}

/// out = ᴬX_B* f for X_AB = (Rot_K(θ), p). `out` may alias `f`.
template <int K>
inline void force_about_axis(double c, double s, const Vec3& p, const double* f, double* out) {
  constexpr int I = (K + 1) % 3, J = (K + 2) % 3;
  double n[3], g[3];
  n[I] = c * f[I] - s * f[J];
  n[J] = s * f[I] + c * f[J];
  n[K] = f[K];
  g[I] = c * f[3 + I] - s * f[3 + J];
  g[J] = s * f[3 + I] + c * f[3 + J];
  g[K] = f[3 + K];
  out[0] = n[0] + p[1] * g[2] - p[2] * g[1];
  out[1] = n[1] + p[2] * g[0] - p[0] * g[2];
  out[2] = n[2] + p[0] * g[1] - p[1] * g[0];
  out[3] = g[0];
  out[4] = g[1];
  out[5] = g[2];
}

/// out += v ×m m (Featherstone's crm(v) m).
inline void add_cross_motion(const double* v, const double* m, double* out) {
  out[0] += v[1] * m[2] - v[2] * m[1];
  out[1] += v[2] * m[0] - v[0] * m[2];
  out[2] += v[0] * m[1] - v[1] * m[0];
  out[3] += v[1] * m[5] - v[2] * m[4] + v[4] * m[2] - v[5] * m[1];
  out[4] += v[2] * m[3] - v[0] * m[5] + v[5] * m[0] - v[3] * m[2];
  out[5] += v[0] * m[4] - v[1] * m[3] + v[3] * m[1] - v[4] * m[0];
}

/// out += v ×m (s e_K) for the unit basis vector e_K (K < 3 a rotation, else a translation):
/// add_cross_motion for a joint whose axis is a coordinate axis, four products instead of 30.
template <int K>
inline void add_cross_motion_axis(const double* v, double s, double* out) {
  if constexpr (K < 3) {
    // [ω × e_K; v × e_K]: (ω × e_K)_I = ω_J, (ω × e_K)_J = −ω_I with (K, I, J) cyclic.
    constexpr int I = (K + 1) % 3, J = (K + 2) % 3;
    out[I] += s * v[J];
    out[J] -= s * v[I];
    out[3 + I] += s * v[3 + J];
    out[3 + J] -= s * v[3 + I];
  } else {
    // [0; ω × e_{K−3}].
    constexpr int I = (K - 2) % 3, J = (K - 1) % 3;
    out[3 + I] += s * v[J];
    out[3 + J] -= s * v[I];
  }
}

/// add_cross_motion_axis for an axis k known at run time. The branch, not an index computed
/// from k, picks the entries: `out` and `v` can then stay in registers.
inline void add_cross_motion_basis(const double* v, int k, double s, double* out) {
  switch (k) {
    case 0:
      return add_cross_motion_axis<0>(v, s, out);
    case 1:
      return add_cross_motion_axis<1>(v, s, out);
    case 2:
      return add_cross_motion_axis<2>(v, s, out);
    case 3:
      return add_cross_motion_axis<3>(v, s, out);
    case 4:
      return add_cross_motion_axis<4>(v, s, out);
    default:
      return add_cross_motion_axis<5>(v, s, out);
  }
}

/// out += s e_k (k < 6), without indexing `out` by a run-time value (see above).
inline void add_basis(int k, double s, double* out) {
  for (int r = 0; r < 6; ++r) out[r] += r == k ? s : 0.0;
}

/// out += v ×* f (Featherstone's crf(v) f = −crm(v)ᵀ f).
inline void add_cross_force(const double* v, const double* f, double* out) {
  out[0] += v[1] * f[2] - v[2] * f[1] + v[4] * f[5] - v[5] * f[4];
  out[1] += v[2] * f[0] - v[0] * f[2] + v[5] * f[3] - v[3] * f[5];
  out[2] += v[0] * f[1] - v[1] * f[0] + v[3] * f[4] - v[4] * f[3];
  out[3] += v[1] * f[5] - v[2] * f[4];
  out[4] += v[2] * f[3] - v[0] * f[5];
  out[5] += v[0] * f[4] - v[1] * f[3];
}

/// out = I v for the rigid-body spatial inertia (mass m, first moment h, inertia I_O about the
/// frame's origin): [I_O ω + h × v; m v − h × ω].
inline void inertia_times(double m, const Vec3& h, const Mat3& I_O, const double* v, double* out) {
  out[0] = I_O(0, 0) * v[0] + I_O(0, 1) * v[1] + I_O(0, 2) * v[2] + h[1] * v[5] - h[2] * v[4];
  out[1] = I_O(1, 0) * v[0] + I_O(1, 1) * v[1] + I_O(1, 2) * v[2] + h[2] * v[3] - h[0] * v[5];
  out[2] = I_O(2, 0) * v[0] + I_O(2, 1) * v[1] + I_O(2, 2) * v[2] + h[0] * v[4] - h[1] * v[3];
  out[3] = m * v[3] - (h[1] * v[2] - h[2] * v[1]);
  out[4] = m * v[4] - (h[2] * v[0] - h[0] * v[2]);
  out[5] = m * v[5] - (h[0] * v[1] - h[1] * v[0]);
}

/// out = I e_k, column k of the spatial inertia's matrix [I_O [h]×; [h]×ᵀ m 1]: inertia_times
/// for an axis-aligned motion subspace, without products.
inline void inertia_column(double m, const Vec3& h, const Mat3& I_O, int k, double* out) {
  if (k < 3) {
    // [I_O e_k; e_k × h].
    const Vec3 lower = Vec3::Unit(k).cross(h);
    for (int r = 0; r < 3; ++r) {
      out[r] = I_O(r, k);
      out[3 + r] = lower[r];
    }
  } else {
    // [h × e_l; m e_l], l = k − 3.
    const Vec3 upper = h.cross(Vec3::Unit(k - 3));
    for (int r = 0; r < 3; ++r) {
      out[r] = upper[r];
      out[3 + r] = r == k - 3 ? m : 0.0;
    }
  }
}

}  // namespace momenta::kernel
