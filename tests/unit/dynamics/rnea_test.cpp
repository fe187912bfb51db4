// RNEA against the pendulum's equation of motion and the external-force convention.
#include "momenta/dynamics/rnea.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
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

// Joints turning about a coordinate axis of a child at the joint, with the joint frame parallel
// to the parent's, take the half-cost transforms (JointConstants::turns_about_axis). The same
// chain with each joint frame pre-turned by α about its own axis takes the general path and is
// the same mechanism at q − α: every algorithm must agree to round-off.
TEST(Rnea, JointsTurningAboutAnAxisAgreeWithTheGeneralPath) {
  const double alpha = 0.3;
  const auto chain = [&](bool pre_turned) {
    model::ModelBuilder b;
    b.set_gravity(Vec3(0, 0, -9.81));
    for (int k = 0; k < 4; ++k) {
      // Names built with += (GCC 12 warns falsely on "link" + std::to_string(k) under -O3).
      std::string name = "link", parent = k == 0 ? "world" : "link", joint = "j";
      name += std::to_string(k);
      if (k > 0) parent += std::to_string(k - 1);
      joint += std::to_string(k);
      b.add_body(name, inertia::MassProperties(1.0 + k, Vec3(0.2, 0.05 * k, -0.1),
                                               Vec3(0.02, 0.03, 0.04).asDiagonal()));
      const Vec3 axis = Vec3::Unit(k % 3);
      const Transform X_PJ(pre_turned ? rotation_from_axis_angle(axis, alpha) : Mat3::Identity(),
                           k == 0 ? Vec3::Zero() : Vec3(0.4, 0.1, 0));
      b.add_joint(test::make_joint(joint, model::JointType::revolute, parent, name, axis, X_PJ));
    }
    return b.build();
  };
  const Model fast = chain(false), general = chain(true);
  for (int j = 0; j < 4; ++j) {
    EXPECT_TRUE(fast.joint_constants()[j].turns_about_axis);
    EXPECT_FALSE(general.joint_constants()[j].turns_about_axis);
  }
  const VecX q = (VecX(4) << 0.7, -1.2, 2.5, 0.4).finished();
  const VecX q_general = q - VecX::Constant(4, alpha);
  const VecX v = (VecX(4) << 1.5, -0.3, 0.8, 2.0).finished();
  const VecX a = (VecX(4) << -0.4, 1.1, 0.2, -2.2).finished();
  Data d_fast(fast), d_general(general);
  EXPECT_MATRIX_NEAR(rnea(fast, d_fast, q, v, a), rnea(general, d_general, q_general, v, a), 1e-13);
  EXPECT_MATRIX_NEAR(aba(fast, d_fast, q, v, a), aba(general, d_general, q_general, v, a), 1e-13);
  EXPECT_MATRIX_NEAR(crba(fast, d_fast, q), crba(general, d_general, q_general), 1e-14);
  forward_kinematics(fast, d_fast, q, v);
  forward_kinematics(general, d_general, q_general, v);
  for (int i = 1; i <= 4; ++i) {
    EXPECT_MATRIX_NEAR(d_fast.V_WB_B[i], d_general.V_WB_B[i], 1e-14);
    EXPECT_TRUE(d_fast.X_WB[i].isApprox(d_general.X_WB[i], 1e-14));
  }
}

}  // namespace
}  // namespace momenta::dynamics
