// The mass matrix of a double pendulum against its closed form.
#include "momenta/dynamics/crba.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

// M11 = m1 l1² + m2 (l1² + l2² + 2 l1 l2 cos θ2), M12 = m2 (l2² + l1 l2 cos θ2), M22 = m2 l2².
TEST(Crba, DoublePendulumClosedForm) {
  const double m1 = 1.5, m2 = 0.8, l1 = 0.6, l2 = 0.45;
  const Model model = test::double_pendulum(m1, m2, l1, l2);
  Data data(model);
  for (double t2 : {0.0, 0.7, -2.1, 3.1}) {
    const VecX q = (VecX(2) << 0.9, t2).finished();
    const double c = std::cos(t2);
    Eigen::Matrix2d expected;
    expected(0, 0) = m1 * l1 * l1 + m2 * (l1 * l1 + l2 * l2 + 2 * l1 * l2 * c);
    expected(0, 1) = expected(1, 0) = m2 * (l2 * l2 + l1 * l2 * c);
    expected(1, 1) = m2 * l2 * l2;
    EXPECT_MATRIX_NEAR(crba(model, data, q), expected, 1e-14);
    EXPECT_MATRIX_NEAR(mass_matrix(model, q), expected, 1e-14);
  }
}

// Branches that are not ancestors of one another do not couple: M has zeros there.
TEST(Crba, SiblingBranchesDoNotCouple) {
  model::ModelBuilder b;
  b.add_body("trunk", inertia::MassProperties(1.0, Vec3(0, 0, -0.2), 0.01 * Mat3::Identity()));
  b.add_body("left", inertia::MassProperties(1.0, Vec3(0.1, 0, -0.3), 0.01 * Mat3::Identity()));
  b.add_body("right", inertia::MassProperties(1.0, Vec3(0, 0, -0.3), 0.01 * Mat3::Identity()));
  b.add_joint(test::make_joint("j0", model::JointType::revolute, "world", "trunk"));
  b.add_joint(test::make_joint("j1", model::JointType::revolute, "trunk", "left", Vec3::UnitX()));
  b.add_joint(test::make_joint("j2", model::JointType::revolute, "trunk", "right", Vec3::UnitZ()));
  const Model model = b.build();
  Data data(model);
  const MatX M = crba(model, data, VecX::Constant(3, 0.4));
  EXPECT_EQ(M(1, 2), 0.0);
  EXPECT_EQ(M(2, 1), 0.0);
  EXPECT_NE(M(0, 1), 0.0);
}

}  // namespace
}  // namespace momenta::dynamics
