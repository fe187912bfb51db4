#pragma once
// Rotations: matrices, quaternions, Euler angles, the exponential map.
//
// Conventions (docs/conventions.md): R_AB maps vectors expressed in B into A, v_A = R_AB * v_B,
// and its columns are B's unit axes expressed in A. Quaternions are Hamilton, scalar first when
// written as a list [w, x, y, z], and q_AB rotates B into A like R_AB.

#include <string_view>

#include "momenta/math/types.hpp"

namespace momenta {

/// The cross-product matrix: skew(a) * b == a.cross(b).
Mat3 skew(const Vec3& a);

/// Rotation by `angle` (rad) about the unit axis `axis`. Throws InvalidArgument if the axis is
/// zero or not finite (it is normalized otherwise).
Mat3 rotation_from_axis_angle(const Vec3& axis, double angle);

/// Rodrigues' formula: the rotation about the unit axis a by the angle whose cosine and sine are
/// c and s, R = c 1 + s [a]× + (1 − c) a aᵀ. Unchecked (a must be unit), for the joints' hot
/// paths; rotation_from_axis_angle checks its axis.
inline Mat3 unit_axis_rotation(const Vec3& a, double c, double s) {
  const double t = 1.0 - c;
  Mat3 R;
  R << t * a.x() * a.x() + c, t * a.x() * a.y() - s * a.z(), t * a.x() * a.z() + s * a.y(),
      t * a.x() * a.y() + s * a.z(), t * a.y() * a.y() + c, t * a.y() * a.z() - s * a.x(),
      t * a.x() * a.z() - s * a.y(), t * a.y() * a.z() + s * a.x(), t * a.z() * a.z() + c;
  return R;
}

/// Rotation from three Euler angles (rad) applied in the named sequence, SciPy's convention:
/// upper case ("ZYX", "ZXZ") is intrinsic — R = R_1(a0) R_2(a1) R_3(a2) about the moving axes —
/// and lower case ("zyx", "zxz") is extrinsic — R = R_3(a2) R_2(a1) R_1(a0) about fixed axes.
/// All 12 sequences (6 Tait–Bryan, 6 proper Euler) are accepted. Throws InvalidArgument for any
/// other sequence, naming it.
Mat3 rotation_from_euler(std::string_view sequence, const Vec3& angles);

/// Throws InvalidArgument, naming it, unless `sequence` is one of the 12 Euler sequences
/// (three axis letters of one case, no two neighbours equal).
void check_euler_sequence(std::string_view sequence);

/// The three Euler angles (rad) of R in the named sequence, rotation_from_euler's inverse:
/// rotation_from_euler(sequence, euler_from_rotation(sequence, R)) = R. The first and last lie in
/// (−π, π]; the middle one in [0, π] for a proper sequence (ZXZ) and [−π/2, π/2] for a Tait–Bryan
/// one (ZYX). At gimbal lock (middle angle 0 or π, resp. ±π/2) the first and last angles are not
/// unique: the third of an intrinsic sequence (the first of an extrinsic one) is set to 0.
/// Throws InvalidArgument for an unknown sequence.
Vec3 euler_from_rotation(std::string_view sequence, const Mat3& R);

/// E with ω = E ȧ: the angular velocity (in the fixed frame) of the rotation
/// rotation_from_euler(sequence, a) when the angles change at ȧ. Its columns are the three
/// rotation axes at `angles`; it is singular at gimbal lock (|det E| = |sin| resp. |cos| of the
/// middle angle).
Mat3 euler_rate_matrix(std::string_view sequence, const Vec3& angles);

/// A tangent t₁ of the plane of unit normal n: the x axis projected on it, or the y axis where
/// |n_x| ≥ 0.9 (the projection of x would be short). A contact's friction rows lie along t₁ and
/// n × t₁ (model::Contact).
Vec3 plane_tangent(const Vec3& n);
/// The frame [t₁, n × t₁, n] of a plane of unit normal n: z along n, x along plane_tangent(n).
Mat3 plane_frame(const Vec3& n);

/// True when R is orthonormal with determinant +1 to within `tolerance` (max-norm of RᵀR − I).
bool is_rotation_matrix(const Mat3& R, double tolerance = 1e-9);

/// Throws InvalidArgument naming `what`, the orthonormality error and the determinant if R is not a
/// rotation matrix to within `tolerance`.
void check_rotation_matrix(const Mat3& R, std::string_view what, double tolerance = 1e-9);

/// Unit quaternion from a list [w, x, y, z]; throws InvalidArgument naming `what` if its norm is
/// zero, not finite, or further than `tolerance` from 1 (it is normalized otherwise).
Quat quaternion_from_wxyz(const Eigen::Vector4d& wxyz, std::string_view what,
                          double tolerance = 1e-6);

/// The exponential map so(3) -> unit quaternions: the rotation by |phi| about phi/|phi|.
/// Accurate near phi = 0 (series), so integrators can use it for any step.
Quat quaternion_exp(const Vec3& phi);

/// The logarithm: the rotation vector phi (|phi| <= pi) with quaternion_exp(phi) == ±q.
Vec3 quaternion_log(const Quat& q);

}  // namespace momenta
