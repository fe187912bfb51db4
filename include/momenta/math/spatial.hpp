#pragma once
// Spatial (6-D) algebra: rigid transforms, motion and force vectors, spatial inertia.
//
// Conventions (docs/conventions.md, Featherstone 2008 ch. 2): spatial vectors put rotation first.
// A spatial motion vector (velocity, acceleration, motion subspace column) is [ω; v] with v the
// velocity of the point at the origin of the frame it is expressed in; a spatial force (wrench) is
// [n; f] with n the moment about that origin. Both are stored as Vec6.
//
// A Transform X_AB is the pose of frame B in frame A (Drake's monogram): R_AB and p_AoBo_A. Its
// actions map vectors expressed in B (about Bo) into A (about Ao) — Featherstone's ᴬX_B for
// motion and ᴬX_B* for force:
//   ᴬX_B  = [ R      0 ]      ᴬX_B* = [ R   [p]×R ]
//           [ [p]×R  R ]              [ 0     R   ]
//
// Everything here is inline: these are the inner-loop operations of the dynamics algorithms.

#include "momenta/inertia/mass_properties.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/math/types.hpp"

namespace momenta {

/// The angular (first three) part of a spatial vector.
inline auto angular(Vec6& x) { return x.head<3>(); }
inline auto angular(const Vec6& x) { return x.head<3>(); }
/// The linear (last three) part of a spatial vector.
inline auto linear(Vec6& x) { return x.tail<3>(); }
inline auto linear(const Vec6& x) { return x.tail<3>(); }

/// Stacks [a; b] into a spatial vector.
inline Vec6 spatial(const Vec3& a, const Vec3& b) {
  Vec6 x;
  x << a, b;
  return x;
}

/// Rigid transform X_AB: the pose of frame B in frame A, R = R_AB, p = p_AoBo_A (m).
struct Transform {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();

  Transform() = default;
  Transform(const Mat3& R_AB, const Vec3& p_AoBo_A) : R(R_AB), p(p_AoBo_A) {}

  static Transform identity() { return Transform(); }
  /// A pure translation by p_AoBo_A.
  static Transform translation(const Vec3& p_AoBo_A) { return {Mat3::Identity(), p_AoBo_A}; }
  /// A pure rotation R_AB about the common origin.
  static Transform rotation(const Mat3& R_AB) { return {R_AB, Vec3::Zero()}; }

  /// X_AC = X_AB * X_BC.
  Transform operator*(const Transform& X_BC) const { return {R * X_BC.R, p + R * X_BC.p}; }

  /// X_BA from X_AB.
  Transform inverse() const {
    const Mat3 Rt = R.transpose();
    return {Rt, -(Rt * p)};
  }

  /// Point Q: p_AoQ_A from p_BoQ_B.
  Vec3 apply(const Vec3& p_BoQ_B) const { return p + R * p_BoQ_B; }

  /// Motion vector expressed in B (about Bo) → expressed in A (about Ao): ᴬX_B m.
  Vec6 act_motion(const Vec6& m_B) const {
    Vec6 out;
    out.head<3>() = R * m_B.head<3>();
    out.tail<3>() = R * m_B.tail<3>() + p.cross(out.head<3>());
    return out;
  }
  /// Motion vector expressed in A (about Ao) → expressed in B (about Bo): ᴮX_A m.
  Vec6 act_motion_inverse(const Vec6& m_A) const {
    Vec6 out;
    out.head<3>() = R.transpose() * m_A.head<3>();
    out.tail<3>() = R.transpose() * (m_A.tail<3>() - p.cross(m_A.head<3>()));
    return out;
  }
  /// Force vector expressed in B (about Bo) → expressed in A (about Ao): ᴬX_B* f.
  Vec6 act_force(const Vec6& f_B) const {
    Vec6 out;
    out.tail<3>() = R * f_B.tail<3>();
    out.head<3>() = R * f_B.head<3>() + p.cross(out.tail<3>());
    return out;
  }
  /// Force vector expressed in A (about Ao) → expressed in B (about Bo): ᴮX_A* f.
  Vec6 act_force_inverse(const Vec6& f_A) const {
    Vec6 out;
    out.tail<3>() = R.transpose() * f_A.tail<3>();
    out.head<3>() = R.transpose() * (f_A.head<3>() - p.cross(f_A.tail<3>()));
    return out;
  }

  /// The 6×6 motion transform ᴬX_B.
  Mat6 motion_matrix() const {
    Mat6 X;
    X.topLeftCorner<3, 3>() = R;
    X.topRightCorner<3, 3>().setZero();
    X.bottomLeftCorner<3, 3>() = skew(p) * R;
    X.bottomRightCorner<3, 3>() = R;
    return X;
  }
  /// The 6×6 force transform ᴬX_B* = (ᴮX_A)ᵀ.
  Mat6 force_matrix() const {
    Mat6 X;
    X.topLeftCorner<3, 3>() = R;
    X.topRightCorner<3, 3>() = skew(p) * R;
    X.bottomLeftCorner<3, 3>().setZero();
    X.bottomRightCorner<3, 3>() = R;
    return X;
  }

  bool isApprox(const Transform& other, double precision = 1e-12) const {
    return R.isApprox(other.R, precision) && (p - other.p).norm() <= precision * (1 + p.norm());
  }
};

/// Spatial cross product for motion: v ×m, Featherstone's crm(v) m.
inline Vec6 cross_motion(const Vec6& v, const Vec6& m) {
  Vec6 out;
  out.head<3>() = v.head<3>().cross(m.head<3>());
  out.tail<3>() = v.head<3>().cross(m.tail<3>()) + v.tail<3>().cross(m.head<3>());
  return out;
}

/// Spatial cross product for force: v ×* f, Featherstone's crf(v) f = −crm(v)ᵀ f.
inline Vec6 cross_force(const Vec6& v, const Vec6& f) {
  Vec6 out;
  out.head<3>() = v.head<3>().cross(f.head<3>()) + v.tail<3>().cross(f.tail<3>());
  out.tail<3>() = v.head<3>().cross(f.tail<3>());
  return out;
}

/// The 6×6 matrix crm(v) with crm(v) m == cross_motion(v, m) (Featherstone 2008, eq. 2.31).
inline Mat6 crm(const Vec6& v) {
  Mat6 X;
  X.topLeftCorner<3, 3>() = skew(v.head<3>());
  X.topRightCorner<3, 3>().setZero();
  X.bottomLeftCorner<3, 3>() = skew(v.tail<3>());
  X.bottomRightCorner<3, 3>() = skew(v.head<3>());
  return X;
}

/// The 6×6 matrix crf(v) = −crm(v)ᵀ with crf(v) f == cross_force(v, f) (eq. 2.32).
inline Mat6 crf(const Vec6& v) { return -crm(v).transpose(); }

/// Rigid-body spatial inertia about the origin O of the frame it is expressed in
/// (Featherstone 2008, eq. 2.63): mass m, first moment h = m c (c the centre of mass from O) and
/// rotational inertia I_O about O (not about the centre of mass). As a matrix:
///   [ I_O    [h]× ]
///   [ [h]×ᵀ  m 1  ]
struct SpatialInertia {
  double mass = 0.0;        ///< kg.
  Vec3 h = Vec3::Zero();    ///< m · p_OBcm, kg·m.
  Mat3 I_O = Mat3::Zero();  ///< Inertia about O, kg·m² (off-diagonals minus products).

  SpatialInertia() = default;
  SpatialInertia(double m, const Vec3& first_moment, const Mat3& I_about_origin)
      : mass(m), h(first_moment), I_O(I_about_origin) {}

  /// From mass properties of body B described in B: the inertia about Bo, expressed in B.
  static SpatialInertia from_mass_properties(const inertia::MassProperties& mp) {
    const Vec3& c = mp.center_of_mass();
    return {mp.mass(), mp.mass() * c, mp.inertia_about(Vec3::Zero())};
  }

  /// Centre of mass from O (m); zero for a massless body.
  Vec3 center_of_mass() const { return mass > 0 ? Vec3(h / mass) : Vec3::Zero(); }

  /// Momentum of the body moving with spatial velocity V (same frame): I V = [I_O ω + h × v;
  /// m v − h × ω].
  Vec6 operator*(const Vec6& V) const {
    Vec6 out;
    out.head<3>() = I_O * V.head<3>() + h.cross(V.tail<3>());
    out.tail<3>() = mass * V.tail<3>() - h.cross(V.head<3>());
    return out;
  }

  /// The 6×6 matrix.
  Mat6 matrix() const {
    Mat6 M;
    const Mat3 hx = skew(h);
    M.topLeftCorner<3, 3>() = I_O;
    M.topRightCorner<3, 3>() = hx;
    M.bottomLeftCorner<3, 3>() = hx.transpose();
    M.bottomRightCorner<3, 3>() = mass * Mat3::Identity();
    return M;
  }

  /// Kinetic energy ½ Vᵀ I V (J) of the body moving with V.
  double kinetic_energy(const Vec6& V) const { return 0.5 * V.dot((*this) * V); }

  /// This inertia (expressed in B about Bo) expressed in A about Ao, B at pose X_AB in A:
  /// ᴬX_B* I ᴮX_A.
  SpatialInertia transformed(const Transform& X_AB) const {
    const Vec3 h_A = X_AB.R * h;
    // Rotate about Bo, then shift the reference point to Ao (parallel axes for the first moment).
    const Mat3 I_Bo_A = X_AB.R * I_O * X_AB.R.transpose();
    const Vec3& p = X_AB.p;
    const Mat3 shift = -skew(p) * skew(h_A) - skew(h_A + mass * p) * skew(p);
    return {mass, h_A + mass * p, I_Bo_A + shift};
  }

  SpatialInertia& operator+=(const SpatialInertia& other) {
    mass += other.mass;
    h += other.h;
    I_O += other.I_O;
    return *this;
  }
};

inline SpatialInertia operator+(SpatialInertia a, const SpatialInertia& b) { return a += b; }

}  // namespace momenta
