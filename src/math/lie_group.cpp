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

Mat3 so3_right_jacobian_rate(const Vec3& delta, const Vec3& delta_rate) {
  // J_r = I − a(s) K + b(s) K², s = θ², K = [δ]×, so with ṡ = 2 δ·δ̇ and K̇ = [δ̇]×
  //   J̇_r = −a′ ṡ K − a K̇ + b′ ṡ K² + b (K̇ K + K K̇).
  // a(s) = Σ (−s)ᵏ/(2k+2)!, b(s) = Σ (−s)ᵏ/(2k+3)!; their derivatives in closed form lose ε/θ² to
  // cancellation, so below θ = 0.1 the series through s⁴ are used (next term < 1e-20).
  const double s = delta.squaredNorm();
  const double theta = std::sqrt(s);
  double a, b, da, db;
  if (theta < 0.1) {
    a = 0.5 - s / 24.0 + s * s / 720.0 - s * s * s / 40320.0 + s * s * s * s / 3628800.0;
    b = 1.0 / 6.0 - s / 120.0 + s * s / 5040.0 - s * s * s / 362880.0 + s * s * s * s / 39916800.0;
    da = -1.0 / 24.0 + 2.0 * s / 720.0 - 3.0 * s * s / 40320.0 + 4.0 * s * s * s / 3628800.0 -
         5.0 * s * s * s * s / 479001600.0;
    db = -1.0 / 120.0 + 2.0 * s / 5040.0 - 3.0 * s * s / 362880.0 + 4.0 * s * s * s / 39916800.0 -
         5.0 * s * s * s * s / 6227020800.0;
  } else {
    const double half_sine = std::sin(0.5 * theta);
    const double one_minus_cos = 2.0 * half_sine * half_sine;
    const double sine = std::sin(theta);
    a = one_minus_cos / s;
    b = (theta - sine) / (s * theta);
    da = (theta * sine - 2.0 * one_minus_cos) / (2.0 * s * s);
    db = (theta * one_minus_cos - 3.0 * (theta - sine)) / (2.0 * s * s * theta);
  }
  const double s_rate = 2.0 * delta.dot(delta_rate);
  const Mat3 K = skew(delta);
  const Mat3 K_rate = skew(delta_rate);
  return -da * s_rate * K - a * K_rate + db * s_rate * K * K + b * (K_rate * K + K * K_rate);
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
