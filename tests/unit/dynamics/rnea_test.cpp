// RNEA against the pendulum's equation of motion and the external-force convention.
#include "momenta/dynamics/rnea.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/dynamics/kinematics.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

// I_O θ̈ + m g l sin θ = τ with I_O = I_c + m l² (round-off only: 1e-13 relative).
TEST(Rnea, PendulumEquationOfMotion) {
  const double m = 2.0, l = 0.7, I_c = 0.05, g = 9.81;
  const Model model = test::pendulum(m, l, I_c, g);
  Data data(model);
  for (double theta : {0.0, 0.4, -1.3, 2.9}) {
    const VecX q = VecX::Constant(1, theta), v = VecX::Constant(1, 1.7),
               vdot = VecX::Constant(1, -0.8);
    const double expected = (I_c + m * l * l) * vdot[0] + m * g * l * std::sin(theta);
    EXPECT_TRUE(test::relatively_near(rnea(model, data, q, v, vdot)[0], expected, 1e-13, 1e-14));
    EXPECT_TRUE(test::relatively_near(generalized_gravity(model, data, q)[0],
                                      m * g * l * std::sin(theta), 1e-13, 1e-14));
    // The velocity does not enter a single pendulum's torque.
    EXPECT_NEAR(nonlinear_effects(model, data, q, v)[0], m * g * l * std::sin(theta), 1e-13);
  }
}

// f_ext is a wrench on the body in its own frame about its origin: the weight, applied upward
// at the centre of mass through body_wrench_from_world_force, cancels gravity exactly.
TEST(Rnea, ExternalWrenchInBodyFrame) {
  const double m = 2.0, l = 0.7;
  const Model model = test::pendulum(m, l, 0.05);
  Data data(model);
  const VecX q = VecX::Constant(1, 0.6), zero = VecX::Zero(1);
  forward_kinematics(model, data, q);
  const Vec3 p_cm = data.X_WB[1].apply(Vec3(0, 0, -l));
  std::vector<Vec6> f_ext(2, Vec6::Zero());
  f_ext[1] = body_wrench_from_world_force(data, 1, Vec3(0, 0, m * 9.81), p_cm);
  EXPECT_NEAR(rnea(model, data, q, zero, zero, f_ext)[0], 0.0, 1e-13);
  // A pure torque about y in the body frame: τ = −f_ext moment along the axis.
  f_ext[1] = spatial(Vec3(0, 3.0, 0), Vec3::Zero());
  EXPECT_NEAR(rnea(model, data, q, zero, zero, f_ext)[0], m * 9.81 * l * std::sin(0.6) - 3.0,
              1e-13);
}

TEST(Rnea, AllocatingFormMatches) {
  const Model model = test::double_pendulum(1.0, 2.0, 0.5, 0.4);
  Data data(model);
  const VecX q = VecX::LinSpaced(2, 0.3, -0.5), v = VecX::LinSpaced(2, 1, 2),
             a = VecX::LinSpaced(2, -1, 3);
  EXPECT_EQ(inverse_dynamics(model, q, v, a), rnea(model, data, q, v, a));
}

}  // namespace
}  // namespace momenta::dynamics
