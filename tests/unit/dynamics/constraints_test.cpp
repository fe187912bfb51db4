// The constraint rows (dynamics/constraints.hpp) against finite differences, on a model with
// every kind of constraint at random states: G v is the rate of φ, G v̇ + k the rate of G v, and
// the forces add_constraint_forces applies deliver the power λᵀ G v.
//
// Tolerances: central differences of step h = 1e-5 have truncation ~h² ≈ 1e-10 and round-off
// ~ε/h ≈ 1e-11 relative to the rows' scale; 1e-7 leaves room for the second derivatives' size.

#include <gtest/gtest.h>

#include <random>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/constraints.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/inertia/primitives.hpp"
#include "momenta/model/model_builder.hpp"

namespace momenta {
namespace {

using model::JointType;

model::Model every_constraint_model() {
  model::ModelBuilder b;
  const auto box = inertia::box(inertia::Amount::mass(1.0), Vec3(0.1, 0.2, 0.3));
  for (const char* name : {"b1", "b2", "b3", "b4", "b5"}) b.add_body(name, box);
  const auto joint = [&](const char* name, JointType type, const char* parent, const char* child,
                         const Vec3& at, const Vec3& axis) {
    model::Joint j;
    j.name = name;
    j.type = type;
    j.parent = parent;
    j.child = child;
    j.X_PJ = Transform::translation(at);
    j.axis = axis;
    b.add_joint(j);
  };
  joint("j1", JointType::revolute, "world", "b1", Vec3::Zero(), Vec3::UnitZ());
  joint("j2", JointType::spherical, "b1", "b2", Vec3(0.3, 0, 0), Vec3::UnitZ());
  joint("j3", JointType::free, "world", "b3", Vec3::Zero(), Vec3::UnitZ());
  joint("j4", JointType::prismatic, "world", "b4", Vec3(0, 1, 0), Vec3(0.6, 0.8, 0));
  joint("j5", JointType::planar, "world", "b5", Vec3::Zero(), Vec3::UnitZ());
  const Transform X(Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix(),
                    Vec3(0.1, -0.2, 0.05));
  const auto frame = [](const char* body, const Transform& X_BF) {
    return model::BodyFrame{body, X_BF, -1};
  };
  b.add_constraint(
      model::LoopClosure{"weld", model::LoopType::weld, frame("b2", X), frame("b3", {})});
  b.add_constraint(
      model::LoopClosure{"ball", model::LoopType::point, frame("b1", X), frame("b3", X)});
  b.add_constraint(model::LoopClosure{"pin", model::LoopType::hinge, frame("world", X),
                                      frame("b3", X.inverse())});
  b.add_constraint(
      model::LoopClosure{"slide", model::LoopType::slider, frame("b2", {}), frame("b4", X)});
  b.add_constraint(model::DistanceLink{"wire", frame("b1", X), frame("b3", {}), 0.5});
  b.add_constraint(model::RollingContact{"wheel", frame("b3", X), model::RollingShape::disk, 0.2,
                                         Vec3(0, 0.6, 0.8), Vec3(0, 0, -0.1)});
  b.add_constraint(model::RollingContact{"ball_roll", frame("b2", X), model::RollingShape::sphere,
                                         0.1, Vec3::UnitZ(), Vec3::Zero()});
  b.add_constraint(model::KnifeEdge{"blade", frame("b5", X), Vec3::UnitZ()});
  b.add_constraint(model::JointCoupler{"gear", "j1", "j4", -1.7, 0.2});
  return b.build();
}

struct RandomState {
  VecX q, v, vdot;
};

RandomState random_state(const model::Model& model, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  RandomState s;
  s.q = VecX::NullaryExpr(model.nq(), [&] { return u(rng); });
  model::normalize(model, s.q);
  s.v = VecX::NullaryExpr(model.nv(), [&] { return 2 * u(rng); });
  s.vdot = VecX::NullaryExpr(model.nv(), [&] { return 3 * u(rng); });
  return s;
}

class ConstraintRowsTest : public ::testing::Test {
 protected:
  model::Model model = every_constraint_model();
  dynamics::Data data{model};
  dynamics::ConstraintRows rows{model};
  std::mt19937 rng{7};

  void rows_at(const VecX& q, const VecX& v) {
    dynamics::forward_kinematics(model, data, q, v);
    dynamics::constraint_equations(model, data, q, rows,
                                   dynamics::RowTerms::with_velocity_products);
  }
};

TEST_F(ConstraintRowsTest, SizesAndNames) {
  EXPECT_EQ(rows.count, 6 + 3 + 5 + 5 + 1 + 3 + 3 + 1 + 1);
  EXPECT_EQ(model.num_constraint_rows(), rows.count);
  EXPECT_EQ(rows.names[6], "ball.x");
  EXPECT_EQ(rows.names[21], "wheel.longitudinal");
  int position_rows = 0;
  for (char h : rows.holonomic) position_rows += h;
  EXPECT_EQ(position_rows, rows.count - 2 - 2 - 1);
}

TEST_F(ConstraintRowsTest, JacobianIsTheRateOfThePositionRows) {
  const double h = 1e-5;
  for (int trial = 0; trial < 20; ++trial) {
    const RandomState s = random_state(model, rng);
    rows_at(s.q, s.v);
    const VecX Gv = rows.G * s.v;
    dynamics::forward_kinematics(model, data, model::integrate(model, s.q, s.v, h));
    dynamics::constraint_equations(model, data, model::integrate(model, s.q, s.v, h), rows);
    const VecX plus = rows.position;
    dynamics::forward_kinematics(model, data, model::integrate(model, s.q, s.v, -h));
    dynamics::constraint_equations(model, data, model::integrate(model, s.q, s.v, -h), rows);
    const VecX rate = (plus - rows.position) / (2 * h);
    for (int i = 0; i < rows.count; ++i) {
      if (!rows.holonomic[i]) continue;
      EXPECT_NEAR(Gv[i], rate[i], 1e-7 * (1 + std::abs(Gv[i])))
          << rows.names[i] << " trial " << trial;
    }
  }
}

TEST_F(ConstraintRowsTest, VelocityProductTermIsTheRateOfTheVelocityRows) {
  const double h = 1e-5;
  for (int trial = 0; trial < 20; ++trial) {
    const RandomState s = random_state(model, rng);
    rows_at(s.q, s.v);
    const VecX accel = rows.G * s.vdot + rows.bias;
    // G v along the motion q(t) = q ⊕ (t v + ½ t² v̇), v(t) = v + t v̇.
    const auto Gv_at = [&](double t) {
      const VecX q = model::integrate(model, s.q, t * s.v + 0.5 * t * t * s.vdot, 1.0);
      const VecX v = s.v + t * s.vdot;
      rows_at(q, v);
      return VecX(rows.G * v);
    };
    const VecX rate = (Gv_at(h) - Gv_at(-h)) / (2 * h);
    for (int i = 0; i < rows.count; ++i) {
      EXPECT_NEAR(accel[i], rate[i], 1e-7 * (1 + std::abs(accel[i])))
          << rows.names[i] << " trial " << trial;
    }
  }
}

TEST_F(ConstraintRowsTest, ForcesDeliverThePowerOfTheirMultipliers) {
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 10; ++trial) {
    const RandomState s = random_state(model, rng);
    rows_at(s.q, s.v);
    const VecX lambda = VecX::NullaryExpr(rows.count, [&] { return u(rng); });
    std::vector<Vec6> f_ext(model.num_bodies(), Vec6::Zero());
    VecX tau = VecX::Zero(model.nv());
    dynamics::add_constraint_forces(model, data, rows, lambda, f_ext, tau);
    double power = tau.dot(s.v);
    for (int b = 1; b < model.num_bodies(); ++b) power += f_ext[b].dot(data.V_WB_B[b]);
    EXPECT_NEAR(power, lambda.dot(rows.G * s.v), 1e-12 * (1 + std::abs(power)));
  }
}

TEST(ConstraintRows, DegenerateDirectionIsNamed) {
  model::ModelBuilder b;
  b.add_body("arm", inertia::box(inertia::Amount::mass(1.0), Vec3(0.1, 0.2, 0.3)));
  model::Joint j;
  j.name = "hinge";
  j.parent = "world";
  j.child = "arm";
  b.add_joint(j);
  b.add_constraint(model::DistanceLink{"tie", {"world", {}, -1}, {"arm", {}, -1}, 1.0});
  const model::Model model = b.build();
  dynamics::Data data(model);
  dynamics::ConstraintRows rows(model);
  const VecX q = model.initial_q();
  dynamics::forward_kinematics(model, data, q);
  try {
    dynamics::constraint_equations(model, data, q, rows);
    FAIL() << "coincident points accepted";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("constraint 'tie': its two points coincide"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace momenta
