// The regressor against RNEA (a second algorithm): τ = Y π + armature ∘ v̇ on random trees of
// every joint type, and Y the only matrix that is so for 31 random inertias of one chain.
#include "momenta/identify/inertial_regressor.hpp"

#include <random>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"

#include "momenta/dynamics/rnea.hpp"
#include "momenta_test/allocation_counter.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/multibody_models.hpp"

namespace momenta::identify {
namespace {

using model::JointType;
using model::ModelBuilder;

double relative_error(const VecX& a, const VecX& b) {
  return (a - b).cwiseAbs().maxCoeff() / std::max(b.cwiseAbs().maxCoeff(), 1.0);
}

// Round-off of an RNEA-sized sum: ~1e-15 of the largest torque; 1e-12 leaves room for trees of
// eight bodies with quaternion joints, and any wrong column (a missed transform, a sign) shows at
// order one.
TEST(InertialRegressor, TimesTheModelsParametersIsRneaOnRandomTreesOfEveryJoint) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Model model = test::random_tree(8, seed, test::all_joint_types(), Vec3(0.3, -1.2, -9.81),
                                          /*armature=*/0.01);
    InertialRegressor regressor(model);
    const VecX pi = inertial_parameters(model);
    std::mt19937 rng(seed);
    for (int trial = 0; trial < 5; ++trial) {
      const VecX q = test::random_configuration(model, rng);
      const VecX v = test::random_vector(model.nv(), rng, 2.0);
      const VecX vdot = test::random_vector(model.nv(), rng, 3.0);
      const VecX tau = dynamics::inverse_dynamics(model, q, v, vdot);
      const VecX from_Y = regressor.compute(q, v, vdot) * pi + regressor.armature_torque(vdot);
      EXPECT_LT(relative_error(from_Y, tau), 1e-12) << "seed " << seed << " trial " << trial;
    }
  }
}

// A chain of a revolute, a ball and a prismatic joint off the coordinate axes, with given bodies.
Model chain(const std::vector<inertia::MassProperties>& bodies) {
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -9.81));
  const std::vector<JointType> types = {JointType::revolute, JointType::spherical,
                                        JointType::prismatic};
  const std::vector<Vec3> axes = {Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0.6, 0.0, 0.8)};
  for (int k = 0; k < 3; ++k) {
    const std::string name = fmt::format("b{}", k);
    b.add_body(name, bodies[k]);
    b.add_joint(test::make_joint(fmt::format("j{}", k), types[k],
                                 k == 0 ? "world" : fmt::format("b{}", k - 1), name, axes[k],
                                 Transform::translation(Vec3(0.3, 0.1 * k, -0.2))));
  }
  return b.build();
}

// Y does not read the inertias, and Y π_t = rnea_t for 31 random bodies π_t that span the 30
// parameters: no other matrix satisfies all 31, so every column of Y is right.
TEST(InertialRegressor, IsTheOnlyMatrixThatGivesRneaForEveryInertia) {
  std::mt19937 rng(7);
  const auto random_bodies = [&] {
    return std::vector<inertia::MassProperties>{test::random_mass_properties(rng),
                                                test::random_mass_properties(rng),
                                                test::random_mass_properties(rng)};
  };
  const Model first = chain(random_bodies());
  const VecX q = test::random_configuration(first, rng);
  const VecX v = test::random_vector(first.nv(), rng, 2.0);
  const VecX vdot = test::random_vector(first.nv(), rng, 3.0);
  const MatX Y = inertial_regressor(first, q, v, vdot);
  MatX parameters(30, 31);
  for (int t = 0; t < 31; ++t) {
    const Model model = t == 0 ? first : chain(random_bodies());
    EXPECT_EQ(inertial_regressor(model, q, v, vdot), Y);
    parameters.col(t) = inertial_parameters(model);
    EXPECT_LT(relative_error(Y * parameters.col(t), dynamics::inverse_dynamics(model, q, v, vdot)),
              1e-13);
  }
  EXPECT_EQ(Eigen::FullPivLU<MatX>(parameters).rank(), 30);
}

// A hot path: compute() on a built regressor does not allocate (its Y and RNEA's Data are the
// workspace).
TEST(InertialRegressor, ComputeDoesNotAllocate) {
  if (!test::allocation_count_includes_malloc()) {
    GTEST_SKIP() << "under the sanitizers only operator new is counted";
  }
  const Model model = test::random_tree(6, 8);
  InertialRegressor regressor(model);
  std::mt19937 rng(1);
  const VecX q = test::random_configuration(model, rng);
  const VecX v = test::random_vector(model.nv(), rng), vdot = test::random_vector(model.nv(), rng);
  regressor.compute(q, v, vdot);
  const long before = test::allocation_count();
  regressor.compute(q, v, vdot);
  EXPECT_EQ(test::allocation_count() - before, 0);
}

TEST(InertialRegressor, ChecksItsArguments) {
  const Model model = test::double_pendulum(1, 1, 1, 1);
  InertialRegressor regressor(model);
  const VecX two = VecX::Zero(2), three = VecX::Zero(3);
  EXPECT_THROW(regressor.compute(three, two, two), InvalidArgument);
  try {
    regressor.compute(two, two, three);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(), "inertial_regressor: vdot has size 3; the model needs 2 (nv)");
  }
}

TEST(InertialParameters, AreTheSpatialInertiasTen) {
  std::mt19937 rng(3);
  const inertia::MassProperties body = test::random_mass_properties(rng);
  const SpatialInertia I = body.spatial_inertia();
  const Vec10 pi = parameters_of(I);
  EXPECT_EQ(pi[0], I.mass);
  EXPECT_EQ(pi[3], I.h[2]);
  EXPECT_EQ(pi[5], I.I_O(0, 1));  // the tensor's entry: minus the product of inertia
  const SpatialInertia back = spatial_inertia_of(pi);
  EXPECT_TRUE(back.matrix().isApprox(I.matrix(), 1e-15));  // I_O's two halves to round-off
  const Model model = test::double_pendulum(1, 2, 1, 1);
  EXPECT_EQ(parameter_name(model, 0), "upper.m");
  EXPECT_EQ(parameter_name(model, 17), "lower.I_yy");
  EXPECT_THROW(parameter_name(model, 20), InvalidArgument);
}

TEST(PhysicalConsistency, NamesWhatNoBodyCanHave) {
  std::mt19937 rng(5);
  const inertia::MassProperties body = test::random_mass_properties(rng);
  const PhysicalConsistency good = physical_consistency(parameters_of(body.spatial_inertia()));
  EXPECT_TRUE(good.consistent()) << good.verdict();
  EXPECT_NEAR((good.center_of_mass - body.center_of_mass()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(good.principal_moments.sum(), body.inertia_about_com().trace(), 1e-14);

  Vec10 negative = parameters_of(body.spatial_inertia());
  negative[0] = -1.0;
  EXPECT_FALSE(physical_consistency(negative).consistent());
  EXPECT_EQ(physical_consistency(negative).verdict(), "mass -1 kg is not positive");

  // A rod's I_zz larger than I_xx + I_yy about its centre: no mass distribution.
  const Vec10 triangle = parameters_of(
      inertia::MassProperties(1.0, Vec3::Zero(), Vec3(1, 1, 3).asDiagonal()).spatial_inertia());
  const PhysicalConsistency broken = physical_consistency(triangle);
  EXPECT_TRUE(broken.positive_mass && broken.positive_moments);
  EXPECT_FALSE(broken.triangle_inequalities);
}

}  // namespace
}  // namespace momenta::identify
