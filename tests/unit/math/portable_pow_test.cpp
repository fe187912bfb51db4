#include "momenta/math/portable_pow.hpp"

#include <cmath>
#include <cstdint>
#include <random>

#include <gtest/gtest.h>

namespace momenta::math {
namespace {

// Against the C library's pow over the step-size controllers' range (errors from 1e-30 to 1e30,
// the exponents they use) and beyond: within the stated 1e-15 (1 + |y log x|).
TEST(PortablePow, AgreesWithTheLibrarysPowWithinItsBound) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> decade(-30.0, 30.0), exponent(-3.0, 3.0);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i) {
    const double x = std::pow(10.0, decade(random));
    for (const double y : {-0.2, 0.08, 0.2, 0.8, exponent(random)}) {
      const double expected = std::pow(x, y);
      const double bound = 1e-15 * (1.0 + std::abs(y * std::log(x)));
      const double error = std::abs(portable_pow(x, y) - expected) / expected;
      worst = std::max(worst, error / bound);
      ASSERT_LE(error, bound) << x << "^" << y;
    }
  }
  EXPECT_GT(worst, 0.0);  // it is a different computation, not the library's call
}

TEST(PortablePow, HandlesTheEdgesOfItsDomain) {
  EXPECT_EQ(portable_pow(2.0, 0.0), 1.0);
  EXPECT_EQ(portable_pow(1.0, 0.37), 1.0);
  EXPECT_DOUBLE_EQ(portable_pow(4.0, 0.5), 2.0);
  EXPECT_NEAR(portable_pow(1e-300, 0.2) / 1e-60, 1.0, 1e-15 * (1.0 + 0.2 * 690.8));
  // The smallest subnormal: |y log x| = 372, within 1e-15 (1 + 372) of its square root.
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_NEAR(portable_pow(tiny, 0.5) / std::sqrt(tiny), 1.0, 1e-15 * 373.0);
  EXPECT_EQ(portable_pow(1e300, 2.0), std::numeric_limits<double>::infinity());
  EXPECT_EQ(portable_pow(1e-300, 2.0), 0.0);
  // Zero and infinity as std::pow has them (a step's error estimate of exactly 0).
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  for (const double x : {0.0, kInfinity}) {
    for (const double y : {0.17, -0.2, 0.0}) EXPECT_EQ(portable_pow(x, y), std::pow(x, y));
  }
  EXPECT_TRUE(std::isnan(portable_pow(-1.0, 0.2)));
  EXPECT_TRUE(std::isnan(portable_pow(std::nan(""), 0.2)));
  EXPECT_TRUE(std::isnan(portable_pow(2.0, std::nan(""))));
}

}  // namespace
}  // namespace momenta::math
