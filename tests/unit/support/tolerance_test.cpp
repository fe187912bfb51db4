// The shared comparison helpers must fail on anything non-finite, wherever it sits: a helper that
// lets NaN through makes every test that uses it unable to fail.
#include "momenta_test/tolerance.hpp"

#include <limits>

#include <gtest/gtest.h>
#include <Eigen/Core>

namespace momenta::test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(MatricesNear, PassesWithinToleranceAndFailsBeyondIt) {
  const Eigen::Vector3d a(1.0, 2.0, 3.0);
  EXPECT_TRUE(matrices_near(a, Eigen::Vector3d(1.0, 2.0, 3.0 + 1e-12), 2e-12));
  EXPECT_FALSE(matrices_near(a, Eigen::Vector3d(1.0, 2.0, 3.0 + 1e-9), 1e-12));
}

TEST(MatricesNear, FailsOnNaNInEveryPositionOfEitherOperand) {
  for (int i = 0; i < 4; ++i) {
    Eigen::Matrix2d with_nan = Eigen::Matrix2d::Identity();
    with_nan(i) = kNaN;
    EXPECT_FALSE(matrices_near(with_nan, Eigen::Matrix2d::Identity(), 1.0)) << "entry " << i;
    EXPECT_FALSE(matrices_near(Eigen::Matrix2d::Identity(), with_nan, 1.0)) << "entry " << i;
    EXPECT_FALSE(matrices_near(with_nan, with_nan, 1.0)) << "entry " << i;
  }
}

TEST(MatricesNear, FailsOnInfinityEvenWhenBothAgree) {
  const Eigen::Vector2d a(kInf, 0.0);
  EXPECT_FALSE(matrices_near(a, a, 1.0));
  EXPECT_FALSE(matrices_near(Eigen::Vector2d(0.0, -kInf), Eigen::Vector2d::Zero(), kInf));
}

TEST(MatricesNear, FailsOnSizeMismatchAndPassesOnEmpty) {
  EXPECT_FALSE(matrices_near(Eigen::VectorXd::Zero(2), Eigen::VectorXd::Zero(3), 1.0));
  EXPECT_TRUE(matrices_near(Eigen::VectorXd(), Eigen::VectorXd(), 0.0));
}

TEST(RelativelyNear, FailsOnNonFiniteOperands) {
  EXPECT_TRUE(relatively_near(1.0, 1.0 + 1e-15, 1e-14));
  EXPECT_FALSE(relatively_near(1.0, 1.0 + 1e-12, 1e-14));
  EXPECT_FALSE(relatively_near(kNaN, 1.0, 1e300));
  EXPECT_FALSE(relatively_near(1.0, kNaN, 1e300, 1e300));
  EXPECT_FALSE(relatively_near(kInf, kInf, 1.0));
}

}  // namespace
}  // namespace momenta::test
