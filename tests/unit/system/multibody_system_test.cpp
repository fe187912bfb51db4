// MultibodySystem: closed-form responses (mass–spring–damper, cruise control), the power balance
// of a driven damped model, fourth-order energy convergence and momentum conservation of
// conservative ones, prescribed motion against a second algorithm, and no allocation.
#include "momenta/system/multibody_system.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/force_elements.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/symplectic_euler.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta_test/allocation_counter.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::system {
namespace {

using model::AppliedTorque;
using model::Joint;
using model::JointFriction;
using model::JointType;
using model::LinearSpringDamper;
using model::LoadFrame;
using model::Model;
using model::ModelBuilder;
using test::applied_force;
using test::body_spring;
using test::joint_spring;
using test::make_joint;

inertia::MassProperties box(double m, const Vec3& c, const Vec3& moments) {
  return {m, c, moments.asDiagonal().toDenseMatrix()};
}

// Runs RK4 with step h from the model's initial state to t_end, calling observer(state) at
// every step (the start included), with the prescribed coordinates applied.
template <class Observer>
void simulate_rk4(MultibodySystem& system, double h, int steps, Observer&& observer) {
  integrate::RungeKutta4 rk4;
  integrate::State state{0.0, system.model().initial_q(), system.model().initial_v()};
  system.apply_prescribed_motion(state.t, state.q, state.v);
  rk4.initialize(system, state);
  observer(state);
  for (int k = 1; k <= steps; ++k) {
    rk4.step(system, state, h);
    state.t = k * h;
    system.apply_prescribed_motion(state.t, state.q, state.v);
    observer(state);
  }
}

// --- Closed forms ---------------------------------------------------------------------------

// m ẍ + c ẋ + k x = 0 on a prismatic joint along x (gravity along −z, across the rail), built
// two ways: the joint-form spring with the joint's own damping, and a linear spring from a world
// point 1 m behind the rest position with joint friction. Underdamped (ζ = 0.075):
// x(t) = e^{−ζωt} (x0 cos ω_d t + (v0 + ζω x0)/ω_d sin ω_d t).
TEST(MultibodySystem, MassSpringDamperMatchesClosedForm) {
  const double m = 2.0, k = 50.0, c = 1.5, rest = 0.05, x0 = 0.15, v0 = -0.2;
  const double w = std::sqrt(k / m), zeta = c / (2 * std::sqrt(k * m));
  const double wd = w * std::sqrt(1 - zeta * zeta);
  for (const bool linear_spring : {false, true}) {
    ModelBuilder b;
    b.add_body("mass", box(m, Vec3::Zero(), Vec3(0.1, 0.1, 0.1)));
    Joint rail = make_joint("rail", JointType::prismatic, "world", "mass", Vec3::UnitX());
    rail.q0 = VecX::Constant(1, x0);
    rail.v0 = VecX::Constant(1, v0);
    if (linear_spring) {
      b.add_force_element(LinearSpringDamper{.name = "spring",
                                             .a = {.body = "world", .p_BoP_B = {-1, 0, 0}},
                                             .b = {.body = "mass"},
                                             .stiffness = k,
                                             .free_length = 1 + rest});
      b.add_force_element(JointFriction{.name = "friction", .joint = "rail", .viscous = c});
    } else {
      rail.damping = c;
      b.add_force_element(joint_spring("spring", "rail", k, 0.0, rest));
    }
    b.add_joint(rail);
    const Model model = b.build();
    MultibodySystem system(model);
    EXPECT_FALSE(system.conserves_energy());
    // RK4's global error on a linear oscillator is about T ω (hω)⁴ / 120 relative: 2e-10 for
    // T = 4 s, ω = 5 rad/s, h = 1e-3 s, so 2e-11 m on an amplitude of 0.1 m.
    double worst = 0.0;
    simulate_rk4(system, 1e-3, 4000, [&](const integrate::State& s) {
      const double u0 = x0 - rest;
      const double x =
          rest + std::exp(-zeta * w * s.t) *
                     (u0 * std::cos(wd * s.t) + (v0 + zeta * w * u0) / wd * std::sin(wd * s.t));
      worst = std::max(worst, std::abs(s.q[0] - x));
    });
    EXPECT_LT(worst, 1e-10) << (linear_spring ? "linear spring" : "joint spring");
  }
}

// Cruise control (Åström & Murray's car, linearized): m v̇ = u − b v, m = 1000 kg, b = 50 N·s/m,
// a step force u = 500 N at t = 0: v(t) = (u/b)(1 − e^{−bt/m}), x(t) = (u/b)(t − (m/b)(1 −
// e^{−bt/m})). The force is an applied world load scaled by a step signal; b is the joint's
// damping.
TEST(MultibodySystem, CruiseControlStepResponse) {
  const double m = 1000.0, b_drag = 50.0, u = 500.0;
  ModelBuilder b;
  b.add_signal(
      model::Signal("throttle", model::StepSignal{.start = 0.0, .initial = 0.0, .final = 1.0}));
  b.add_body("car", box(m, Vec3::Zero(), Vec3(100, 100, 100)));
  Joint road = make_joint("road", JointType::prismatic, "world", "car", Vec3::UnitX());
  road.damping = b_drag;
  b.add_joint(road);
  b.add_force_element(
      applied_force("engine", "car", Vec3(0, 0, 0), LoadFrame::world, Vec3(u, 0, 0), "throttle"));
  const Model model = b.build();
  MultibodySystem system(model);
  // λh = 0.005: RK4's relative error over T = 60 s is ~ T λ (λh)⁴ / 120 ≈ 1e-12.
  double worst_v = 0.0, worst_x = 0.0;
  simulate_rk4(system, 0.1, 600, [&](const integrate::State& s) {
    const double decay = 1 - std::exp(-b_drag * s.t / m);
    worst_v = std::max(worst_v, std::abs(s.v[0] - (u / b_drag) * decay));
    worst_x = std::max(worst_x, std::abs(s.q[0] - (u / b_drag) * (s.t - (m / b_drag) * decay)));
  });
  EXPECT_LT(worst_v, 2e-10);  // 10 × (1e-12 of v → 10 m/s); observed 2e-11
  EXPECT_LT(worst_x, 4e-9);   // 10 × (1e-12 of x(60) ≈ 400 m); observed 4e-10
}

// --- Power balance ----------------------------------------------------------------------------

// A driven, damped model with every kind of element: a cart on a rail prescribed by a sine, an
// arm hinged on it (joint damping, friction, torsional spring), a ball-jointed bob on the arm
// (two-body torsional spring–damper), and a free body tied to the world and to the bob by linear
// spring–dampers, pushed by a follower force and twisted by a world torque, both signal-driven.
// `stiffness_scale` multiplies every spring's stiffness (0 leaves the dampers alone).
Model driven_damped_model(double stiffness_scale = 1.0) {
  const double ks = stiffness_scale;
  ModelBuilder b;
  b.add_signal(model::Signal("cart", model::SineSignal{.amplitude = 0.3, .frequency = 0.7}));
  b.add_signal(
      model::Signal("push", model::SineSignal{.amplitude = 2.0, .frequency = 1.3, .phase = 0.4}));
  b.add_signal(model::Signal("twist", model::RampSignal{.slope = 0.5, .offset = 0.2}));
  b.add_body("cart", box(3.0, Vec3::Zero(), Vec3(0.1, 0.1, 0.1)));
  b.add_body("arm", box(1.0, Vec3(0, 0, -0.25), Vec3(0.02, 0.03, 0.01)));
  b.add_body("bob", box(0.5, Vec3(0.05, 0, -0.1), Vec3(0.004, 0.005, 0.006)));
  b.add_body("drone", box(1.2, Vec3(0.02, 0.01, 0), Vec3(0.03, 0.04, 0.05)));
  Joint rail = make_joint("rail", JointType::prismatic, "world", "cart", Vec3::UnitX());
  rail.prescribed_signals = {"cart"};
  b.add_joint(rail);
  Joint hinge = make_joint("hinge", JointType::revolute, "cart", "arm");
  hinge.damping = 0.05;
  hinge.q0 = VecX::Constant(1, 0.6);
  b.add_joint(hinge);
  Joint ball = make_joint("ball", JointType::spherical, "arm", "bob", Vec3::UnitZ(),
                          Transform::translation(Vec3(0, 0, -0.5)));
  ball.v0 = Vec3(0.5, -1.0, 2.0);
  b.add_joint(ball);
  Joint floating = make_joint("float", JointType::free, "world", "drone");
  floating.q0 = (VecX(7) << 0.4, 0.2, -0.3, 1, 0, 0, 0).finished();
  floating.v0 = (VecX(6) << 0.3, 0.2, -0.4, 0.1, 0.0, 0.2).finished();
  b.add_joint(floating);
  b.add_force_element(JointFriction{.name = "hinge_friction", .joint = "hinge", .viscous = 0.03});
  b.add_force_element(joint_spring("hinge_spring", "hinge", 2.0 * ks, 0.01, 0.1));
  b.add_force_element(body_spring("wrist", "arm", "bob", 1.5 * ks, 0.02));
  b.add_force_element(LinearSpringDamper{.name = "tether",
                                         .a = {.body = "world", .p_BoP_B = {0.5, 0, 0.5}},
                                         .b = {.body = "drone", .p_BoP_B = {0.1, 0, 0}},
                                         .stiffness = 20.0 * ks,
                                         .damping = 0.5,
                                         .free_length = 0.3});
  b.add_force_element(LinearSpringDamper{.name = "link",
                                         .a = {.body = "bob", .p_BoP_B = {0.1, 0, 0}},
                                         .b = {.body = "drone", .p_BoP_B = {0, 0.1, 0}},
                                         .stiffness = 5.0 * ks,
                                         .damping = 0.1,
                                         .free_length = 0.4});
  b.add_force_element(applied_force("thrust", "drone", Vec3(0, 0, 0.1), LoadFrame::body,
                                    Vec3(0.3, 0, 1.0), "push"));
  b.add_force_element(AppliedTorque{.name = "yaw",
                                    .body = "drone",
                                    .frame = LoadFrame::world,
                                    .vector = {0, 0, 0.2},
                                    .signal = "twist"});
  return b.build();
}

// Power balance at several instants of an RK4 trajectory (h = 1e-3 s):
//  - the bodies' mechanical energy T + V_gravity changes at the power of every force element
//    (springs included) plus the drive's power at the prescribed joint;
//  - the total energy (springs' energy added) changes at the power of the non-conservative part
//    alone: the same elements with zero stiffness (the same dampers and loads), plus the drive.
// Rates by the fourth-order central difference (E₋₂ − 8E₋₁ + 8E₁ − E₂)/(12h): truncation
// h⁴ |E⁽⁵⁾|/30 with frequencies ≲ 10 rad/s, i.e. ≲ 1e-12 · 1e5 · |P| ~ 1e-7 |P| at worst, |P| ≲ 10
// W; the integrator's local error O(h⁵) adds O(h⁴); round-off ε|E|/h ~ 1e-12. Observed ≲ 4e-8 W;
// allowed 1e-6 W, while a missing or mis-signed term is ≳ 1e-2 W.
TEST(MultibodySystem, PowerBalanceOfADrivenDampedModel) {
  const Model model = driven_damped_model();
  const Model dampers_only = driven_damped_model(0.0);
  MultibodySystem system(model), dissipative(dampers_only);
  EXPECT_FALSE(system.conserves_energy());
  EXPECT_FALSE(system.conserves_angular_momentum());
  const double h = 1e-3;
  std::vector<integrate::State> trajectory;
  simulate_rk4(system, h, 1500, [&](const integrate::State& s) { trajectory.push_back(s); });
  std::vector<double> mechanical, total;
  for (const auto& s : trajectory) {
    const Energy e = system.energy(s.q, s.v);
    mechanical.push_back(e.kinetic + e.potential_gravity);
    total.push_back(e.total());
  }
  const auto rate = [h](const std::vector<double>& E, int k) {
    return (E[k - 2] - 8 * E[k - 1] + 8 * E[k + 1] - E[k + 2]) / (12 * h);
  };
  const int rail = model.joint(model.joint_index("rail")).v_index;
  for (const int k : {300, 700, 1100, 1450}) {
    const auto& s = trajectory[k];
    system.evaluate(s.t, s.q, s.v);
    const dynamics::Data& d = system.data();
    const double elements = dynamics::force_element_power(model, d, s.v, system.element_forces(),
                                                          system.external_wrenches());
    // The drive's effort: the total force at the rail minus what the elements put there.
    const double drive = (d.tau[rail] - system.element_forces()[rail]) * s.v[rail];
    EXPECT_NEAR(rate(mechanical, k), elements + drive, 1e-6) << "t = " << s.t;

    dissipative.evaluate(s.t, s.q, s.v);
    const double losses = dynamics::force_element_power(dampers_only, dissipative.data(), s.v,
                                                        dissipative.element_forces(),
                                                        dissipative.external_wrenches());
    EXPECT_NEAR(rate(total, k), losses + drive, 1e-6) << "t = " << s.t;
    // Every part matters at these instants.
    EXPECT_GT(std::abs(drive), 1e-2) << "t = " << s.t;
    EXPECT_GT(std::abs(elements - losses), 1e-2) << "t = " << s.t;
  }
}

// --- Conservative models ----------------------------------------------------------------------

// Max |E(t) − E(0)| over an RK4 run of `duration` with step h.
double energy_drift(const Model& model, double h, double duration) {
  MultibodySystem system(model);
  double E0 = 0.0, worst = 0.0;
  bool first = true;
  simulate_rk4(system, h, static_cast<int>(std::lround(duration / h)),
               [&](const integrate::State& s) {
                 const double E = system.energy(s.q, s.v).total();
                 if (first) E0 = E, first = false;
                 worst = std::max(worst, std::abs(E - E0));
               });
  return worst;
}

// A pendulum with a spring to the world, and a second body on a ball joint at its end held by a
// two-body torsional spring.
Model spring_pendulum() {
  ModelBuilder b;
  b.add_body("rod", box(1.0, Vec3(0, 0, -0.4), Vec3(0.02, 0.02, 0.005)));
  b.add_body("head", box(0.6, Vec3(0.05, 0.02, -0.05), Vec3(0.003, 0.004, 0.005)));
  Joint pivot = make_joint("pivot", JointType::revolute, "world", "rod");
  pivot.q0 = VecX::Constant(1, 1.0);
  b.add_joint(pivot);
  Joint neck = make_joint("neck", JointType::spherical, "rod", "head", Vec3::UnitZ(),
                          Transform::translation(Vec3(0, 0, -0.8)));
  neck.v0 = Vec3(1.0, -0.5, 2.0);
  b.add_joint(neck);
  b.add_force_element(LinearSpringDamper{.name = "spring",
                                         .a = {.body = "world", .p_BoP_B = {0.6, 0, 0}},
                                         .b = {.body = "rod", .p_BoP_B = {0, 0, -0.5}},
                                         .stiffness = 15.0,
                                         .free_length = 0.3});
  b.add_force_element(body_spring("neck_spring", "rod", "head", 0.4, 0.0));
  return b.build();
}

// Two bodies floating under gravity: a free body (I = diag(1, 2, 3)) and a second one on a ball
// joint held by a two-body torsional spring. No external moment about the centre of mass.
Model floating_pair() {
  ModelBuilder b;
  b.add_body("base", box(2.0, Vec3::Zero(), Vec3(1.0, 2.0, 3.0)));
  b.add_body("tail", box(0.5, Vec3(0.3, 0, 0), Vec3(0.01, 0.05, 0.05)));
  Joint floating = make_joint("float", JointType::free, "world", "base");
  floating.v0 = (VecX(6) << 0.4, 1.5, -0.3, 0.2, -0.1, 3.0).finished();
  b.add_joint(floating);
  Joint ball = make_joint("ball", JointType::spherical, "base", "tail", Vec3::UnitZ(),
                          Transform::translation(Vec3(0.5, 0, 0)));
  ball.v0 = Vec3(0.0, 2.0, -1.0);
  b.add_joint(ball);
  b.add_force_element(body_spring("hinge", "base", "tail", 3.0, 0.0));
  return b.build();
}

// A carriage on a rail carrying a double pendulum, the three joints sharing a tendon spring
// L = 0.05 + 0.5 θ1 − 0.5 θ2 + 2 x (k = 4, relaxed at 0.1): its energy ½ k (L − 0.1)² is the
// potential of its joint forces, so the whole is conservative.
Model tendon_chain() {
  ModelBuilder b;
  b.add_body("carriage", box(2.0, Vec3::Zero(), Vec3(0.01, 0.01, 0.01)));
  b.add_body("upper", box(1.0, Vec3(0, 0, -0.5), Vec3(0.08, 0.08, 0.001)));
  b.add_body("lower", box(0.5, Vec3(0, 0, -0.4), Vec3(0.03, 0.03, 0.001)));
  Joint rail = make_joint("rail", JointType::prismatic, "world", "carriage", Vec3::UnitX());
  rail.q0 = VecX::Constant(1, 0.1);
  b.add_joint(rail);
  Joint shoulder = make_joint("shoulder", JointType::revolute, "carriage", "upper", Vec3::UnitY());
  shoulder.q0 = VecX::Constant(1, 0.7);
  b.add_joint(shoulder);
  Joint elbow = make_joint("elbow", JointType::revolute, "upper", "lower", Vec3::UnitY(),
                           Transform::translation(Vec3(0, 0, -1)));
  elbow.q0 = VecX::Constant(1, -0.5);
  elbow.v0 = VecX::Constant(1, 1.0);
  b.add_joint(elbow);
  b.add_force_element(
      test::fixed_tendon("cord", {{"shoulder", 0.5, -1}, {"elbow", -0.5, -1}, {"rail", 2.0, -1}},
                         0.05, 4.0, 0.0, 0.1));
  return b.build();
}

// RK4 is fourth order: halving h divides the energy error by ~16. log2 of the ratio must lie
// within 0.5 of 4 at steps where the error (≳ 1e-10 J) is far above round-off (~1e-15 J).
TEST(MultibodySystem, EnergyErrorOfConservativeModelsIsFourthOrder) {
  // The tendon chain's double pendulum swings faster: its steps start at 0.01 s to be in RK4's
  // asymptotic range (at 0.02 s the first ratio is 2^4.8).
  for (const auto& [model, h] :
       {std::pair{spring_pendulum(), 0.02}, std::pair{floating_pair(), 0.02},
        std::pair{tendon_chain(), 0.01}}) {
    EXPECT_TRUE(MultibodySystem(model).conserves_energy());
    const double e1 = energy_drift(model, h, 2.0);
    const double e2 = energy_drift(model, h / 2, 2.0);
    const double e3 = energy_drift(model, h / 4, 2.0);
    EXPECT_NEAR(std::log2(e1 / e2), 4.0, 0.5) << e1 << " " << e2;
    EXPECT_NEAR(std::log2(e2 / e3), 4.0, 0.5) << e2 << " " << e3;
    EXPECT_GT(e3, 1e-12);  // still above round-off, so the ratios measure truncation
  }
}

// The floating pair conserves H about its centre of mass, and its linear momentum obeys L(t) =
// L(0) + M g t (uniform gravity is the only external force; the internal spring's wrenches
// cancel). RK4 keeps neither exactly (both are nonlinear in (q, v) through the free joint's
// body-frame ω), so the drifts must shrink at fourth order as h halves.
TEST(MultibodySystem, FreeFloatingSystemConservesAngularMomentumAboutItsCentreOfMass) {
  const Model model = floating_pair();
  MultibodySystem system(model);
  EXPECT_TRUE(system.conserves_energy());
  EXPECT_TRUE(system.conserves_angular_momentum());
  dynamics::Data data(model);
  const auto drift = [&](double h) {
    Vec3 H0 = Vec3::Zero(), L0 = Vec3::Zero();
    double worst_H = 0.0, worst_L = 0.0;
    simulate_rk4(system, h, static_cast<int>(std::lround(2.0 / h)), [&](const integrate::State& s) {
      const dynamics::Momentum p = dynamics::momentum(model, data, s.q, s.v);
      if (s.t == 0.0) H0 = p.angular_about_com, L0 = p.linear;
      worst_H = std::max(worst_H, (p.angular_about_com - H0).norm());
      worst_L =
          std::max(worst_L, (p.linear - L0 - model.total_mass() * model.gravity() * s.t).norm());
    });
    return std::pair{worst_H, worst_L};
  };
  const auto [H1, L1] = drift(0.01);
  const auto [H2, L2] = drift(0.005);
  EXPECT_NEAR(std::log2(H1 / H2), 4.0, 0.5) << H1 << " " << H2;
  EXPECT_NEAR(std::log2(L1 / L2), 4.0, 0.5) << L1 << " " << L2;
  EXPECT_LT(H2, 1e-8);  // |H| ≈ 6 kg·m²/s
  EXPECT_LT(L2, 1e-8);  // |L| ≈ 8 kg·m/s
}

TEST(MultibodySystem, ConservationFlags) {
  EXPECT_TRUE(MultibodySystem(spring_pendulum()).conserves_energy());
  EXPECT_FALSE(MultibodySystem(spring_pendulum()).conserves_angular_momentum());  // held by a pivot
  EXPECT_FALSE(MultibodySystem(driven_damped_model()).conserves_energy());
  // A spring to the world breaks the free system's angular momentum, not its energy.
  ModelBuilder b;
  b.add_body("base", box(1.0, Vec3::Zero(), Vec3(1.0, 2.0, 3.0)));
  b.add_joint(make_joint("float", JointType::free, "world", "base"));
  b.add_force_element(LinearSpringDamper{
      .name = "s", .a = {.body = "world"}, .b = {.body = "base"}, .stiffness = 1.0});
  const Model tethered = b.build();
  EXPECT_TRUE(MultibodySystem(tethered).conserves_energy());
  EXPECT_FALSE(MultibodySystem(tethered).conserves_angular_momentum());
}

// --- Prescribed motion --------------------------------------------------------------------------

// A pendulum (point mass m, length l) on a cart whose position is prescribed, x(t) = A sin(2π f t).
// The prescribed coordinate follows its signal exactly; the pendulum obeys θ̈ = (ẍ cos θ − g sin
// θ)/l, integrated here by a scalar RK4 with the same step (the same arithmetic path up to
// round-off, so 1e-12); the cart's drive force equals rnea's τ at the evaluated state.
TEST(MultibodySystem, PrescribedJointFollowsItsSignal) {
  const double M = 2.0, m = 0.5, l = 0.8, g = 9.81, A = 0.2, f = 1.0;
  ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -g));
  b.add_signal(model::Signal("cart_x", model::SineSignal{.amplitude = A, .frequency = f}));
  b.add_body("cart", box(M, Vec3::Zero(), Vec3(0.1, 0.1, 0.1)));
  b.add_body("bob", inertia::MassProperties(m, Vec3(0, 0, -l), Mat3::Zero()));
  Joint rail = make_joint("rail", JointType::prismatic, "world", "cart", Vec3::UnitX());
  rail.prescribed_signals = {"cart_x"};
  b.add_joint(rail);
  Joint pivot = make_joint("pivot", JointType::revolute, "cart", "bob");
  pivot.q0 = VecX::Constant(1, 0.3);
  b.add_joint(pivot);
  const Model model = b.build();
  MultibodySystem system(model);
  EXPECT_FALSE(system.conserves_energy());
  const model::Signal& signal = model.signals()[0];

  const auto theta_dd = [&](double t, double th) {
    return (signal.sample(t).acceleration * std::cos(th) - g * std::sin(th)) / l;
  };
  const double h = 1e-3;
  double th = 0.3, w = 0.0;  // the scalar reference
  dynamics::Data data(model);
  int checked = 0;
  simulate_rk4(system, h, 2000, [&](const integrate::State& s) {
    EXPECT_EQ(s.q[0], signal.sample(s.t).value);
    EXPECT_EQ(s.v[0], signal.sample(s.t).rate);
    ASSERT_NEAR(s.q[1], th, 1e-12) << "t = " << s.t;
    ASSERT_NEAR(s.v[1], w, 1e-12) << "t = " << s.t;
    // The reference's RK4 step to the next instant.
    const double t = s.t;
    const double k1 = theta_dd(t, th), k2 = theta_dd(t + h / 2, th + h / 2 * w);
    const double k3 = theta_dd(t + h / 2, th + h / 2 * (w + h / 2 * k1));
    const double k4 = theta_dd(t + h, th + h * (w + h / 2 * k2));
    th += h * (w + h / 6 * (k1 + k2 + k3));
    w += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);

    if (++checked % 250 != 0) return;
    // Whatever the state says at the rail, the evaluation uses the signal.
    VecX q_wrong = s.q, v_wrong = s.v;
    q_wrong[0] += 0.7;
    v_wrong[0] -= 3.0;
    const VecX vdot = system.evaluate(s.t, q_wrong, v_wrong);
    EXPECT_EQ(vdot[0], signal.sample(s.t).acceleration);
    EXPECT_MATRIX_NEAR(vdot, system.evaluate(s.t, s.q, s.v), 0.0);
    // The drive force against the second algorithm: rnea at the same state and accelerations...
    const VecX& tau = dynamics::rnea(model, data, s.q, s.v, vdot, system.external_wrenches());
    EXPECT_NEAR(system.data().tau[0], tau[0], 1e-12);
    EXPECT_NEAR(tau[1], 0.0, 1e-12);  // the pendulum is free
    // ...and the closed form F = (M + m) ẍ − m l cos θ θ̈ + m l sin θ θ̇².
    const double F = (M + m) * vdot[0] - m * l * std::cos(s.q[1]) * vdot[1] +
                     m * l * std::sin(s.q[1]) * s.v[1] * s.v[1];
    EXPECT_NEAR(system.data().tau[0], F, 1e-12);
  });
  EXPECT_EQ(checked, 2001);
}

// residual(): the generalized force that accelerations leave unbalanced, r = ID(q̄, v̄, v̇̄) − Q.
// Inverse dynamics is affine in v̇ with slope M, so on the free rows r(a + δ) = M_ff δ exactly
// (to round-off) at the system's own accelerations a, where r = 0; a second model whose springs
// are 0.1 % stiffer has the same M, so its accelerations differ from a by exactly −M_ff⁻¹ r —
// checked against its own forward dynamics (ABA and hybrid dynamics, a second algorithm). The
// model has a prescribed rail (its row zero), body springs, a free body and loads on it. Bounds:
// round-off of sums of terms ≲ 100 (N, N·m), 1e-12 relative; 1e-10 allowed.
TEST(MultibodySystem, ResidualIsTheForceAccelerationsLeaveUnbalanced) {
  const Model model = driven_damped_model();
  const Model stiffer = driven_damped_model(1.001);
  MultibodySystem system(model), stiffer_system(stiffer);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  dynamics::Data data(model);
  for (const double t : {0.0, 0.37, 1.9}) {
    VecX q = model.initial_q(), v = model.initial_v();
    for (int i = 0; i < model.nv(); ++i) v[i] += unit(rng);
    const VecX a = system.evaluate(t, q, v);
    const VecX q_bar = system.evaluated_q();
    EXPECT_LT(system.residual(t, q, v, a).norm(), 1e-10);

    VecX delta(model.nv());
    for (int i = 0; i < model.nv(); ++i) delta[i] = unit(rng);
    const VecX r = system.residual(t, q, v, a + delta);
    const MatX M = dynamics::crba(model, data, q_bar);
    EXPECT_EQ(r[0], 0.0);  // the rail is prescribed
    const VecX expected =
        M.bottomRightCorner(model.nv() - 1, model.nv() - 1) * delta.tail(model.nv() - 1);
    EXPECT_MATRIX_NEAR(r.tail(model.nv() - 1), expected, 1e-10);

    const VecX a_stiffer = stiffer_system.evaluate(t, q, v);
    const VecX r_stiffer = stiffer_system.residual(t, q, v, a);
    EXPECT_GT(r_stiffer.norm(), 1e-4);  // the springs pull: not a vacuous check
    const VecX change = M.bottomRightCorner(model.nv() - 1, model.nv() - 1)
                            .llt()
                            .solve(-r_stiffer.tail(model.nv() - 1));
    EXPECT_MATRIX_NEAR(change, (a_stiffer - a).tail(model.nv() - 1), 1e-10);
  }
}

// --- Signals and interface ----------------------------------------------------------------------

// Offsets perturb the signals (linearization): a force u(t) · (3, 0, 0) N on a 2 kg free body
// accelerates it by 1.5 (u + δu) m/s², and the samples report the offset values.
TEST(MultibodySystem, SignalOffsetsPerturbTheInputs) {
  ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  b.add_signal(model::Signal("u", model::RampSignal{.slope = 2.0}));
  b.add_body("box", box(2.0, Vec3::Zero(), Vec3(0.1, 0.2, 0.3)));
  b.add_joint(make_joint("float", JointType::free, "world", "box"));
  b.add_force_element(
      applied_force("f", "box", Vec3(0, 0, 0), LoadFrame::world, Vec3(3, 0, 0), "u"));
  const Model model = b.build();
  MultibodySystem system(model);
  const VecX q = model.initial_q(), v = model.initial_v();
  EXPECT_NEAR(system.evaluate(1.5, q, v)[3], 1.5 * 3.0, 1e-14);
  const std::vector<double> dv{0.25}, dr{-1.0}, da{4.0};
  system.set_signal_offsets(dv, dr, da);
  EXPECT_NEAR(system.evaluate(1.5, q, v)[3], 1.5 * 3.25, 1e-14);
  EXPECT_EQ(system.signal_samples()[0].value, 3.25);
  EXPECT_EQ(system.signal_samples()[0].rate, 1.0);
  EXPECT_EQ(system.signal_samples()[0].acceleration, 4.0);
  const std::vector<double> two{0.0, 0.0};
  EXPECT_THROW(system.set_signal_offsets(two, dr, da), InvalidArgument);
}

// The configuration-space functions come from the model; names are the model's.
TEST(MultibodySystem, DelegatesToTheModelsConfigurationSpace) {
  const Model model = floating_pair();
  MultibodySystem system(model);
  EXPECT_EQ(system.nq(), 11);
  EXPECT_EQ(system.nv(), 9);
  for (int i = 0; i < model.nq(); ++i) EXPECT_EQ(system.coordinate_name(i, false), model.q_name(i));
  for (int i = 0; i < model.nv(); ++i) EXPECT_EQ(system.coordinate_name(i, true), model.v_name(i));
  std::mt19937 rng(4);
  const VecX q = test::random_configuration(model, rng);
  const VecX dq = test::random_vector(model.nv(), rng);
  VecX q_out(model.nq());
  system.integrate(q, dq, q_out);
  EXPECT_MATRIX_NEAR(q_out, model::integrate(model, q, dq, 1.0), 0.0);
  VecX rate(model.nv()), expected(model.nv());
  system.local_coordinate_rate(0.3 * dq, dq, rate);
  model::local_coordinate_rate(model, 0.3 * dq, dq, expected);
  EXPECT_MATRIX_NEAR(rate, expected, 0.0);
  // Scale: ω of the free joint and the ball count 1 rad; the free joint's position |p|.
  VecX scale;
  system.configuration_scale(q, scale);
  VecX want(9);
  want << 1, 1, 1, q.head<3>().cwiseAbs(), 1, 1, 1;
  EXPECT_MATRIX_NEAR(scale, want, 0.0);
}

// Energy is the three parts, here by hand: a 2 kg mass on a rail along x with its centre of mass
// 0.5 m up, a spring k = 8 on the rail, at x = 0.5 m moving at 3 m/s.
TEST(MultibodySystem, EnergyParts) {
  ModelBuilder b;
  b.add_body("mass", box(2.0, Vec3(0, 0, 0.5), Vec3(0.1, 0.1, 0.1)));
  b.add_joint(make_joint("rail", JointType::prismatic, "world", "mass", Vec3::UnitX()));
  b.add_force_element(joint_spring("s", "rail", 8.0, 0.0, 0.0));
  const Model model = b.build();
  MultibodySystem system(model);
  const Energy e = system.energy(VecX::Constant(1, 0.5), VecX::Constant(1, 3.0));
  EXPECT_NEAR(e.kinetic, 0.5 * 2.0 * 9.0, 1e-14);
  EXPECT_NEAR(e.potential_gravity, 2.0 * 9.81 * 0.5, 1e-14);
  EXPECT_NEAR(e.potential_springs, 0.5 * 8.0 * 0.25, 1e-14);
  EXPECT_NEAR(e.total(), 9.0 + 9.81 + 1.0, 1e-13);
}

// --- No allocation ------------------------------------------------------------------------------

TEST(MultibodySystem, AccelerationDoesNotAllocate) {
  const Model model = driven_damped_model();
  MultibodySystem system(model);
  VecX q = model.initial_q(), v = model.initial_v(), vdot(model.nv());
  integrate::RungeKutta4 rk4;
  integrate::SymplecticEuler euler;
  integrate::State state{0.0, q, v};
  rk4.initialize(system, state);
  euler.initialize(system, state);
  const long before = test::allocation_count();
  system.acceleration(0.3, q, v, vdot);
  system.evaluate(0.4, q, v);
  system.apply_prescribed_motion(0.5, q, v);
  const Energy e = system.energy(q, v);
  system.residual(0.6, q, v, vdot);
  rk4.step(system, state, 1e-3);
  euler.step(system, state, 1e-3);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(std::isfinite(e.total()) && vdot.allFinite() && state.q.allFinite());
}

}  // namespace
}  // namespace momenta::system
