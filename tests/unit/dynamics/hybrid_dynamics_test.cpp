// Hybrid dynamics: a pendulum hanging from a cart whose motion is prescribed.
#include "momenta/dynamics/hybrid_dynamics.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/model/signal.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

using model::JointType;

// Cart (mass M) with prescribed acceleration a along x; pendulum of point mass m hanging l below
// the pivot, x_c = x − l sin θ, z_c = −l cos θ. Then θ̈ = (a cos θ − g sin θ)/l and the force that
// drives the cart is F = (M + m) a − m l cos θ θ̈ + m l sin θ θ̇².
TEST(HybridDynamics, PendulumOnPrescribedCart) {
  const double M = 2.0, m = 0.5, l = 0.8, g = 9.81;
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_signal(model::Signal("cart_x", model::SineSignal{.amplitude = 0.2, .frequency = 1.0}));
  b.add_body("cart", inertia::MassProperties(M, Vec3::Zero(), 0.1 * Mat3::Identity()));
  b.add_body("bob", inertia::MassProperties(m, Vec3(0, 0, -l), Mat3::Zero()));
  auto rail = test::make_joint("rail", JointType::prismatic, "world", "cart", Vec3::UnitX());
  rail.prescribed_signals = {"cart_x"};
  b.add_joint(rail);
  b.add_joint(test::make_joint("pivot", JointType::revolute, "cart", "bob"));
  const Model model = b.build();
  ASSERT_TRUE(model.has_prescribed_joints());
  EXPECT_EQ(prescribed_joint_mask(model), (std::vector<char>{1, 0}));
  Data data(model);
  const double a = 1.7, theta = 0.6, w = -1.1;
  const VecX q = (VecX(2) << 0.1, theta).finished();
  const VecX v = (VecX(2) << 0.3, w).finished();
  const VecX vdot_in = (VecX(2) << a, 123.0).finished();   // entry 1 is ignored
  const VecX tau_in = (VecX(2) << 456.0, 0.0).finished();  // entry 0 is ignored
  hybrid_dynamics(model, data, q, v, vdot_in, tau_in);
  const double theta_dd = (a * std::cos(theta) - g * std::sin(theta)) / l;
  const double F =
      (M + m) * a - m * l * std::cos(theta) * theta_dd + m * l * std::sin(theta) * w * w;
  EXPECT_NEAR(data.vdot[0], a, 0.0);
  EXPECT_NEAR(data.vdot[1], theta_dd, 1e-13);
  EXPECT_NEAR(data.tau[0], F, 1e-12);
  EXPECT_EQ(data.tau[1], 0.0);
}

}  // namespace
}  // namespace momenta::dynamics
