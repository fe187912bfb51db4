// OutputSet: column names, and every quantity's value against a hand computation on a model simple
// enough to solve by hand (a pendulum, a prescribed lift, a spring to the world).

#include "momenta/system/output_set.hpp"

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::system {

using model::OutputQuantity;
using model::OutputSpec;
namespace {

using model::Joint;
using model::JointType;
using model::ModelBuilder;
using test::make_joint;
using Q = OutputQuantity;

// Every value here is a few products of O(1) numbers: round-off is a few ulps, 1e-12 allows for
// the kinematics' rotation products with margin and still catches any wrong term.
constexpr double kTol = 1e-12;

OutputSpec spec(std::string name, OutputQuantity quantity, std::string target,
                Vec3 point = Vec3::Zero(), int component = -1) {
  OutputSpec s;
  s.name = std::move(name);
  s.quantity = quantity;
  s.target = std::move(target);
  s.point = point;
  s.component = component;
  return s;
}

// A point mass m on a rigid massless rod of length L, hinged at the world origin about y, θ = 0
// hanging down (−z). The body frame is at the pivot, the mass at (0, 0, −L) in it.
model::Model pendulum(double m, double L, double g) { return test::pendulum(m, L, 0.0, g); }

TEST(OutputSet, ColumnNamesFollowTheQuantityAndComponent) {
  const model::Model m = pendulum(1.0, 1.0, 9.81);
  const OutputSet set(
      m, {spec("tip", Q::body_position, "bob"),
          spec("tip_z", Q::body_position, "bob", Vec3::Zero(), 2),
          spec("angle", Q::joint_position, "pivot"), spec("w", Q::body_angular_velocity, "bob"),
          spec("pin", Q::reaction_force, "pivot")});
  const std::vector<std::string> expected = {"tip.x", "tip.y", "tip.z", "tip_z", "angle", "w.x",
                                             "w.y",   "w.z",   "pin.x", "pin.y", "pin.z"};
  EXPECT_EQ(set.column_names(), expected);
  EXPECT_EQ(set.size(), expected.size());
  EXPECT_TRUE(set.needs_reactions());
  EXPECT_FALSE(OutputSet(m, {spec("tip", Q::body_position, "bob")}).needs_reactions());
}

TEST(OutputSet, MultiCoordinateJointGetsOneColumnPerCoordinate) {
  ModelBuilder b;
  b.add_body("ball", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity()));
  b.add_joint(make_joint("socket", JointType::spherical, "world", "ball", Vec3::UnitZ()));
  const model::Model m = b.build();
  const OutputSet set(
      m, {spec("quat", Q::joint_position, "socket"), spec("rate", Q::joint_velocity, "socket"),
          spec("qw", Q::joint_position, "socket", Vec3::Zero(), 0)});
  const std::vector<std::string> expected = {"quat.0", "quat.1", "quat.2", "quat.3",
                                             "rate.0", "rate.1", "rate.2", "qw"};
  EXPECT_EQ(set.column_names(), expected);
}

// Body point kinematics on the swinging pendulum: p = L (−sin θ, 0, −cos θ) (R_y(θ) applied to
// (0, 0, −L)), v = dp/dt, a = d²p/dt² with θ̈ = −(g/L) sin θ, ω = (0, θ̇, 0).
TEST(OutputSet, PendulumPointMotionMatchesHandComputation) {
  const double m = 2.0, L = 0.75, g = 9.81;
  const model::Model model = pendulum(m, L, g);
  MultibodySystem system(model);
  const OutputSet set(
      model, {spec("p", Q::body_position, "bob", Vec3(0, 0, -L)),
              spec("v", Q::body_velocity, "bob", Vec3(0, 0, -L)),
              spec("a", Q::body_acceleration, "bob", Vec3(0, 0, -L)),
              spec("w", Q::body_angular_velocity, "bob"), spec("theta", Q::joint_position, "pivot"),
              spec("rate", Q::joint_velocity, "pivot"), spec("torque", Q::joint_effort, "pivot"),
              spec("alpha", Q::body_angular_acceleration, "bob")});
  const double theta = 0.7, rate = -1.3;
  VecX q(1), v(1);
  q << theta;
  v << rate;
  std::vector<double> y(set.size());
  set.evaluate(system, 0.0, q, v, y);

  const double s = std::sin(theta), c = std::cos(theta);
  const double acc = -(g / L) * s;
  const Vec3 p(-L * s, 0, -L * c);
  const Vec3 vel(-L * c * rate, 0, L * s * rate);
  const Vec3 a(-L * c * acc + L * s * rate * rate, 0, L * s * acc + L * c * rate * rate);
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(y[k], p[k], kTol) << k;
    EXPECT_NEAR(y[3 + k], vel[k], kTol) << k;
    EXPECT_NEAR(y[6 + k], a[k], kTol) << k;
  }
  EXPECT_NEAR(y[9], 0.0, kTol);
  EXPECT_NEAR(y[10], rate, kTol);
  EXPECT_NEAR(y[11], 0.0, kTol);
  EXPECT_EQ(y[12], theta);
  EXPECT_EQ(y[13], rate);
  EXPECT_EQ(y[14], 0.0);          // no force element acts on the hinge
  EXPECT_NEAR(y[15], 0.0, kTol);  // α = θ̈ ŷ about the hinge
  EXPECT_NEAR(y[16], acc, kTol);
  EXPECT_NEAR(y[17], 0.0, kTol);
}

// A body of mass m lifted along z by a prescribed sine z(t) = A sin(2π f t): the joint carries
// F = m (a − g) = m (a_z + 9.81) ẑ, its effort is F_z, and, with the centre of mass r = (0.2, 0, 0)
// from the joint origin and no rotation, its moment about J'o is r × F (moment balance about the
// centre of mass). The signal output is the sine itself.
TEST(OutputSet, PrescribedLiftReactionIsMassTimesGPlusA) {
  const double m = 3.0, A = 0.1, f = 2.0, g = 9.81;
  const Vec3 r(0.2, 0.0, 0.0);
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_signal(model::Signal("lift", model::SineSignal{A, f, 0.0, 0.0, 0.0}));
  b.add_body("carriage", inertia::MassProperties(m, r, Mat3::Identity() * 0.01));
  Joint j = make_joint("slide", JointType::prismatic, "world", "carriage", Vec3::UnitZ());
  j.prescribed_signals = {"lift"};
  b.add_joint(j);
  const model::Model model = b.build();
  MultibodySystem system(model);
  const OutputSet set(
      model, {spec("F", Q::reaction_force, "slide"), spec("M", Q::reaction_moment, "slide"),
              spec("effort", Q::joint_effort, "slide"), spec("u", Q::signal, "lift"),
              spec("z", Q::joint_position, "slide"), spec("zdot", Q::joint_velocity, "slide")});
  const double t = 0.37;
  const double w = 2 * M_PI * f;
  const double z = A * std::sin(w * t), zdot = A * w * std::cos(w * t),
               zddot = -A * w * w * std::sin(w * t);
  // The state's prescribed coordinates are deliberately wrong: outputs use the signal's values.
  VecX q(1), v(1);
  q << 5.0;
  v << -7.0;
  std::vector<double> y(set.size());
  set.evaluate(system, t, q, v, y);

  const Vec3 F(0, 0, m * (zddot + g));
  const Vec3 M = r.cross(F);
  // Scale m g ≈ 30 N: a few ulps of it.
  for (int k = 0; k < 3; ++k) {
    EXPECT_NEAR(y[k], F[k], 1e-12 * m * g) << k;
    EXPECT_NEAR(y[3 + k], M[k], 1e-12 * m * g) << k;
  }
  EXPECT_NEAR(y[6], F.z(), 1e-12 * m * g);
  EXPECT_NEAR(y[7], z, kTol);
  EXPECT_NEAR(y[8], z, kTol);
  EXPECT_NEAR(y[9], zdot, kTol);
}

// A spring from the world point a = (−0.5, 0.3, 0) to the point (0.1, 0, 0) of a body sliding
// along x: d = (x + 0.6, −0.3, 0), ℓ = |d|, ℓ̇ = (x + 0.6) ẋ / ℓ, T = k (ℓ − ℓ0) + c ℓ̇.
TEST(OutputSet, SpringLengthAndTensionMatchHandComputation) {
  const double k = 250.0, c = 3.5, l0 = 0.4;
  ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  b.add_body("slider", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity() * 0.01));
  b.add_joint(make_joint("rail", JointType::prismatic, "world", "slider", Vec3::UnitX()));
  model::LinearSpringDamper spring;
  spring.name = "spring";
  spring.a = {"world", Vec3(-0.5, 0.3, 0.0)};
  spring.b = {"slider", Vec3(0.1, 0.0, 0.0)};
  spring.stiffness = k;
  spring.damping = c;
  spring.free_length = l0;
  b.add_force_element(spring);
  const model::Model model = b.build();
  MultibodySystem system(model);
  const OutputSet set(model, {spec("len", Q::spring_length, "spring"),
                              spec("tension", Q::spring_tension, "spring")});
  const double x = 0.25, xdot = -0.8;
  VecX q(1), v(1);
  q << x;
  v << xdot;
  std::vector<double> y(set.size());
  set.evaluate(system, 0.0, q, v, y);
  const double length = std::hypot(x + 0.6, 0.3);
  const double rate = (x + 0.6) * xdot / length;
  EXPECT_NEAR(y[0], length, kTol);
  EXPECT_NEAR(y[1], k * (length - l0) + c * rate, 1e-12 * k);
}

// Each bad output names itself and what is wrong, with a suggestion for a misspelt target.
TEST(OutputSet, BadOutputsAreRejectedWithTheirName) {
  ModelBuilder b;
  b.add_body("bob", inertia::MassProperties(1.0, Vec3(0, 0, -1), Mat3::Zero()));
  b.add_body("plate", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity()));
  b.add_joint(make_joint("pivot", JointType::revolute, "world", "bob"));
  b.add_joint(make_joint("weld", JointType::fixed, "bob", "plate", Vec3::UnitZ()));
  model::JointFriction friction;
  friction.name = "friction";
  friction.joint = "pivot";
  friction.viscous = 0.1;
  b.add_force_element(friction);
  const model::Model m = b.build();

  const auto expect_error = [&](const OutputSpec& s, const std::vector<std::string>& pieces) {
    SCOPED_TRACE(s.name);
    try {
      OutputSet(m, {s});
      ADD_FAILURE() << "no exception";
    } catch (const InvalidArgument& e) {
      const std::string what = e.what();
      for (const std::string& piece : pieces)
        EXPECT_NE(what.find(piece), std::string::npos) << what;
    }
  };
  expect_error(spec("angle", Q::joint_position, "pivt"),
               {"output 'angle'", "unknown joint 'pivt'", "did you mean 'pivot'"});
  expect_error(spec("tip", Q::body_position, "bobb"), {"unknown body 'bobb'", "'bob'"});
  expect_error(spec("u", Q::signal, "drive"), {"output 'u'", "unknown signal 'drive'"});
  expect_error(spec("len", Q::spring_length, "friction"),
               {"output 'len'", "linear spring-damper", "'friction'"});
  expect_error(spec("tip", Q::body_position, "bob", Vec3::Zero(), 3),
               {"output 'tip'", "component 3", "3 values"});
  expect_error(spec("a", Q::joint_position, "pivot", Vec3::Zero(), 1), {"component 1", "1 value"});
  expect_error(spec("w", Q::joint_position, "weld"), {"'weld' is fixed", "no coordinates"});
  expect_error(spec("", Q::joint_position, "pivot"), {"name is empty"});
  expect_error(spec("a", Q::joint_position, "pivot", Vec3(1, 0, 0)),
               {"point", "only to body quantities"});
  // Two outputs producing the same column.
  try {
    OutputSet(m, {spec("tip", Q::body_position, "bob"), spec("tip.x", Q::joint_position, "pivot")});
    ADD_FAILURE() << "no exception";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("'tip.x' is already taken"), std::string::npos)
        << e.what();
  }
}

TEST(OutputSet, EvaluateChecksTheSpanSize) {
  const model::Model m = pendulum(1.0, 1.0, 9.81);
  MultibodySystem system(m);
  const OutputSet set(m, {spec("tip", Q::body_position, "bob")});
  std::vector<double> y(2);
  EXPECT_THROW(set.evaluate(system, 0.0, VecX::Zero(1), VecX::Zero(1), y), InvalidArgument);
}

}  // namespace
}  // namespace momenta::system
