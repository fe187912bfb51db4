// Telling stiffness: the linearization's eigenvalues against the explicit methods' stability
// regions, and dopri5's own estimate of h|λ| inside its steps.

#include <cmath>
#include <complex>

#include <gtest/gtest.h>

#include "momenta/integrate/run.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/stiffness.hpp"
#include "test_systems.hpp"

namespace momenta::integrate {
namespace {

TEST(Stiffness, StabilityRegionsMeetTheAxesWhereTheTextbooksSay) {
  // Hairer & Wanner II, Fig. IV.2.1: rk4 meets the negative real axis at −2.7853 and the
  // imaginary axis at 2√2; dopri5's fifth-order solution the real axis at −3.3066 (roots of
  // |R| = 1 computed independently with SciPy's brentq).
  EXPECT_NEAR(amplification("rk4", {-2.785293563405282, 0.0}), 1.0, 1e-13);
  EXPECT_NEAR(amplification("rk4", {0.0, 2.0 * std::sqrt(2.0)}), 1.0, 1e-13);
  EXPECT_NEAR(amplification("dopri5", {-3.306567892634946, 0.0}), 1.0, 1e-13);
  EXPECT_TRUE(std::isnan(amplification("bdf", {-1.0, 0.0})));
  const Eigen::VectorXcd eigenvalues = Eigen::VectorXcd::Constant(1, {-8117.0, 0.0});
  const StepStability at_4e4 = check_step_stability("rk4", eigenvalues, 4e-4);
  EXPECT_FALSE(at_4e4.stable);
  // (The check allows |R| ≤ 1 + 1e-9, for the round-off of a mode on the imaginary axis: the
  // edge moves by less than 1e-9 of the step; measured 2.4e-10 and 1.4e-10.)
  EXPECT_NEAR(at_4e4.largest_stable_step, 2.785293563405282 / 8117.0, 1e-9 * 3.4e-4);
  EXPECT_TRUE(check_step_stability("rk4", eigenvalues, 3e-4).stable);
  // An undamped mode at 100 rad/s: stable up to h = 2√2 / 100.
  const Eigen::VectorXcd oscillator{{{0.0, 100.0}, {0.0, -100.0}}};
  EXPECT_NEAR(check_step_stability("rk4", oscillator, 0.01).largest_stable_step,
              2.0 * std::sqrt(2.0) / 100.0, 1e-9 * 0.028);
  // A growing mode (an inverted pendulum) is unstable for every method: not the step's fault.
  const Eigen::VectorXcd growing = Eigen::VectorXcd::Constant(1, {5.0, 0.0});
  EXPECT_TRUE(check_step_stability("rk4", growing, 10.0).stable);
}

TEST(Stiffness, LinearizationOfTheSpringDamperHasItsTwoRoots) {
  // m λ² + c λ + k = 0: −20.010 and −39 979.99 1/s; forward differences with a √ε probe on a
  // linear system are exact to round-off relative to the largest entry (k/m = 8e5).
  test::SpringDamper system(1.0, 8e5, 4e4);
  const Eigen::VectorXcd lambda =
      linearization_eigenvalues(system, State{0.0, VecX::Constant(1, 0.01), VecX::Zero(1)});
  ASSERT_EQ(lambda.size(), 2);
  const double d = std::sqrt(4e4 * 4e4 - 4 * 8e5);
  const double slow = (-4e4 + d) / 2, fast = (-4e4 - d) / 2;
  const double found_slow = std::max(lambda[0].real(), lambda[1].real());
  const double found_fast = std::min(lambda[0].real(), lambda[1].real());
  EXPECT_NEAR(found_fast, fast, 1e-6 * std::abs(fast));
  EXPECT_NEAR(found_slow, slow, 1e-4 * std::abs(slow));
  EXPECT_EQ(lambda[0].imag(), 0.0);
}

TEST(Stiffness, Dopri5NoticesItIsHeldByStability) {
  // On the stiff spring-damper its steps settle at h|λ2| ≈ 3.3 (Hairer's estimate of |λ| within
  // 1 % of 39 980 1/s, measured); on a gentle oscillator at a loose tolerance, never.
  test::SpringDamper stiff(1.0, 8e5, 4e4);
  DormandPrince5 dopri(Tolerances{1e-6, 1e-8});
  State state{0.0, VecX::Constant(1, 0.01), VecX::Zero(1)};
  run(stiff, dopri, state, {1.0, 0.01, 1}, [](const State&) {});
  const IntegratorStatistics& s = dopri.statistics();
  EXPECT_GT(s.stability_limited_steps, s.steps / 2);
  EXPECT_LT(s.stiff_from, 0.01);
  EXPECT_NEAR(s.stiff_eigenvalue, 39979.99, 0.03 * 39979.99);

  test::HarmonicOscillator gentle(2.0);
  DormandPrince5 relaxed(Tolerances{1e-3, 1e-6});
  State start{0.0, VecX::Constant(1, 1.0), VecX::Zero(1)};
  run(gentle, relaxed, start, {10.0, 1.0, 1}, [](const State&) {});
  EXPECT_TRUE(std::isnan(relaxed.statistics().stiff_from));
}

}  // namespace
}  // namespace momenta::integrate
