// Force elements against hand calculations at known poses, the springs' forces against the
// gradient of their potential energy, and Newton's third law between bodies.
#include "momenta/dynamics/force_elements.hpp"
#include "momenta/common/error.hpp"

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

using model::AppliedTorque;
using model::ForceElement;
using model::JointFriction;
using model::LinearSpringDamper;
using model::LoadFrame;
using model::TorsionalSpringDamper;
using test::applied_force;
using test::body_spring;
using test::joint_spring;

// Hand calculations below are a few operations on O(1) numbers: round-off ~1e-15.
constexpr double kTol = 1e-13;

// One body on a free joint from the world (mass 2, inertia diag(0.1, 0.2, 0.3)), no gravity,
// with the given elements and a signal "u" (constant 2.5).
Model free_body_with(const std::vector<ForceElement>& elements) {
  model::ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  b.add_signal(model::Signal("u", model::ConstantSignal{2.5}));
  b.add_body("box", inertia::MassProperties(2.0, Vec3::Zero(), Vec3(0.1, 0.2, 0.3).asDiagonal()));
  b.add_joint(test::make_joint("float", model::JointType::free, "world", "box"));
  for (const auto& e : elements) b.add_force_element(e);
  return b.build();
}

// The free body at p = (1, 2, 0.5) turned 90° about z (R_WB maps x to y), moving with
// ṗ = (0.1, 0, 0.3) and ω_B = (0, 0, 0.5).
struct FreeBodyState {
  VecX q = (VecX(7) << 1.0, 2.0, 0.5, std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)).finished();
  VecX v = (VecX(6) << 0.0, 0.0, 0.5, 0.1, 0.0, 0.3).finished();
};

struct Evaluated {
  VecX tau;
  std::vector<Vec6> f_ext;
};

Evaluated evaluate(const Model& m, Data& data, const VecX& q, const VecX& v,
                   std::vector<double> signal_values = {}) {
  if (signal_values.empty()) signal_values.assign(m.signals().size(), 1.0);
  forward_kinematics(m, data, q, v);
  Evaluated out{VecX(m.nv()), std::vector<Vec6>(m.num_bodies())};
  force_element_forces(m, data, signal_values, q, v, out.tau, out.f_ext);
  return out;
}

// A spring–damper from the world point A = (0, 0, 3) to the body point P = (0.2, 0, 0)_B. By
// hand: P = (1, 2, 0) + (0, 0.2, 0) + (0, 0, 0.5) = (1, 2.2, 0.5), d = P − A = (1, 2.2, −2.5),
// ℓ = √12.09. P moves at ṗ + R (ω × p_B) = (0.1, 0, 0.3) + R (0, 0.1, 0) = (0, 0, 0.3), so
// ℓ̇ = d·v_P / ℓ = −0.75 / ℓ. The force on P is −T d/ℓ with T = k (ℓ − ℓ0) + c ℓ̇.
TEST(ForceElements, LinearSpringFromWorldToBodyPoint) {
  const double k = 40.0, c = 3.0, l0 = 1.5;
  const Model m = free_body_with({LinearSpringDamper{.name = "s",
                                                     .a = {.body = "world", .p_BoP_B = {0, 0, 3}},
                                                     .b = {.body = "box", .p_BoP_B = {0.2, 0, 0}},
                                                     .stiffness = k,
                                                     .damping = c,
                                                     .free_length = l0}});
  Data data(m);
  const FreeBodyState s;
  const Evaluated e = evaluate(m, data, s.q, s.v);
  const double l = std::sqrt(12.09), ldot = -0.75 / l;
  const double T = k * (l - l0) + c * ldot;
  const Vec3 f_W = -T * Vec3(1, 2.2, -2.5) / l;
  // In B (R_WBᵀ maps x → −y, y → x) about Bo: p_BoP_B × f_B.
  const Vec3 f_B(f_W.y(), -f_W.x(), f_W.z());
  EXPECT_MATRIX_NEAR(e.f_ext[1].tail<3>(), f_B, kTol);
  EXPECT_MATRIX_NEAR(e.f_ext[1].head<3>(), Vec3(0.2, 0, 0).cross(f_B), kTol);
  EXPECT_TRUE(e.f_ext[0].isZero(0.0));  // nothing is written on the world
  EXPECT_TRUE(e.tau.isZero(0.0));
  // Power: the force on P times P's velocity, −T ℓ̇.
  EXPECT_NEAR(force_element_power(m, data, s.v, e.tau, e.f_ext), -T * ldot, kTol);
  // Potential energy ½ k (ℓ − ℓ0)².
  EXPECT_NEAR(spring_potential_energy(m, data, s.q), 0.5 * k * (l - l0) * (l - l0), kTol);
}

// Coincident points: the direction is undefined. A zero-free-length spring has k (ℓ − 0) u = k d
// = 0 there and its damper has no line to act along: no force, no NaN. Just off coincidence the
// zero-free-length spring is exactly −k d (no direction needed).
TEST(ForceElements, LinearSpringWithCoincidentPoints) {
  for (const double l0 : {0.0, 0.3}) {
    const Model m =
        free_body_with({LinearSpringDamper{.name = "s",
                                           .a = {.body = "world", .p_BoP_B = {1, 2, 0.5}},
                                           .b = {.body = "box"},
                                           .stiffness = 10.0,
                                           .damping = 2.0,
                                           .free_length = l0}});
    Data data(m);
    const FreeBodyState s;
    const Evaluated e = evaluate(m, data, s.q, s.v);
    EXPECT_TRUE(e.f_ext[1].allFinite()) << "l0 = " << l0;
    EXPECT_TRUE(e.f_ext[1].isZero(0.0)) << "l0 = " << l0;
    EXPECT_NEAR(spring_potential_energy(m, data, s.q), 0.5 * 10.0 * l0 * l0, kTol);
  }
  const Model m = free_body_with({LinearSpringDamper{.name = "s",
                                                     .a = {.body = "world", .p_BoP_B = {1, 2, 0.5}},
                                                     .b = {.body = "box"},
                                                     .stiffness = 10.0}});
  Data data(m);
  FreeBodyState s;
  const double x = std::ldexp(1.0, -30);  // ~1e-9 m, exact in 1 + x
  s.q[0] += x;  // d = (x, 0, 0) in W, so the force is (−10x, 0, 0) in W: (0, 10x, 0) in B
  const Evaluated e = evaluate(m, data, s.q, s.v);
  // Round-off: the rotation's ~1e-16 relative error on a ~1e-8 N force.
  EXPECT_MATRIX_NEAR(e.f_ext[1].tail<3>(), Vec3(0, 10 * x, 0), 1e-23);
}

// The same load (1, 0, 0) · u at p_BoP_B = (0, 0.3, 0): as a world load it stays along world x,
// which is −y in B; as a follower it is along the body's x. Scaled by the signal's value 2.5.
TEST(ForceElements, AppliedForceWorldVersusFollower) {
  for (const LoadFrame frame : {LoadFrame::world, LoadFrame::body}) {
    const Model m =
        free_body_with({applied_force("push", "box", Vec3(0, 0.3, 0), frame, Vec3(1, 0, 0), "u")});
    Data data(m);
    const FreeBodyState s;
    const Evaluated e = evaluate(m, data, s.q, s.v, {2.5});
    const Vec3 f_B = frame == LoadFrame::world ? Vec3(0, -2.5, 0) : Vec3(2.5, 0, 0);
    // n = (0, 0.3, 0) × f_B: zero for the world load (parallel), (0, 0, −0.75) for the follower.
    const Vec3 n_B = frame == LoadFrame::world ? Vec3::Zero() : Vec3(0, 0, -0.75);
    EXPECT_MATRIX_NEAR(e.f_ext[1].tail<3>(), f_B, kTol);
    EXPECT_MATRIX_NEAR(e.f_ext[1].head<3>(), n_B, kTol);
  }
}

// A torque (0, 2, 0) · 0.5 (the signal's value): world y is +x in B (R_WB is 90° about z).
TEST(ForceElements, AppliedTorqueWorldVersusBody) {
  for (const LoadFrame frame : {LoadFrame::world, LoadFrame::body}) {
    const Model m = free_body_with({AppliedTorque{
        .name = "twist", .body = "box", .frame = frame, .vector = {0, 2, 0}, .signal = "u"}});
    Data data(m);
    const FreeBodyState s;
    const Evaluated e = evaluate(m, data, s.q, s.v, {0.5});
    const Vec3 n_B = frame == LoadFrame::world ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    EXPECT_MATRIX_NEAR(e.f_ext[1].head<3>(), n_B, kTol);
    EXPECT_TRUE(e.f_ext[1].tail<3>().isZero(0.0));
  }
}

// A revolute joint with its own damping 0.1, a friction element 0.2 and a torsional spring
// k = 3, c = 0.5, rest 0.2; at q = 0.7, q̇ = −1.2 by hand: τ = −3 (0.5) − (0.5 + 0.1 + 0.2)(−1.2)
// = −0.54. Every dissipative term opposes the motion (positive here, v < 0).
TEST(ForceElements, JointSpringDampingAndFriction) {
  model::ModelBuilder b;
  b.add_body("bob", inertia::MassProperties(1.0, Vec3(0, 0, -1), 0.1 * Mat3::Identity()));
  auto joint = test::make_joint("pivot", model::JointType::revolute, "world", "bob");
  joint.damping = 0.1;
  b.add_joint(joint);
  b.add_force_element(JointFriction{.name = "f", .joint = "pivot", .viscous = 0.2});
  b.add_force_element(joint_spring("t", "pivot", 3.0, 0.5, 0.2));
  const Model m = b.build();
  Data data(m);
  const VecX q = VecX::Constant(1, 0.7), v = VecX::Constant(1, -1.2);
  const Evaluated e = evaluate(m, data, q, v);
  EXPECT_NEAR(e.tau[0], -0.54, kTol);
  EXPECT_NEAR(spring_potential_energy(m, data, q), 0.5 * 3.0 * 0.25, kTol);
  EXPECT_NEAR(force_element_power(m, data, v, e.tau, e.f_ext), -0.54 * -1.2, kTol);
  EXPECT_FALSE(force_elements_conservative(m));
  // At the rest angle only the dissipative terms remain: −0.8 v, opposing either direction.
  for (const double rate : {-1.2, 0.9}) {
    const Evaluated r = evaluate(m, data, VecX::Constant(1, 0.2), VecX::Constant(1, rate));
    EXPECT_NEAR(r.tau[0], -0.8 * rate, kTol);
  }
}

// Two bodies hanging 1 m below their joints: `first` a hinge from the world, `second` of `type`.
model::ModelBuilder two_bodies_on(const char* first, const char* second, model::JointType type) {
  model::ModelBuilder b;
  b.add_body("a", inertia::MassProperties(1.0, Vec3(0, 0, -1), 0.1 * Mat3::Identity()));
  b.add_body("b", inertia::MassProperties(1.0, Vec3(0, 0, -1), 0.1 * Mat3::Identity()));
  b.add_joint(test::make_joint(first, model::JointType::revolute, "world", "a"));
  b.add_joint(test::make_joint(second, type, "a", "b"));
  return b;
}

// A fixed tendon L = 0.1 + θa − 0.5 θb over two hinges (MuJoCo's fixed tendon), k = 3, c = 0.2,
// rest 0.4. By hand at θ = (0.7, −0.4), θ̇ = (1.5, 2): L = 1.0, L̇ = 0.5, T = 3 · 0.6 + 0.2 · 0.5 =
// 1.9, τ = −c T = (−1.9, 0.95); V = ½ 3 0.6² = 0.54; the power τ·θ̇ = −T L̇ = −0.95.
TEST(ForceElements, FixedTendonPullsEachJointByItsCoefficient) {
  model::ModelBuilder b = two_bodies_on("ja", "jb", model::JointType::revolute);
  b.add_force_element(
      test::fixed_tendon("cord", {{"ja", 1.0, -1}, {"jb", -0.5, -1}}, 0.1, 3.0, 0.2, 0.4));
  const Model m = b.build();
  Data data(m);
  const VecX q = (VecX(2) << 0.7, -0.4).finished(), v = (VecX(2) << 1.5, 2.0).finished();
  const auto& built = std::get<model::FixedTendon>(m.force_elements()[0]);
  EXPECT_NEAR(tendon_length(m, built, q), 1.0, kTol);
  EXPECT_NEAR(tendon_rate(m, built, v), 0.5, kTol);
  const Evaluated e = evaluate(m, data, q, v);
  EXPECT_MATRIX_NEAR(e.tau, (VecX(2) << -1.9, 0.95).finished(), kTol);
  for (const Vec6& w : e.f_ext) EXPECT_TRUE(w.isZero(0.0));
  EXPECT_NEAR(spring_potential_energy(m, data, q), 0.54, kTol);
  EXPECT_NEAR(force_element_power(m, data, v, e.tau, e.f_ext), -0.95, kTol);
  EXPECT_FALSE(force_elements_conservative(m));
}

// A tendon's joints are 1-dof, each named once, with a coefficient that is finite and not zero.
TEST(ForceElements, ATendonRefusesWhatIsNotALinearCombinationOfCoordinates) {
  const auto build = [](std::vector<model::TendonTerm> terms) {
    model::ModelBuilder b = two_bodies_on("ja", "jb", model::JointType::spherical);
    b.add_force_element(test::fixed_tendon("cord", std::move(terms), 0.0, 0.0, 0.0, 0.0));
    return b.build();
  };
  const auto message = [&](std::vector<model::TendonTerm> terms) {
    try {
      build(std::move(terms));
    } catch (const InvalidArgument& error) {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message({}).find("at least one joint"), std::string::npos);
  EXPECT_NE(message({{"jb", 1.0, -1}}).find("joint 'jb' is spherical with 3 degrees of freedom"),
            std::string::npos);
  EXPECT_NE(message({{"ja", 1.0, -1}, {"ja", 2.0, -1}}).find("joint 'ja' is listed twice"),
            std::string::npos);
  EXPECT_NE(message({{"ja", 0.0, -1}}).find("must be finite and not zero"), std::string::npos);
  EXPECT_NE(message({{"jx", 1.0, -1}}).find("unknown joint 'jx'"), std::string::npos);
}

// Two bodies: A on a revolute joint about z, B on a ball joint on A whose initial orientation is
// 0.4 rad about x — the spring's rest. At the ball joint's quaternion Rx(0.4) Ry(0.3) the rotation
// from rest is θ = (0, 0.3, 0) in B, so n_B = −k θ − c ω_rel_B, and A gets −R_AB n_B.
TEST(ForceElements, TwoBodyTorsionalSpringMeasuredFromInitialOrientation) {
  const double k = 7.0, c = 0.6;
  model::ModelBuilder b;
  b.add_body("a", inertia::MassProperties(1.0, Vec3(0.1, 0, 0), 0.1 * Mat3::Identity()));
  b.add_body("b", inertia::MassProperties(1.0, Vec3(0, 0.1, 0), 0.1 * Mat3::Identity()));
  b.add_joint(test::make_joint("hinge", model::JointType::revolute, "world", "a", Vec3::UnitZ()));
  auto ball = test::make_joint("ball", model::JointType::spherical, "a", "b", Vec3::UnitZ(),
                               Transform::translation(Vec3(0.5, 0, 0)));
  const Quat q_rest(Eigen::AngleAxisd(0.4, Vec3::UnitX()));
  ball.q0 = (VecX(4) << q_rest.w(), q_rest.x(), q_rest.y(), q_rest.z()).finished();
  b.add_joint(ball);
  b.add_force_element(body_spring("t", "a", "b", k, c));
  const Model m = b.build();
  const auto& spring = std::get<TorsionalSpringDamper>(m.force_elements()[0]);
  EXPECT_MATRIX_NEAR(spring.R_AB_rest, q_rest.toRotationMatrix(), kTol);

  Data data(m);
  const Quat q_ball = q_rest * Quat(Eigen::AngleAxisd(0.3, Vec3::UnitY()));
  VecX q(5), v(4);
  q << 0.9, q_ball.w(), q_ball.x(), q_ball.y(), q_ball.z();
  v << 0.8, 0.1, -0.2, 0.3;  // hinge rate; the ball's ω_AB_B
  const Evaluated e = evaluate(m, data, q, v);
  const Vec3 n_B = -k * Vec3(0, 0.3, 0) - c * Vec3(0.1, -0.2, 0.3);
  EXPECT_MATRIX_NEAR(e.f_ext[2].head<3>(), n_B, kTol);
  EXPECT_MATRIX_NEAR(e.f_ext[1].head<3>(), -(q_ball.toRotationMatrix() * n_B), kTol);
  EXPECT_TRUE(e.f_ext[1].tail<3>().isZero(0.0));
  EXPECT_TRUE(e.f_ext[2].tail<3>().isZero(0.0));
  EXPECT_NEAR(spring_potential_energy(m, data, q), 0.5 * k * 0.09, kTol);
  // Power: the moments on the relative angular velocity, n_B · ω_rel.
  EXPECT_NEAR(force_element_power(m, data, v, e.tau, e.f_ext), n_B.dot(Vec3(0.1, -0.2, 0.3)), kTol);
}

// On a 1-dof chain the two-body form about the joint's own axis equals the joint form: the same
// spring seen two ways gives the same generalized force (its Jᵀ n through rnea).
TEST(ForceElements, TwoBodyTorsionalSpringEqualsJointSpringOnAHinge) {
  const auto build = [](bool two_body) {
    model::ModelBuilder b;
    b.add_body("a", inertia::MassProperties(1.0, Vec3(0.1, 0, 0), 0.1 * Mat3::Identity()));
    b.add_body("b", inertia::MassProperties(1.0, Vec3(0.1, 0, 0), 0.1 * Mat3::Identity()));
    b.add_joint(test::make_joint("j0", model::JointType::revolute, "world", "a"));
    auto j1 = test::make_joint("j1", model::JointType::revolute, "a", "b", Vec3::UnitY(),
                               Transform::translation(Vec3(0.3, 0, 0)));
    j1.q0 = VecX::Constant(1, 0.25);
    b.add_joint(j1);
    if (two_body) {
      b.add_force_element(body_spring("t", "a", "b", 4.0, 0.7));
    } else {
      b.add_force_element(joint_spring("t", "j1", 4.0, 0.7, 0.25));
    }
    return b.build();
  };
  const Model joint_form = build(false), body_form = build(true);
  Data dj(joint_form), db(body_form);
  const VecX q = (VecX(2) << 0.3, -0.6).finished(), v = (VecX(2) << 0.4, 1.3).finished();
  const Evaluated ej = evaluate(joint_form, dj, q, v), eb = evaluate(body_form, db, q, v);
  // Generalized force of the body wrenches: rnea(q, 0, 0) − rnea(q, 0, 0, f_ext) = Jᵀ f_ext
  // (rnea returns data.tau, so the first is copied before the second overwrites it).
  const VecX zero = VecX::Zero(2);
  const VecX without = rnea(body_form, db, q, zero, zero);
  const VecX Jt_f = without - rnea(body_form, db, q, zero, zero, eb.f_ext);
  EXPECT_MATRIX_NEAR(Jt_f, ej.tau, 1e-13);
  EXPECT_NEAR(spring_potential_energy(body_form, db, q), spring_potential_energy(joint_form, dj, q),
              1e-14);
}

// Every spring element on a random tree (all joint types): the generalized force the springs
// exert, τ + Jᵀ f_ext, is −∂V/∂q — checked along random tangent directions by a central
// difference of the potential on the configuration manifold (q ⊕ εδ). Springs between bodies
// also obey Newton's third law: their wrenches on both ends cancel about the world origin.
TEST(ForceElements, SpringForcesAreTheGradientOfTheirPotential) {
  const auto base = test::random_tree(8, 5);
  model::ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  for (int i = 1; i < base.num_bodies(); ++i) b.add_body(base.body(i));
  for (auto j : base.joints()) b.add_joint(j);
  // Joints 0 and 2 are revolute and prismatic (random_tree's type cycle).
  b.add_force_element(joint_spring("tj", "j0", 2.0, 0.0, 0.3));
  b.add_force_element(joint_spring("tp", "j2", 5.0, 0.0, -0.1));
  b.add_force_element(
      test::fixed_tendon("cord", {{"j0", 0.6, -1}, {"j2", -2.0, -1}}, 0.1, 4.0, 0.0, 0.3));
  b.add_force_element(body_spring("tb", "b1", "b5", 3.0, 0.0));
  b.add_force_element(body_spring("tw", "world", "b3", 1.5, 0.0));
  b.add_force_element(LinearSpringDamper{.name = "lw",
                                         .a = {.body = "world", .p_BoP_B = {0.1, -0.2, 0.3}},
                                         .b = {.body = "b4", .p_BoP_B = {0.05, 0.1, 0}},
                                         .stiffness = 6.0,
                                         .free_length = 0.2});
  b.add_force_element(LinearSpringDamper{.name = "lb",
                                         .a = {.body = "b2", .p_BoP_B = {0.1, 0, 0}},
                                         .b = {.body = "b7", .p_BoP_B = {0, 0.2, 0.1}},
                                         .stiffness = 8.0,
                                         .free_length = 0.1});
  const Model m = b.build();
  ASSERT_TRUE(force_elements_conservative(m));
  Data data(m);
  std::mt19937 rng(3);
  const VecX q = test::random_configuration(m, rng);
  const VecX zero = VecX::Zero(m.nv());
  const Evaluated e = evaluate(m, data, q, zero);
  const VecX without = rnea(m, data, q, zero, zero);
  const VecX Q = e.tau + without - rnea(m, data, q, zero, zero, e.f_ext);
  // Central difference with ε = 1e-5: truncation ε² V'''/6 ~ 1e-10 for O(10) third derivatives,
  // round-off ε_mach V / ε ~ 1e-11; both far below the 1e-7 allowed.
  const double eps = 1e-5;
  for (int trial = 0; trial < 5; ++trial) {
    const VecX delta = test::random_vector(m.nv(), rng);
    const auto V_at = [&](double s) {
      const VecX qs = model::integrate(m, q, delta, s);
      forward_kinematics(m, data, qs);
      return spring_potential_energy(m, data, qs);
    };
    const double dV = (V_at(eps) - V_at(-eps)) / (2 * eps);
    EXPECT_NEAR(Q.dot(delta), -dV, 1e-7) << "trial " << trial;
  }
  // Newton's third law for the body-to-body springs alone, at a moving state (dampers on too).
  model::ModelBuilder b2;
  b2.set_gravity(Vec3::Zero());
  for (int i = 1; i < base.num_bodies(); ++i) b2.add_body(base.body(i));
  for (auto j : base.joints()) b2.add_joint(j);
  b2.add_force_element(body_spring("tb", "b1", "b5", 3.0, 0.4));
  b2.add_force_element(LinearSpringDamper{.name = "lb",
                                          .a = {.body = "b2", .p_BoP_B = {0.1, 0, 0}},
                                          .b = {.body = "b7", .p_BoP_B = {0, 0.2, 0.1}},
                                          .stiffness = 8.0,
                                          .damping = 0.9,
                                          .free_length = 0.1});
  const Model m2 = b2.build();
  Data d2(m2);
  const VecX v = test::random_vector(m2.nv(), rng);
  const Evaluated e2 = evaluate(m2, d2, q, v);
  Vec6 total = Vec6::Zero();
  for (int i = 1; i < m2.num_bodies(); ++i) total += d2.X_WB[i].act_force(e2.f_ext[i]);
  EXPECT_MATRIX_NEAR(total, Vec6::Zero(), 1e-13);
  EXPECT_GT(e2.f_ext[m2.body_index("b5")].head<3>().norm(), 0.1);  // the wrenches are not zero
}

TEST(ForceElements, RejectsWrongSizes) {
  const Model m = free_body_with({});
  Data data(m);
  const FreeBodyState s;
  forward_kinematics(m, data, s.q, s.v);
  VecX tau;
  std::vector<Vec6> f_ext(1);
  const std::vector<double> values{1.0};
  EXPECT_THROW(force_element_forces(m, data, values, s.q, s.v, tau, f_ext), InvalidArgument);
  f_ext.resize(2);
  EXPECT_THROW(force_element_forces(m, data, {}, s.q, s.v, tau, f_ext), InvalidArgument);
  force_element_forces(m, data, values, s.q, s.v, tau, f_ext);
  EXPECT_EQ(tau.size(), 6);
}

}  // namespace
}  // namespace momenta::dynamics
