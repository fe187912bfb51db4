#include "momenta/analysis/time_response.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "analysis_test_systems.hpp"
#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

// ẍ + 2ζωn ẋ + ωn² x = ωn² u, output x (unit DC gain).
StateSpace second_order(double wn, double zeta) {
  MatX A(2, 2), B(2, 1), C(1, 2);
  A << 0, 1, -wn * wn, -2 * zeta * wn;
  B << 0, wn * wn;
  C << 1, 0;
  return StateSpace(A, B, C, MatX(), {"x", "x_dot"}, {"u"}, {"x"});
}

TEST(ZeroOrderHold, ScalarClosedForm) {
  // ẋ = a x + b u: Φ = e^(ah), Γ = b (e^(ah) − 1)/a.
  const double a = -0.7, b = 3.0, h = 0.25;
  MatX A(1, 1), B(1, 1);
  A << a;
  B << b;
  const Discretization zoh = zero_order_hold(A, B, h);
  // Padé approximant of degree 13 with scaling: ~ε relative.
  EXPECT_REL_NEAR(zoh.transition(0, 0), std::exp(a * h), 1e-15);
  EXPECT_REL_NEAR(zoh.input(0, 0), b * std::expm1(a * h) / a, 1e-15);
}

TEST(ZeroOrderHold, SatisfiesIntegralIdentity) {
  // For invertible A: A Γ = (Φ − I) B, a property of ∫₀ʰ e^(Aτ) dτ independent of the method.
  const StateSpace system = test::random_system(5, 2, 1, 9u, false);
  const Discretization zoh = zero_order_hold(system, 0.3);
  EXPECT_MATRIX_NEAR(system.A() * zoh.input, (zoh.transition - MatX::Identity(5, 5)) * system.B(),
                     1e-14);
  EXPECT_THROW(zero_order_hold(system, 0.0), InvalidArgument);
  EXPECT_THROW(zero_order_hold(system.A(), MatX::Ones(4, 1), 0.1), InvalidArgument);
}

TEST(StepResponse, UnderdampedSecondOrderClosedForm) {
  // y(t) = 1 − e^(−ζωn t) (cos ωd t + ζ/√(1−ζ²) sin ωd t).
  const double wn = 2.0, zeta = 0.3;
  const double wd = wn * std::sqrt(1 - zeta * zeta);
  const TimeResponse r = step_response(second_order(wn, zeta), 0, {10.0, 2001});
  ASSERT_EQ(r.time.size(), 2001);
  EXPECT_EQ(r.time[0], 0.0);
  EXPECT_EQ(r.time[2000], 10.0);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < r.time.size(); ++k) {
    const double t = r.time[k];
    const double exact =
        1 - std::exp(-zeta * wn * t) *
                (std::cos(wd * t) + zeta / std::sqrt(1 - zeta * zeta) * std::sin(wd * t));
    worst = std::max(worst, std::abs(r.outputs(k, 0) - exact));
  }
  // 2000 steps of a contracting recurrence, each adding ~ε: 1e-13 is 450 ε of headroom.
  EXPECT_LT(worst, 1e-13);
  EXPECT_EQ(r.states.cols(), 2);
  EXPECT_EQ(r.output_names[0], "x");
}

TEST(ImpulseResponse, IsTheDerivativeOfTheStepResponse) {
  // Impulse g(t) = (ωn/√(1−ζ²)) e^(−ζωn t) sin ωd t, and g = d/dt step.
  const double wn = 2.0, zeta = 0.3;
  const double root = std::sqrt(1 - zeta * zeta);
  const StateSpace system = second_order(wn, zeta);
  const TimeGrid grid{8.0, 8001};
  const TimeResponse step = step_response(system, 0, grid);
  const TimeResponse impulse = impulse_response(system, 0, grid);
  const double h = 8.0 / 8000;
  double worst_closed = 0.0;
  double worst_derivative = 0.0;
  for (Eigen::Index k = 1; k + 1 < impulse.time.size(); ++k) {
    const double t = impulse.time[k];
    const double exact = wn / root * std::exp(-zeta * wn * t) * std::sin(wn * root * t);
    worst_closed = std::max(worst_closed, std::abs(impulse.outputs(k, 0) - exact));
    const double central = (step.outputs(k + 1, 0) - step.outputs(k - 1, 0)) / (2 * h);
    worst_derivative = std::max(worst_derivative, std::abs(central - impulse.outputs(k, 0)));
  }
  // Round-off of 8000 steps on a response of size ~2.
  EXPECT_LT(worst_closed, 1e-12);
  // Central difference truncation h²/6 max|g''| with |g''| ≤ ωn³/√(1−ζ²) (g = Im c e^(λt),
  // |c| = ωn/√(1−ζ²), |λ| = ωn), plus the round-off ε/h of differencing the step samples.
  const double truncation = h * h / 6 * wn * wn * wn / root;
  EXPECT_LT(worst_derivative, truncation + 1e-12);
  // And the bound is not vacuous: the difference is of the order of the truncation.
  EXPECT_GT(worst_derivative, 0.1 * truncation);
  // The t = 0 sample is g(0⁺) = C B = 0 here.
  EXPECT_EQ(impulse.outputs(0, 0), 0.0);
}

TEST(TimeResponse, AutomaticHorizonFromThePoles) {
  // First-order pole −0.05: 7/0.05 = 140 s.
  MatX a(1, 1), b(1, 1), c(1, 1);
  a << -0.05;
  b << 1;
  c << 1;
  EXPECT_DOUBLE_EQ(automatic_final_time(StateSpace(a, b, c, MatX())), 140.0);
  // Unstable pole +2 (and a slow stable one): 5/2.
  EXPECT_DOUBLE_EQ(automatic_final_time(test::canonical_form({-1.99, -0.02}, {1, 0})), 5.0 / 2.0);
  // Double integrator: no time scale, 10 s.
  EXPECT_DOUBLE_EQ(automatic_final_time(test::canonical_form({0, 0}, {1, 0})), 10.0);
  // Undamped oscillator ω = 2: five periods.
  EXPECT_NEAR(automatic_final_time(test::canonical_form({0, 4}, {1, 0})), 5 * M_PI, 1e-12);
  // Lightly damped ζ = 0.01, ωn = 10: 7/(ζωn) = 70 s and 20 samples per period → 2229 samples.
  const TimeResponse r = step_response(second_order(10.0, 0.01), 0);
  EXPECT_NEAR(r.time[r.time.size() - 1], 70.0, 1e-9);
  EXPECT_GE(static_cast<double>(r.time.size()), 20 * 70.0 * 10 * std::sqrt(1 - 1e-4) / (2 * M_PI));
}

TEST(TimeResponse, Errors) {
  const StateSpace system = second_order(1.0, 0.5);
  EXPECT_THROW(step_response(system, 1), InvalidArgument);
  EXPECT_THROW(step_response(system, 0, {-1.0, 10}), InvalidArgument);
  EXPECT_THROW(step_response(system, 0, {1.0, 1}), InvalidArgument);
  EXPECT_THROW(impulse_response(system, 0, {std::nan(""), 10}), InvalidArgument);
  // A fast unstable pole over a long horizon overflows: reported, not returned as inf.
  MatX a(1, 1), b(1, 1), c(1, 1);
  a << 10.0;
  b << 1;
  c << 1;
  EXPECT_THROW(step_response(StateSpace(a, b, c, MatX()), 0, {100.0, 11}), NumericalError);
}

}  // namespace
}  // namespace momenta::analysis
