// examples/rotating_shaft_bent_rod.yaml, unbalanced_rotor.yaml and gyroscope.yaml simulated:
// bearing reactions of rotors turning at constant speed against Euler's equations, and the
// gyroscope's precession against m g l/(C ωs).

#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "example_simulation.hpp"
#include "momenta/system/output_set.hpp"

namespace momenta {
namespace {

constexpr double kG = 9.81;

// The rotor (every body but the world, all welded to the turning shaft) as one body described in
// the shaft's frame, from the mass-properties engine alone: each body's mass properties moved by
// its fixed pose in the shaft frame (X_shaft_body of the weld chain at q = 0).
inertia::MassProperties rotor_in_shaft_frame(const model::Model& m) {
  inertia::MassProperties total = m.body(1).mass_properties;
  for (int j = 1; j < m.num_joints(); ++j) {
    const model::Joint& weld = m.joint(j);
    EXPECT_EQ(weld.type, model::JointType::fixed);
    EXPECT_EQ(weld.parent_index, 1);
    const Transform X_SB = weld.X_PJ * weld.X_CJ.inverse();
    total += m.body(weld.child_index).mass_properties.transformed(X_SB.R, X_SB.p);
  }
  return total;
}

// A rotor turning at constant ω about the shaft's z axis, through the bearing joint's origin O:
// in the shaft frame S every quantity is constant. Newton and Euler for the whole rotor give the
// wrench the bearing joint transmits to it, about O, in S:
//   F = m a_cm − m g_S,  a_cm = ω × (ω × r_cm);   M = ω × (I_O ω) − r_cm × m g_S,
// where g_S is gravity seen from the turning frame at that instant.
void expect_reactions_follow_euler(const char* example, double omega, double tolerance) {
  const io::ModelFile file = test::load_example(example);
  const model::Model& m = file.model;
  const inertia::MassProperties rotor = rotor_in_shaft_frame(m);
  const double mass = rotor.mass();
  const Vec3 r_cm = rotor.center_of_mass();
  const Mat3 I_O = rotor.inertia_about(Vec3::Zero());
  const Vec3 w(0, 0, omega);
  system::MultibodySystem system(m);
  using model::OutputQuantity;
  system::OutputSet outputs(m, {{.name = "F",
                                 .quantity = OutputQuantity::reaction_force,
                                 .target = "bearing",
                                 .frame = model::ReactionFrame::child},
                                {.name = "M",
                                 .quantity = OutputQuantity::reaction_moment,
                                 .target = "bearing",
                                 .frame = model::ReactionFrame::child}});
  std::vector<double> values(6);
  double worst_F = 0, worst_M = 0;
  test::simulate_rk4(system, 0.2, 1e-3, [&](const integrate::State& s) {
    outputs.evaluate(system, s.t, s.q, s.v, values);
    EXPECT_NEAR(s.v[0], omega, 1e-12);
    // The world's gravity in the shaft frame, turned by the shaft angle θ about z.
    const Mat3 R_WS = Eigen::AngleAxisd(s.q[0], Vec3::UnitZ()).toRotationMatrix();
    const Vec3 g_S = R_WS.transpose() * m.gravity();
    const Vec3 F = mass * w.cross(w.cross(r_cm)) - mass * g_S;
    const Vec3 M = w.cross(I_O * w) - r_cm.cross(mass * g_S);
    worst_F = std::max(worst_F, (Vec3(values[0], values[1], values[2]) - F).norm());
    worst_M = std::max(worst_M, (Vec3(values[3], values[4], values[5]) - M).norm());
  });
  EXPECT_LT(worst_F, tolerance);
  EXPECT_LT(worst_M, tolerance);
}

TEST(RotorExamples, BentRodBearingCoupleIsOmegaSquaredTimesTheProductOfInertia) {
  // The rod's centre of mass is on the axis: no rotating force, only the weight (3 kg · g) and
  // the couple −(m L²/12) ω² sin β cos β = −10.3923 N·m about the shaft's x, constant in the
  // shaft frame. Dynamics and the closed form agree to round-off on these O(10) N values.
  expect_reactions_follow_euler("rotating_shaft_bent_rod", 20.0, 1e-11);
  const double m = 2.0, L = 0.6, beta = std::numbers::pi / 6, w = 20.0;
  const io::ModelFile file = test::load_example("rotating_shaft_bent_rod");
  const Mat3 I_O = rotor_in_shaft_frame(file.model).inertia_about(Vec3::Zero());
  // The couple comes from the product of inertia: the rod, turned by β about x, runs along
  // (0, −sin β, cos β), so ∫yz dm = −(m L²/12) sin β cos β and the tensor's yz entry (minus the
  // product) is +(m L²/12) sin β cos β; M_x = −ω² I_yz.
  EXPECT_NEAR(I_O(1, 2), m * L * L / 12 * std::sin(beta) * std::cos(beta), 1e-15);
  EXPECT_NEAR(m * L * L / 12 * w * w * std::sin(beta) * std::cos(beta), 10.3923, 1e-4);
}

TEST(RotorExamples, SkewedDiskBearingCoupleIsCMinusATimesOmegaSquared) {
  // (C − A) ω² sin δ cos δ = 4.30165 N·m for a disk skewed by δ = 2° at ω = 100 rad/s.
  expect_reactions_follow_euler("unbalanced_rotor", 100.0, 1e-10);
  const io::ModelFile file = test::load_example("unbalanced_rotor");
  const Mat3 I_O = rotor_in_shaft_frame(file.model).inertia_about(Vec3::Zero());
  const Vec3 w(0, 0, 100.0);
  EXPECT_NEAR(w.cross(I_O * w).norm(), 4.30165, 1e-5);
}

TEST(RotorExamples, GyroscopePrecessesAtMglOverCOmegaWithItsAxleLevel) {
  // A horizontal axle precessing steadily: Ω = g (m d + m_axle L/2)/(C ωs) = 2.77296 rad/s is
  // exact for a level axle (Goldstein §5.7; the axle's and disk's diametral inertias multiply
  // cos θ = 0), so simulated from it the axle must stay level and turn at Ω. Steady precession
  // is a uniform rotation, which RK4 on the rotation group (Munthe-Kaas) follows to round-off:
  // 1e-12 in height (m) and rate (rad/s) over a full turn (measured 6e-15). A model off by a
  // product of inertia or a sign in the gyroscopic term would nutate by > 1e-4.
  const io::ModelFile file = test::load_example("gyroscope");
  const model::Model& m = file.model;
  const double Omega = 9.81 * (0.5 * 0.1 + 0.05 * 0.06) / (0.5 * 0.05 * 0.05 / 2 * 300.0);
  EXPECT_NEAR(Omega, 2.77296, 1e-5);
  using model::OutputQuantity;
  system::OutputSet outputs(
      m, {{.name = "end",
           .quantity = OutputQuantity::body_position,
           .target = "axle",
           .point = Vec3(0.1, 0, 0)},
          {.name = "w", .quantity = OutputQuantity::body_angular_velocity, .target = "axle"}});
  const auto deviation = [&](double h) {
    system::MultibodySystem system(m);
    std::vector<double> values(6);
    double worst = 0.0;
    test::simulate_rk4(system, 2.2659, h, [&](const integrate::State& s) {
      outputs.evaluate(system, s.t, s.q, s.v, values);
      worst = std::max({worst, std::abs(values[2]), std::abs(values[5] - Omega)});
    });
    return worst;
  };
  EXPECT_LT(deviation(2e-4), 1e-12);
}

}  // namespace
}  // namespace momenta
