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
// Everything here is inline. The arithmetic of every action, cross product and inertia product
// is written once, in math/spatial_kernels.hpp; these are its Eigen-typed forms.

#include "momenta/math/rotation.hpp"
#include "momenta/math/spatial_kernels.hpp"
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
  x.head<3>() = a;
  x.tail<3>() = b;
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
    kernel::motion(R, p, m_B.data(), out.data());
    return out;
  }
  /// Motion vector expressed in A (about Ao) → expressed in B (about Bo): ᴮX_A m.
  Vec6 act_motion_inverse(const Vec6& m_A) const {
    Vec6 out;
    kernel::motion_inverse(R, p, m_A.data(), out.data());
    return out;
  }
  /// Force vector expressed in B (about Bo) → expressed in A (about Ao): ᴬX_B* f.
  Vec6 act_force(const Vec6& f_B) const {
    Vec6 out;
    kernel::force(R, p, f_B.data(), out.data());
    return out;
  }
  /// Force vector expressed in A (about Ao) → expressed in B (about Bo): ᴮX_A* f.
  Vec6 act_force_inverse(const Vec6& f_A) const {
    Vec6 out;
    kernel::force_inverse(R, p, f_A.data(), out.data());
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
  Vec6 out = Vec6::Zero();
  kernel::add_cross_motion(v.data(), m.data(), out.data());
  return out;
}

/// Spatial cross product for force: v ×* f, Featherstone's crf(v) f = −crm(v)ᵀ f.
inline Vec6 cross_force(const Vec6& v, const Vec6& f) {
  Vec6 out = Vec6::Zero();
  kernel::add_cross_force(v.data(), f.data(), out.data());
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

  /// Centre of mass from O (m); zero for a massless body.
  Vec3 center_of_mass() const { return mass > 0 ? Vec3(h / mass) : Vec3::Zero(); }

  /// Momentum of the body moving with spatial velocity V (same frame): I V = [I_O ω + h × v;
  /// m v − h × ω].
  Vec6 operator*(const Vec6& V) const {
    Vec6 out;
    kernel::inertia_times(mass, h, I_O, V.data(), out.data());
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
    // Rotate about Bo (R I_Bo Rᵀ on its six distinct entries, R h), then move to Ao.
    const Mat3& R = X_AB.R;
    Mat3 RI;  // R I_Bo
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        RI(i, j) = R(i, 0) * I_O(0, j) + R(i, 1) * I_O(1, j) + R(i, 2) * I_O(2, j);
      }
    }
    Mat3 I_rotated;
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j) {
        I_rotated(i, j) = I_rotated(j, i) =
            RI(i, 0) * R(j, 0) + RI(i, 1) * R(j, 1) + RI(i, 2) * R(j, 2);
      }
    }
    return moved(mass, R * h, I_rotated, X_AB.p);
  }

  /// The inertia (mass m, first moment h and rotational inertia I about a point O, all already
  /// expressed along A's axes) moved to the point Ao, with O at p = p_AoO_A:
  /// with [a]×[b]× = b aᵀ − (a·b) 1,
  ///   I_Ao = I − [p]×[h]× − [h + m p]×[p]× = I − (h pᵀ + p hᵀ + m p pᵀ) + (2 p·h + m p·p) 1,
  ///   h_Ao = h + m p,
  /// a symmetric sum computed on its six distinct entries.
  static SpatialInertia moved(double m, const Vec3& h, const Mat3& I, const Vec3& p) {
    const double diag = 2.0 * (p[0] * h[0] + p[1] * h[1] + p[2] * h[2]) +
                        m * (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    Mat3 I_A;
    for (int i = 0; i < 3; ++i) {
      for (int j = i; j < 3; ++j) {
        const double shift = h[i] * p[j] + p[i] * h[j] + m * p[i] * p[j];
        I_A(i, j) = I_A(j, i) = I(i, j) - shift + (i == j ? diag : 0.0);
      }
    }
    return {m, Vec3(h[0] + m * p[0], h[1] + m * p[1], h[2] + m * p[2]), I_A};
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
