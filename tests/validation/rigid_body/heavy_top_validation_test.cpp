// The heavy symmetric top's closed-form references against an independent integration of the
// top (Euler's equations with the gravity torque about the pivot, Taylor series in long double).

#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "momenta/math/rotation.hpp"
#include "momenta/rigid_body/analytic_references.hpp"
#include "momenta_test/rotation_reference.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::rigid_body {
namespace {

constexpr long double kLongDoubleEps = 1.0842021724855044340e-19L;

// A toy top: 0.5 kg, centre of mass 4 cm above the pivot, I1 = 1e-3, I3 = 2e-4 kg·m² (about the
// pivot), spinning at 150 rad/s.
SymmetricTop toy_top() { return {1e-3, 2e-4, 0.5, 0.04, 9.81}; }

// The top released at nutation angle θ0 with rates (θ̇0, φ̇0) and spin ω3, at φ = ψ = 0:
// R_WB = Rx(θ0), ω_B = (θ̇0, φ̇0 sin θ0, ω3).
test::TaylorRotation<long double> start(const SymmetricTop& top, double theta0, double theta_dot0,
                                        double phi_dot0, double spin) {
  const Mat3 I = Vec3(top.transverse_moment, top.transverse_moment, top.axial_moment).asDiagonal();
  const Mat3 R0 = rotation_from_axis_angle(Vec3::UnitX(), theta0);
  const Vec3 w0(theta_dot0, phi_dot0 * std::sin(theta0), spin);
  test::TaylorRotation<long double> ref(I, R0, w0, kLongDoubleEps);
  ref.set_gravity(top.mass, Vec3(0, 0, top.com_distance), Vec3(0, 0, -top.gravity));
  return ref;
}

double nutation_angle(const test::TaylorRotation<long double>& ref) {
  return std::acos(static_cast<double>(ref.R()[2][2]));
}

// Extremes of θ(t) over [0, t_end], sampled every dt and refined by the parabola through the
// three samples around each extreme (error O(dt³ θ''')).
struct Extremes {
  double min, max;
};
Extremes theta_extremes(test::TaylorRotation<long double> ref, double t_end, double dt) {
  Extremes e{1e9, -1e9};
  double a = nutation_angle(ref), b = a;
  long double t = 0;
  ref.advance_to(t += dt, 0.005L);
  b = nutation_angle(ref);
  while (t < t_end) {
    ref.advance_to(t += dt, 0.005L);
    const double c = nutation_angle(ref);
    const double curvature = a - 2 * b + c;
    if ((b >= a && b >= c) || (b <= a && b <= c)) {
      const double peak = curvature != 0 ? b - (c - a) * (c - a) / (8 * curvature) : b;
      e.max = std::max(e.max, peak);
      e.min = std::min(e.min, peak);
    }
    a = b;
    b = c;
  }
  return e;
}

TEST(HeavyTopValidation, BothSteadyPrecessionRatesAreSteady) {
  // At either root the nutation angle stays put; the reference drifts by ~1e-17 per step, so
  // 1e-12 over 2 s (hundreds of precession cycles at the fast rate) means the root is exact to
  // about that. A rate 1e-6 off gives a nutation of ~1e-7 (the negative control).
  const SymmetricTop top = toy_top();
  const double theta0 = 0.6, spin = 150.0;
  const SteadyPrecession p = steady_precession(top, theta0, spin);
  for (const double rate : {p.slow, p.fast}) {
    SCOPED_TRACE(rate);
    const Extremes e = theta_extremes(start(top, theta0, 0, rate, spin), 2.0, 1e-3);
    EXPECT_NEAR(e.max, theta0, 1e-12);
    EXPECT_NEAR(e.min, theta0, 1e-12);
  }
  const Extremes off = theta_extremes(start(top, theta0, 0, p.slow * (1 + 1e-6), spin), 2.0, 1e-3);
  EXPECT_GT(off.max - off.min, 1e-9);
}

TEST(HeavyTopValidation, GyroscopicFormulaIsExactOnlyForAHorizontalAxle) {
  const SymmetricTop top = toy_top();
  const double spin = 150.0;
  const double rate = gyroscopic_precession_rate(top, spin);
  // Horizontal axle: m g l/(I3 ω3) is the steady precession, the axle stays level.
  EXPECT_DOUBLE_EQ(steady_precession(top, std::numbers::pi / 2, spin).slow, rate);
  const Extremes level = theta_extremes(start(top, std::numbers::pi / 2, 0, rate, spin), 2.0, 1e-3);
  EXPECT_NEAR(level.max, std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(level.min, std::numbers::pi / 2, 1e-12);
  // Tilted, the same rate nutates: the exact slow root differs from it by the factor
  // (1 − √(1 − 4ε))/(2ε) = 1 + ε + 2ε² + …, ε = I1 m g l cos θ/(I3 ω3)² — ε = 0.180 here, so
  // the exact root is 30.8 % above m g l/(I3 ω3), not 18 %.
  const double theta0 = 0.6;
  const Extremes tilted = theta_extremes(start(top, theta0, 0, rate, spin), 2.0, 1e-3);
  EXPECT_GT(tilted.max - tilted.min, 1e-6);
  const double eps = top.transverse_moment * top.mass * top.gravity * top.com_distance *
                     std::cos(theta0) / std::pow(top.axial_moment * spin, 2);
  const double factor = (1 - std::sqrt(1 - 4 * eps)) / (2 * eps);
  EXPECT_NEAR(eps, 0.1799, 1e-4);
  EXPECT_NEAR(factor - 1, 0.3077, 1e-4);
  EXPECT_REL_NEAR(steady_precession(top, theta0, spin).slow / rate, factor, 1e-12);
}

TEST(HeavyTopValidation, NutationStaysBetweenTheTurningPoints) {
  // Released from rest in θ and φ (the classic "fast top"), and with a push in θ: θ(t) reaches
  // exactly the roots of the effective-potential cubic. Sampling at 0.1 ms with parabolic
  // refinement resolves the extremes to ~1e-11 rad; 1e-9 is the tolerance.
  const SymmetricTop top = toy_top();
  struct Start {
    double theta, theta_dot, phi_dot, spin;
  };
  for (const Start s : {Start{0.6, 0.0, 0.0, 150.0}, Start{0.6, 1.5, 2.0, 150.0},
                        Start{2.0, -0.5, 1.0, 60.0}, Start{0.3, 0.0, -3.0, 40.0}}) {
    SCOPED_TRACE(s.theta_dot);
    const NutationBounds b = nutation_bounds(top, s.theta, s.theta_dot, s.phi_dot, s.spin);
    ASSERT_LE(b.theta_min, s.theta + 4e-16);  // acos(cos θ) rounds
    ASSERT_GE(b.theta_max, s.theta - 4e-16);
    const Extremes e =
        theta_extremes(start(top, s.theta, s.theta_dot, s.phi_dot, s.spin), 1.0, 1e-4);
    EXPECT_NEAR(e.min, b.theta_min, 1e-9);
    EXPECT_NEAR(e.max, b.theta_max, 1e-9);
  }
}

TEST(HeavyTopValidation, SleepingTopThreshold) {
  // A top tilted by 1 mrad from the vertical, spinning 2 % above the critical ω3 = √(4 m g l
  // I1)/I3, stays within a few mrad; 2 % below, it falls far (here to 0.4 rad). The nutation bounds
  // predict both, to the sampling resolution.
  const SymmetricTop top = toy_top();
  const double critical = sleeping_top_critical_spin(top);
  EXPECT_NEAR(critical,
              std::sqrt(4 * top.mass * top.gravity * top.com_distance * top.transverse_moment) /
                  top.axial_moment,
              1e-12 * critical);
  const double tilt = 1e-3;
  const Extremes above = theta_extremes(start(top, tilt, 0, 0, 1.02 * critical), 3.0, 1e-3);
  EXPECT_LT(above.max, 20 * tilt);
  EXPECT_LT(nutation_bounds(top, tilt, 0, 0, 1.02 * critical).theta_max, 20 * tilt);
  const Extremes below = theta_extremes(start(top, tilt, 0, 0, 0.98 * critical), 3.0, 1e-3);
  EXPECT_GT(below.max, 100 * tilt);
  EXPECT_NEAR(nutation_bounds(top, tilt, 0, 0, 0.98 * critical).theta_max, below.max, 1e-6);
}

}  // namespace
}  // namespace momenta::rigid_body
