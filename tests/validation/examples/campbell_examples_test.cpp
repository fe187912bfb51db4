// Rotors in joint coordinates (analysis/joint_steady_motion.hpp) against closed forms:
//  - examples/rotor_on_bearings.yaml, a rigid rotor on two elastic bearings: its whirl
//    frequencies at several speeds against the roots of the quartic
//    (k₁₁ − m ω²)(k₂₂ + I_p Ω ω − I_d ω²) − k₁₂² = 0 (ω > 0 forward, < 0 backward; Genta, Dynamics
//    of Rotating Systems §4.4), its critical speeds against the roots of
//    m (I_d − I_p) Ω⁴ − [k₁₁ (I_d − I_p) + m k₂₂] Ω² + k₁₁ k₂₂ − k₁₂² = 0, and its simulated motion
//    from a small disturbance against the reduced linearization's free response;
//  - a sleeping top held by a universal joint and a spin joint: the two precession frequencies
//    (I₃ω₃ ± √(I₃²ω₃² − 4 I₁ m g l))/(2 I₁) above the critical spin and the growth rate
//    √(4 I₁ m g l − I₃²ω₃²)/(2 I₁) below it (Goldstein §5.7), the same as the Euler–Poisson
//    analysis of the top on a ball joint gives;
//  - what is not a steady motion, refused with the reason.

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "example_simulation.hpp"
#include "momenta/analysis/joint_steady_motion.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"

namespace momenta {
namespace {

// examples/rotor_on_bearings.yaml's figures (its header).
struct Bearings {
  double m = 12.0, Id = 0.40, Ip = 0.12, kA = 2e5, kB = 3e5, a = 0.25, b = 0.20;
  double k11() const { return kA + kB; }
  double k12() const { return kB * b - kA * a; }
  double k22() const { return kA * a * a + kB * b * b; }
};

// The quartic's four real roots ω at spin Ω, ascending, each polished by Newton's method.
std::vector<double> whirl_roots(const Bearings& r, double spin) {
  const double c4 = r.m * r.Id, c3 = -r.m * r.Ip * spin, c2 = -(r.m * r.k22() + r.k11() * r.Id),
               c1 = r.k11() * r.Ip * spin, c0 = r.k11() * r.k22() - r.k12() * r.k12();
  Eigen::Matrix4d companion = Eigen::Matrix4d::Zero();
  companion.row(0) << -c3 / c4, -c2 / c4, -c1 / c4, -c0 / c4;
  companion.bottomLeftCorner<3, 3>().setIdentity();
  const Eigen::Vector4cd z = Eigen::EigenSolver<Eigen::Matrix4d>(companion).eigenvalues();
  std::vector<double> roots;
  for (int k = 0; k < 4; ++k) {
    EXPECT_LT(std::abs(z[k].imag()), 1e-9 * std::abs(z[k])) << "a complex whirl root";
    long double w = z[k].real();
    for (int it = 0; it < 4; ++it) {
      const long double p = (((c4 * w + c3) * w + c2) * w + c1) * w + c0;
      const long double dp = ((4 * c4 * w + 3 * c3) * w + 2 * c2) * w + c1;
      w -= p / dp;
    }
    roots.push_back(static_cast<double>(w));
  }
  std::sort(roots.begin(), roots.end());
  return roots;
}

TEST(CampbellExamples, RotorOnBearingsWhirlsAreTheQuarticsRootsAtEverySpeed) {
  const io::ModelFile file = test::load_example("rotor_on_bearings");
  const Bearings r;
  const analysis::JointSteadyMotion motion =
      analysis::joint_steady_motion(file.model, analysis::initial_operating_point(file.model));
  ASSERT_EQ(motion.turning_names, std::vector<std::string>{"spin.angle"});
  EXPECT_NEAR(motion.speed, 2000 * 2 * M_PI / 60, 1e-12);
  EXPECT_EQ(motion.residual, 0.0);           // exactly at rest across the axis
  EXPECT_LT(motion.cyclic_residual, 1e-13);  // round-off of the linearization's differences
  EXPECT_NEAR((motion.spin_axis_W - Vec3::UnitZ()).norm(), 0.0, 1e-15);
  // 9 states: x, y and the two tilts with their rates, and the spin rate (its angle left out).
  EXPECT_EQ(motion.reduced.state_count(), 9u);
  for (const double rpm : {0.5, 500.0, 2000.0, 5000.0, 20000.0}) {
    const double spin = rpm * 2 * M_PI / 60;
    const analysis::JointSteadyMotion at =
        analysis::joint_steady_motion_at(file.model, motion, spin);
    const std::vector<double> roots = whirl_roots(r, spin);
    ASSERT_EQ(at.modes.size(), 4u) << rpm << " rev/min";
    EXPECT_TRUE(at.stable);
    // Ascending frequency; each matched to the root of that magnitude and its sign.
    std::vector<std::pair<double, std::string>> expected;
    for (const double w : roots) expected.emplace_back(std::abs(w), w > 0 ? "forward" : "backward");
    std::sort(expected.begin(), expected.end());
    for (std::size_t k = 0; k < 4; ++k) {
      // The linearization's position derivatives are Richardson-extrapolated differences, 1e-12
      // relative; the eigenvalues inherit it.
      EXPECT_NEAR(at.modes[k].frequency, expected[k].first, 1e-10 * expected[k].first)
          << rpm << " rev/min, mode " << k;
      EXPECT_EQ(at.modes[k].whirl, expected[k].second) << rpm << " rev/min, mode " << k;
      EXPECT_LT(std::abs(at.modes[k].eigenvalue.real()), 1e-9 * expected[k].first);
    }
  }
}

TEST(CampbellExamples, RotorOnBearingsCriticalSpeedsAreTheClosedForms) {
  const io::ModelFile file = test::load_example("rotor_on_bearings");
  const Bearings r;
  const analysis::JointSteadyMotion motion =
      analysis::joint_steady_motion(file.model, analysis::initial_operating_point(file.model));
  const double kRpm = 2 * M_PI / 60;
  const analysis::CampbellDiagram d =
      analysis::campbell_diagram(file.model, motion, 500 * kRpm, 5000 * kRpm, 19);
  // m (I_d − I_p) s² − [k₁₁ (I_d − I_p) + m k₂₂] s + k₁₁ k₂₂ − k₁₂² = 0, s = Ω².
  const double A = r.m * (r.Id - r.Ip), B = -(r.k11() * (r.Id - r.Ip) + r.m * r.k22()),
               C = r.k11() * r.k22() - r.k12() * r.k12();
  const double q = -0.5 * (B - std::sqrt(B * B - 4 * A * C));  // B < 0: no cancellation
  const double low = std::sqrt(C / q), high = std::sqrt(q / A);
  ASSERT_EQ(d.critical_speeds.size(), 2u);
  EXPECT_NEAR(d.critical_speeds[0].speed, low, 1e-9 * low);
  EXPECT_NEAR(d.critical_speeds[1].speed, high, 1e-9 * high);
  EXPECT_EQ(d.critical_speeds[0].whirl, "forward");
  // The header's figures.
  EXPECT_NEAR(low / kRpm, 1934.204401, 1e-6);
  EXPECT_NEAR(high / kRpm, 2835.038083, 1e-6);
  // Every point: two backward and two forward whirls, ordered backward first.
  for (const analysis::CampbellPoint& p : d.points) {
    EXPECT_EQ(p.whirl, (std::vector<std::string>{"backward", "backward", "forward", "forward"}));
  }
}

// The reduced linearization describes the rotor's motion: from a small disturbance (x = 1 µm at
// rest across the axis, the spin unchanged), the simulated bearing displacement follows
// C e^{At} x₀ to the integrator's and the neglected second-order terms' size.
TEST(CampbellExamples, RotorOnBearingsSimulatedWhirlFollowsTheLinearization) {
  io::ModelFile file = test::load_example("rotor_on_bearings");
  const analysis::JointSteadyMotion motion =
      analysis::joint_steady_motion(file.model, analysis::initial_operating_point(file.model));
  const analysis::StateSpace& s = motion.reduced;
  const Eigen::Index x = static_cast<Eigen::Index>(s.state_index("x.position"));
  const Eigen::Index tilt = static_cast<Eigen::Index>(s.state_index("tilt.angle2"));
  const double delta = 1e-6;
  VecX x0 = VecX::Zero(static_cast<Eigen::Index>(s.state_count()));
  x0[x] = delta;
  const Eigen::EigenSolver<MatX> eig(s.A());
  const Eigen::MatrixXcd V = eig.eigenvectors();
  const Eigen::VectorXcd c = V.partialPivLu().solve(x0.cast<std::complex<double>>());
  const auto linear_state = [&](double t) {
    Eigen::VectorXcd e = c;
    for (Eigen::Index k = 0; k < e.size(); ++k) e[k] *= std::exp(eig.eigenvalues()[k] * t);
    return VecX((V * e).real());
  };
  // The simulation: the same disturbance, no tap (the hammer strikes at 10 ms: stop before).
  system::MultibodySystem system(file.model);
  const int qx = file.model.joint(file.model.joint_index("x")).q_index;
  const int qtilt = file.model.joint(file.model.joint_index("tilt")).q_index + 1;
  integrate::State state = test::initial_state(system);
  state.q[qx] = delta;
  integrate::RungeKutta4 rk4;
  double worst = 0.0;
  integrate::run(system, rk4, state, {0.0095, 5e-6, 1}, [&](const integrate::State& st) {
    const VecX lin = linear_state(st.t);
    worst = std::max({worst, std::abs(st.q[qx] - lin[x]), std::abs(st.q[qtilt] - lin[tilt]) * 0.2});
  });
  // RK4 at h = 5e-6 s against periods of 22 ms: (ωh)⁴/120 ~ 1e-11 per radian over ~3 radians;
  // the neglected second-order terms ~ δ/L ~ 1e-5 of δ at most (the unstretched springs' and the
  // tilts' geometry). Measured: 4.4e-8 δ. A wrong gyroscopic term would be off by ~1e-1 δ.
  EXPECT_LT(worst, 1e-6 * delta);
  EXPECT_GT(std::abs(linear_state(0.005)[x]), 0.1 * delta);  // it moved
}

// A symmetric top (I₁ transverse, I₃ axial about its tip, centre of mass l above it) in a gimbal:
// a massless universal joint at the tip, then a spin joint about the top's axis.
std::string gimbal_top(double I1, double I3, double l, double spin) {
  return fmt::format(R"(
name: gimbal top
gravity: [0, 0, -9.81]
bodies:
  - {{name: gimbal, mass: 0}}
  - {{name: top, mass: 1.0, com: [0, 0, {l}], inertia: [{I1}, {I1}, {I3}], inertia_about: [0, 0, 0]}}
joints:
  - {{name: tilt, type: universal, parent: world, child: gimbal, axis: [1, 0, 0], axis2: [0, 1, 0]}}
  - {{name: spin, type: revolute, parent: gimbal, child: top, axis: [0, 0, 1], v0: {spin}}}
)",
                     fmt::arg("I1", I1), fmt::arg("I3", I3), fmt::arg("l", l),
                     fmt::arg("spin", spin));
}

TEST(CampbellExamples, SleepingTopInAGimbalMatchesTheClosedFormAboveAndBelowItsCriticalSpin) {
  const double m = 1.0, g = 9.81, l = 0.1, I1 = 0.05, mgl = m * g * l;
  for (const double ratio : {0.25, 0.6, 1.4}) {
    const double I3 = ratio * I1, critical = 2 * std::sqrt(I1 * mgl) / I3;
    for (const double factor : {0.6, 1.5, 4.0}) {
      const double w3 = factor * critical;
      const io::ModelFile file =
          io::parse_model_file(gimbal_top(I1, I3, l, w3), "gimbal_top.yaml", ".");
      const analysis::JointSteadyMotion s =
          analysis::joint_steady_motion(file.model, analysis::initial_operating_point(file.model));
      const double D = I3 * I3 * w3 * w3 - 4 * I1 * mgl;
      ASSERT_EQ(s.stable, D > 0) << "I3/I1 " << ratio << ", ω3 = " << factor << " ω_c";
      if (D > 0) {
        const double slow = (I3 * w3 - std::sqrt(D)) / (2 * I1),
                     fast = (I3 * w3 + std::sqrt(D)) / (2 * I1);
        ASSERT_EQ(s.modes.size(), 2u);
        EXPECT_NEAR(s.modes[0].frequency, slow, 1e-10 * fast);
        EXPECT_NEAR(s.modes[1].frequency, fast, 1e-10 * fast);
        // Both precessions turn with the spin, as Euler–Poisson's space frequencies do.
        EXPECT_EQ(s.modes[0].whirl, "forward");
        EXPECT_EQ(s.modes[1].whirl, "forward");
      } else {
        EXPECT_NEAR(s.growth_rate, std::sqrt(-D) / (2 * I1), 1e-10 * std::sqrt(mgl / I1));
      }
    }
  }
}

TEST(CampbellExamples, WhatIsNotASteadyMotionIsRefusedWithTheReason) {
  const auto refused = [](const std::string& yaml, const std::string& expected) {
    const io::ModelFile file = io::parse_model_file(yaml, "rotor.yaml", ".");
    try {
      analysis::joint_steady_motion(file.model, analysis::initial_operating_point(file.model));
      ADD_FAILURE() << "accepted; expected: " << expected;
    } catch (const InvalidArgument& e) {
      EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    }
  };
  // Not round: moments 0.05 and 0.06 across the spin axis — the motion is periodic.
  std::string oval = gimbal_top(0.05, 0.03, 0.1, 100.0);
  oval.replace(oval.find("[0.05, 0.05"), 11, "[0.05, 0.06");
  refused(oval, "depend on its position");
  // Tilted at rest: gravity's moment accelerates it.
  std::string tilted = gimbal_top(0.05, 0.02, 0.1, 100.0);
  tilted.replace(tilted.find("axis2: [0, 1, 0]}"), 17, "axis2: [0, 1, 0], q0: [0.1, 0]}");
  refused(tilted, "not a steady motion: 'tilt.angle1_rate' accelerates");
  // Nothing turns.
  refused(gimbal_top(0.05, 0.02, 0.1, 0.0), "nothing turns");
}

}  // namespace
}  // namespace momenta
