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

}  // namespace

Mat3 skew(const Vec3& a) {
  Mat3 S;
  S << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return S;
}

Mat3 rotation_from_axis_angle(const Vec3& axis, double angle) {
  const double n = axis.norm();
  if (!(n > 0) || !std::isfinite(n) || !std::isfinite(angle)) {
    throw InvalidArgument(fmt::format("rotation axis [{}, {}, {}] with angle {} is not a finite "
                                      "non-zero axis and a finite angle",
                                      axis.x(), axis.y(), axis.z(), angle));
  }
  return Eigen::AngleAxisd(angle, axis / n).toRotationMatrix();
}

Mat3 rotation_from_euler(std::string_view sequence, const Vec3& angles) {
  // Three axis letters of one case, no two neighbours equal.
  const auto valid = [&] {
    if (sequence.size() != 3) return false;
    const bool upper = std::isupper(static_cast<unsigned char>(sequence[0])) != 0;
    for (char c : sequence) {
      if ((std::isupper(static_cast<unsigned char>(c)) != 0) != upper) return false;
      if (axis_index(c) < 0 || axis_index(c) > 2) return false;
    }
    return sequence[0] != sequence[1] && sequence[1] != sequence[2];
  }();
  if (!valid) {
    throw InvalidArgument(fmt::format(
        "Euler sequence '{}' is not one of the 12 sequences such as 'ZYX' (intrinsic, upper case) "
        "or 'zyx' (extrinsic, lower case)",
        sequence));
  }
  if (!angles.allFinite()) {
    throw InvalidArgument(fmt::format("Euler angles [{}, {}, {}] are not finite", angles[0],
                                      angles[1], angles[2]));
  }
  const Mat3 R0 = elementary_rotation(axis_index(sequence[0]), angles[0]);
  const Mat3 R1 = elementary_rotation(axis_index(sequence[1]), angles[1]);
  const Mat3 R2 = elementary_rotation(axis_index(sequence[2]), angles[2]);
  // Intrinsic rotations compose about the moving axes (post-multiply), extrinsic about the fixed.
  const bool intrinsic = std::isupper(static_cast<unsigned char>(sequence[0])) != 0;
  return intrinsic ? Mat3(R0 * R1 * R2) : Mat3(R2 * R1 * R0);
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
