// Gain and phase margins against the closed forms of two textbook loops (Franklin, Powell &
// Emami-Naeini §6.4): L = 1/(s (s + 1)(s + 2)), whose phase crosses −180° at ω = √2 where |L| =
// 1/6 (GM = 6, 15.56 dB), and L = 4/(s + 1)³, crossing at ω = √3 with |L| = 1/2 (GM = 2); their
// gain crossovers from |L| = 1 solved independently (bisection on the polynomial, and in closed
// form), PM = 180° + ∠L there.

#include "momenta/analysis/stability_margins.hpp"

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"

namespace momenta::analysis::stability_margins_test {
namespace {

constexpr double kDeg = 180.0 / std::numbers::pi;

// b0 / (s³ + a2 s² + a1 s + a0) in controllable canonical form.
StateSpace third_order(double b0, double a2, double a1, double a0) {
  MatX A(3, 3), B(3, 1), C(1, 3), D(1, 1);
  A << 0, 1, 0, 0, 0, 1, -a0, -a1, -a2;
  B << 0, 0, 1;
  C << b0, 0, 0;
  D << 0;
  return StateSpace(A, B, C, D, {}, {"u"}, {"y"});
}

TEST(StabilityMargins, ATypeOneLoopAsFranklinHasIt) {
  const StabilityMargins m = stability_margins(third_order(1.0, 3.0, 2.0, 0.0), 0, 0, 0.01, 100.0);
  // Located to 1e-12 relative in ω; GM and PM then follow to a few ulps of their slopes.
  EXPECT_NEAR(m.phase_crossover, std::sqrt(2.0), 1e-11);
  EXPECT_NEAR(m.gain_margin, 6.0, 1e-10);
  EXPECT_NEAR(m.gain_margin_db, 20.0 * std::log10(6.0), 1e-9);
  // |L(jω)| = 1 ⇔ x³ + 5x² + 4x − 1 = 0 with x = ω²: its root in (0, 1) by bisection.
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 200; ++i) {
    const double x = 0.5 * (lo + hi);
    (x * x * x + 5 * x * x + 4 * x - 1 > 0 ? hi : lo) = x;
  }
  const double w = std::sqrt(0.5 * (lo + hi));
  EXPECT_NEAR(m.gain_crossover, w, 1e-11);
  EXPECT_NEAR(m.phase_margin_deg, 90.0 - (std::atan(w) + std::atan(w / 2)) * kDeg, 1e-9);
  EXPECT_EQ(m.phase_crossovers.size(), 1u);
  EXPECT_EQ(m.gain_crossovers.size(), 1u);
}

TEST(StabilityMargins, AThirdOrderLagAsFranklinHasIt) {
  const StabilityMargins m = stability_margins(third_order(4.0, 3.0, 3.0, 1.0), 0, 0, 0.01, 100.0);
  EXPECT_NEAR(m.phase_crossover, std::sqrt(3.0), 1e-11);
  EXPECT_NEAR(m.gain_margin, 2.0, 1e-10);
  // (1 + ω²)^{3/2} = 4.
  const double w = std::sqrt(std::pow(4.0, 2.0 / 3.0) - 1.0);
  EXPECT_NEAR(m.gain_crossover, w, 1e-11);
  EXPECT_NEAR(m.phase_margin_deg, 180.0 - 3.0 * std::atan(w) * kDeg, 1e-9);
}

// |L| < 1 everywhere and a phase that never reaches −180°: both margins infinite, no crossing.
TEST(StabilityMargins, NoCrossingMeansInfiniteMargins) {
  MatX A(1, 1), B(1, 1), C(1, 1), D(1, 1);
  A << -1;
  B << 1;
  C << 0.5;
  D << 0;
  const StabilityMargins m = stability_margins(StateSpace(A, B, C, D), 0, 0, 0.01, 100.0);
  EXPECT_TRUE(std::isinf(m.gain_margin) && std::isinf(m.phase_margin_deg));
  EXPECT_TRUE(std::isnan(m.phase_crossover) && std::isnan(m.gain_crossover));
  EXPECT_TRUE(m.phase_crossovers.empty() && m.gain_crossovers.empty());
  EXPECT_THROW(stability_margins(StateSpace(A, B, C, D), 1, 0, 0.01, 100.0), InvalidArgument);
  EXPECT_THROW(stability_margins(StateSpace(A, B, C, D), 0, 0, 10.0, 1.0), InvalidArgument);
}

// A sampled loop, read on the unit circle z = e^{jωT}: an integrator with one sample of delay,
// L(z) = K T / (z (z − 1)). On the circle L = K T e^{−j3ωT/2} / (2j sin(ωT/2)): its phase
// −90° − 1.5 ωT reaches −180° at ωT = π/3, where |L| = K T (GM = 1/(K T)); |L| = 1 where
// sin(ωT/2) = K T/2, PM = 90° − 3 asin(K T/2). Refined on G(jω) instead (the old mistake, with
// the grid's brackets right) a crossing lands anywhere in its grid step, 0.4 % wide.
TEST(StabilityMargins, ASampledLoopOnTheUnitCircle) {
  const double K = 1.0, T = 0.1;
  MatX A(2, 2), B(2, 1), C(1, 2), D(1, 1);
  A << 0, 1, 0, 1;
  B << 0, 1;
  C << K * T, 0;
  D << 0;
  const StateSpace loop(A, B, C, D, {}, {"u"}, {"y"}, T);
  const StabilityMargins m = stability_margins(loop, 0, 0, 0.01, std::numbers::pi / T);
  EXPECT_NEAR(m.phase_crossover, std::numbers::pi / (3.0 * T), 1e-11);
  EXPECT_NEAR(m.gain_margin, 1.0 / (K * T), 1e-10);
  const double w = 2.0 / T * std::asin(K * T / 2.0);
  EXPECT_NEAR(m.gain_crossover, w, 1e-11);
  EXPECT_NEAR(m.phase_margin_deg, 90.0 - 3.0 * std::asin(K * T / 2.0) * kDeg, 1e-9);
}

}  // namespace
}  // namespace momenta::analysis::stability_margins_test
