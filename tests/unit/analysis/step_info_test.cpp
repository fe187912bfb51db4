#include "momenta/analysis/step_info.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "analysis_test_systems.hpp"
#include "momenta/common/error.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

// The first time t in [a, b] where the closed form f crosses zero, by bisection to an interval
// of 1e-15 s — an algorithm and a formula independent of the library's exponential.
template <class F>
double bisect(F f, double a, double b) {
  double fa = f(a);
  for (int k = 0; k < 200 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++k) {
    const double m = 0.5 * (a + b);
    const double fm = f(m);
    if ((fm > 0) == (fa > 0)) {
      a = m;
      fa = fm;
    } else {
      b = m;
    }
  }
  return 0.5 * (a + b);
}

TEST(StepInfo, FirstOrderLagExactly) {
  // G = 3/(τ s + 1), τ = 0.5 s: y = 3(1 − e^(−t/τ)); 10 %→90 % takes τ ln 9; the 2 % band is
  // entered at τ ln 50; no overshoot. The figures come from the analytic response: the grid
  // (the automatic one, 501 samples over 7τ) only brackets the crossings.
  const double tau = 0.5;
  const StateSpace system = test::canonical_form({1 / tau}, {3 / tau});
  const StepInfo info = step_info(system, 0, 0);
  EXPECT_REL_NEAR(info.final_value, 3.0, 1e-15);
  // Roots of y(t) − level to full precision; y from exp(A t) to ~1e-16: a few ulps of the time.
  EXPECT_REL_NEAR(info.rise_time, tau * std::log(9.0), 1e-13);
  EXPECT_REL_NEAR(info.settling_time, tau * std::log(50.0), 1e-13);
  EXPECT_EQ(info.overshoot, 0.0);
  EXPECT_EQ(info.undershoot, 0.0);
  // The peak of a monotone response is at the grid's end: 7τ.
  EXPECT_REL_NEAR(info.peak, 3.0 * -std::expm1(-7.0), 1e-14);
}

TEST(StepInfo, SampledFiguresInterpolateBetweenSamples) {
  // The sampled overload reads the figures off the samples: crossing times interpolated
  // linearly, error ≤ h²/(8τ) ≈ 2.5e-7 s at h = 1 ms.
  const double tau = 0.5;
  const StateSpace system = test::canonical_form({1 / tau}, {3 / tau});
  const StepInfo info = step_info(step_response(system, 0, {5.0, 5001}), 0, 3.0);
  EXPECT_NEAR(info.rise_time, tau * std::log(9.0), 5e-7);
  EXPECT_NEAR(info.settling_time, tau * std::log(50.0), 3e-7);
  EXPECT_GT(std::abs(info.rise_time - tau * std::log(9.0)), 1e-12);  // sampled, not exact
}

TEST(StepInfo, UnderdampedSecondOrderExactly) {
  // ωn²/(s² + 2ζωn s + ωn²): y = 1 − e^(−ζωn t)(cos ωd t + ζ/√(1−ζ²) sin ωd t); overshoot
  // 100 e^(−πζ/√(1−ζ²)) % at tp = π/ωd (Franklin §3.4).
  for (const double zeta : {0.05, 0.2, 0.5, 0.8}) {
    const double wn = 2.0, root = std::sqrt(1 - zeta * zeta), wd = wn * root;
    const StateSpace system = test::canonical_form({2 * zeta * wn, wn * wn}, {wn * wn, 0});
    const StepInfo info = step_info(system, 0, 0);
    const auto y = [&](double t) {
      return 1 - std::exp(-zeta * wn * t) * (std::cos(wd * t) + zeta / root * std::sin(wd * t));
    };
    EXPECT_REL_NEAR(info.peak_time, M_PI / wd, 1e-13) << "ζ = " << zeta;
    EXPECT_REL_NEAR(info.overshoot, 100 * std::exp(-M_PI * zeta / root), 1e-12) << "ζ = " << zeta;
    EXPECT_REL_NEAR(info.peak, 1 + std::exp(-M_PI * zeta / root), 1e-14) << "ζ = " << zeta;
    // Rise time: 10 % and 90 % crossings of the closed form (before the peak, y rises).
    const double t10 = bisect([&](double t) { return y(t) - 0.1; }, 0.0, M_PI / wd);
    const double t90 = bisect([&](double t) { return y(t) - 0.9; }, 0.0, M_PI / wd);
    EXPECT_REL_NEAR(info.rise_time, t90 - t10, 1e-12) << "ζ = " << zeta;
    // Settling: the last time |y − 1| = 2 %, found on a 1e-4 s scan of the closed form.
    double last_out = 0.0;
    for (double t = 0.0; t < 60.0; t += 1e-4) {
      if (std::abs(y(t) - 1) > 0.02) last_out = t;
    }
    const double edge = y(last_out) > 1 ? 1.02 : 0.98;
    const double ts = bisect([&](double t) { return y(t) - edge; }, last_out, last_out + 1e-4);
    EXPECT_REL_NEAR(info.settling_time, ts, 1e-12) << "ζ = " << zeta;
  }
}

TEST(StepInfo, NonMinimumPhaseUndershootExactly) {
  // (1 − s)/(s + 1)² starts the wrong way: y(t) = 1 − e^(−t) − 2 t e^(−t),
  // y' = e^(−t)(2t − 1), minimum at t = ½ where y = 1 − 2 e^(−½) ≈ −0.213.
  const StateSpace nmp = test::canonical_form({2, 1}, {1, -1});
  const StepInfo under = step_info(nmp, 0, 0);
  EXPECT_REL_NEAR(under.undershoot, -100 * (1 - 2 * std::exp(-0.5)), 1e-13);
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
