// Rotating-frame kinematics (dynamics/relative_kinematics.hpp), body momentum and kinetic energy
// split (dynamics/momentum.hpp), prescribed ball and free joints (model/prescribed_motion.hpp) and
// body outputs seen from a body's frame (system/output_set.hpp), against closed forms and finite
// differences of the motion itself.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/dynamics/energy.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/relative_kinematics.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/math/rotation.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta/system/output_set.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

using model::JointType;
using model::ModelBuilder;
using model::OutputQuantity;
using model::SineSignal;
using test::make_joint;
constexpr double kPi = std::numbers::pi;

// Every closed-form value below is a few products of O(1) numbers: 1e-12 is round-off with
// margin and catches any wrong term.
constexpr double kTol = 1e-12;

// The motion at time t of a model whose joints are all prescribed: the state from the signals,
// then the system's evaluation (kinematics with accelerations in data).
struct Instant {
  explicit Instant(const model::Model& m) : model(m), system(m), q(m.nq()), v(m.nv()) {}
  const dynamics::Data& at(double t) {
    q = model.initial_q();
    v = model.initial_v();
    system.apply_prescribed_motion(t, q, v);
    system.evaluate(t, q, v);
    return system.data();
  }
  const model::Model& model;
  system::MultibodySystem system;
  VecX q, v;
};

// A turntable turning about the world z axis by θ(t) = A sin(ω t) and a bead on a radial slot
// (prismatic along the turntable's x) at x(t) = x0 + B sin(ω2 t), both prescribed; the bead is
// a point at the slot's origin.
model::Model turntable_and_bead(double A, double w, double x0, double B, double w2) {
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -9.81));
  b.add_signal(model::Signal("turn", SineSignal{A, w / (2 * kPi), 0.0, 0.0, 0.0}));
  b.add_signal(model::Signal("slide", SineSignal{B, w2 / (2 * kPi), 0.0, x0, 0.0}));
  b.add_body("turntable", inertia::MassProperties(2.0, Vec3::Zero(), Mat3::Identity()));
  b.add_body("bead", inertia::MassProperties(0.1, Vec3::Zero(), 1e-4 * Mat3::Identity()));
  model::Joint spin = make_joint("spin", JointType::revolute, "world", "turntable", Vec3::UnitZ());
  spin.prescribed_signals = {"turn"};
  model::Joint slot = make_joint("slot", JointType::prismatic, "turntable", "bead", Vec3::UnitX());
  slot.prescribed_signals = {"slide"};
  b.add_joint(spin);
  b.add_joint(slot);
  return b.build();
}

// Beer & Johnston §15.10: in the turntable's frame r = (x, 0, 0), v_rel = (ẋ, 0, 0),
// a_rel = (ẍ, 0, 0), Ω = θ̇ ẑ, and the terms are Coriolis 2 θ̇ ẋ ŷ, centripetal −θ̇² x x̂,
// Euler θ̈ x ŷ.
TEST(RotatingFrame, BeadOnATurntableHasTheTextbookTerms) {
  const double A = 0.8, w = 2.5, x0 = 0.3, B = 0.1, w2 = 4.0;
  const model::Model m = turntable_and_bead(A, w, x0, B, w2);
  Instant instant(m);
  for (const double t : {0.0, 0.37, 1.9}) {
    const dynamics::Data& data = instant.at(t);
    const auto k = dynamics::relative_kinematics(m, data, *m.find_body("bead"), Vec3::Zero(),
                                                 *m.find_body("turntable"));
    const double th_d = A * w * std::cos(w * t), th_dd = -A * w * w * std::sin(w * t);
    const double x = x0 + B * std::sin(w2 * t), x_d = B * w2 * std::cos(w2 * t),
                 x_dd = -B * w2 * w2 * std::sin(w2 * t);
    EXPECT_MATRIX_NEAR(k.p_FoP_F, Vec3(x, 0, 0), kTol);
    EXPECT_MATRIX_NEAR(k.w_WF_F, Vec3(0, 0, th_d), kTol);
    EXPECT_MATRIX_NEAR(k.alpha_WF_F, Vec3(0, 0, th_dd), kTol);
    EXPECT_MATRIX_NEAR(k.v_relative, Vec3(x_d, 0, 0), kTol);
    EXPECT_MATRIX_NEAR(k.v_transport(), Vec3(0, th_d * x, 0), kTol);
    EXPECT_MATRIX_NEAR(k.a_relative, Vec3(x_dd, 0, 0), kTol);
    EXPECT_MATRIX_NEAR(k.a_coriolis, Vec3(0, 2 * th_d * x_d, 0), kTol);
    EXPECT_MATRIX_NEAR(k.a_centripetal, Vec3(-th_d * th_d * x, 0, 0), kTol);
    EXPECT_MATRIX_NEAR(k.a_euler, Vec3(0, th_dd * x, 0), kTol);
    // Polar acceleration in the turntable's axes: (ẍ − x θ̇², x θ̈ + 2 ẋ θ̇, 0).
    EXPECT_MATRIX_NEAR(k.a_WP_F, Vec3(x_dd - x * th_d * th_d, x * th_dd + 2 * x_d * th_d, 0), kTol);
  }
}

// A shaft turning about z carries a disk turning about the shaft's x axis (both prescribed
// sines); a point off the disk's centre seen from the shaft's frame. The relative velocity and
// acceleration are the first and second differences of the point's components in the shaft's
// frame, the absolute ones those of its world position (central differences, h = 1e-4:
// truncation h² |p⁽⁴⁾| / 12 ≈ 1e-8 on the acceleration, round-off 4 ε / h² ≈ 1e-8).
TEST(RotatingFrame, TermsSumToTheFiniteDifferencesOfThePointsMotion) {
  ModelBuilder b;
  b.add_signal(model::Signal("yaw", SineSignal{1.1, 0.3, 0.2, 0.0, 0.0}));
  b.add_signal(model::Signal("roll", SineSignal{0.9, 0.45, -0.4, 0.3, 0.0}));
  b.add_body("shaft", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity()));
  b.add_body("disk", inertia::MassProperties(1.0, Vec3::Zero(), Mat3::Identity()));
  model::Joint yaw = make_joint("yaw", JointType::revolute, "world", "shaft", Vec3::UnitZ(),
                                Transform(Mat3::Identity(), Vec3(0.1, -0.2, 0.3)));
  yaw.prescribed_signals = {"yaw"};
  model::Joint roll = make_joint("roll", JointType::revolute, "shaft", "disk", Vec3::UnitX(),
                                 Transform(Mat3::Identity(), Vec3(0.5, 0.1, 0.0)));
  roll.prescribed_signals = {"roll"};
  b.add_joint(yaw);
  b.add_joint(roll);
  const model::Model m = b.build();
  const int disk = *m.find_body("disk"), shaft = *m.find_body("shaft");
  const Vec3 p_BoP_B(0.05, 0.2, -0.15);
  Instant instant(m);
  const auto relative = [&](double t) {
    return dynamics::relative_kinematics(m, instant.at(t), disk, p_BoP_B, shaft);
  };
  const auto world = [&](double t) { return instant.at(t).X_WB[disk].apply(p_BoP_B); };
  const double t = 0.83, h = 1e-4;
  const auto k = relative(t);
  const Vec3 r_minus = relative(t - h).p_FoP_F, r_plus = relative(t + h).p_FoP_F;
  EXPECT_MATRIX_NEAR(k.v_relative, (r_plus - r_minus) / (2 * h), 1e-7);
  EXPECT_MATRIX_NEAR(k.a_relative, (r_plus - 2 * k.p_FoP_F + r_minus) / (h * h), 1e-6);
  const Mat3 R_FW = instant.at(t).X_WB[shaft].R.transpose();
  const Vec3 p_minus = world(t - h), p = world(t), p_plus = world(t + h);
  EXPECT_MATRIX_NEAR(k.v_WP_F, R_FW * (p_plus - p_minus) / (2 * h), 1e-7);
  EXPECT_MATRIX_NEAR(k.a_WP_F, R_FW * (p_plus - 2 * p + p_minus) / (h * h), 1e-6);
  // None of the terms vanishes here: each one is exercised.
  for (const Vec3& term : {k.a_coriolis, k.a_centripetal, k.a_euler, k.a_relative})
    EXPECT_GT(term.norm(), 1e-2);
}

// A ball joint prescribed by a rotation vector φ(t) (three sines): the quaternion is Exp(φ), the
// joint's speed is the body angular velocity (central difference of the rotation, h = 1e-5) and
// its acceleration the difference of the speeds. The drive it needs is Euler's equations,
// τ = Ī ω̇ + ω × Ī ω, for a body whose centre is the joint's (gravity has no moment).
TEST(PrescribedBallJoint, FollowsTheRotationVectorAndNeedsEulersTorque) {
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -9.81));
  b.add_signal(model::Signal("phi_x", SineSignal{0.7, 0.2, 0.1, 0.2, 0.0}));
  b.add_signal(model::Signal("phi_y", SineSignal{-0.5, 0.35, 0.0, 0.1, 0.0}));
  b.add_signal(model::Signal("phi_z", SineSignal{1.2, 0.15, 0.5, -0.3, 0.0}));
  Mat3 I;
  I << 0.3, 0.02, -0.01, 0.02, 0.5, 0.03, -0.01, 0.03, 0.7;
  b.add_body("rotor", inertia::MassProperties(2.0, Vec3::Zero(), I));
  model::Joint ball = make_joint("ball", JointType::spherical, "world", "rotor");
  ball.prescribed_signals = {"phi_x", "phi_y", "phi_z"};
  b.add_joint(ball);
  const model::Model m = b.build();
  Instant instant(m);
  const auto phi = [&](double t) {
    Vec3 p;
    for (int k = 0; k < 3; ++k) p[k] = m.signals()[k].value(t);
    return p;
  };
  const auto quaternion = [&](double t) {
    instant.at(t);
    return Quat(instant.q[0], instant.q[1], instant.q[2], instant.q[3]);
  };
  const double t = 1.3, h = 1e-5;
  const dynamics::Data& data = instant.at(t);
  const Quat q = Quat(instant.q[0], instant.q[1], instant.q[2], instant.q[3]);
  const Vec3 w = instant.v;
  const Vec3 w_dot = data.vdot;
  const Vec3 tau = data.tau;
  EXPECT_MATRIX_NEAR(q.coeffs(), quaternion_exp(phi(t)).coeffs(), kTol);
  const Vec3 w_fd = quaternion_log(quaternion(t - h).conjugate() * quaternion(t + h)) / (2 * h);
  EXPECT_MATRIX_NEAR(w, w_fd, 1e-8);
  instant.at(t + h);
  const Vec3 w_plus = instant.v;
  instant.at(t - h);
  const Vec3 w_minus = instant.v;
  EXPECT_MATRIX_NEAR(w_dot, (w_plus - w_minus) / (2 * h), 1e-8);
  EXPECT_MATRIX_NEAR(tau, I * w_dot + w.cross(I * w), 1e-12);
}

// A free joint prescribed by [φ; p]: the position follows its three signals, the rotation its
// rotation vector; the drive is m (p̈ − g) on the translation, in J, for a body at its centre.
TEST(PrescribedFreeJoint, PositionAndRotationFollowTheirSignals) {
  ModelBuilder b;
  const double mass = 1.5, g = 9.81;
  b.set_gravity(Vec3(0, 0, -g));
  const char* names[] = {"rx", "ry", "rz", "x", "y", "z"};
  for (int k = 0; k < 6; ++k) {
    b.add_signal(
        model::Signal(names[k], SineSignal{0.3 + 0.1 * k, 0.2 + 0.05 * k, 0.1 * k, 0.05, 0.0}));
  }
  b.add_body("drone", inertia::MassProperties(mass, Vec3::Zero(), 0.1 * Mat3::Identity()));
  model::Joint free = make_joint("flight", JointType::free, "world", "drone");
  free.prescribed_signals = {"rx", "ry", "rz", "x", "y", "z"};
  b.add_joint(free);
  const model::Model m = b.build();
  Instant instant(m);
  const double t = 0.9;
  const dynamics::Data& data = instant.at(t);
  Vec3 phi, p, p_dd;
  for (int k = 0; k < 3; ++k) {
    phi[k] = m.signals()[k].value(t);
    p[k] = m.signals()[3 + k].value(t);
    p_dd[k] = m.signals()[3 + k].sample(t).acceleration;
  }
  EXPECT_MATRIX_NEAR(instant.q.head<3>(), p, kTol);
  const Quat r = quaternion_exp(phi);
  EXPECT_MATRIX_NEAR(instant.q.tail<4>(), Eigen::Vector4d(r.w(), r.x(), r.y(), r.z()), kTol);
  EXPECT_MATRIX_NEAR(data.X_WB[1].p, p, kTol);
  // The free joint's translational effort is the force along J's axes; here J = W.
  EXPECT_MATRIX_NEAR(data.tau.tail<3>(), mass * (p_dd - Vec3(0, 0, -g)), 1e-12);
}

// T = ½ m v̄² + ½ ωᵀ Ī ω adds up to the spatial-inertia kinetic energy; H about any point from
// H_G agrees with the system momentum (computed from spatial momenta about the world origin).
TEST(BodyMomentum, KineticEnergySplitAndAngularMomentumAboutAPoint) {
  ModelBuilder b;
  Mat3 I;
  I << 0.4, 0.05, 0.0, 0.05, 0.2, -0.02, 0.0, -0.02, 0.3;
  b.add_body("link", inertia::MassProperties(3.0, Vec3(0.2, -0.1, 0.4), I));
  b.add_joint(make_joint("free", JointType::free, "world", "link"));
  const model::Model m = b.build();
  dynamics::Data data(m);
  VecX q(7), v(6);
  const Quat r = quaternion_exp(Vec3(0.3, -0.6, 0.9));
  q << 0.5, -0.2, 1.0, r.w(), r.x(), r.y(), r.z();
  v << 1.2, -0.7, 2.1, 0.4, 0.9, -1.3;
  const double T = dynamics::kinetic_energy(m, data, q, v);
  const auto body = dynamics::body_momentum(m, data, 1);
  EXPECT_NEAR(body.kinetic_energy(), T, 1e-13 * T);
  EXPECT_GT(body.kinetic_translation, 0.1);
  EXPECT_GT(body.kinetic_rotation, 0.1);
  const auto system = dynamics::momentum(m, data);
  const Vec3 A(1.0, 2.0, -0.5);
  EXPECT_MATRIX_NEAR(body.angular_about(A), system.angular_about(A), 1e-13);
  EXPECT_MATRIX_NEAR(body.linear, system.linear, 1e-13);
}

// An output of body `target` seen from body `frame` ("" for the world).
model::OutputSpec seen_from(std::string name, OutputQuantity q, std::string target,
                            std::string frame) {
  model::OutputSpec s;
  s.name = std::move(name);
  s.quantity = q;
  s.target = std::move(target);
  s.relative_to = std::move(frame);
  return s;
}

// Outputs with `frame:` read the same terms as the library, in the frame's axes.
TEST(RotatingFrameOutputs, ColumnsSeenFromTheTurntable) {
  const model::Model m = turntable_and_bead(0.8, 2.5, 0.3, 0.1, 4.0);
  const auto spec = [](std::string name, OutputQuantity q) {
    return seen_from(std::move(name), q, "bead", "turntable");
  };
  const system::OutputSet set(
      m, {spec("r", OutputQuantity::body_position), spec("v", OutputQuantity::body_velocity),
          spec("a", OutputQuantity::body_acceleration),
          spec("cor", OutputQuantity::coriolis_acceleration),
          spec("cen", OutputQuantity::centripetal_acceleration),
          spec("eul", OutputQuantity::euler_acceleration),
          spec("tv", OutputQuantity::transport_velocity),
          spec("ta", OutputQuantity::transport_acceleration),
          spec("w", OutputQuantity::body_angular_velocity)});
  Instant instant(m);
  const double t = 0.37;
  const auto k = dynamics::relative_kinematics(m, instant.at(t), 2, Vec3::Zero(), 1);
  std::vector<double> y(set.size());
  set.evaluate(instant.system, t, instant.q, instant.v, y);
  const std::vector<Vec3> expected = {k.p_FoP_F,       k.v_relative,    k.a_relative,
                                      k.a_coriolis,    k.a_centripetal, k.a_euler,
                                      k.v_transport(), k.a_transport(), Vec3::Zero()};
  for (std::size_t o = 0; o < expected.size(); ++o)
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(y[3 * o + c], expected[o][c], kTol) << o << c;

  model::OutputSpec lonely = spec("cor", OutputQuantity::coriolis_acceleration);
  lonely.relative_to.clear();
  EXPECT_THROW(system::OutputSet(m, {lonely}), InvalidArgument);
  model::OutputSpec unknown = spec("cor", OutputQuantity::coriolis_acceleration);
  unknown.relative_to = "turntabel";
  EXPECT_THROW(system::OutputSet(m, {unknown}), InvalidArgument);
}

// Angular acceleration (issue 28): a disk symmetric about its axle x spins at ω_r = 3 rad/s on a
// turntable turned at a constant Ω = 2 rad/s about z. Torque-free about the axle (I_y = I_z), its
// spin stays constant, so seen from the turntable α_FB = 0, while in the world the spin axis turns
// with the table: α_WB = Ω ẑ × ω_r x̂' = Ω ω_r ŷ' (x̂', ŷ' the table's axes at angle Ω t), the
// gyroscopic term a textbook writes for a wheel on a turning mount (Beer & Johnston §18.9).
TEST(RotatingFrameOutputs, AngularAccelerationOfASpinningWheelOnATurntable) {
  const std::string text = R"(gravity: [0, 0, 0]
inputs:
  - {name: table_angle, type: ramp, start: 0.0, offset: 0.0, slope: 2.0}
bodies:
  - {name: table, mass: 10, inertia: [1, 1, 2]}
  - {name: wheel, mass: 1, com: [0.3, 0, 0], inertia: [0.5, 0.25, 0.25]}
joints:
  - {name: turn, type: revolute, parent: world, child: table, axis: [0, 0, 1], prescribed: table_angle}
  - {name: axle, type: revolute, parent: table, child: wheel, axis: [1, 0, 0], v0: 3.0}
)";
  const io::ModelFile file = io::parse_model_file(text, "wheel.yaml", ".");
  const model::Model& m = file.model;
  const auto spec = [](std::string name, OutputQuantity q, std::string frame) {
    return seen_from(std::move(name), q, "wheel", std::move(frame));
  };
  const system::OutputSet set(
      m, {spec("alpha", OutputQuantity::body_angular_acceleration, ""),
          spec("alpha_rel", OutputQuantity::body_angular_acceleration, "table"),
          spec("w_rel", OutputQuantity::body_angular_velocity, "table")});
  EXPECT_EQ(set.column_names()[0], "alpha.x");
  system::MultibodySystem system(m);
  for (const double t : {0.1, 0.4, 1.3}) {
    VecX q = m.initial_q(), v = m.initial_v();
    const double turn = 2.0 * t;
    q[m.joint(m.joint_index("turn")).q_index] = turn;
    v[m.joint(m.joint_index("turn")).v_index] = 2.0;
    q[m.joint(m.joint_index("axle")).q_index] = 0.9;
    std::vector<double> y(set.size());
    set.evaluate(system, t, q, v, y);
    const Vec3 y_table(-std::sin(turn), std::cos(turn), 0.0);
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(y[c], 2.0 * 3.0 * y_table[c], 1e-12) << t << c;  // α_WB_W = Ω ω_r ŷ'
      EXPECT_NEAR(y[3 + c], 0.0, 1e-12) << t << c;                 // α_FB_F = 0
      EXPECT_NEAR(y[6 + c], c == 0 ? 3.0 : 0.0, 1e-12) << t << c;  // w_FB_F = ω_r x̂
    }
  }
}

// The bundled example: a bead free to slide in a radial slot of a turntable spun at constant Ω
// slides out as x = x0 cosh Ω t (no gravity in the plane, no friction); the slot pushes it
// sideways with N = m (2 Ω ẋ) — the Coriolis term read from the CSV.
TEST(TurntableBeadExample, SlidesOutAsCoshAndTheSlotCarriesTheCoriolisForce) {
  const io::ModelFile file = io::read_model_file("examples/kinematics/turntable_bead.yaml");
  simulate::SimulationOptions options;
  options.duration = 1.0;
  options.step = 1e-3;
  options.integrator = "rk4";
  simulate::Simulation sim(file.model, file.outputs, options);
  simulate::TableSink table;
  sim.run(table);
  const double Omega = 2.0, x0 = 0.05, mass = 0.02;
  const int x_col = table.column("bead.position.x");
  const int v_col = table.column("bead.velocity.x");
  const int cor_col = table.column("bead.coriolis.y");
  const int force_col = table.column("slot_force.y");
  for (const auto& row : table.rows) {
    const double t = row[0];
    const double x = x0 * std::cosh(Omega * t), x_dot = x0 * Omega * std::sinh(Omega * t);
    // RK4 with h = 1e-3 on growth e^{Ω t}: global error ~ (Ω h)⁴ x / 120 ≈ 1e-14 relative.
    EXPECT_NEAR(row[x_col], x, 1e-12) << t;
    EXPECT_NEAR(row[v_col], x_dot, 1e-11) << t;
    EXPECT_NEAR(row[cor_col], 2 * Omega * x_dot, 1e-10) << t;
    // The slot's sideways force on the bead, in the turntable's frame: m (2 Ω ẋ), the only
    // tangential acceleration at constant Ω.
    EXPECT_NEAR(row[force_col], mass * 2 * Omega * x_dot, 1e-10) << t;
  }
}

}  // namespace
}  // namespace momenta
