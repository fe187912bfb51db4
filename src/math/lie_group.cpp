#include "momenta/math/lie_group.hpp"

#include <cmath>

#include "momenta/math/rotation.hpp"

namespace momenta {

namespace {
// Below this angle the closed-form coefficients lose digits to cancellation; their Taylor series
// truncated after the θ⁴ term are exact to round-off there (next term ~ θ⁶ < 1e-24).
constexpr double kSeriesAngle = 1e-4;
}  // namespace

Mat3 so3_right_jacobian(const Vec3& delta) {
  const double theta2 = delta.squaredNorm();
  const double theta = std::sqrt(theta2);
  double a, b;  // J_r = I − a [δ]× + b [δ]×²
  if (theta < kSeriesAngle) {
    a = 0.5 - theta2 / 24.0 + theta2 * theta2 / 720.0;
    b = 1.0 / 6.0 - theta2 / 120.0 + theta2 * theta2 / 5040.0;
  } else {
    // 1 − cos θ = 2 sin²(θ/2) without the cancellation that would cost ε/θ of accuracy.
    const double half_sine = std::sin(0.5 * theta);
    a = 2.0 * half_sine * half_sine / theta2;
    b = (theta - std::sin(theta)) / (theta2 * theta);
  }
  const Mat3 K = skew(delta);
  return Mat3::Identity() - a * K + b * K * K;
}

Mat3 so3_right_jacobian_inverse(const Vec3& delta) {
  const double theta2 = delta.squaredNorm();
  const double theta = std::sqrt(theta2);
  double c;  // J_r⁻¹ = I + ½ [δ]× + c [δ]×²
  if (theta < kSeriesAngle) {
    c = 1.0 / 12.0 + theta2 / 720.0 + theta2 * theta2 / 30240.0;
  } else {
    c = 1.0 / theta2 - (1.0 + std::cos(theta)) / (2.0 * theta * std::sin(theta));
  }
  const Mat3 K = skew(delta);
  return Mat3::Identity() + 0.5 * K + c * K * K;
}

}  // namespace momenta
