// Cruise control, Franklin, Powell & Emami-Naeini, Feedback Control of Dynamic Systems, ch. 2:
// m v̇ + b v = u, m = 1000 kg, b = 50 N·s/m, so G(s) = V/U = (1/m)/(s + b/m) = 1/(m s + b).
// A step u = 500 N gives v(t) = (u/b)(1 − e^(−bt/m)) → 10 m/s with time constant m/b = 20 s.

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/step_info.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

constexpr double kMass = 1000.0;   // kg
constexpr double kDamping = 50.0;  // N·s/m

StateSpace cruise_control() {
  MatX A(1, 1), B(1, 1), C(1, 1);
  A << -kDamping / kMass;
  B << 1.0 / kMass;
  C << 1.0;
  return StateSpace(A, B, C, MatX(), {"v"}, {"u"}, {"v"});
}

TEST(CruiseControl, PoleGainAndDcGain) {
  const TransferFunction tf = transfer_function(cruise_control(), "u", "v");
  ASSERT_EQ(tf.poles.size(), 1u);
  EXPECT_TRUE(tf.zeros.empty());
  // One division each: exact to an ulp or two.
  EXPECT_REL_NEAR(tf.poles[0].real(), -0.05, 1e-15);
  EXPECT_REL_NEAR(tf.gain, 1.0 / kMass, 1e-15);
  EXPECT_REL_NEAR(tf.dc_gain, 1.0 / kDamping, 1e-15);
  const Modes m = modes(cruise_control());
  EXPECT_REL_NEAR(m.modes[0].natural_frequency, 0.05, 1e-15);
  EXPECT_EQ(m.modes[0].damping_ratio, 1.0);
}

TEST(CruiseControl, StepResponseMatchesTheExponential) {
  const double u = 500.0;  // N
  // Automatic horizon: 7 time constants = 140 s.
  const TimeResponse r = step_response(cruise_control(), 0, {}, u);
  EXPECT_REL_NEAR(r.time[r.time.size() - 1], 7 * kMass / kDamping, 1e-15);
  double worst = 0.0;
  for (Eigen::Index k = 0; k < r.time.size(); ++k) {
    const double exact = u / kDamping * -std::expm1(-kDamping * r.time[k] / kMass);
    worst = std::max(worst, std::abs(r.outputs(k, 0) - exact));
  }
  // Exact discretization: the only error is the round-off of ~500 recurrence steps on a
  // 10 m/s response, ≤ 500 · 4ε · 10 ≈ 4e-12 m/s.
  EXPECT_LT(worst, 4e-12);
  // Impulse response (1/m) e^(−bt/m): the derivative of the unit step response.
  const TimeResponse g = impulse_response(cruise_control(), 0);
  for (Eigen::Index k = 0; k < g.time.size(); k += 50) {
    EXPECT_REL_NEAR(g.outputs(k, 0), std::exp(-kDamping * g.time[k] / kMass) / kMass, 1e-12);
  }
}

TEST(CruiseControl, StepFiguresAreTheTimeConstantsLogarithms) {
  // v = (u/b)(1 − e^(−t/τ)), τ = m/b = 20 s: rise (10 → 90 %) τ ln 9 = 43.9445 s, settling
  // (2 %) τ ln 50 = 78.2404 s, no overshoot; exact figures from the analytic response.
  const StepInfo info = step_info(cruise_control(), 0, 0);
  const double tau = kMass / kDamping;
  EXPECT_REL_NEAR(info.rise_time, tau * std::log(9.0), 1e-12);
  EXPECT_REL_NEAR(info.settling_time, tau * std::log(50.0), 1e-12);
  EXPECT_EQ(info.overshoot, 0.0);
  EXPECT_REL_NEAR(info.final_value, 1.0 / kDamping, 1e-15);
}

TEST(CruiseControl, BodeCornerAtBOverM) {
  // At ω = b/m: |G| = 1/(b√2), phase −45°.
  VecX w(1);
  w << kDamping / kMass;
  const FrequencyResponse fr = frequency_response(cruise_control(), 0, 0, w);
  EXPECT_REL_NEAR(fr.magnitude[0], 1.0 / (kDamping * std::sqrt(2.0)), 1e-15);
  EXPECT_NEAR(fr.phase_deg[0], -45.0, 1e-13);
}

}  // namespace
}  // namespace momenta::analysis
