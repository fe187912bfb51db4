#include "momenta/analysis/step_info.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "analysis_test_systems.hpp"
#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

TEST(StepInfo, FirstOrderLag) {
  // G = 3/(τ s + 1), τ = 0.5 s: y = 3(1 − e^(−t/τ)); 10 %→90 % takes τ ln 9; the 2 % band is
  // entered at τ ln 50; no overshoot.
  const double tau = 0.5;
  const StateSpace system = test::canonical_form({1 / tau}, {3 / tau});
  const StepInfo info = step_info(system, 0, 0, {5.0, 5001});
  EXPECT_REL_NEAR(info.final_value, 3.0, 1e-15);
  // Linear interpolation between samples h = 1 ms apart: error ≤ h²/8 · |y''|/|y'| ≤ h²/(8τ)
  // per crossing ≈ 2.5e-7 s.
  EXPECT_NEAR(info.rise_time, tau * std::log(9.0), 5e-7);
  EXPECT_NEAR(info.settling_time, tau * std::log(50.0), 3e-7);
  EXPECT_EQ(info.overshoot, 0.0);
  EXPECT_EQ(info.undershoot, 0.0);
  EXPECT_NEAR(info.peak, 3.0 * (1 - std::exp(-10.0)), 1e-12);
}

TEST(StepInfo, UnderdampedOvershootAndNonMinimumPhaseUndershoot) {
  // ωn²/(s² + 2ζωn s + ωn²): overshoot 100 e^(−πζ/√(1−ζ²)) % at tp = π/ωd.
  const double wn = 2.0, zeta = 0.2;
  const StateSpace system = test::canonical_form({2 * zeta * wn, wn * wn}, {wn * wn, 0});
  const StepInfo info = step_info(system, 0, 0, {10.0, 100001});
  const double root = std::sqrt(1 - zeta * zeta);
  // Sampled peak: off by ≤ ½ ωn²/√(1−ζ²) (h/2)² = 1e-9 relative of the output; in % ×100.
  EXPECT_NEAR(info.overshoot, 100 * std::exp(-M_PI * zeta / root), 1e-6);
  EXPECT_NEAR(info.peak_time, M_PI / (wn * root), 1e-4 / 2 + 1e-12);
  // (1 − s)/(s + 1)² starts the wrong way: y(t) = 1 − e^(−t) − 2 t e^(−t),
  // y' = e^(−t)(2t − 1), minimum at t = ½ where y = 1 − 2 e^(−½) ≈ −0.213.
  const StateSpace nmp = test::canonical_form({2, 1}, {1, -1});
  const StepInfo under = step_info(nmp, 0, 0, {10.0, 10001});
  // Sampled minimum: off by ≤ ½ |y''(½)| (h/2)² = e^(−½) (5e-4)² ≈ 1.5e-7, ×100 in %.
  EXPECT_NEAR(under.undershoot, -100 * (1 - 2 * std::exp(-0.5)), 2e-5);
  EXPECT_EQ(under.overshoot, 0.0);
}

TEST(StepInfo, UndefinedAndErrors) {
  // An integrator never settles: final value ∞, figures NaN, peak still reported.
  const StateSpace integrator = test::canonical_form({0}, {1});
  const StepInfo info = step_info(integrator, 0, 0, {2.0, 11});
  EXPECT_TRUE(std::isinf(info.final_value));
  EXPECT_TRUE(std::isnan(info.rise_time));
  EXPECT_NEAR(info.peak, 2.0, 1e-14);
  const TimeResponse r = step_response(integrator, 0, {2.0, 11});
  EXPECT_THROW(step_info(r, 1, 1.0), InvalidArgument);
  EXPECT_THROW(step_info(r, 0, 1.0, 1.5), InvalidArgument);
}

}  // namespace
}  // namespace momenta::analysis
