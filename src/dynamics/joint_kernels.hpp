#pragma once
// Per-joint kernels shared by the dynamics algorithms (private to src/dynamics): the child's pose
// in its parent, the motion subspace in the child frame, and the joint's velocity-product term.
// Specialized per joint type; axis-aligned 1-dof joints at the child origin take a fast path.

#include <cmath>
#include <type_traits>

#include "momenta/dynamics/data.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/math/sin_cos.hpp"
#include "momenta/model/model.hpp"

namespace momenta::dynamics::detail {

using model::JointConstants;
using model::JointType;

// Rodrigues (math/rotation.hpp): rotation about unit axis a by θ given c = cos θ, s = sin θ.
inline Mat3 axis_rotation(const Vec3& a, double c, double s) { return unit_axis_rotation(a, c, s); }

// A · Rot(e_k, θ): only two columns of A mix.
inline void multiply_basis_rotation(const Mat3& A, int k, double c, double s, Mat3& out) {
  const int i = (k + 1) % 3;
  const int j = (k + 2) % 3;
  out.col(i) = c * A.col(i) + s * A.col(j);
  out.col(j) = c * A.col(j) - s * A.col(i);
  out.col(k) = A.col(k);
}

// A joint turning about coordinate axis k of its child (JointConstants::turns_about_axis) has
// X_PB.R = Rot_k(q), which holds c = cos q at (i, i) and s = sin q at (j, i), (k, i, j) cyclic.
// Calls f(std::integral_constant<int, k>{}, c, s), so that f can take k as a template argument.
template <class F>
[[gnu::always_inline]] inline void with_axis_rotation(int k, const Mat3& R, F&& f) {
  switch (k) {
    case 0:
      return f(std::integral_constant<int, 0>{}, R(1, 1), R(2, 1));
    case 1:
      return f(std::integral_constant<int, 1>{}, R(2, 2), R(0, 2));
    default:
      return f(std::integral_constant<int, 2>{}, R(0, 0), R(1, 0));
  }
}

// f(std::integral_constant<int, k>{}) for the coordinate axis k = 0, 1, 2.
template <class F>
[[gnu::always_inline]] inline void with_axis(int k, F&& f) {
  switch (k) {
    case 0:
      return f(std::integral_constant<int, 0>{});
    case 1:
      return f(std::integral_constant<int, 1>{});
    default:
      return f(std::integral_constant<int, 2>{});
  }
}

// X = (Rot_K(q), p): the pose of a joint turning about axis K of a child frame on its axis.
template <int K>
[[gnu::always_inline]] inline void set_axis_rotation(double c, double s, const Vec3& p,
                                                     Transform& X) {
  constexpr int I = (K + 1) % 3, J = (K + 2) % 3;
  X.R.setZero();
  X.R(I, I) = c;
  X.R(J, I) = s;
  X.R(I, J) = -s;
  X.R(J, J) = c;
  X.R(K, K) = 1.0;
  X.p = p;
}

// out = A Rot_K(q): columns I and J of A mix, column K stays.
template <int K>
[[gnu::always_inline]] inline void mix_columns(const Mat3& A, double c, double s, Mat3& out) {
  constexpr int I = (K + 1) % 3, J = (K + 2) % 3;
  out.col(I) = c * A.col(I) + s * A.col(J);
  out.col(J) = c * A.col(J) - s * A.col(I);
  out.col(K) = A.col(K);
}

inline Mat3 quaternion_matrix(const double* wxyz) {
  return Quat(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized().toRotationMatrix();
}

// X_PB(q) = X_PJ · X_JJ'(q) · X_JC for any joint, and the motion subspace in C where it depends
// on q (universal, planar, free; constant subspaces are set by Data's constructor).
inline void joint_position_general(const JointConstants& c, const double* q, Transform& X_PB,
                                   Mat6& S);

// joint_position_general with the commonest case inline: a revolute joint about a coordinate
// axis of the child frame, whose origin is on the axis (two columns of X_PJ's rotation mix).
[[gnu::always_inline]] inline void joint_position(const JointConstants& c, const double* q,
                                                  Transform& X_PB, Mat6& S) {
  if (c.type == JointType::revolute && c.child_at_joint && c.S_basis >= 0) {
    const auto [sq, cq] = math::sin_cos(q[0]);
    multiply_basis_rotation(c.X_PJ.R, c.S_basis, cq, sq, X_PB.R);
    X_PB.p = c.X_PJ.p;
    return;
  }
  joint_position_general(c, q, X_PB, S);
}

inline void joint_position_general(const JointConstants& c, const double* q, Transform& X_PB,
                                   Mat6& S) {
  switch (c.type) {
    case JointType::revolute: {
      const Mat3 R_PJ2 = c.X_PJ.R * axis_rotation(c.axis, std::cos(q[0]), std::sin(q[0]));
      X_PB.R = R_PJ2 * c.X_JC.R;
      X_PB.p = c.X_PJ.p + R_PJ2 * c.X_JC.p;
      return;
    }
    case JointType::prismatic: {
      X_PB.R = c.X_PJ.R * c.X_JC.R;
      X_PB.p = c.X_PJ.p + c.X_PJ.R * (c.axis * q[0] + c.X_JC.p);
      return;
    }
    case JointType::fixed:
      X_PB = c.X_PJ * c.X_JC;
      return;
    case JointType::cylindrical:
    case JointType::universal:
    case JointType::spherical:
    case JointType::planar:
    case JointType::free:
      break;
  }
  // Multi-dof joints: X_JJ'(q) and, where it varies, S in J'.
  Transform X_JJ2;
  Mat6 S_J = Mat6::Zero();
  bool s_varies = false;
  switch (c.type) {
    case JointType::cylindrical:
      X_JJ2 = {axis_rotation(c.axis, std::cos(q[0]), std::sin(q[0])), c.axis * q[1]};
      break;
    case JointType::universal: {
      const Mat3 R2 = axis_rotation(c.axis2, std::cos(q[1]), std::sin(q[1]));
      X_JJ2 = Transform::rotation(axis_rotation(c.axis, std::cos(q[0]), std::sin(q[0])) * R2);
      S_J.block<3, 1>(0, 0) = R2.transpose() * c.axis;
      S_J.block<3, 1>(0, 1) = c.axis2;
      s_varies = true;
      break;
    }
    case JointType::spherical:
      X_JJ2 = Transform::rotation(quaternion_matrix(q));
      break;
    case JointType::planar: {
      const Mat3 Rz = axis_rotation(Vec3::UnitZ(), std::cos(q[2]), std::sin(q[2]));
      X_JJ2 = {Rz, Vec3(q[0], q[1], 0.0)};
      S_J.block<3, 2>(3, 0) = Rz.transpose().leftCols<2>();
      S_J(2, 2) = 1.0;
      s_varies = true;
      break;
    }
    case JointType::free: {
      X_JJ2 = {quaternion_matrix(q + 3), Vec3(q[0], q[1], q[2])};
      S_J.topLeftCorner<3, 3>().setIdentity();
      S_J.block<3, 3>(3, 3) = X_JJ2.R.transpose();
      s_varies = true;
      break;
    }
    case JointType::fixed:
    case JointType::revolute:
    case JointType::prismatic:
      break;  // done above
  }
  X_PB = c.X_PJ * X_JJ2 * c.X_JC;
  if (s_varies) {
    for (int k = 0; k < c.nv; ++k) S.col(k) = c.X_JC.act_motion_inverse(S_J.col(k));
  }
}

// The joint's velocity-product acceleration Ṡ v̄ (Featherstone's c_J, the component derivative
// of S in J' times the joint rates), expressed in C. Zero except for universal, planar, free.
inline bool joint_bias(const JointConstants& c, const double* q, const double* qd, Vec6& cJ_C) {
  Vec6 cJ = Vec6::Zero();
  switch (c.type) {
    case JointType::universal: {
      // d/dt (R2ᵀ a1) = −θ̇2 a2 × (R2ᵀ a1).
      const Mat3 R2 = axis_rotation(c.axis2, std::cos(q[1]), std::sin(q[1]));
      const Vec3 s1 = R2.transpose() * c.axis;
      cJ.head<3>() = qd[0] * qd[1] * s1.cross(c.axis2);
      break;
    }
    case JointType::planar: {
      // d/dt (Rzᵀ) = −θ̇ ẑ × Rzᵀ.
      const Mat3 Rz = axis_rotation(Vec3::UnitZ(), std::cos(q[2]), std::sin(q[2]));
      const Vec3 v_J2 = Rz.transpose() * Vec3(qd[0], qd[1], 0.0);
      cJ.tail<3>() = -qd[2] * Vec3::UnitZ().cross(v_J2);
      break;
    }
    case JointType::free: {
      // d/dt (Rᵀ) v = −ω × (Rᵀ v).
      const Mat3 R = quaternion_matrix(q + 3);
      const Vec3 w(qd[0], qd[1], qd[2]);
      cJ.tail<3>() = -w.cross(R.transpose() * Vec3(qd[3], qd[4], qd[5]));
      break;
    }
    case JointType::fixed:
    case JointType::revolute:
    case JointType::prismatic:
    case JointType::cylindrical:
    case JointType::spherical:
      return false;  // S constant in J'
  }
  cJ_C = c.X_JC.act_motion_inverse(cJ);
  return true;
}

// Joint velocity S v̄ in C.
inline Vec6 joint_velocity(const JointConstants& c, const Mat6& S, const double* qd) {
  if (c.nv == 1) {
    if (c.S_basis >= 0) {
      Vec6 out = Vec6::Zero();
      out[c.S_basis] = qd[0];
      return out;
    }
    return S.col(0) * qd[0];
  }
  Vec6 out = Vec6::Zero();
  for (int k = 0; k < c.nv; ++k) out += S.col(k) * qd[k];
  return out;
}

}  // namespace momenta::dynamics::detail
