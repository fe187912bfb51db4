// The base parameters against Khalil's closed-form regrouping of a planar two-link arm, a free
// body's ten, and the regrouping's promise Y π = Y_I β on random trees.
#include "momenta/identify/base_parameters.hpp"

#include <random>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"

#include "momenta/identify/inertial_regressor.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/two_link_arm.hpp"

namespace momenta::identify {
namespace {

using model::JointType;
using model::ModelBuilder;

std::vector<std::string> independent_names(const Model& model, const BaseParameters& base) {
  std::vector<std::string> names;
  for (int k : base.independent) names.push_back(parameter_name(model, k));
  return names;
}

// Khalil & Dombre (2002, §12.3.2): a planar arm's link j keeps its moment about the axis and its
// two first moments in the plane; the next link's mass regroups onto them, m₂ l₁² onto I_yy and
// −l₁ m₂ onto h_z (the elbow at z = −l₁). Six with gravity in the plane.
TEST(BaseParameters, OfAPlanarTwoLinkArmAreKhalilsSix) {
  const test::TwoLinkArm arm;
  const Model model = arm.model();
  const BaseParameters base = base_parameters(model);
  EXPECT_EQ(independent_names(model, base),
            (std::vector<std::string>{"upper.h_x", "upper.h_z", "upper.I_yy", "lower.h_x",
                                      "lower.h_z", "lower.I_yy"}));
  EXPECT_EQ(base.describe(model, 2), "upper.I_yy + 0.64·lower.m");
  EXPECT_EQ(base.describe(model, 1), "upper.h_z − 0.8·lower.m");
  // β in the textbook's terms (I about each centre, lc from each joint):
  const VecX beta = base.base_of(inertial_parameters(model));
  const double l1 = arm.l1;
  const VecX expected = (VecX(6) << 0.0, -(arm.m1 * arm.lc1 + arm.m2 * l1),
                         arm.I1 + arm.m1 * arm.lc1 * arm.lc1 + arm.m2 * l1 * l1, 0.0,
                         -arm.m2 * arm.lc2, arm.I2 + arm.m2 * arm.lc2 * arm.lc2)
                            .finished();
  EXPECT_LT((beta - expected).cwiseAbs().maxCoeff(), 1e-14);
  // Everything else is regrouped (lower.m) or never felt.
  EXPECT_EQ(base.dependent.size(), 14u);
  EXPECT_EQ(base.no_effect.size(), 13u);
}

// With gravity along the joints' axes the first moments of the first link do no work: four.
TEST(BaseParameters, OfATwoLinkArmWithoutGravityInItsPlaneAreFour) {
  const Model model = test::TwoLinkArm().model(/*gravity_along_axes=*/true);
  EXPECT_EQ(independent_names(model, base_parameters(model)),
            (std::vector<std::string>{"upper.I_yy", "lower.h_x", "lower.h_z", "lower.I_yy"}));
}

// A free body's wrench decides all ten of its parameters.
TEST(BaseParameters, OfAFreeBodyAreAllTen) {
  ModelBuilder b;
  std::mt19937 rng(2);
  b.add_body("body", test::random_mass_properties(rng));
  b.add_joint(test::make_joint("float", JointType::free, "world", "body"));
  const Model model = b.build();
  EXPECT_EQ(base_parameters(model).rank(), 10);
}

// Y π = Y_I β at states the base parameters were not found from, on random trees of every joint
// type (round-off: 1e-12 of the largest torque).
TEST(BaseParameters, RegroupingKeepsTheTorquesAtFreshStates) {
  for (unsigned seed : {4u, 5u}) {
    const Model model = test::random_tree(7, seed);
    const BaseParameters base = base_parameters(model);
    ASSERT_GT(base.rank(), 0);
    EXPECT_LT(base.rank(), num_inertial_parameters(model));
    const VecX pi = inertial_parameters(model), beta = base.base_of(pi);
    InertialRegressor regressor(model);
    std::mt19937 rng(100 + seed);
    for (int trial = 0; trial < 5; ++trial) {
      const VecX q = test::random_configuration(model, rng);
      const MatX& Y = regressor.compute(q, test::random_vector(model.nv(), rng, 2.0),
                                        test::random_vector(model.nv(), rng, 3.0));
      MatX Y_I(Y.rows(), base.rank());
      for (int i = 0; i < base.rank(); ++i) Y_I.col(i) = Y.col(base.independent[i]);
      const VecX tau = Y * pi;
      EXPECT_LT((Y_I * beta - tau).cwiseAbs().maxCoeff(), 1e-12 * tau.cwiseAbs().maxCoeff());
    }
  }
}

TEST(BaseParameters, AreTheSameEveryCall) {
  const Model model = test::random_tree(5, 9);
  const BaseParameters a = base_parameters(model), b = base_parameters(model);
  EXPECT_EQ(a.independent, b.independent);
  EXPECT_EQ(a.regrouping, b.regrouping);
}

}  // namespace
}  // namespace momenta::identify
