// Forward kinematics: poses of a double pendulum in closed form, and the world-frame helpers.
#include "momenta/dynamics/kinematics.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

TEST(Kinematics, DoublePendulumPosesVelocitiesAccelerations) {
  const double l1 = 0.6, l2 = 0.45;
  const Model model = test::double_pendulum(1.0, 1.0, l1, l2);
  Data data(model);
  const VecX q = (VecX(2) << 0.4, -0.9).finished();
  const VecX v = (VecX(2) << 1.3, 2.1).finished();
  const VecX a = (VecX(2) << -0.7, 0.5).finished();
  forward_kinematics(model, data, q, v, a);
  const auto Ry = [](double f) { return Eigen::AngleAxisd(f, Vec3::UnitY()).toRotationMatrix(); };
  EXPECT_MATRIX_NEAR(data.X_WB[1].R, Ry(0.4), 1e-15);
  EXPECT_MATRIX_NEAR(data.X_WB[2].R, Ry(-0.5), 1e-15);
  EXPECT_MATRIX_NEAR(data.X_WB[2].p, Vec3(-l1 * std::sin(0.4), 0, -l1 * std::cos(0.4)), 1e-15);
  // Angular velocity and acceleration of the lower link, in W: (θ̇1 + θ̇2) ŷ, (θ̈1 + θ̈2) ŷ.
  EXPECT_MATRIX_NEAR(body_velocity_in_world(data, 2).head<3>(), Vec3(0, 3.4, 0), 1e-15);
  EXPECT_MATRIX_NEAR(body_acceleration_in_world(data, 2).head<3>(), Vec3(0, -0.2, 0), 1e-15);
  // The elbow (lower link origin) moves on a circle of radius l1: a = l1 (θ̈ t̂ − θ̇² r̂).
  const Vec3 r(-std::sin(0.4), 0, -std::cos(0.4)), t(-std::cos(0.4), 0, std::sin(0.4));
  EXPECT_MATRIX_NEAR(body_velocity_in_world(data, 2).tail<3>(), l1 * 1.3 * t, 1e-15);
  EXPECT_MATRIX_NEAR(body_acceleration_in_world(data, 2).tail<3>(), l1 * (-0.7 * t - 1.3 * 1.3 * r),
                     1e-14);
}

TEST(Kinematics, WorldForceToBodyWrench) {
  const Model model = test::pendulum(1.0, 0.5, 0.01);
  Data data(model);
  forward_kinematics(model, data, VecX::Constant(1, 0.3));
  const Vec3 f_W(1, 2, 3), p_W(0.1, -0.2, 0.4);
  const Vec6 F_B = body_wrench_from_world_force(data, 1, f_W, p_W);
  // Back to W about Wo: moment p × f, force f.
  const Vec6 F_W = data.X_WB[1].act_force(F_B);
  EXPECT_MATRIX_NEAR(F_W, spatial(p_W.cross(f_W), f_W), 1e-15);
}

}  // namespace
}  // namespace momenta::dynamics
