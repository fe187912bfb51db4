#pragma once
// Small vector algebra on GiNaC expressions for the symbolic Newton–Euler passes: 3-vectors,
// 3×3 matrices, spatial motions [ω; v] and forces [n; f] (rotation first, as everywhere in
// momenta), with the operations Featherstone's recursions need.

#include <array>

#include <ginac/ginac.h>

#include "momenta/math/types.hpp"

namespace momenta::symbolic::detail {

using GiNaC::ex;

/// The double as an exact rational where it is a short decimal (9.81 → 981/100, so sums cancel
/// exactly), else as a float; 0 as exact zero.
ex exact_number(double x);

struct V3 {
  std::array<ex, 3> e{0, 0, 0};
  ex& operator[](int i) { return e[static_cast<std::size_t>(i)]; }
  const ex& operator[](int i) const { return e[static_cast<std::size_t>(i)]; }
};

struct M3 {
  std::array<std::array<ex, 3>, 3> e{{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}};
  ex& operator()(int r, int c) {
    return e[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
  }
  const ex& operator()(int r, int c) const {
    return e[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
  }
  static M3 identity();
};

V3 to_v3(const Vec3& v);
M3 to_m3(const Mat3& m);
V3 operator+(const V3& a, const V3& b);
V3 operator-(const V3& a, const V3& b);
V3 operator*(const ex& s, const V3& a);
V3 operator*(const M3& m, const V3& a);
M3 operator*(const M3& a, const M3& b);
M3 transpose(const M3& m);
V3 cross(const V3& a, const V3& b);
ex dot(const V3& a, const V3& b);

/// Rotation by θ about the unit axis a (Rodrigues), as model::joint_transform writes it.
M3 axis_rotation(const V3& axis, const ex& theta);
/// The rotation of the unit quaternion (w, x, y, z).
M3 quaternion_rotation(const ex& w, const ex& x, const ex& y, const ex& z);

struct Motion {
  V3 w, v;
};
struct Force {
  V3 n, f;
};
Motion operator+(const Motion& a, const Motion& b);
Force operator+(const Force& a, const Force& b);
/// [ω; v] × [ω'; v'] = [ω × ω'; ω × v' + v × ω'].
Motion cross_motion(const Motion& a, const Motion& b);
/// [ω; v] ×* [n; f] = [ω × n + v × f; ω × f].
Force cross_force(const Motion& a, const Force& b);
/// A motion of the parent expressed in the child, X_PC = (R, p) the child's pose in the parent.
Motion motion_to_child(const M3& R, const V3& p, const Motion& m);
/// A force on the child expressed in the parent.
Force force_to_parent(const M3& R, const V3& p, const Force& f);
/// A motion in J' moved to C, X_CJ = (R, p) the pose of J' in C.
Motion motion_to_body(const M3& R, const V3& p, const Motion& m);

/// A body's spatial inertia about its origin: mass, first moment h = m c, and inertia about the
/// origin I_o = Ī + m (|c|² 1 − c cᵀ).
struct Inertia {
  ex mass;
  V3 h;
  M3 I_o;
  Force apply(const Motion& m) const;  ///< [I_o ω + h × v; m v − h × ω]
};

/// Expanded, sin² θ written as 1 − cos² θ, expanded again.
ex tidy(const ex& e);

/// Nodes in the expression tree, counting stops past `cap`.
int expression_size(const ex& e, int cap);

/// tidy(e) when e has at most kTidyNodes nodes, else e as it is (expanding a large product of
/// sums multiplies out its terms: exponential in the depth of the tree of bodies).
inline constexpr int kTidyNodes = 600;
ex tidy_if_small(const ex& e);

}  // namespace momenta::symbolic::detail
