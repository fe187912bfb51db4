// math::sin_cos (math/sin_cos.hpp) against the C library's sin and cos: within 1 ulp over a
// million angles spread across the reduced range, at and next to the multiples of π/2 (where
// the reduction cancels most), at the edges of each path, and for what goes to the C library.

#include "momenta/math/sin_cos.hpp"

#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace momenta::math {
namespace {

// Units in the last place between a and b (0 for equal doubles).
double ulps(double a, double b) {
  if (a == b) return 0.0;
  const double ulp =
      std::nextafter(std::abs(b), std::numeric_limits<double>::infinity()) - std::abs(b);
  return std::abs(a - b) / ulp;
}

void expect_close(double x) {
  const auto [s, c] = sin_cos(x);
  // The C library is within 1 ulp itself; both within 1 ulp of the exact value puts them within
  // 2 of each other, and a sin or cos near 0 has its own tiny ulp.
  EXPECT_LE(ulps(s, std::sin(x)), 1.0) << "sin " << x;
  EXPECT_LE(ulps(c, std::cos(x)), 1.0) << "cos " << x;
}

TEST(SinCos, WithinOneUlpOfTheCLibraryOverAMillionAngles) {
  std::mt19937_64 random(20261124);
  std::uniform_real_distribution<double> small(-10.0, 10.0), large(-1e6, 1e6);
  double worst = 0.0;
  for (int k = 0; k < 1'000'000; ++k) {
    const double x = k % 10 == 0 ? large(random) : small(random);
    const auto [s, c] = sin_cos(x);
    worst = std::max({worst, ulps(s, std::sin(x)), ulps(c, std::cos(x))});
  }
  EXPECT_LE(worst, 1.0);
}

TEST(SinCos, AtAndNextToTheMultiplesOfHalfPi) {
  for (int n = -2000; n <= 2000; ++n) {
    const double x = n * (M_PI / 2);
    expect_close(x);
    expect_close(std::nextafter(x, 1e300));
    expect_close(std::nextafter(x, -1e300));
  }
  // The largest multiple of π/2 in double near 2²⁰ π/2 and the cut-over.
  for (double x : {0x1.921fb54442d18p+20, 0x1.921fb54442d17p+20, 0x1.921fb54442d19p+20}) {
    expect_close(x);
    expect_close(-x);
  }
}

TEST(SinCos, TheEdgesOfEachPath) {
  for (double x : {0.0, -0.0, 1e-300, 5e-324, 1e-8, 0x1.921fb54442d18p-1, 0x1.921fb54442d19p-1, 1.0,
                   3.0, 1e5, 1e300, -1e300}) {
    expect_close(x);
  }
  EXPECT_EQ(std::signbit(sin_cos(-0.0).first), true);
  EXPECT_TRUE(std::isnan(sin_cos(std::numeric_limits<double>::infinity()).first));
  EXPECT_TRUE(std::isnan(sin_cos(std::numeric_limits<double>::quiet_NaN()).second));
}

}  // namespace
}  // namespace momenta::math
