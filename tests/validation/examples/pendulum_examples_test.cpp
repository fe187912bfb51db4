// examples/pendulum.yaml, compound_pendulum.yaml and double_pendulum.yaml simulated, against the
// elliptic-integral period, hand-derived pin reactions, and the Lagrange equations of the double
// pendulum integrated independently.

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>
#include <boost/math/special_functions/ellint_1.hpp>

#include "example_simulation.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta {
namespace {

constexpr double kG = 9.81;

// Period of a pendulum released from rest at θ0 whose equation is θ̈ = −ω0² sin θ:
// T = (4/ω0) K(k), k = sin(θ0/2) (Landau & Lifshitz, Mechanics §11). Boost takes the modulus k.
double pendulum_period(double omega0, double theta0) {
  return 4.0 / omega0 * boost::math::ellint_1(std::sin(0.5 * theta0));
}

// Simulates a one-joint pendulum example and returns its period from the downward zero
// crossings of θ (a quarter period, then whole periods apart).
double simulated_period(system::MultibodySystem& system, double t_end, double h) {
  test::DownwardCrossings crossings;
  test::simulate_rk4(system, t_end, h,
                     [&](const integrate::State& s) { crossings.add(s.t, s.q[0], s.v[0]); });
  EXPECT_GE(crossings.times.size(), 3u);
  const std::size_t n = crossings.times.size();
  return (crossings.times[n - 1] - crossings.times[0]) / static_cast<double>(n - 1);
}

TEST(PendulumExamples, LargeAmplitudePeriodIsTheEllipticIntegral) {
  // A point mass L below the pivot, released at 120°: T = 4 √(L/g) K(sin 60°) = 2.754090 s,
  // 37 % longer than the small-angle 2π √(L/g). RK4 with h = 1 ms has a phase error of order
  // (ωh)⁴/120 ≈ 1e-12 per radian, the crossings are located to O(h⁴) ≈ 1e-13 s: 1e-10 relative
  // is far above both (measured 3.4e-13) and far below any modelling error (a wrong length or g:
  // > 1e-3).
  const io::ModelFile file = test::load_example("pendulum");
  const model::Model& m = file.model;
  ASSERT_EQ(m.nq(), 1);
  const double L = m.body(1).mass_properties.center_of_mass().norm();
  const double theta0 = m.initial_q()[0];
  EXPECT_NEAR(theta0, 2 * std::numbers::pi / 3, 1e-15);
  system::MultibodySystem system(m);
  const double expected = pendulum_period(std::sqrt(kG / L), theta0);
  EXPECT_NEAR(expected, 2.754090, 1e-6);  // the example's documented figure
  EXPECT_NEAR(simulated_period(system, 10.0, 1e-3), expected, 1e-10 * expected);
}

TEST(PendulumExamples, CompoundPendulumPeriodAndPinReactionAlongTheMotion) {
  // A uniform rod about its end: I_O θ̈ = −m g d sin θ with I_O = m L²/3, d = L/2, so
  // ω0² = m g d / I_O = 3g/(2L). The pin force on the rod is m a_cm − m g with
  // a_cm = α × r − θ̇² r (r the centre of mass from the pivot, α = θ̈ about the axis): checked at
  // every step against the reaction the model reports, to 1e-12 of the weight (the formula reads
  // the same state, so only round-off separates them: 7e-15 N measured). The period agrees with
  // the elliptic integral to 1.8e-12 (relative).
  const io::ModelFile file = test::load_example("compound_pendulum");
  const model::Model& m = file.model;
  const inertia::MassProperties& rod = m.body(1).mass_properties;
  const double mass = rod.mass();
  const Vec3 r_B = rod.center_of_mass();  // from the pivot, in the rod frame
  const double d = r_B.norm();
  const double I_O = rod.inertia_about(Vec3::Zero())(1, 1);  // about the y axis through O
  EXPECT_NEAR(I_O, mass * 1.0 * 1.0 / 3, 1e-12);
  const double omega0 = std::sqrt(mass * kG * d / I_O);
  system::MultibodySystem system(m);
  const double expected = pendulum_period(omega0, m.initial_q()[0]);
  EXPECT_NEAR(expected, 1.641070, 1e-6);
  EXPECT_NEAR(simulated_period(system, 10.0, 1e-3), expected, 1e-10 * expected);

  // The pin reaction, in the world frame, along the motion.
  system::OutputSet outputs(m, {{.name = "pin",
                                 .quantity = model::OutputQuantity::reaction_force,
                                 .target = "pivot",
                                 .frame = model::ReactionFrame::world}});
  std::vector<double> F(3);
  double worst = 0.0;
  test::simulate_rk4(system, 2.0, 1e-3, [&](const integrate::State& s) {
    outputs.evaluate(system, s.t, s.q, s.v, F);
    const double theta = s.q[0], theta_dot = s.v[0];
    // The rod frame turned by θ about world y: r = R_y(θ) r_B.
    const Mat3 R = Eigen::AngleAxisd(theta, Vec3::UnitY()).toRotationMatrix();
    const Vec3 r = R * r_B;
    const double alpha = -mass * kG * d * std::sin(theta) / I_O;
    const Vec3 a_cm = (alpha * Vec3::UnitY()).cross(r) - theta_dot * theta_dot * r;
    const Vec3 expected_F = mass * a_cm - mass * Vec3(0, 0, -kG);
    worst = std::max(worst, (Vec3(F[0], F[1], F[2]) - expected_F).norm());
  });
  EXPECT_LT(worst, 1e-12 * mass * kG);
}

// The double pendulum of point masses in absolute angles a1, a2 from the downward vertical
// (Lagrange's equations), integrated by its own RK4 — an independent second derivation.
struct DoublePendulumReference {
  double m1, m2, L1, L2;
  // [a1, a2, ȧ1, ȧ2] → derivatives.
  Eigen::Vector4d rate(const Eigen::Vector4d& x) const {
    const double a1 = x[0], a2 = x[1], w1 = x[2], w2 = x[3];
    const double c = std::cos(a1 - a2), s = std::sin(a1 - a2);
    // (m1 + m2) L1 ä1 + m2 L2 c ä2 = −m2 L2 s ȧ2² − (m1 + m2) g sin a1
    // L1 c ä1 + L2 ä2 = L1 s ȧ1² − g sin a2
    Eigen::Matrix2d A;
    A << (m1 + m2) * L1, m2 * L2 * c, L1 * c, L2;
    const Eigen::Vector2d b(-m2 * L2 * s * w2 * w2 - (m1 + m2) * kG * std::sin(a1),
                            L1 * s * w1 * w1 - kG * std::sin(a2));
    const Eigen::Vector2d acc = A.partialPivLu().solve(b);
    return {w1, w2, acc[0], acc[1]};
  }
  void step(Eigen::Vector4d& x, double h) const {
    const Eigen::Vector4d k1 = rate(x), k2 = rate(x + 0.5 * h * k1), k3 = rate(x + 0.5 * h * k2),
                          k4 = rate(x + h * k3);
    x += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  double energy(const Eigen::Vector4d& x) const {
    const double a1 = x[0], a2 = x[1], w1 = x[2], w2 = x[3];
    const double v2sq =
        L1 * L1 * w1 * w1 + L2 * L2 * w2 * w2 + 2 * L1 * L2 * w1 * w2 * std::cos(a1 - a2);
    return 0.5 * m1 * L1 * L1 * w1 * w1 + 0.5 * m2 * v2sq - (m1 + m2) * kG * L1 * std::cos(a1) -
           m2 * kG * L2 * std::cos(a2);
  }
};

TEST(PendulumExamples, DoublePendulumFollowsLagrangesEquationsAndKeepsItsEnergy) {
  // Released with the upper rod horizontal, the motion is chaotic: two correct integrations
  // separate like e^{λt}. Over 3 s both RK4 solutions (h = 0.5 ms) agree to 1e-11 rad (measured
  // 7e-15: RK4 applied to the same equations in other coordinates); a wrong mass matrix or
  // Coriolis term differs by > 1e-2.
  // The energy E = 0 J is kept to RK4's truncation error: over 20 s at most 2.6e-9 J at
  // h = 0.5 ms (bound 1e-8 J), falling 15.5-fold at h/2 — fourth order, no other error source.
  const io::ModelFile file = test::load_example("double_pendulum");
  const model::Model& m = file.model;
  ASSERT_EQ(m.nv(), 2);
  const DoublePendulumReference ref{m.body(1).mass_properties.mass(),
                                    m.body(2).mass_properties.mass(),
                                    m.body(1).mass_properties.center_of_mass().norm(),
                                    m.body(2).mass_properties.center_of_mass().norm()};
  system::MultibodySystem system(m);
  const double h = 5e-4;
  // Model coordinates: θ1 absolute, θ2 relative to the upper rod.
  Eigen::Vector4d x(m.initial_q()[0], m.initial_q()[0] + m.initial_q()[1], m.initial_v()[0],
                    m.initial_v()[0] + m.initial_v()[1]);
  const double E0 = ref.energy(x);
  EXPECT_NEAR(E0, 0.0, 1e-12);
  double worst_angle = 0.0;
  long k = 0;
  test::simulate_rk4(system, 3.0, h, [&](const integrate::State& s) {
    if (k++ > 0) ref.step(x, h);
    worst_angle =
        std::max({worst_angle, std::abs(s.q[0] - x[0]), std::abs(s.q[0] + s.q[1] - x[1])});
  });
  EXPECT_LT(worst_angle, 1e-11);

  const auto energy_error = [&](double step) {
    double worst_energy = 0.0;
    test::simulate_rk4(system, 20.0, step, [&](const integrate::State& s) {
      worst_energy = std::max(worst_energy, std::abs(system.energy(s.q, s.v).total() - E0));
    });
    return worst_energy;
  };
  const double coarse = energy_error(h), fine = energy_error(h / 2);
  EXPECT_LT(coarse, 1e-8);
  EXPECT_GT(coarse / fine, 12.0);  // 16 for RK4's fourth order
}

}  // namespace
}  // namespace momenta
