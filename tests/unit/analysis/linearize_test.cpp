#include "momenta/analysis/linearize.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/analysis/transfer_function.hpp"
#include "momenta/common/error.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tangent_differences.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

using model::Joint;
using model::JointType;
using model::ModelBuilder;
using test::make_joint;

constexpr double kG = 9.81;

// A point mass m at distance l below a pivot turning about y, with a torque input "tau" about y.
model::Model pendulum(double m, double l) {
  ModelBuilder b = test::pendulum_builder(m, l, 0.0, kG);
  b.add_signal(model::Signal("tau", model::ConstantSignal{0.0}));
  b.add_force_element(
      model::AppliedTorque{"motor", "bob", model::LoadFrame::world, Vec3::UnitY(), "tau"});
  return b.build();
}

// Something with every kind of term: a revolute, universal and prismatic chain with offsets, a
// spring-damper to the world, joint damping, a follower force scaled by a signal and a
// two-body torsional spring-damper.
model::Model mixed_chain() {
  ModelBuilder b;
  b.set_gravity(Vec3(0.3, -0.2, -kG));
  Mat3 I1 = Vec3(0.02, 0.03, 0.025).asDiagonal();
  b.add_body("link1", inertia::MassProperties(1.3, Vec3(0.1, 0.02, -0.3), I1));
  b.add_body("link2", inertia::MassProperties(0.8, Vec3(0.0, 0.05, -0.2), Mat3(0.6 * I1)));
  b.add_body("slider", inertia::MassProperties(0.5, Vec3(0.03, 0, 0), Mat3(0.3 * I1)));
  Joint j1 = make_joint("shoulder", JointType::revolute, "world", "link1", Vec3(0, 1, 0));
  j1.damping = 0.15;
  b.add_joint(j1);
  Joint j2 = make_joint("elbow", JointType::universal, "link1", "link2", Vec3::UnitX());
  j2.axis2 = Vec3::UnitY();
  j2.X_PJ = Transform::translation(Vec3(0.05, 0, -0.6));
  b.add_joint(j2);
  Joint j3 = make_joint("rail", JointType::prismatic, "link2", "slider", Vec3(0, 0.6, -0.8));
  j3.X_PJ = Transform::translation(Vec3(0, 0.02, -0.4));
  b.add_joint(j3);
  model::LinearSpringDamper spring;
  spring.name = "spring";
  spring.a.body = "world";
  spring.a.p_BoP_B = Vec3(0.4, 0.1, -0.2);
  spring.b.body = "slider";
  spring.b.p_BoP_B = Vec3(0.01, 0.02, 0);
  spring.stiffness = 40.0;
  spring.damping = 0.7;
  spring.free_length = 0.3;
  b.add_force_element(spring);
  model::TorsionalSpringDamper twist;
  twist.name = "twist";
  twist.body_a = "link1";
  twist.body_b = "link2";
  twist.stiffness = 3.0;
  twist.damping = 0.2;
  b.add_force_element(twist);
  b.add_signal(model::Signal("push", model::ConstantSignal{2.0}));
  model::AppliedForce thruster;
  thruster.name = "thruster";
  thruster.at.body = "slider";
  thruster.at.p_BoP_B = Vec3(0, 0.05, 0);
  thruster.frame = model::LoadFrame::body;
  thruster.vector = Vec3(1, 0.5, 0);
  thruster.signal = "push";
  b.add_force_element(thruster);
  return b.build();
}

// A free body on a spring to the world, and a heavy top on a ball joint, under gravity.
model::Model free_and_ball() {
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -kG));
  b.add_body("capsule", inertia::MassProperties(2.0, Vec3(0.05, -0.02, 0.1),
                                                Mat3(Vec3(0.04, 0.05, 0.03).asDiagonal())));
  b.add_body("top", inertia::MassProperties(1.5, Vec3(0.0, 0.0, 0.3),
                                            Mat3(Vec3(0.02, 0.02, 0.01).asDiagonal())));
  b.add_joint(make_joint("float", JointType::free, "world", "capsule"));
  b.add_joint(make_joint("ball", JointType::spherical, "world", "top"));
  model::LinearSpringDamper spring;
  spring.name = "tether";
  spring.a.body = "world";
  spring.a.p_BoP_B = Vec3(0, 0, 1);
  spring.b.body = "capsule";
  spring.b.p_BoP_B = Vec3(0.1, 0.0, 0.05);
  spring.stiffness = 80.0;
  spring.damping = 0.5;
  spring.free_length = 0.4;
  b.add_force_element(spring);
  return b.build();
}

// A state away from any equilibrium, moving.
OperatingPoint moving_point(const model::Model& m, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const auto random = [&] { return uniform(rng); };
  VecX tangent(m.nv()), v(m.nv());
  for (int i = 0; i < m.nv(); ++i) {
    tangent[i] = 0.6 * random();
    v[i] = 1.5 * random();
  }
  return {0.0, model::integrate(m, model::neutral(m), tangent, 1.0), v};
}

// Plain central differences of the nonlinear vector field ẋ = [δ̇; a(q₀ ⊕ δ, v)] at δ = 0:
// the reference A (no Richardson, no inverse dynamics).
MatX finite_difference_A(const model::Model& m, const OperatingPoint& p, double h) {
  system::MultibodySystem system(m);
  const int nv = m.nv();
  MatX A(2 * nv, 2 * nv);
  VecX rate_plus(nv), rate_minus(nv), a_plus(nv), a_minus(nv);
  for (int i = 0; i < 2 * nv; ++i) {
    VecX delta = VecX::Zero(nv), v = p.v;
    const auto field = [&](double s, VecX& rate, VecX& a) {
      VecX d = delta, w = v;
      if (i < nv)
        d[i] += s;
      else
        w[i - nv] += s;
      model::local_coordinate_rate(m, d, w, rate);
      system.acceleration(p.t, model::integrate(m, p.q, d, 1.0), w, a);
    };
    field(h, rate_plus, a_plus);
    field(-h, rate_minus, a_minus);
    A.col(i) << (rate_plus - rate_minus) / (2 * h), (a_plus - a_minus) / (2 * h);
  }
  return A;
}

TEST(Linearize, PendulumAtAnAngleMatchesClosedForm) {
  // θ̈ = −(g/l) sin θ + τ/(m l²): about θ₀, A = [0 1; −(g/l) cos θ₀ 0], B = [0; 1/(m l²)].
  const double m = 1.7, l = 0.8, theta0 = 1.0;
  const model::Model model = pendulum(m, l);
  const LinearModel lin = linearize(model, {0.0, VecX::Constant(1, theta0), VecX::Zero(1)});
  const MatX& A = lin.system.A();
  EXPECT_EQ(A(0, 0), 0.0);
  EXPECT_EQ(A(0, 1), 1.0);
  // Analytic (rnea_derivatives): round-off of a few operations, 4 ε relative. (The finite
  // differences linearize used before reached 1e-11 here.)
  EXPECT_TRUE(test::relatively_near(A(1, 0), -(kG / l) * std::cos(theta0), 4 * test::kEps));
  // Velocity: exact (quadratic in v); no velocity dependence here at all.
  EXPECT_EQ(A(1, 1), 0.0);
  // B from a load linear in its signal: exact to round-off of M⁻¹.
  EXPECT_TRUE(test::relatively_near(lin.system.B()(1, 0), 1.0 / (m * l * l), 1e-15));
  EXPECT_EQ(lin.system.B()(0, 0), 0.0);
  EXPECT_TRUE(test::relatively_near(lin.mass(0, 0), m * l * l, 1e-15));
  // At rest away from equilibrium: the acceleration is gravity's.
  EXPECT_TRUE(test::relatively_near(lin.acceleration[0], -(kG / l) * std::sin(theta0), 1e-14));
  EXPECT_EQ(lin.system.state_names(),
            (std::vector<std::string>{"pivot.angle", "pivot.angle_rate"}));
  EXPECT_EQ(lin.system.input_names(), std::vector<std::string>{"tau"});
  EXPECT_EQ(lin.system.output_names(), std::vector<std::string>{"pivot.angle"});
  EXPECT_FALSE(lin.states_shifted);
}

TEST(Linearize, MatchesFiniteDifferencesOfTheNonlinearAcceleration) {
  const model::Model model = mixed_chain();
  for (unsigned seed : {1u, 2u, 3u}) {
    const OperatingPoint p = moving_point(model, seed);
    const LinearModel lin = linearize(model, p);
    // Plain central differences at h = 1e-6: truncation h²/6·|f'''| ~ 1e-12·|f'''|, round-off
    // ε|f|/h ~ 2e-10·|f|; 1e-7 of the largest entry bounds both with room.
    const MatX reference = finite_difference_A(model, p, 1e-6);
    const double scale = reference.cwiseAbs().maxCoeff();
    EXPECT_MATRIX_NEAR(lin.system.A(), reference, 1e-7 * scale) << "seed " << seed;
  }
}

TEST(Linearize, AnalyticDerivativesMatchHighOrderDifferences) {
  // linearize differentiates the equations of motion analytically (rnea_derivatives,
  // force_element_derivatives): ∂v̇/∂δq against twice-extrapolated central differences of the
  // simulator's own accelerations (tangent_differences.hpp, h = 0.01: ~1e-12 of the scale), on
  // the mixed chain (every force element kind) and on a free body and a ball joint (quaternions).
  for (const model::Model& model : {mixed_chain(), free_and_ball()}) {
    system::MultibodySystem system(model);
    for (unsigned seed : {1u, 2u, 3u}) {
      const OperatingPoint p = moving_point(model, seed);
      const LinearModel lin = linearize(model, p);
      const int nv = model.nv();
      VecX a(nv);
      const MatX reference = test::tangent_jacobian(
          model, p.q,
          [&](const VecX& q) {
            system.acceleration(p.t, q, p.v, a);
            return VecX(a);
          },
          0.01);
      const double scale = std::max(1.0, reference.cwiseAbs().maxCoeff());
      EXPECT_MATRIX_NEAR(lin.system.A().bottomLeftCorner(nv, nv), reference, 1e-10 * scale)
          << "nv " << nv << ", seed " << seed;
    }
  }
}

TEST(Linearize, TheDifferencesCheckAgreesWithTheAnalyticDerivatives) {
  // LinearizationOptions::Derivatives::differences: the equations' rows by Richardson
  // differences (error ~1e-12 of the scale, linearize.hpp), the same A to 1e-10.
  for (const model::Model& model : {mixed_chain(), free_and_ball()}) {
    for (unsigned seed : {1u, 2u}) {
      const OperatingPoint p = moving_point(model, seed);
      LinearizationOptions options;
      const MatX analytic = linearize(model, p, options).system.A();
      options.derivatives = LinearizationOptions::Derivatives::differences;
      const MatX differences = linearize(model, p, options).system.A();
      const double scale = std::max(1.0, analytic.cwiseAbs().maxCoeff());
      EXPECT_MATRIX_NEAR(differences, analytic, 1e-10 * scale) << "seed " << seed;
    }
  }
}

TEST(Linearize, VelocityDerivativeIsExactBecauseDynamicsAreQuadraticInV) {
  // v̇ = M(q)⁻¹ (τ(q, v) − C(q, v) v − g(q)) is a quadratic polynomial in v at fixed q (Coriolis
  // and centrifugal terms quadratic, dampers linear). Proof on the mixed chain:
  const model::Model model = mixed_chain();
  const OperatingPoint p = moving_point(model, 7);
  system::MultibodySystem system(model);
  const int nv = model.nv();
  VecX a(nv);
  const auto acceleration = [&](int i, double s) {
    VecX v = p.v;
    v[i] += s;
    system.acceleration(0.0, p.q, v, a);
    return VecX(a);
  };
  const LinearModel lin = linearize(model, p);
  for (int i = 0; i < nv; ++i) {
    // (1) Its third difference vanishes for a large step (h = 1 rad/s or m/s): a cubic term of
    // size c would leave 6c. Round-off of |a| ~ 10, 1e-12 absolute.
    const VecX third =
        acceleration(i, 2) - 3 * acceleration(i, 1) + 3 * acceleration(i, 0) - acceleration(i, -1);
    EXPECT_LT(third.cwiseAbs().maxCoeff(), 1e-12) << "coordinate " << i;
    // (2) So central differences do not depend on the step: h = 1e-2, 1 and 10 agree to
    // round-off (ε|a|/h ≤ 2e-13 at h = 1e-2) with each other and with A's velocity block.
    const VecX lin_col = lin.system.A().col(nv + i).tail(nv);
    for (double h : {1e-2, 1.0, 10.0}) {
      const VecX d = (acceleration(i, h) - acceleration(i, -h)) / (2 * h);
      EXPECT_MATRIX_NEAR(d, lin_col, 1e-12) << "coordinate " << i << ", h = " << h;
    }
  }
}

TEST(Linearize, InputColumnMatchesFiniteDifferencesOfTheSignal) {
  const model::Model model = mixed_chain();
  const OperatingPoint p = moving_point(model, 4);
  const LinearModel lin = linearize(model, p);
  ASSERT_EQ(lin.system.input_names(), std::vector<std::string>{"push"});
  system::MultibodySystem system(model);
  VecX a_plus(model.nv()), a_minus(model.nv());
  const double h = 0.5;  // loads are linear in the signal: any step, round-off only
  const std::vector<double> zero{0.0};
  std::vector<double> offset{h};
  system.set_signal_offsets(offset, zero, zero);
  system.acceleration(0.0, p.q, p.v, a_plus);
  offset[0] = -h;
  system.set_signal_offsets(offset, zero, zero);
  system.acceleration(0.0, p.q, p.v, a_minus);
  const VecX reference = (a_plus - a_minus) / (2 * h);
  EXPECT_TRUE(lin.system.B().topRows(model.nv()).isZero(0.0));
  EXPECT_MATRIX_NEAR(lin.system.B().bottomRows(model.nv()), reference, 1e-13);
}

TEST(Linearize, FreeAndBallJointsLinearizeInTangentCoordinates) {
  // 7 + 4 configuration coordinates, 6 + 3 tangent ones: 18 states, checked against central
  // differences of the nonlinear field in the same tangent coordinates (q = q₀ ⊕ δ), including
  // the kinematic block ∂δ̇/∂δ = −½[ω₀]× of a turning body.
  const model::Model model = free_and_ball();
  const OperatingPoint p = moving_point(model, 11);
  const LinearModel lin = linearize(model, p);
  ASSERT_EQ(lin.system.state_count(), 18u);
  EXPECT_EQ(lin.system.state_names()[0], "float.rx");
  EXPECT_EQ(lin.system.state_names()[3], "float.x");
  EXPECT_EQ(lin.system.state_names()[6], "ball.rx");
  EXPECT_EQ(lin.system.state_names()[9], "float.wx");
  const MatX reference = finite_difference_A(model, p, 1e-6);
  const double scale = reference.cwiseAbs().maxCoeff();
  EXPECT_MATRIX_NEAR(lin.system.A(), reference, 1e-7 * scale);
  // The rotation block of the ball joint is −½[ω₀]×, exactly (the remainder of J_r⁻¹ is even).
  const Vec3 w = p.v.segment<3>(6);
  Mat3 expected;
  expected << 0, w.z(), -w.y(), -w.z(), 0, w.x(), w.y(), -w.x(), 0;
  EXPECT_MATRIX_NEAR(lin.system.A().block(6, 6, 3, 3), 0.5 * expected, 1e-15);
}

TEST(Linearize, SphericalPendulumAboutTheBottom) {
  // A body hanging from a ball joint, centre of mass l below it: tilts about x and y oscillate at
  // ω² = m g l / I_pivot with I_pivot = I_cm + m l²; the spin about the vertical is a rigid-body
  // mode (ω = 0).
  const double m = 2.0, l = 0.5, Ixx = 0.03, Iyy = 0.05, Izz = 0.02;
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -kG));
  b.add_body("bob",
             inertia::MassProperties(m, Vec3(0, 0, -l), Mat3(Vec3(Ixx, Iyy, Izz).asDiagonal())));
  b.add_joint(make_joint("ball", JointType::spherical, "world", "bob"));
  const model::Model model = b.build();
  const LinearModel lin = linearize(model, initial_operating_point(model));
  const NormalModes nm = undamped_modes(lin);
  ASSERT_EQ(nm.modes.size(), 3u);
  EXPECT_EQ(nm.modes[0].natural_frequency, 0.0);
  // Ascending: the larger pivot inertia (about y) first. The stiffness is analytic, so the
  // eigensolver's round-off is all that is left (1e-14).
  EXPECT_TRUE(
      test::relatively_near(nm.modes[1].squared_frequency, m * kG * l / (Iyy + m * l * l), 1e-14));
  EXPECT_TRUE(
      test::relatively_near(nm.modes[2].squared_frequency, m * kG * l / (Ixx + m * l * l), 1e-14));
}

// The quarter car written two ways: (1) wheel, body and road on their own prismatic joints to
// the world, tyre and suspension as spring-dampers; (2) the wheel riding on the road body (its
// coordinate relative to the road, the tyre a spring on that joint), so the road's rate and
// acceleration enter the wheel's equation through the mass matrix.
model::Model quarter_car(bool wheel_on_road) {
  const double m1 = 20, m2 = 375, ks = 130000, kw = 1e6, bs = 9800;
  ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  b.add_signal(model::Signal("road", model::ConstantSignal{0.0}));
  b.add_body("road_surface", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Zero()));
  b.add_body("wheel", inertia::MassProperties(m1, Vec3::Zero(), Mat3::Zero()));
  b.add_body("body", inertia::MassProperties(m2, Vec3::Zero(), Mat3::Zero()));
  Joint road = make_joint("road", JointType::prismatic, "world", "road_surface", Vec3::UnitZ());
  road.prescribed_signals = {"road"};
  b.add_joint(road);
  Joint wheel = make_joint("wheel_travel", JointType::prismatic,
                           wheel_on_road ? "road_surface" : "world", "wheel", Vec3::UnitZ());
  wheel.X_PJ = Transform::translation(Vec3(0, 0, 0.3));
  b.add_joint(wheel);
  Joint body = make_joint("body_travel", JointType::prismatic, "world", "body", Vec3::UnitZ());
  body.X_PJ = Transform::translation(Vec3(0, 0, 0.8));
  b.add_joint(body);
  if (wheel_on_road) {
    model::TorsionalSpringDamper tyre;
    tyre.name = "tyre";
    tyre.joint = "wheel_travel";
    tyre.stiffness = kw;
    b.add_force_element(tyre);
  } else {
    model::LinearSpringDamper tyre;
    tyre.name = "tyre";
    tyre.a.body = "road_surface";
    tyre.a.p_BoP_B = Vec3::Zero();
    tyre.b.body = "wheel";
    tyre.b.p_BoP_B = Vec3::Zero();
    tyre.stiffness = kw;
    tyre.free_length = 0.3;
    b.add_force_element(tyre);
  }
  model::LinearSpringDamper suspension;
  suspension.name = "suspension";
  suspension.a.body = "wheel";
  suspension.a.p_BoP_B = Vec3::Zero();
  suspension.b.body = "body";
  suspension.b.p_BoP_B = Vec3::Zero();
  suspension.stiffness = ks;
  suspension.damping = bs;
  suspension.free_length = 0.5;
  b.add_force_element(suspension);
  return b.build();
}

TEST(Linearize, PrescribedMotionFoldsIntoOneInputWhateverTheLayout) {
  const model::Model sibling = quarter_car(false);
  const model::Model serial = quarter_car(true);
  LinearizationOptions options;
  options.inputs = {"road.position"};  // the prescribed coordinate stands for its signal
  options.outputs = {"body_travel.position"};
  const LinearModel a = linearize(sibling, initial_operating_point(sibling), options);
  const LinearModel b = linearize(serial, initial_operating_point(serial), options);
  EXPECT_EQ(a.system.input_names(), std::vector<std::string>{"road.position"});
  // (1) The tyre is a spring on separate joints: only the road's position enters, no shift.
  EXPECT_FALSE(a.states_shifted);
  EXPECT_TRUE(a.input_rate.isZero(0.0));
  EXPECT_TRUE(a.input_acceleration.isZero(0.0));
  // (2) The wheel rides on the road: its relative acceleration feels −r̈, the states shift.
  EXPECT_TRUE(b.states_shifted);
  const auto wheel_rate =
      static_cast<Eigen::Index>(b.system.state_index("wheel_travel.position_rate"));
  EXPECT_TRUE(test::relatively_near(b.input_acceleration(wheel_rate, 0), -1.0, 1e-15));
  // Same physics, so the same transfer function road → body at every s (the folded state space
  // against the factored C(sI − A)⁻¹(B₀ + B₁ s + B₂ s²) of the raw columns, and across layouts).
  for (const Complex s : {Complex(0, 1), Complex(0, 40), Complex(-3, 200), Complex(0, 1e4)}) {
    const Complex ga = evaluate(a.system, 0, 0, s);
    const Complex gb = evaluate(b.system, 0, 0, s);
    const MatX& A = b.system.A();
    const Eigen::MatrixXcd sI_A =
        s * Eigen::MatrixXcd::Identity(A.rows(), A.cols()) - A.cast<Complex>();
    const Eigen::VectorXcd rhs = b.input_value.col(0).cast<Complex>() +
                                 s * b.input_rate.col(0).cast<Complex>() +
                                 s * s * b.input_acceleration.col(0).cast<Complex>();
    const Complex raw =
        (b.system.C().cast<Complex>() * sI_A.lu().solve(rhs))(0) + b.feedthrough_value(0, 0);
    // LU solves of a 4×4 system whose entries span 1e0..1e5: 1e-10 relative.
    EXPECT_LT(std::abs(gb - raw), 1e-10 * std::abs(raw)) << s;
    EXPECT_LT(std::abs(ga - gb), 1e-10 * std::abs(ga)) << s;
  }
  // An output carried by the prescribed joint feels ṙ directly: improper, refused by name.
  options.outputs = {"wheel_travel.position_rate"};
  try {
    linearize(serial, initial_operating_point(serial), options);
    ADD_FAILURE() << "an improper pair was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("wheel_travel.position_rate"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("improper"), std::string::npos);
  }
  // The wheel's absolute velocity is proper: D₁ = 1 cancels C E₂ = −1.
  options.outputs = {"wheel_speed"};
  options.output_specs = {
      {"wheel_speed", model::OutputQuantity::body_velocity, "wheel", Vec3::Zero(), 2}};
  EXPECT_NO_THROW(linearize(serial, initial_operating_point(serial), options));
}

// A link hinged (about y) at the end of an arm whose angle φ about y a signal sets, gravity −ẑ.
// With J = I_c + m c² about the hinge, the link's equation at rest (φ̇ = φ̈ = 0) is
// J θ̈ = m g c cos(φ + θ), so ∂θ̈/∂φ = ∂θ̈/∂θ = −m g c sin(φ + θ) / J: the input's value column
// of B and the stiffness, both analytic (∂τ/∂δq's column of the arm's coordinate).
TEST(Linearize, ASetCoordinatesInputColumnIsTheClosedFormToRoundOff) {
  const double m = 2.0, c = 0.3, Ic = 0.05, L1 = 0.5, phi = 0.4, theta = 0.3;
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -kG));
  b.add_signal(model::Signal("arm_angle", model::ConstantSignal{phi}));
  b.add_body("arm", inertia::MassProperties(1.0, Vec3(0.25, 0, 0), Mat3::Identity() * 0.01));
  b.add_body("link", inertia::MassProperties(m, Vec3(c, 0, 0),
                                             Vec3(0.01, Ic, Ic).asDiagonal().toDenseMatrix()));
  Joint arm = make_joint("arm", JointType::revolute, "world", "arm", Vec3::UnitY());
  arm.prescribed_signals = {"arm_angle"};
  b.add_joint(arm);
  Joint hinge = make_joint("hinge", JointType::revolute, "arm", "link", Vec3::UnitY());
  hinge.X_PJ = Transform::translation(Vec3(L1, 0, 0));
  b.add_joint(hinge);
  const model::Model model = b.build();
  LinearizationOptions options;
  options.inputs = {"arm.angle"};
  const LinearModel lin =
      linearize(model, {0.0, Eigen::Vector2d(phi, theta), VecX::Zero(2)}, options);
  const double J = Ic + m * c * c;
  const double expected = -m * kG * c * std::sin(phi + theta) / J;
  const auto rate = static_cast<Eigen::Index>(lin.system.state_index("hinge.angle_rate"));
  // Differences of the signal's value had left 2e-13 relative here.
  EXPECT_TRUE(test::relatively_near(lin.input_value(rate, 0), expected, 1e-14))
      << lin.input_value(rate, 0) << " against " << expected;
  EXPECT_TRUE(test::relatively_near(lin.system.A()(rate, 0), expected, 1e-14));
}

TEST(Linearize, OutputsFromModelQuantitiesAndCoordinates) {
  // The bob's position x = −l sin θ, z = −l cos θ; velocity ẋ = −l cos θ θ̇.
  const double m = 1.0, l = 0.7, theta0 = 0.4, w0 = 0.9;
  const model::Model model = pendulum(m, l);
  LinearizationOptions options;
  options.output_specs = {
      {"bob", model::OutputQuantity::body_position, "bob", Vec3(0, 0, -l), -1},
      {"bob_v", model::OutputQuantity::body_velocity, "bob", Vec3(0, 0, -l), 0}};
  options.outputs = {"bob.x", "bob.z", "bob_v", "pivot.angle_rate"};
  const LinearModel lin =
      linearize(model, {0.0, VecX::Constant(1, theta0), VecX::Constant(1, w0)}, options);
  const MatX& C = lin.system.C();
  // Richardson accuracy on positions (1e-11), exact on velocities (round-off).
  EXPECT_TRUE(test::relatively_near(C(0, 0), -l * std::cos(theta0), 1e-11));
  EXPECT_TRUE(test::relatively_near(C(1, 0), l * std::sin(theta0), 1e-11));
  EXPECT_TRUE(test::relatively_near(C(2, 0), l * std::sin(theta0) * w0, 1e-11));
  EXPECT_TRUE(test::relatively_near(C(2, 1), -l * std::cos(theta0), 1e-14));
  EXPECT_EQ(C(3, 0), 0.0);
  EXPECT_EQ(C(3, 1), 1.0);
  EXPECT_TRUE(test::relatively_near(lin.output_values[0], -l * std::sin(theta0), 1e-15));
  EXPECT_EQ(lin.output_values[3], w0);
  EXPECT_TRUE(lin.system.D().isZero(0.0));
}

TEST(Linearize, ErrorsNameTheCulprit) {
  const model::Model model = pendulum(1.0, 1.0);
  const OperatingPoint p = initial_operating_point(model);
  const auto message = [&](LinearizationOptions o, OperatingPoint point) -> std::string {
    try {
      linearize(model, point, o);
    } catch (const InvalidArgument& e) {
      return e.what();
    }
    return "no throw";
  };
  LinearizationOptions o;
  o.inputs = {"taux"};
  EXPECT_NE(message(o, p).find("did you mean 'tau'"), std::string::npos) << message(o, p);
  o = {};
  o.outputs = {"pivot.angel"};
  EXPECT_NE(message(o, p).find("did you mean 'pivot.angle'"), std::string::npos) << message(o, p);
  o = {};
  o.outputs = {"pivot.angle", "pivot.angle"};
  EXPECT_NE(message(o, p).find("named twice"), std::string::npos);
  OperatingPoint bad = p;
  bad.q = VecX::Zero(2);
  EXPECT_NE(message({}, bad).find("operating point"), std::string::npos) << message({}, bad);
  // A signal nothing reads.
  ModelBuilder b;
  b.add_body("bob", inertia::MassProperties(1.0, Vec3(0, 0, -1), Mat3::Zero()));
  b.add_joint(make_joint("pivot", JointType::revolute, "world", "bob"));
  b.add_signal(model::Signal("idle", model::ConstantSignal{0.0}));
  const model::Model idle = b.build();
  LinearizationOptions io;
  io.inputs = {"idle"};
  EXPECT_THROW(linearize(idle, initial_operating_point(idle), io), InvalidArgument);
  // By default it is left out.
  EXPECT_EQ(linearize(idle, initial_operating_point(idle)).system.input_count(), 0u);
  // Nothing free: a shaft turned by a prescribed signal has no state.
  ModelBuilder shaft;
  shaft.add_body("shaft", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity()));
  model::Joint bearing = make_joint("bearing", JointType::revolute, "world", "shaft");
  bearing.prescribed_signals = {"angle"};
  shaft.add_joint(bearing);
  shaft.add_signal(model::Signal("angle", model::RampSignal{.slope = 10.0}));
  const model::Model driven = shaft.build();
  try {
    linearize(driven, initial_operating_point(driven));
    ADD_FAILURE() << "a model without a free joint was linearized";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("no degree of freedom"), std::string::npos) << e.what();
  }
}

TEST(Linearize, CharacteristicLengthAndStateNames) {
  const model::Model model = mixed_chain();
  // Largest of the offsets: the elbow at |(0.05, 0, −0.6)|.
  EXPECT_DOUBLE_EQ(characteristic_length(model), Vec3(0.05, 0, -0.6).norm());
  const std::vector<std::string> names = linear_state_names(model);
  ASSERT_EQ(names.size(), 8u);
  EXPECT_EQ(names[1], "elbow.angle1");
  EXPECT_EQ(names[4], "shoulder.angle_rate");
}

TEST(Linearize, UndampedModesRefuseAnAsymmetricStiffness) {
  // A follower force makes ∂r/∂q non-symmetric: no undamped normal modes.
  const model::Model model = mixed_chain();
  const LinearModel lin = linearize(model, moving_point(model, 5));
  EXPECT_THROW(undamped_modes(lin), InvalidArgument);
}

}  // namespace
}  // namespace momenta::analysis
