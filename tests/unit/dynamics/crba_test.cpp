// The mass matrix of a double pendulum against its closed form.
#include "momenta/dynamics/crba.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
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

// A gimbal: yaw about z carries a massless frame, roll about x carries a slender rod lying along
// y. At the neutral configuration both joints move inertia (the builder accepts it); rolled by
// 90° the rod lies along z, where yaw turns it about its own axis: nothing resists the yaw, and
// the mass matrix is singular at that state. check_mass_matrix must refuse it, naming the joint
// and its coordinate, as data too (Error::item) so a file reader can point at the joint's line.
TEST(CheckMassMatrix, RefusesACoordinateNothingResistsAndNamesIt) {
  const double m = 2.0, L = 1.0;
  model::ModelBuilder b;
  b.add_body("gimbal", inertia::MassProperties());
  b.add_body("rod", inertia::MassProperties(m, Vec3::Zero(),
                                            Vec3(m * L * L / 12, 0, m * L * L / 12).asDiagonal()));
  b.add_joint(
      test::make_joint("yaw", model::JointType::revolute, "world", "gimbal", Vec3::UnitZ()));
  b.add_joint(test::make_joint("roll", model::JointType::revolute, "gimbal", "rod", Vec3::UnitX()));
  const Model model = b.build();
  EXPECT_NO_THROW(check_mass_matrix(model, VecX::Zero(2)));
  const VecX rolled = (VecX(2) << 0.0, std::numbers::pi / 2).finished();
  try {
    check_mass_matrix(model, rolled);
    FAIL() << "a singular mass matrix was accepted";
  } catch (const InvalidArgument& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("joint 'yaw': the mass matrix is singular along its coordinate "
                           "'yaw.angle_rate'"),
              std::string::npos)
        << message;
    EXPECT_NE(message.find("no inertia resists that motion"), std::string::npos) << message;
    ASSERT_TRUE(e.item().has_value());
    EXPECT_EQ(e.item()->kind, ModelItemRef::Kind::joint);
    EXPECT_EQ(e.item()->name, "yaw");
  }
  // Near the singular state (1e-3 rad off) the rod still has m L² sin²(1e-3)/12 about z: accepted.
  const VecX nearly = (VecX(2) << 0.0, std::numbers::pi / 2 - 1e-3).finished();
  EXPECT_NO_THROW(check_mass_matrix(model, nearly));
}

// Prescribed coordinates are left out: their acceleration is given, not solved for.
TEST(CheckMassMatrix, IgnoresPrescribedCoordinates) {
  model::ModelBuilder b;
  model::RampSignal ramp;
  ramp.slope = 2.0;
  b.add_signal(model::Signal("spin", ramp));
  b.add_body("table", inertia::MassProperties());
  b.add_body("bead", inertia::MassProperties(0.1, Vec3::Zero(), Mat3::Zero()));
  model::Joint drive =
      test::make_joint("drive", model::JointType::revolute, "world", "table", Vec3::UnitZ());
  drive.prescribed_signals = {"spin"};
  b.add_joint(drive);
  b.add_joint(
      test::make_joint("slot", model::JointType::prismatic, "table", "bead", Vec3::UnitX()));
  const Model model = b.build();
  EXPECT_NO_THROW(check_mass_matrix(model, model.initial_q()));
}

}  // namespace
}  // namespace momenta::dynamics
