// Joint reactions: a swinging pendulum's pin force and the bearing loads of an unbalanced shaft
// spun at a prescribed constant rate (Beer & Johnston, §18.3: a rotor on a rotating shaft).
#include "momenta/dynamics/reactions.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta/model/signal.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

using model::JointType;

// The pin pulls the bob along the rod with T = m (g cos θ + l θ̇²) and pushes it sideways with
// whatever the tangential acceleration needs: F = m a_cm − m g in W. With I_c = 0 the moment
// about the pin is zero except along nothing: a point mass needs no moment.
TEST(Reactions, PendulumPinForce) {
  const double m = 1.5, l = 0.9, g = 9.81, theta = 0.7, w = 2.3;
  const Model model = test::pendulum(m, l, 0.0, g);
  Data data(model);
  const VecX q = VecX::Constant(1, theta), v = VecX::Constant(1, w);
  const VecX vdot = aba(model, data, q, v, VecX::Zero(1));
  EXPECT_NEAR(vdot[0], -g / l * std::sin(theta), 1e-13);
  joint_reactions(model, data, q, v, vdot);
  const JointReaction r = joint_reaction(model, data, 0, ReactionFrame::world);
  // Centre of mass at l (−sin θ, 0, −cos θ); acceleration = tangential + centripetal.
  const Vec3 u(-std::sin(theta), 0, -std::cos(theta));
  const Vec3 u_theta(-std::cos(theta), 0, std::sin(theta));
  const Vec3 a_cm = l * vdot[0] * u_theta - l * w * w * u;
  EXPECT_MATRIX_NEAR(r.force, m * a_cm - m * Vec3(0, 0, -g), 1e-13);
  EXPECT_NEAR(-r.force.dot(u), m * (g * std::cos(theta) + l * w * w), 1e-13);  // tension
  EXPECT_MATRIX_NEAR(r.moment, Vec3::Zero(), 1e-13);
  // The same reaction in the child (body) frame, rotated.
  const JointReaction rc = joint_reaction(model, data, 0, ReactionFrame::child);
  EXPECT_MATRIX_NEAR(data.X_WB[1].R * rc.force, r.force, 1e-14);
}

// A rotor on a vertical shaft (revolute about z), spun at a constant ω by a prescribed signal.
// Newton–Euler about the fixed joint origin O, body frame: the bearing moment is
// M = ω × (I_O ω) − c × m g_B and the force F = m ω × (ω × c) − m g_B. With
// I_O = [[Ixx, 0, −0.02], [0, Iyy, 0.01], [−0.02, 0.01, Izz]] and ω = 10 ẑ:
// ω × (I_O ω) = ω² (−I_yz, I_xz, 0) = 100 (−0.01, −0.02, 0) = (−1, −2, 0) N·m, where I_xz, I_yz
// are the tensor entries (minus the products of inertia). The shaft needs no torque.
TEST(Reactions, UnbalancedRotorBearingLoads) {
  const double m = 4.0, g = 9.81, omega = 10.0;
  const Vec3 c(0.05, 0.0, 0.2);
  Mat3 I_O;
  I_O << 0.3, 0.0, -0.02, 0.0, 0.4, 0.01, -0.02, 0.01, 0.2;
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_signal(model::Signal("spin", model::RampSignal{.start = 0.0, .slope = omega}));
  b.add_body("rotor", inertia::MassProperties::from_inertia_about(m, c, I_O, Vec3::Zero()));
  auto shaft = test::make_joint("shaft", JointType::revolute, "world", "rotor", Vec3::UnitZ());
  shaft.prescribed_signals = {"spin"};
  b.add_joint(shaft);
  const Model model = b.build();
  Data data(model);
  const double t = 0.37;  // any instant: the loads turn with the rotor
  const auto s = model.signals()[0].sample(t);
  const VecX q = VecX::Constant(1, s.value), v = VecX::Constant(1, s.rate),
             vdot = VecX::Constant(1, s.acceleration);
  hybrid_dynamics(model, data, q, v, vdot, VecX::Zero(1));
  EXPECT_NEAR(data.tau[0], 0.0, 1e-13);
  joint_reactions(model, data, q, v, data.vdot);
  const JointReaction r = joint_reaction(model, data, 0, ReactionFrame::child);
  const Vec3 g_B(0, 0, -g);  // vertical axis: gravity is the same in the body frame
  const Vec3 expected_moment = Vec3(-1.0, -2.0, 0.0) - c.cross(m * g_B);
  const Vec3 expected_force = m * Vec3(-omega * omega * c.x(), 0, 0) - m * g_B;
  EXPECT_MATRIX_NEAR(r.moment, expected_moment, 1e-12);
  EXPECT_MATRIX_NEAR(r.force, expected_force, 1e-12);
  // In the world frame the same load, rotated by the shaft angle.
  const JointReaction rw = joint_reaction(model, data, 0, ReactionFrame::world);
  const Mat3 R = Eigen::AngleAxisd(s.value, Vec3::UnitZ()).toRotationMatrix();
  EXPECT_MATRIX_NEAR(rw.moment, R * expected_moment, 1e-12);
  EXPECT_MATRIX_NEAR(rw.force, R * expected_force, 1e-12);
}

// The reaction is reported about the child-side joint frame origin, in any frame.
TEST(Reactions, OffsetJointFrame) {
  const double m = 1.0, g = 9.81;
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_body("link", inertia::MassProperties(m, Vec3(0.5, 0, 0), Mat3::Zero()));
  auto j = test::make_joint("hinge", JointType::revolute, "world", "link", Vec3::UnitZ());
  j.X_CJ = Transform::translation(Vec3(0.2, 0, 0));  // the hinge 0.2 m along the link
  b.add_joint(j);
  const Model model = b.build();
  Data data(model);
  const VecX zero = VecX::Zero(1);
  // Held at rest (τ balances gravity about the vertical axis: zero), the hinge carries the
  // weight at its centre: moment about it = (p_cm − p_J) × (−m g) reversed: r × F needed.
  joint_reactions(model, data, zero, zero, zero);
  const JointReaction r = joint_reaction(model, data, 0, ReactionFrame::joint);
  EXPECT_MATRIX_NEAR(r.force, Vec3(0, 0, m * g), 1e-14);
  // Moment about the hinge that balances the weight at 0.3 m along x: −(0.3 x̂ × −m g ẑ).
  EXPECT_MATRIX_NEAR(r.moment, -Vec3(0.3, 0, 0).cross(Vec3(0, 0, -m * g)), 1e-14);
}

// Every reporting frame with turned placements: a bracket A fixed to the world at a turned pose,
// a link B hinged to it with both joint placements turned and offset, held at rest. Statics of
// B alone: the joint carries its weight, f_W = −m_B g, with moment n_W = −(p_cm − p_J') × m_B g
// about the joint centre J'. The poses are composed here from the placements the test gives.
TEST(Reactions, EveryFrameWithTurnedPlacements) {
  const double m_B = 1.5, g = 9.81;
  const Vec3 c_B(0.3, -0.1, 0.2);
  const Transform X_WA(rotation_from_axis_angle(Vec3(1, 1, 0), 0.5), Vec3(0.1, 0.2, 0.3));
  const Transform X_AJ(rotation_from_axis_angle(Vec3(0, 1, 2), -0.8), Vec3(0.4, 0, 0));
  const Transform X_BJ(rotation_from_axis_angle(Vec3(3, 0, 1), 1.1), Vec3(-0.1, 0.05, 0));
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_body("bracket", inertia::MassProperties(2.0, Vec3(0.1, 0, 0), 0.01 * Mat3::Identity()));
  b.add_body("link", inertia::MassProperties(m_B, c_B, Vec3(0.02, 0.03, 0.04).asDiagonal()));
  b.add_joint(test::make_joint("mount", JointType::fixed, "world", "bracket", Vec3::UnitZ(), X_WA));
  auto hinge =
      test::make_joint("hinge", JointType::revolute, "bracket", "link", Vec3::UnitZ(), X_AJ);
  hinge.X_CJ = X_BJ;
  b.add_joint(hinge);
  const Model model = b.build();
  Data data(model);
  const VecX zero = VecX::Zero(1);
  joint_reactions(model, data, zero, zero, zero);

  // At q = 0, J' coincides with J: X_WB = X_WA X_AJ X_BJ⁻¹.
  const Mat3 R_WJ = X_WA.R * X_AJ.R;
  const Vec3 p_J_W = X_WA.p + X_WA.R * X_AJ.p;
  const Mat3 R_WB = R_WJ * X_BJ.R.transpose();
  const Vec3 p_Bo_W = p_J_W - R_WB * X_BJ.p;
  const Vec3 p_cm_W = p_Bo_W + R_WB * c_B;
  const Vec3 weight(0, 0, -m_B * g);
  const Vec3 f_W = -weight;
  const Vec3 n_W = -(p_cm_W - p_J_W).cross(weight);
  const auto expect = [&](ReactionFrame frame, const Mat3& R_WF) {
    const JointReaction r = joint_reaction(model, data, 1, frame);
    EXPECT_MATRIX_NEAR(r.force, R_WF.transpose() * f_W, 1e-13);
    EXPECT_MATRIX_NEAR(r.moment, R_WF.transpose() * n_W, 1e-13);
  };
  expect(ReactionFrame::world, Mat3::Identity());
  expect(ReactionFrame::parent, X_WA.R);
  expect(ReactionFrame::joint, R_WJ);
  expect(ReactionFrame::child, R_WB);
}

}  // namespace
}  // namespace momenta::dynamics
