#include "momenta/math/rotation.hpp"

#include <cctype>
#include <cmath>

#include <fmt/format.h>

#include "momenta/common/error.hpp"

namespace momenta {
namespace {

// Rotation about coordinate axis 0, 1 or 2.
Mat3 elementary_rotation(int axis, double angle) {
  return Eigen::AngleAxisd(angle, Vec3::Unit(axis)).toRotationMatrix();
}

int axis_index(char c) { return std::tolower(static_cast<unsigned char>(c)) - 'x'; }

bool is_upper(char c) { return std::isupper(static_cast<unsigned char>(c)) != 0; }

// Upper case: intrinsic (about the moving axes).
bool is_intrinsic(std::string_view sequence) { return is_upper(sequence[0]); }

// ω = E ȧ of R = R_i(a0) R_j(a1) R_k(a2): ω = ȧ0 e_i + ȧ1 R_i e_j + ȧ2 R_i R_j e_k.
Mat3 intrinsic_rate_matrix(int i, int j, int k, const Vec3& angles) {
  const Mat3 I = Mat3::Identity();
  const Mat3 R0 = elementary_rotation(i, angles[0]);
  Mat3 E;
  E.col(0) = I.col(i);
  E.col(1) = R0 * I.col(j);
  E.col(2) = R0 * elementary_rotation(j, angles[1]) * I.col(k);
  return E;
}

// The parity of the axis permutation (i, j, k): +1 for a cyclic one (x, y, z), −1 otherwise.
double parity(int i, int j, int k) {
  return ((j - i + 3) % 3 == 1 && (k - j + 3) % 3 == 1) ? 1.0 : -1.0;
}

// Intrinsic angles of R = R_i(a) R_j(b) R_k(c) (worked from ZXZ and XYZ and their parities).
Vec3 intrinsic_angles(int i, int j, int k, const Mat3& R) {
  if (i == k) {  // proper Euler: the third axis l completes (i, j, l)
    const int l = 3 - i - j;
    const double e = parity(i, j, l);
    const double s = std::hypot(R(i, j), R(i, l));
    const double b = std::atan2(s, R(i, i));
    if (s > 1e-12) return {std::atan2(R(j, i), -e * R(l, i)), b, std::atan2(R(i, j), e * R(i, l))};
    // Gimbal lock: R = R_i(a ± c) R_j(b); take c = 0.
    return {std::atan2(-e * R(j, l), R(j, j)), b, 0.0};
  }
  const double e = parity(i, j, k);
  const double c_b = std::hypot(R(i, i), R(i, j));
  const double b = std::atan2(e * R(i, k), c_b);
  if (c_b > 1e-12) {
    return {std::atan2(-e * R(j, k), R(k, k)), b, std::atan2(-e * R(i, j), R(i, i))};
  }
  // Gimbal lock: take c = 0; then R = R_i(a) R_j(b), whose (k, j) and (j, j) entries give a.
  return {std::atan2(e * R(k, j), R(j, j)), b, 0.0};
}

}  // namespace

Vec3 plane_tangent(const Vec3& n) {
  const Vec3 x = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return (x - n * n.dot(x)).normalized();
}

Mat3 plane_frame(const Vec3& n) {
  const Vec3 t1 = plane_tangent(n);
  Mat3 R;
  R << t1, n.cross(t1), n;
  return R;
}

Mat3 skew(const Vec3& a) {
  Mat3 S;
  S << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return S;
}

Mat3 rotation_from_axis_angle(const Vec3& axis, double angle) {
  const double n = axis.norm();
  if (!(n > 0) || !std::isfinite(n) || !std::isfinite(angle)) {
    throw InvalidArgument(
        fmt::format("rotation axis [{}, {}, {}] with angle {} is not a finite "
                    "non-zero axis and a finite angle",
                    axis.x(), axis.y(), axis.z(), angle));
  }
  return Eigen::AngleAxisd(angle, axis / n).toRotationMatrix();
}

void check_euler_sequence(std::string_view sequence) {
  bool valid = sequence.size() == 3;
  if (valid) {
    for (char c : sequence) {
      valid = valid && is_upper(c) == is_intrinsic(sequence) && axis_index(c) >= 0 &&
              axis_index(c) <= 2;
    }
    valid = valid && sequence[0] != sequence[1] && sequence[1] != sequence[2];
  }
  if (!valid) {
    throw InvalidArgument(fmt::format(
        "Euler sequence '{}' is not one of the 12 sequences such as 'ZYX' (intrinsic, upper case) "
        "or 'zyx' (extrinsic, lower case)",
        sequence));
  }
}

Mat3 rotation_from_euler(std::string_view sequence, const Vec3& angles) {
  check_euler_sequence(sequence);
  if (!angles.allFinite()) {
    throw InvalidArgument(
        fmt::format("Euler angles [{}, {}, {}] are not finite", angles[0], angles[1], angles[2]));
  }
  const Mat3 R0 = elementary_rotation(axis_index(sequence[0]), angles[0]);
  const Mat3 R1 = elementary_rotation(axis_index(sequence[1]), angles[1]);
  const Mat3 R2 = elementary_rotation(axis_index(sequence[2]), angles[2]);
  // Intrinsic rotations compose about the moving axes (post-multiply), extrinsic about the fixed.
  return is_intrinsic(sequence) ? Mat3(R0 * R1 * R2) : Mat3(R2 * R1 * R0);
}

Vec3 euler_from_rotation(std::string_view sequence, const Mat3& R) {
  check_euler_sequence(sequence);
  const int a0 = axis_index(sequence[0]), a1 = axis_index(sequence[1]),
            a2 = axis_index(sequence[2]);
  // Extrinsic "abc" is R = R_c(γ) R_b(β) R_a(α): the intrinsic sequence "CBA" with the angles
  // reversed.
  if (is_intrinsic(sequence)) return intrinsic_angles(a0, a1, a2, R);
  const Vec3 reversed = intrinsic_angles(a2, a1, a0, R);
  return {reversed[2], reversed[1], reversed[0]};
}

Mat3 euler_rate_matrix(std::string_view sequence, const Vec3& angles) {
  check_euler_sequence(sequence);
  const int a0 = axis_index(sequence[0]), a1 = axis_index(sequence[1]),
            a2 = axis_index(sequence[2]);
  if (is_intrinsic(sequence)) return intrinsic_rate_matrix(a0, a1, a2, angles);
  // Extrinsic "abc" is the intrinsic "CBA" with the angles, and so the columns, reversed.
  const Mat3 E = intrinsic_rate_matrix(a2, a1, a0, Vec3(angles[2], angles[1], angles[0]));
  Mat3 reversed;
  reversed << E.col(2), E.col(1), E.col(0);
  return reversed;
}

bool is_rotation_matrix(const Mat3& R, double tolerance) {
  if (!R.allFinite()) return false;
  const double orthonormality = (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff();
  return orthonormality <= tolerance && std::abs(R.determinant() - 1.0) <= tolerance;
}

void check_rotation_matrix(const Mat3& R, std::string_view what, double tolerance) {
  if (is_rotation_matrix(R, tolerance)) return;
  const double orthonormality = (R.transpose() * R - Mat3::Identity()).cwiseAbs().maxCoeff();
  throw InvalidArgument(fmt::format(
      "{} is not a rotation matrix: max |RᵀR − I| = {:.3g}, det R = {:.6g} (need an orthonormal "
      "matrix with determinant +1 to within {:.1g}; a reflection has det −1)",
      what, orthonormality, R.determinant(), tolerance));
}

Quat quaternion_from_wxyz(const Eigen::Vector4d& wxyz, std::string_view what, double tolerance) {
  const double n = wxyz.norm();
  if (!std::isfinite(n) || std::abs(n - 1.0) > tolerance) {
    throw InvalidArgument(fmt::format(
        "{} quaternion [{}, {}, {}, {}] has norm {:.9g}; a rotation needs a unit quaternion "
        "[w, x, y, z] (to within {:.1g})",
        what, wxyz[0], wxyz[1], wxyz[2], wxyz[3], n, tolerance));
  }
  return Quat(wxyz[0] / n, wxyz[1] / n, wxyz[2] / n, wxyz[3] / n);
}

Quat quaternion_exp(const Vec3& phi) {
  const double theta = phi.norm();
  const double half = 0.5 * theta;
  // sin(θ/2)/θ, by its Taylor series where the quotient would lose digits.
  const double sinc_half = theta < 1e-4 ? 0.5 - theta * theta / 48.0 : std::sin(half) / theta;
  const Vec3 xyz = sinc_half * phi;
  return Quat(std::cos(half), xyz.x(), xyz.y(), xyz.z());
}

Vec3 quaternion_log(const Quat& q_in) {
  // Take the representative with w >= 0 so the angle lies in [0, π].
  const Quat q = q_in.w() < 0 ? Quat(-q_in.w(), -q_in.x(), -q_in.y(), -q_in.z()) : q_in;
  const double s = q.vec().norm();
  const double theta = 2.0 * std::atan2(s, q.w());
  // θ / sin(θ/2), by its series near zero.
  const double scale = s < 1e-8 ? 2.0 / q.w() : theta / s;
  return scale * q.vec();
}

}  // namespace momenta
