// force_element_derivatives against high-order finite differences of the elements' generalized
// force Q = τ_elements + Σ J_bᵀ f_ext, on a tree with every joint type carrying every kind of
// force element.
#include "momenta/dynamics/force_element_derivatives.hpp"

#include <random>

#include <gtest/gtest.h>

#include "momenta/dynamics/force_elements.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tangent_differences.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics::force_element_derivatives_test {
namespace {

using model::JointType;

// Eight bodies on every joint type (random frames and inertias), joint damping everywhere, and
// every force element: springs between bodies and to the world, a two-body torsional spring, a
// joint spring and friction, a tendon, world and follower forces and torques, one scaled by a
// signal.
Model loaded_tree() {
  std::mt19937 rng(42);
  model::ModelBuilder builder;
  builder.set_gravity(Vec3(0, 0, -9.81));
  const std::vector<JointType> types = {
      JointType::revolute,    JointType::free,      JointType::prismatic, JointType::spherical,
      JointType::cylindrical, JointType::universal, JointType::planar,    JointType::revolute};
  for (int k = 0; k < static_cast<int>(types.size()); ++k) {
    const std::string name = fmt::format("b{}", k);
    builder.add_body(name, test::random_mass_properties(rng));
    model::Joint j;
    j.name = fmt::format("j{}", k);
    j.type = types[static_cast<std::size_t>(k)];
    j.parent = k == 0 ? "world" : fmt::format("b{}", k - 1 - (k % 3 == 2 ? 1 : 0));
    j.child = name;
    j.X_PJ = test::random_transform(rng, 0.3);
    j.X_CJ = test::random_transform(rng, 0.2);
    j.axis = test::random_unit(rng);
    const Vec3 a2 = test::random_unit(rng);
    j.axis2 = (a2 - a2.dot(j.axis) * j.axis).normalized();
    j.damping = 0.3;
    builder.add_joint(j);
  }
  builder.add_signal(model::Signal("push", model::ConstantSignal{1.0}));
  // Fields set by name: GCC 12 warns (falsely) of uninitialized strings in nested aggregates.
  const auto spring = [&](const char* a, const Vec3& pa, const char* b, const Vec3& pb, double k,
                          double c, double free_length) {
    model::LinearSpringDamper e;
    e.name = fmt::format("spring_{}_{}", a, b);
    e.a.body = a;
    e.a.p_BoP_B = pa;
    e.b.body = b;
    e.b.p_BoP_B = pb;
    e.stiffness = k;
    e.damping = c;
    e.free_length = free_length;
    builder.add_force_element(e);
  };
  spring("b2", Vec3(0.1, 0.0, 0.05), "b6", Vec3(-0.05, 0.1, 0.0), 40.0, 1.5, 0.2);
  spring("world", Vec3(0.3, 0.2, 1.0), "b4", Vec3(0.02, 0.03, 0.1), 25.0, 0.8, 0.5);
  model::TorsionalSpringDamper twist;
  twist.name = "t";
  twist.body_a = "b1";
  twist.body_b = "b5";
  twist.stiffness = 3.0;
  twist.damping = 0.4;
  builder.add_force_element(twist);
  model::TorsionalSpringDamper hinge_spring;
  hinge_spring.name = "h";
  hinge_spring.joint = "j7";
  hinge_spring.stiffness = 7.0;
  hinge_spring.damping = 0.2;
  hinge_spring.rest_angle = 0.3;
  builder.add_force_element(hinge_spring);
  model::JointFriction friction;
  friction.name = "friction";
  friction.joint = "j3";
  friction.viscous = 0.6;
  builder.add_force_element(friction);
  // A tendon over two hinges and a slide (j0, j7 revolute; j2 prismatic).
  builder.add_force_element(test::fixed_tendon(
      "cord", {{"j0", 0.8, -1}, {"j2", -1.7, -1}, {"j7", 0.4, -1}}, 0.1, 4.0, 0.3, 0.25));
  const auto force = [&](const char* name, const char* body, const Vec3& at, model::LoadFrame frame,
                         const Vec3& vector, const char* signal) {
    model::AppliedForce e;
    e.name = name;
    e.at.body = body;
    e.at.p_BoP_B = at;
    e.frame = frame;
    e.vector = vector;
    e.signal = signal;
    builder.add_force_element(e);
  };
  force("wind", "b3", Vec3(0.1, 0.0, 0.0), model::LoadFrame::world, Vec3(1.0, -2.0, 0.5), "");
  force("thrust", "b7", Vec3(0.0, 0.1, 0.0), model::LoadFrame::body, Vec3(0.0, 0.0, 3.0), "push");
  const auto torque = [&](const char* name, const char* body, model::LoadFrame frame,
                          const Vec3& vector) {
    model::AppliedTorque e;
    e.name = name;
    e.body = body;
    e.frame = frame;
    e.vector = vector;
    builder.add_force_element(e);
  };
  torque("motor", "b6", model::LoadFrame::body, Vec3(0.2, 0.0, -0.4));
  torque("gust", "b2", model::LoadFrame::world, Vec3(0.0, 0.7, 0.1));
  return builder.build();
}

// Q(q, v) = τ_elements + Σ J_bᵀ f_ext: the wrenches' share from two inverse dynamics at rest
// (gravity cancels between them).
VecX generalized_element_force(const Model& m, const VecX& q, const VecX& v,
                               std::span<const double> signals) {
  Data data(m);
  forward_kinematics(m, data, q, v);
  VecX tau;
  std::vector<Vec6> f_ext(m.num_bodies());
  force_element_forces(m, data, signals, q, v, tau, f_ext);
  const VecX zero = VecX::Zero(m.nv());
  const VecX plain = rnea(m, data, q, zero, zero);
  return tau + plain - rnea(m, data, q, zero, zero, f_ext);
}

TEST(ForceElementDerivatives, EveryElementOnEveryJointTypeMatchesDifferences) {
  const Model m = loaded_tree();
  const std::vector<double> signals = {1.7};
  for (unsigned seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE(fmt::format("seed {}", seed));
    std::mt19937 rng(seed);
    // Near the initial configuration, so the torsional spring's angle stays well below π.
    const VecX q = model::integrate(m, m.initial_q(), test::random_vector(m.nv(), rng, 0.5), 1.0);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    Data data(m);
    rnea_derivatives(m, data, q, v, VecX::Zero(m.nv()));
    force_element_derivatives(m, data, signals);

    const MatX dq_reference = test::tangent_jacobian(
        m, q, [&](const VecX& qq) { return generalized_element_force(m, qq, v, signals); });
    const double scale = std::max(1.0, dq_reference.cwiseAbs().maxCoeff());
    // 1e-10 relative, as for rnea_derivatives (tangent_differences.hpp: ~1e-12 expected).
    EXPECT_MATRIX_NEAR(data.dQ_dq, dq_reference, 1e-10 * scale);
    // Q is linear in v (dampers, friction), so one central difference is exact.
    const MatX dv_reference = test::quadratic_jacobian(
        v, [&](const VecX& vv) { return generalized_element_force(m, q, vv, signals); });
    EXPECT_MATRIX_NEAR(data.dQ_dv, dv_reference,
                       1e-12 * std::max(1.0, dv_reference.cwiseAbs().maxCoeff()));
  }
}

TEST(ForceElementDerivatives, ASpringAloneHasTheTextbookStiffness) {
  // A particle on a prismatic joint along x, held by a spring to the world point at x = 0 with
  // free length ℓ0: at x > 0, Q = −k (x − ℓ0), so ∂Q/∂x = −k; a damper c gives ∂Q/∂ẋ = −c.
  model::ModelBuilder builder;
  builder.set_gravity(Vec3::Zero());
  builder.add_body("slider", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity() * 0.01));
  model::Joint rail;
  rail.name = "rail";
  rail.type = JointType::prismatic;
  rail.parent = "world";
  rail.child = "slider";
  rail.axis = Vec3::UnitX();
  builder.add_joint(rail);
  model::LinearSpringDamper spring;
  spring.name = "spring";
  spring.a.body = "world";
  spring.b.body = "slider";
  spring.stiffness = 100.0;
  spring.damping = 2.0;
  spring.free_length = 0.25;
  builder.add_force_element(spring);
  const Model m = builder.build();
  Data data(m);
  const VecX q = VecX::Constant(1, 0.4), v = VecX::Constant(1, 0.3);
  rnea_derivatives(m, data, q, v, VecX::Zero(1));
  force_element_derivatives(m, data, {});
  EXPECT_TRUE(test::relatively_near(data.dQ_dq(0, 0), -100.0, 1e-15));
  EXPECT_TRUE(test::relatively_near(data.dQ_dv(0, 0), -2.0, 1e-15));
}

}  // namespace
}  // namespace momenta::dynamics::force_element_derivatives_test
