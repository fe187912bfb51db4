// examples/cruise_control.yaml, quarter_car.yaml, satellite_attitude.yaml and
// flexible_satellite.yaml (Franklin, Powell & Emami-Naeini, ch. 2) simulated, against closed
// forms and against their textbook equations integrated independently.

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "example_simulation.hpp"

namespace momenta {
namespace {

int q_index(const model::Model& m, const char* joint) {
  return m.joint(m.joint_index(joint)).q_index;
}

// Classic RK4 on ẋ = f(t, x) with a fixed step, for the textbook equations.
template <class Vec, class F>
void rk4_step(Vec& x, double t, double h, const F& f) {
  const Vec k1 = f(t, x), k2 = f(t + h / 2, Vec(x + h / 2 * k1)),
            k3 = f(t + h / 2, Vec(x + h / 2 * k2)), k4 = f(t + h, Vec(x + h * k3));
  x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
}

TEST(LumpedExamples, CruiseControlSpeedFollowsTheFirstOrderClosedForm) {
  // m v̇ + b v = u with a 500 N step at t = 0: v = (u/b)(1 − e^{−bt/m}),
  // x = (u/b)(t − (m/b)(1 − e^{−bt/m})). RK4 with h = 0.01 s on a 20 s time constant errs by
  // (h b/m)⁵/120 ≈ 1e-18 per step: 1e-12 m/s and 1e-10 m cover 12 000 steps of round-off
  // (measured 1.1e-13 m/s and 4.9e-12 m).
  const io::ModelFile file = test::load_example("cruise_control");
  const model::Model& m = file.model;
  const double mass = 1000.0, b = 50.0, u = 500.0;
  EXPECT_EQ(m.body(1).mass_properties.mass(), mass);
  system::MultibodySystem system(m);
  double worst_v = 0, worst_x = 0;
  const integrate::State end =
      test::simulate_rk4(system, 120.0, 0.01, [&](const integrate::State& s) {
        const double decay = std::exp(-b * s.t / mass);
        worst_v = std::max(worst_v, std::abs(s.v[0] - u / b * (1 - decay)));
        worst_x = std::max(worst_x, std::abs(s.q[0] - u / b * (s.t - mass / b * (1 - decay))));
      });
  EXPECT_LT(worst_v, 1e-12);
  EXPECT_LT(worst_x, 1e-10);
  EXPECT_NEAR(end.v[0], 10.0 * (1 - std::exp(-6.0)), 1e-12);  // six time constants
}

TEST(LumpedExamples, QuarterCarFollowsFranklinsEquations) {
  // m1 ẍ + b (ẋ − ẏ) + ks (x − y) + kw (x − r) = 0, m2 ÿ + b (ẏ − ẋ) + ks (y − x) = 0 with the
  // road r(t) a 5 cm quintic step, integrated by its own RK4 at the same h. The model reaches the
  // same linear equations through two spring-dampers and a prescribed joint, so the two RK4
  // solutions agree to round-off (2e-16 m measured; bound 1e-13 m); a wrong sign or coefficient
  // is > 1e-4 m.
  const io::ModelFile file = test::load_example("quarter_car");
  const model::Model& m = file.model;
  const double m1 = 20, m2 = 375, ks = 130000, kw = 1e6, b = 9800;
  const int ix = q_index(m, "wheel_travel"), iy = q_index(m, "body_travel");
  const auto road = [](double t) {
    const double start = 0.1, rise = 0.01, height = 0.05;
    if (t <= start) return 0.0;
    if (t >= start + rise) return height;
    const double s = (t - start) / rise;
    return height * s * s * s * (10 + s * (-15 + 6 * s));
  };
  const auto f = [&](double t, const Eigen::Vector4d& x) {
    const double r = road(t);
    return Eigen::Vector4d(x[2], x[3],
                           (-b * (x[2] - x[3]) - ks * (x[0] - x[1]) - kw * (x[0] - r)) / m1,
                           (-b * (x[3] - x[2]) - ks * (x[1] - x[0])) / m2);
  };
  system::MultibodySystem system(m);
  const double h = 1e-4;
  Eigen::Vector4d x = Eigen::Vector4d::Zero();
  double t_ref = 0.0, worst = 0.0, peak_y = 0.0;
  test::simulate_rk4(system, 1.0, h, [&](const integrate::State& s) {
    // The model's steps land on the road's breakpoints (0.1 s, 0.11 s), which lie on this grid.
    while (t_ref < s.t - 1e-12) {
      rk4_step(x, t_ref, h, f);
      t_ref = std::round((t_ref + h) / h) * h;
    }
    worst = std::max({worst, std::abs(s.q[ix] - x[0]), std::abs(s.q[iy] - x[1])});
    peak_y = std::max(peak_y, s.q[iy]);
  });
  EXPECT_LT(worst, 1e-13);
  EXPECT_GT(peak_y, 0.05);  // the body overshoots the kerb: ζ of the body mode is below 1
}

TEST(LumpedExamples, SatelliteAttitudeUnderATorquePulseIsPiecewiseQuadratic) {
  // I θ̈ = T, T = 10 N·m on [1 s, 2 s): θ = (T/2I)(t − 1)² inside, 0.001 + 0.002 (t − 2) after.
  // The steps land on the pulse's edges, so RK4 integrates the quadratic exactly: round-off only
  // (2.3e-16 rad measured; bound 1e-14). A step straddling an edge would err by h·T/(6I) in θ̇.
  const io::ModelFile file = test::load_example("satellite_attitude");
  const model::Model& m = file.model;
  const double I = 5000.0, T = 10.0;
  system::MultibodySystem system(m);
  double worst = 0.0;
  test::simulate_rk4(system, 10.0, 0.01, [&](const integrate::State& s) {
    double expected = 0.0;
    if (s.t > 1.0) expected = T / (2 * I) * std::pow(std::min(s.t, 2.0) - 1.0, 2);
    if (s.t > 2.0) expected += T / I * (s.t - 2.0);
    worst = std::max(worst, std::abs(s.q[0] - expected));
  });
  EXPECT_LT(worst, 1e-14);
}

TEST(LumpedExamples, FlexibleSatelliteFollowsItsEquationsAndKeepsTheImpulse) {
  // I1 θ̈1 + b (θ̇1 − θ̇2) + k (θ1 − θ2) = Tc, I2 θ̈2 + b (θ̇2 − θ̇1) + k (θ2 − θ1) = 0, integrated
  // by its own RK4 at the same step: agreement to round-off (2.7e-14 rad measured, bound 1e-12; a
  // wrong k or b gives > 1e-4). The spring and damper are internal, so after the pulse the angular
  // momentum I1 θ̇1 + I2 θ̇2 stays at the impulse ∫Tc dt = 0.1 N·m·s (1e-15 measured).
  const io::ModelFile file = test::load_example("flexible_satellite");
  const model::Model& m = file.model;
  const double I1 = 1.0, I2 = 0.1, k = 0.091, b = 0.0036;
  const auto torque = [](double t) { return (t >= 1.0 && t < 2.0) ? 0.1 : 0.0; };
  system::MultibodySystem system(m);
  const int i1 = q_index(m, "theta1"), i2 = q_index(m, "theta2");
  const double h = 0.01;
  Eigen::Vector4d x = Eigen::Vector4d::Zero();
  double t_ref = 0.0, worst = 0.0, worst_momentum = 0.0;
  test::simulate_rk4(system, 60.0, h, [&](const integrate::State& s) {
    while (t_ref < s.t - 1e-12) {
      // The reference's steps also never straddle the pulse edges (1 s and 2 s are grid times);
      // its last stage at an edge takes the torque from before the edge, as the model does.
      const double t0 = t_ref;
      rk4_step(x, t0, h, [&](double t, const Eigen::Vector4d& y) {
        const double u = t >= t0 + h - 1e-12 ? torque(t - 1e-9) : torque(t);
        return Eigen::Vector4d(y[2], y[3], (u - b * (y[2] - y[3]) - k * (y[0] - y[1])) / I1,
                               (-b * (y[3] - y[2]) - k * (y[1] - y[0])) / I2);
      });
      t_ref = std::round((t_ref + h) / h) * h;
    }
    worst = std::max({worst, std::abs(s.q[i1] - x[0]), std::abs(s.q[i2] - x[1])});
    if (s.t >= 2.0) {
      worst_momentum = std::max(worst_momentum, std::abs(I1 * s.v[i1] + I2 * s.v[i2] - 0.1));
    }
  });
  EXPECT_LT(worst, 1e-12);
  EXPECT_LT(worst_momentum, 1e-14);
}

}  // namespace
}  // namespace momenta
