#include "momenta/math/lie_group.hpp"

#include <gtest/gtest.h>

#include "momenta/math/rotation.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

// J_r(δ) maps δ̇ to the body angular velocity of Exp(δ): check it against central differences,
// ω_B ≈ log(Exp(δ)ᵀ Exp(δ + ε u)) / ε, on both sides of the series switch-over.
TEST(LieGroup, RightJacobianMatchesFiniteDifferences) {
  for (const double scale : {1e-6, 1e-4 * 0.5, 1e-4 * 2, 0.3, 2.5}) {
    const Vec3 delta = scale * Vec3(0.6, -0.48, 0.64);
    const Mat3 J = so3_right_jacobian(delta);
    const double eps = 1e-6;
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = Vec3::Unit(k);
      const Quat q = quaternion_exp(delta);
      const Vec3 plus = quaternion_log(q.conjugate() * quaternion_exp(delta + eps * u));
      const Vec3 minus = quaternion_log(q.conjugate() * quaternion_exp(delta - eps * u));
      // Central differences: truncation O(ε²) ≈ 1e-12, round-off ε_mach/ε ≈ 2e-10.
      EXPECT_MATRIX_NEAR(J.col(k), (plus - minus) / (2 * eps), 1e-9) << "scale " << scale;
    }
  }
}

// J̇_r along δ(t) = δ0 + t δ̇ against central differences of J_r itself (truncation h² times the
// third derivative, about 1e-10; round-off ε_mach/h ≈ 2e-11), on both sides of the series
// switch-over at θ = 0.1 and at rest (θ = 0, where only the −½ K̇ term is left).
TEST(LieGroup, RightJacobianRateMatchesFiniteDifferences) {
  const Vec3 rate(-0.3, 1.1, 0.45);
  for (const double scale : {0.0, 1e-7, 0.0999, 0.1001, 0.7, 3.0}) {
    const Vec3 delta = scale * Vec3(0.6, -0.48, 0.64);
    const double h = 1e-5;
    const Mat3 fd =
        (so3_right_jacobian(delta + h * rate) - so3_right_jacobian(delta - h * rate)) / (2 * h);
    EXPECT_MATRIX_NEAR(so3_right_jacobian_rate(delta, rate), fd, 1e-9) << "scale " << scale;
  }
}

TEST(LieGroup, InverseIsTheInverse) {
  for (const double scale : {0.0, 1e-8, 0.9e-4, 1.1e-4, 1.0, 3.0, 6.0}) {
    const Vec3 delta = scale * Vec3(0.36, 0.48, -0.8);
    // Conditioning grows toward θ = 2π; 6 rad is still well conditioned (cond ≈ 20).
    EXPECT_MATRIX_NEAR(so3_right_jacobian(delta) * so3_right_jacobian_inverse(delta),
                       Mat3::Identity(), 1e-14)
        << "scale " << scale;
  }
}

}  // namespace
}  // namespace momenta
