#include "momenta/analysis/equilibrium.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

using model::Joint;
using model::JointType;
using model::ModelBuilder;
using test::make_joint;

constexpr double kG = 9.81;

// Point mass m, l below a pivot about y; optional constant torque about y.
// (A small inertia about the centre of mass keeps a vertical axis non-singular.)
model::Model pendulum(double m, double l, double torque = 0.0, Vec3 axis = Vec3::UnitY()) {
  ModelBuilder b = test::pendulum_builder(m, l, 0.01, kG, axis);
  if (torque != 0.0) {
    b.add_signal(model::Signal("tau", model::ConstantSignal{torque}));
    b.add_force_element(
        model::AppliedTorque{"motor", "bob", model::LoadFrame::world, Vec3::UnitY(), "tau"});
  }
  return b.build();
}

TEST(Equilibrium, PendulumFindsTheBottomStableAndTheTopUnstable) {
  const double m = 1.2, l = 0.9;
  const model::Model model = pendulum(m, l);
  // From 0.3 rad Newton goes to the bottom.
  const Equilibrium bottom = find_equilibrium(model, VecX::Constant(1, 0.3));
  // Converged to tolerance 1e-10 of m g l: θ within 1e-10 rad (K = m g l there).
  EXPECT_NEAR(bottom.point.q[0], 0.0, 1e-10);
  EXPECT_TRUE(bottom.stable());
  EXPECT_EQ(bottom.stiffness_rank, 1);
  EXPECT_GT(bottom.iterations, 0);
  EXPECT_LE(std::abs(bottom.residual[0]), 1e-10 * bottom.force_scale);
  // From 3 rad it goes to the top, θ = π: unstable with λ = +√(m g l / I_pivot), I_pivot =
  // m l² + 0.01 (Richardson K, 1e-11).
  const Equilibrium top = find_equilibrium(model, VecX::Constant(1, 3.0));
  EXPECT_NEAR(top.point.q[0], std::numbers::pi, 1e-10);
  ASSERT_FALSE(top.stable());
  ASSERT_EQ(top.unstable_eigenvalues.size(), 1u);
  EXPECT_TRUE(test::relatively_near(top.unstable_eigenvalues[0].real(),
                                    std::sqrt(m * kG * l / (m * l * l + 0.01)), 1e-11));
  EXPECT_EQ(top.unstable_eigenvalues[0].imag(), 0.0);
}

TEST(Equilibrium, FallsFromWhereNewtonHasNoDirection) {
  // Held horizontal, ∂r/∂θ = m g l cos θ = 0 and ‖r‖ is at its largest: Newton has no step, and
  // ½‖r‖² no descent direction. The search falls the way the pendulum would (−M⁻¹ r) and then
  // converges to the bottom.
  const model::Model model = pendulum(1.0, 1.0);
  const Equilibrium e = find_equilibrium(model, VecX::Constant(1, std::numbers::pi / 2));
  EXPECT_NEAR(e.point.q[0], 0.0, 1e-10);
  EXPECT_TRUE(e.stable());
}

TEST(Equilibrium, ConstantTorqueTiltsThePendulum) {
  // m g l sin θ = τ.
  const double m = 2.0, l = 0.5, tau = 3.0;
  const model::Model model = pendulum(m, l, tau);
  const Equilibrium e = find_equilibrium(model, VecX::Zero(1));
  // r = m g l sin θ − τ converged to 1e-10 F with F ≈ m g l + τ: θ within ~3e-10 rad.
  EXPECT_NEAR(e.point.q[0], std::asin(tau / (m * kG * l)), 1e-9);
  EXPECT_TRUE(e.stable());
}

TEST(Equilibrium, SpringMassSagsUnderGravityFromAPrescribedSupport) {
  // A support at height s (prescribed by a constant signal) holds a mass m on a vertical spring
  // of stiffness k and free length L0: the mass rests at z = s − L0 − m g / k.
  const double m = 3.0, k = 500.0, L0 = 0.4, s = 1.5;
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -kG));
  b.add_signal(model::Signal("height", model::ConstantSignal{s}));
  b.add_body("support", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Zero()));
  b.add_body("mass", inertia::MassProperties(m, Vec3::Zero(), Mat3::Zero()));
  Joint support = make_joint("lift", JointType::prismatic, "world", "support", Vec3::UnitZ());
  support.prescribed_signals = {"height"};
  b.add_joint(support);
  b.add_joint(make_joint("drop", JointType::prismatic, "world", "mass", Vec3::UnitZ()));
  model::LinearSpringDamper spring;
  spring.name = "spring";
  spring.a.body = "support";
  spring.a.p_BoP_B = Vec3::Zero();
  spring.b.body = "mass";
  spring.b.p_BoP_B = Vec3::Zero();
  spring.stiffness = k;
  spring.free_length = L0;
  b.add_force_element(spring);
  const model::Model model = b.build();
  VecX guess(2);
  guess << 0.0, 0.5;  // the support's coordinate is replaced by its signal
  const Equilibrium e = find_equilibrium(model, guess);
  EXPECT_EQ(e.point.q[0], s);
  // A linear problem and K analytic (no constraints): one Newton step, exact to round-off
  // (differences of r had left ~1e-12 here).
  EXPECT_NEAR(e.point.q[1], s - L0 - m * kG / k, 4e-15);
  EXPECT_EQ(e.iterations, 1);
  EXPECT_TRUE(e.stable());
  // The prescribed coordinate is not a state.
  EXPECT_EQ(e.linear.system.state_count(), 2u);
}

TEST(Equilibrium, NoEquilibriumUnderAnUnbalancedPush) {
  // A cart with drag only and a constant push: it accelerates forever.
  ModelBuilder b;
  b.add_body("cart", inertia::MassProperties(1000.0, Vec3::Zero(), Mat3::Zero()));
  Joint road = make_joint("road", JointType::prismatic, "world", "cart", Vec3::UnitX());
  road.damping = 50.0;
  b.add_joint(road);
  b.add_signal(model::Signal("u", model::ConstantSignal{500.0}));
  model::AppliedForce engine;
  engine.name = "engine";
  engine.at.body = "cart";
  engine.vector = Vec3::UnitX();
  engine.signal = "u";
  b.add_force_element(engine);
  const model::Model model = b.build();
  try {
    find_equilibrium(model, VecX::Zero(1));
    ADD_FAILURE() << "an unbalanced push was declared in equilibrium";
  } catch (const NumericalError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("no equilibrium"), std::string::npos) << what;
    EXPECT_NE(what.find("'road.position' = -500"), std::string::npos) << what;
    EXPECT_NE(what.find("rank 0 of 1"), std::string::npos) << what;
  }
}

TEST(Equilibrium, NeutralDirectionIsAnEquilibriumOfLowRank) {
  // A pendulum turning about the vertical: gravity does no work, every angle balances.
  const model::Model model = pendulum(1.0, 1.0, 0.0, Vec3::UnitZ());
  const Equilibrium e = find_equilibrium(model, VecX::Constant(1, 0.7));
  EXPECT_EQ(e.iterations, 0);
  EXPECT_EQ(e.point.q[0], 0.7);
  EXPECT_EQ(e.stiffness_rank, 0);
  EXPECT_TRUE(e.stable());  // a double pole at 0, no positive real part
}

TEST(Equilibrium, RejectsBadArguments) {
  const model::Model model = pendulum(1.0, 1.0);
  EXPECT_THROW(find_equilibrium(model, VecX::Zero(2)), InvalidArgument);
  EquilibriumOptions o;
  o.tolerance = 0.0;
  EXPECT_THROW(find_equilibrium(model, VecX::Zero(1), o), InvalidArgument);
  // Runs out of iterations: one Newton step cannot reach the bottom from 0.5 rad.
  o = {};
  o.max_iterations = 1;
  try {
    find_equilibrium(model, VecX::Constant(1, 0.5), o);
    ADD_FAILURE() << "converged in one iteration";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("in 1 Newton iterations"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace momenta::analysis
