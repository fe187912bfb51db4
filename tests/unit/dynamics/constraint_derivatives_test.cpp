// constraint_derivatives against high-order finite differences on the tangent space
// (momenta_test/tangent_differences.hpp): every kind of constraint, on the joints of
// every_constraint_model and on a universal and a cylindrical joint below them, at random states.
#include "momenta/dynamics/constraint_derivatives.hpp"

#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta_test/constrained_models.hpp"
#include "momenta_test/tangent_differences.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics::constraint_derivatives_test {
namespace {

using model::JointType;
using test::frame;

// every_constraint_model's tree with a universal joint on b2 and a cylindrical one below it,
// every kind of constraint acting on the last body (so each row moves with both stages of the
// universal joint, and a coupler between 1-dof joints).
model::Model deep_constraint_model() {
  model::ModelBuilder b;
  test::add_tree_of_joint_types(b);
  const auto box = inertia::box(inertia::Amount::mass(0.5), Vec3(0.2, 0.1, 0.1));
  b.add_body("b6", box);
  b.add_body("b7", box);
  test::add_joint(b, "j6", JointType::universal, "b2", "b6", Vec3(0.1, 0.2, 0), Vec3::UnitX());
  test::add_joint(b, "j7", JointType::cylindrical, "b6", "b7", Vec3(0, 0, 0.3), Vec3(0.6, 0, 0.8));
  const Transform X(Eigen::AngleAxisd(0.7, Vec3(-1, 2, 1).normalized()).toRotationMatrix(),
                    Vec3(0.05, 0.1, -0.2));
  b.add_constraint(
      model::LoopClosure{"weld", model::LoopType::weld, frame("b7", X), frame("b3", {})});
  b.add_constraint(
      model::LoopClosure{"ball", model::LoopType::point, frame("b1", X), frame("b7", X)});
  b.add_constraint(model::LoopClosure{"pin", model::LoopType::hinge, frame("world", X),
                                      frame("b7", X.inverse())});
  b.add_constraint(
      model::LoopClosure{"slide", model::LoopType::slider, frame("b7", {}), frame("b4", X)});
  b.add_constraint(model::DistanceLink{"wire", frame("b7", X), frame("b5", {}), 0.5});
  b.add_constraint(model::RollingContact{"wheel", frame("b7", X), model::RollingShape::disk, 0.2,
                                         Vec3(0, 0.6, 0.8), Vec3(0, 0, -0.1)});
  b.add_constraint(model::RollingContact{"ball_roll", frame("b6", X), model::RollingShape::sphere,
                                         0.1, Vec3::UnitZ(), Vec3::Zero()});
  b.add_constraint(model::KnifeEdge{"blade", frame("b7", X), Vec3(0.6, 0, 0.8)});
  b.add_constraint(model::JointCoupler{"gear", "j1", "j4", -1.7, 0.2});
  return b.build();
}

// The differences' step: the rows' unit vectors (a tilted disk's way to its contact, a wire's
// direction) have derivatives that grow as 1/sᵏ with s the tilt's sine or the wire's length, and
// random states put some near s ~ 0.1, where h = 0.04 leaves truncation errors of 1e-6. At h =
// 5e-3 the truncation is 8⁶ ≈ 2.6e5 times smaller and round-off ~10 ε / (h/4) ≈ 2e-12.
constexpr double kStep = 5e-3;

double scale_of(const MatX& X) { return std::max(1.0, X.cwiseAbs().maxCoeff()); }

// Every derivative of one state against differences of the rows (constraint_equations).
void expect_constraint_derivatives(const model::Model& m, const test::RandomState& s,
                                   const VecX& lambda, const std::string& what) {
  SCOPED_TRACE(what);
  Data data(m);
  ConstraintDerivatives d(m);
  constraint_derivatives(m, data, s.q, s.v, s.vdot, lambda, d);

  Data work(m);
  ConstraintRows rows(m);
  const auto rows_at = [&](const VecX& q, const VecX& v) {
    forward_kinematics(m, work, q, v);
    constraint_equations(m, work, q, rows, RowTerms::with_velocity_products);
  };
  const auto velocity = [&](const VecX& q) {
    rows_at(q, s.v);
    return VecX(rows.G * s.v);
  };
  const auto residual_at = [&](const VecX& q, const VecX& v) {
    rows_at(q, v);
    return VecX(rows.G * s.vdot + rows.bias);
  };
  const auto force = [&](const VecX& q) {
    rows_at(q, s.v);
    return VecX(rows.G.transpose() * lambda);
  };
  const MatX velocity_dq = test::tangent_jacobian(m, s.q, velocity, kStep);
  const MatX residual_dq = test::tangent_jacobian(
      m, s.q, [&](const VecX& q) { return residual_at(q, s.v); }, kStep);
  const MatX residual_dv =
      test::quadratic_jacobian(s.v, [&](const VecX& v) { return residual_at(s.q, v); });
  const MatX force_dq = test::tangent_jacobian(m, s.q, force, kStep);

  // 1e-10 relative: ~100× the differences' own error (tangent_differences.hpp), the bar of
  // rnea_derivatives' tests. ∂k/∂v: exact differences of a quadratic, so round-off (1e-12).
  EXPECT_MATRIX_NEAR(d.velocity_dq, velocity_dq, 1e-10 * scale_of(velocity_dq));
  EXPECT_MATRIX_NEAR(d.residual_dq, residual_dq, 1e-10 * scale_of(residual_dq));
  EXPECT_MATRIX_NEAR(d.residual_dv, residual_dv, 1e-12 * scale_of(residual_dv));
  EXPECT_MATRIX_NEAR(d.force_dq, force_dq, 1e-10 * scale_of(force_dq));
  rows_at(s.q, s.v);
  EXPECT_MATRIX_NEAR(d.rows.G, rows.G, 1e-15 * scale_of(rows.G));
}

// Four random states of the model, with random multipliers.
void expect_at_random_states(const model::Model& m, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-2, 2);
  for (int trial = 0; trial < 4; ++trial) {
    const test::RandomState s = test::random_state(m, rng);
    const VecX lambda = VecX::NullaryExpr(m.num_constraint_rows(), [&] { return u(rng); });
    expect_constraint_derivatives(m, s, lambda, fmt::format("state {}", trial));
  }
}

TEST(ConstraintDerivatives, EveryKindOfConstraintAtRandomStates) {
  expect_at_random_states(test::every_constraint_model(), 11);
}

TEST(ConstraintDerivatives, RowsBelowUniversalAndCylindricalJoints) {
  expect_at_random_states(deep_constraint_model(), 12);
}

TEST(ConstraintDerivatives, TheMultipliersMustMatchTheRows) {
  const model::Model m = test::every_constraint_model();
  Data data(m);
  ConstraintDerivatives d(m);
  const VecX q = m.initial_q(), v = VecX::Zero(m.nv());
  EXPECT_THROW(constraint_derivatives(m, data, q, v, v, VecX::Zero(2), d), InvalidArgument);
}

}  // namespace
}  // namespace momenta::dynamics::constraint_derivatives_test
