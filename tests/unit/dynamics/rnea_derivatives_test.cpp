// rnea_derivatives against high-order finite differences on the tangent space (every joint type,
// random trees, external forces held in their bodies), M against crba, τ against rnea.
#include "momenta/dynamics/rnea_derivatives.hpp"

#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tangent_differences.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics::rnea_derivatives_test {
namespace {

using model::JointType;

// Largest |entry|, at least 1: the scale a relative tolerance multiplies.
double scale_of(const MatX& X) { return std::max(1.0, X.cwiseAbs().maxCoeff()); }

// Checks ∂τ/∂q, ∂τ/∂v, M and τ of one state; `what` names the case in a failure.
void expect_rnea_derivatives(const Model& m, const VecX& q, const VecX& v, const VecX& a,
                             const std::vector<Vec6>& f_ext, const std::string& what) {
  SCOPED_TRACE(what);
  Data data(m);
  rnea_derivatives(m, data, q, v, a, f_ext);
  Data work(m);
  const MatX dq_reference = test::tangent_jacobian(
      m, q, [&](const VecX& qq) { return VecX(rnea(m, work, qq, v, a, f_ext)); });
  const MatX dv_reference = test::quadratic_jacobian(
      v, [&](const VecX& vv) { return VecX(rnea(m, work, q, vv, a, f_ext)); });
  // 1e-10 relative: the bar, ~100× the differences' own error (tangent_differences.hpp).
  EXPECT_MATRIX_NEAR(data.dtau_dq, dq_reference, 1e-10 * scale_of(dq_reference));
  // ∂τ/∂v: exact differences, so round-off of the analytic sums and of τ (~1e-14 relative).
  EXPECT_MATRIX_NEAR(data.dtau_dv, dv_reference, 1e-12 * scale_of(dv_reference));
  const MatX M = crba(m, work, q);
  EXPECT_MATRIX_NEAR(data.M, M, 1e-13 * scale_of(M));
  const VecX tau = rnea(m, work, q, v, a, f_ext);
  EXPECT_MATRIX_NEAR(data.tau, tau, 1e-13 * std::max(1.0, tau.cwiseAbs().maxCoeff()));
}

TEST(RneaDerivatives, EveryJointTypeAloneAndAfterARevolute) {
  const std::vector<std::pair<JointType, const char*>> types = {
      {JointType::revolute, "revolute"},
      {JointType::prismatic, "prismatic"},
      {JointType::cylindrical, "cylindrical"},
      {JointType::universal, "universal"},
      {JointType::spherical, "spherical"},
      {JointType::planar, "planar"},
      {JointType::free, "free"},
      {JointType::fixed, "fixed"}};
  for (const auto& [type, name] : types) {
    const Model m = test::random_tree(6, 11, {type, JointType::revolute});
    std::mt19937 rng(5);
    const VecX q = test::random_configuration(m, rng);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    const VecX a = test::random_vector(m.nv(), rng, 3.0);
    expect_rnea_derivatives(m, q, v, a, {}, name);
  }
}

// Seeds 4–6 with a rotor's reflected inertia (armature) on every joint: in M and τ.
TEST(RneaDerivatives, RandomTreesWithEveryJointTypeAndBodyForces) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    const Model m = test::random_tree(14, seed, test::all_joint_types(), Vec3(0, 0, -9.81),
                                      seed > 3 ? 0.03 : 0.0);
    std::mt19937 rng(seed + 100);
    const VecX q = test::random_configuration(m, rng);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    const VecX a = test::random_vector(m.nv(), rng, 3.0);
    std::vector<Vec6> f_ext(m.num_bodies());
    for (Vec6& f : f_ext) f = test::random_vector(6, rng, 5.0);
    expect_rnea_derivatives(m, q, v, a, f_ext, fmt::format("seed {}", seed));
  }
}

TEST(RneaDerivatives, AtRestTheConfigurationDerivativeIsTheGravityStiffness) {
  // A pendulum of length ℓ at angle θ from the downward vertical: τ = m g ℓ sin θ, so
  // ∂τ/∂θ = m g ℓ cos θ exactly, and ∂τ/∂v = 0 at rest.
  model::ModelBuilder builder;
  builder.set_gravity(Vec3(0, 0, -9.81));
  const double mass = 2.0, length = 0.7, theta = 0.3;
  builder.add_body("bob", inertia::MassProperties(mass, Vec3(0, 0, -length), Mat3::Zero()));
  model::Joint hinge;
  hinge.name = "hinge";
  hinge.type = JointType::revolute;
  hinge.parent = "world";
  hinge.child = "bob";
  hinge.axis = Vec3::UnitY();
  builder.add_joint(hinge);
  const Model m = builder.build();
  Data data(m);
  const VecX q = VecX::Constant(1, theta), zero = VecX::Zero(1);
  rnea_derivatives(m, data, q, zero, zero);
  EXPECT_TRUE(
      test::relatively_near(data.dtau_dq(0, 0), mass * 9.81 * length * std::cos(theta), 1e-15));
  EXPECT_EQ(data.dtau_dv(0, 0), 0.0);
  EXPECT_TRUE(test::relatively_near(data.M(0, 0), mass * length * length, 1e-15));
}

TEST(RneaDerivatives, ChecksItsArguments) {
  const Model m = test::random_tree(4, 3);
  Data data(m);
  const VecX q = model::neutral(m), v = VecX::Zero(m.nv());
  EXPECT_THROW(rnea_derivatives(m, data, q, VecX::Zero(m.nv() + 1), v), InvalidArgument);
  EXPECT_THROW(rnea_derivatives(m, data, VecX::Zero(1), v, v), InvalidArgument);
}

}  // namespace
}  // namespace momenta::dynamics::rnea_derivatives_test
