// Linearization of constrained models in independent coordinates (analysis/linearize.hpp,
// "Models with constraints") against hand-derived models:
//  - the parallelogram swing (examples/constraints/parallelogram_swing.yaml): one coordinate,
//    ω² = g (m₁/2 + m₃/2 + m₂) / (L (m₁/3 + m₃/3 + m₂)) from its energy (the file's comment);
//  - the upright rolling disk (nonholonomic): the lean obeys
//    A (A + m R²) θ̈ + [C (C + m R²) Ω² − A m g R] θ = 0 (Euler's equations about G with the
//    contact force from m a_G; derived in docs/constraints.md), so its eigenvalues are
//    ±sqrt(A m g R − C (C + m R²) Ω²) / sqrt(A (A + m R²)): stable above Ω² = g/(3R).
// And the analytic derivatives (dynamics/constraint_derivatives.hpp and the chart's maps) against
// Richardson differences along the chart (LinearizationOptions::Derivatives::differences) at
// moving states of every example and of planar and spatial loops.
//
// Tolerances: A is exact to round-off (measured ≤ 5e-16 relative against the closed forms), so
// 1e-13 relative where A or the second-order form is compared directly, 1e-12 for eigenvalues
// (well separated ones move by about the round-off of A).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <filesystem>
#include <numbers>
#include <random>
#include <string>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "momenta/analysis/equilibrium.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/modes.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta_test/closed_chains.hpp"

namespace momenta {
namespace {

using std::numbers::pi;

const io::ModelFile& swing() {
  static const io::ModelFile file =
      io::read_model_file("examples/constraints/parallelogram_swing.yaml");
  return file;
}

// Index into q of a joint's coordinate.
int q_of(const char* joint) {
  const model::Model& model = swing().model;
  return model.joint(model.joint_index(joint)).q_index;
}

// The swing hanging at rest: arms straight down, the seat level.
analysis::OperatingPoint hanging() {
  analysis::OperatingPoint p;
  p.q = VecX(3);
  p.q[q_of("pivot1")] = -pi / 2;
  p.q[q_of("seat_pin")] = pi / 2;
  p.q[q_of("pivot2")] = -pi / 2;
  p.v = VecX::Zero(3);
  return p;
}

double swing_omega_squared() {
  const double g = 9.81, L = 0.25, m1 = 1.0, m2 = 2.0, m3 = 1.5;
  return g * (m1 / 2 + m3 / 2 + m2) / (L * (m1 / 3 + m3 / 3 + m2));
}

TEST(ConstrainedLinearization, ParallelogramSwingMatchesTheSingleCoordinateModel) {
  const analysis::LinearModel lin = analysis::linearize(swing().model, hanging());
  const analysis::StateSpace& s = lin.system;
  ASSERT_EQ(s.state_names(), (std::vector<std::string>{"pivot1.angle", "pivot1.angle_rate"}));
  EXPECT_EQ(lin.dependent_coordinates.size(), 2u);  // the seat's and the second arm's angles
  const double w2 = swing_omega_squared();
  EXPECT_NEAR(s.A()(0, 0), 0.0, 1e-13 * w2);
  EXPECT_NEAR(s.A()(0, 1), 1.0, 1e-13);
  EXPECT_NEAR(s.A()(1, 0), -w2, 1e-13 * w2);
  EXPECT_NEAR(s.A()(1, 1), 0.0, 1e-13 * w2);
  // The reduced second-order form: mass = the effective inertia about the pivots,
  // stiffness = the potential's curvature.
  const double I = 0.25 * 0.25 * (1.0 / 3 + 1.5 / 3 + 2.0);
  EXPECT_NEAR(lin.mass(0, 0), I, 1e-12 * I);
  EXPECT_NEAR(lin.stiffness(0, 0), w2 * I, 1e-13 * w2 * I);
  const analysis::NormalModes modes = analysis::undamped_modes(lin);
  ASSERT_EQ(modes.modes.size(), 1u);
  EXPECT_NEAR(modes.modes[0].natural_frequency, std::sqrt(w2), 1e-12 * std::sqrt(w2));
}

TEST(ConstrainedLinearization, TheSwingSettlesHangingWithItsFrequency) {
  // From the file's 10° swing: Newton in the independent coordinate finds the arms straight down.
  const analysis::Equilibrium e =
      analysis::find_equilibrium(swing().model, swing().model.initial_q());
  const VecX& q = e.point.q;
  EXPECT_NEAR(q[q_of("pivot1")], -pi / 2, 1e-10);
  EXPECT_NEAR(q[q_of("pivot2")], -pi / 2, 1e-10);
  EXPECT_NEAR(q[q_of("seat_pin")], pi / 2, 1e-10);
  EXPECT_TRUE(e.stable());
  EXPECT_EQ(e.stiffness_rank, 1);
  const analysis::NormalModes modes = analysis::undamped_modes(e.linear);
  ASSERT_EQ(modes.modes.size(), 1u);
  const double w = std::sqrt(swing_omega_squared());
  // The equilibrium is found to ~1e-15 rad; the frequency moves with it only quadratically.
  EXPECT_NEAR(modes.modes[0].natural_frequency, w, 1e-12 * w);
}

TEST(ConstrainedLinearization, AnIndependentCoordinateCanBeChosen) {
  analysis::LinearizationOptions options;
  options.independent = {"pivot2.angle"};
  const analysis::LinearModel lin = analysis::linearize(swing().model, hanging(), options);
  ASSERT_EQ(lin.system.state_names(),
            (std::vector<std::string>{"pivot2.angle", "pivot2.angle_rate"}));
  // The second arm turns with the first: the same frequency.
  EXPECT_NEAR(lin.system.A()(1, 0), -swing_omega_squared(), 1e-13 * swing_omega_squared());
  // The seat's position as an output: the arms' tips at L (cos θ, sin θ), so about θ = −π/2,
  // δx = L δθ and δy = 0.
  options.outputs = {"seat_x.x", "seat_x.y"};
  options.output_specs = swing().outputs;
  const analysis::LinearModel out = analysis::linearize(swing().model, hanging(), options);
  EXPECT_NEAR(out.system.C()(0, 0), 0.25, 1e-10);
  EXPECT_NEAR(out.system.C()(1, 0), 0.0, 1e-10);
  options.independent = {"pivot3.angle"};
  EXPECT_THROW(analysis::linearize(swing().model, hanging(), options), InvalidArgument);
}

TEST(ConstrainedLinearization, ThePointIsMadeConsistentFirst) {
  // The seat's angle given 10° off: the point used closes the loop.
  analysis::OperatingPoint p = hanging();
  p.q[q_of("seat_pin")] += 10 * pi / 180;
  const analysis::LinearModel lin = analysis::linearize(swing().model, p);
  const VecX& q = lin.point.q;
  EXPECT_NEAR(q[q_of("pivot1")] + q[q_of("seat_pin")], 0.0, 1e-12);  // the seat level
  EXPECT_NEAR(q[q_of("pivot2")], q[q_of("pivot1")], 1e-12);          // the arms parallel
}

// An upright thin disk (m = 1 kg, R = 0.1 m) rolling along x at spin rate Ω, on a chain of
// joints — x, y, height, heading, lean, spin — so that the steady motion's moving coordinates
// (x, y, the spin angle) are cyclic and its linearization is the same at every instant (on a
// free joint the body-fixed tangent coordinates turn with the spin, and the instantaneous A says
// nothing about stability).
io::ModelFile rolling_disk(double spin) {
  const double R = 0.1;
  const std::string text =
      fmt::format(R"(
name: upright disk
gravity: [0, 0, -9.81]
bodies:
  - {{name: bx, mass: 0}}
  - {{name: by, mass: 0}}
  - {{name: bz, mass: 0}}
  - {{name: bh, mass: 0}}
  - {{name: bl, mass: 0}}
  - {{name: coin, shape: thin_disk, mass: 1.0, radius: {R}, euler: {{sequence: XYZ, angles_deg: [90, 0, 0]}}}}
joints:
  - {{name: slide_x, type: prismatic, parent: world, child: bx, axis: [1, 0, 0], v0: {V}}}
  - {{name: slide_y, type: prismatic, parent: bx, child: by, axis: [0, 1, 0]}}
  - {{name: lift, type: prismatic, parent: by, child: bz, axis: [0, 0, 1], q0: {R}}}
  - {{name: heading, type: revolute, parent: bz, child: bh, axis: [0, 0, 1]}}
  - {{name: lean, type: revolute, parent: bh, child: bl, axis: [1, 0, 0]}}
  - {{name: spin, type: revolute, parent: bl, child: coin, axis: [0, 1, 0], v0: {W}}}
constraints:
  - {{name: floor, type: rolling, body: coin, shape: disk, radius: {R}, axis: [0, 1, 0],
     normal: [0, 0, 1]}}
)",
                  fmt::arg("R", R), fmt::arg("W", spin), fmt::arg("V", R * spin));
  return io::parse_model_file(text, "upright_disk.yaml", ".");
}

// ±sqrt(A m g R − C (C + m R²) Ω²) / sqrt(A (A + m R²)) (the header comment).
double lean_eigenvalue_squared(double spin) {
  const double m = 1.0, R = 0.1, g = 9.81, A = m * R * R / 4, C = m * R * R / 2;
  return (A * m * g * R - C * (C + m * R * R) * spin * spin) / (A * (A + m * R * R));
}

TEST(ConstrainedLinearization, UprightRollingDiskLeansAsTheClosedFormSays) {
  for (const double spin : {15.0, 3.0}) {
    SCOPED_TRACE(spin);
    const io::ModelFile file = rolling_disk(spin);
    analysis::LinearizationOptions options;
    options.independent = {"heading.angle", "lean.angle", "spin.angle"};
    const analysis::LinearModel lin =
        analysis::linearize(file.model, analysis::initial_operating_point(file.model), options);
    // Six coordinates less the height: 5 configuration states; less the two no-slip rows: 3
    // velocity states, the heading's, lean's and spin's rates. No second-order form.
    EXPECT_EQ(lin.coordinates.size(), 5u);
    EXPECT_EQ(lin.velocity_coordinates.size(), 3u);
    EXPECT_EQ(lin.system.state_names().back(), "spin.angle_rate");
    EXPECT_EQ(lin.mass.size(), 0);
    EXPECT_THROW(analysis::undamped_modes(lin), InvalidArgument);

    const Eigen::VectorXcd lambda = lin.system.A().eigenvalues();
    const double l2 = lean_eigenvalue_squared(spin);
    const std::complex<double> expected =
        l2 >= 0 ? std::complex<double>(std::sqrt(l2), 0) : std::complex<double>(0, std::sqrt(-l2));
    // The lean pair is the largest; the others are the cyclic coordinates' and the conserved
    // quantities' zeros.
    std::vector<std::complex<double>> sorted(lambda.data(), lambda.data() + lambda.size());
    std::sort(sorted.begin(), sorted.end(),
              [](auto a, auto b) { return std::abs(a) > std::abs(b); });
    const double scale = std::abs(expected);
    for (int k = 0; k < 2; ++k) {
      const std::complex<double> l = sorted[static_cast<std::size_t>(k)];
      EXPECT_NEAR(std::abs(l.real()), expected.real(), 1e-12 * scale);
      EXPECT_NEAR(std::abs(l.imag()), expected.imag(), 1e-12 * scale);
    }
    // The zeros form a Jordan block, which round-off ε of A splits by ~ε^(1/2) ≈ 1.5e-8 of the
    // scale (measured 1.2e-10).
    EXPECT_LT(std::abs(sorted[2]), 1e-7 * scale);
  }
}

// A's rows analytically (constraint_derivatives and the chart's maps) against Richardson
// differences along the chart (of step `angle_step`; 0: linearize's automatic 1e-3 rad), on a
// model at a state with velocities from `seed`, made consistent by linearize. Returns the
// largest difference relative to A's largest entry.
double analytic_against_differences(const model::Model& model, unsigned seed,
                                    double angle_step = 0.0) {
  analysis::OperatingPoint point = analysis::initial_operating_point(model);
  std::mt19937 rng(seed);
  for (Eigen::Index i = 0; i < point.v.size(); ++i)
    point.v[i] = std::uniform_real_distribution<double>(-1.5, 1.5)(rng);
  analysis::LinearizationOptions options;
  const analysis::LinearModel analytic = analysis::linearize(model, point, options);
  options.derivatives = analysis::LinearizationOptions::Derivatives::differences;
  options.angle_step = angle_step;
  const analysis::LinearModel differences = analysis::linearize(model, point, options);
  const MatX& A = analytic.system.A();
  EXPECT_EQ(A.rows(), differences.system.A().rows());
  EXPECT_TRUE(A.allFinite());
  const double worst = (A - differences.system.A()).cwiseAbs().maxCoeff();
  return worst / std::max(1.0, A.cwiseAbs().maxCoeff());
}

// A spatial loop: a crank turning about z, a coupler on a ball or universal joint at its tip
// reaching out at 45°, a rocker turning about x, the coupler's tip pinned to the rocker's by a
// point closure (closed at q = 0 as written, its three rows independent there). `coupler_joint`:
// the coupler joint's type and axes.
std::string spatial_loop_text(const char* coupler_joint) {
  return fmt::format(R"(name: spatial loop
gravity: [0, -9.81, 0]
bodies:
  - {{name: crank, shape: slender_rod, mass: 0.2, length: 0.1, position: [0.05, 0, 0],
     euler: {{sequence: XYZ, angles_deg: [0, 90, 0]}}}}
  - {{name: coupler, shape: box, mass: 0.3, size: [0.2, 0.04, 0.03], position: [0.075, 0.075, 0],
     euler: {{sequence: XYZ, angles_deg: [0, 0, 45]}}}}
  - {{name: rocker, shape: slender_rod, mass: 0.2, length: 0.1, position: [0, 0, -0.05]}}
joints:
  - {{name: crank_pin, type: revolute, parent: world, child: crank, axis: [0, 0, 1]}}
  - {{name: coupler_joint, {}, parent: crank, child: coupler,
     in_parent: {{position: [0.1, 0, 0]}}}}
  - {{name: rocker_pin, type: revolute, parent: world, child: rocker, axis: [1, 0, 0],
     in_parent: {{position: [0.25, 0.15, 0.1]}}}}
constraints:
  - {{name: tip, type: point, body_a: coupler, point_a: [0.15, 0.15, 0], body_b: rocker,
     point_b: [0, 0, -0.1]}}
)",
                     coupler_joint);
}

// Richardson's error is ~1e-12 of A's scale where the chart bends gently (measured ≤ 2e-12 on
// these loops at 1e-3 rad), so 1e-10 leaves a hundredfold margin. The ten-link V loop starts with
// each half's links in line, where the chart bends sharply (entries of A near 5e3): at 1e-3 rad
// the differences are off by 5e-5 relative, at 1e-4 by 5e-9, at 3e-5 by under 7e-11 — they
// converge on the analytic A, and are compared at 3e-5 rad with 1e-9.
TEST(ConstrainedLinearization, AnalyticDerivativesAgreeWithDifferencesOnLoopsWhileMoving) {
  struct Case {
    const char* name;
    std::string text;
    double angle_step, tolerance;
  };
  const std::vector<Case> cases = {
      {"four-bar", test::four_bar_text(), 0.0, 1e-10},
      {"ten-link loop", test::v_loop_text(10), 3e-5, 1e-9},
      {"spatial loop, ball", spatial_loop_text("type: ball"), 0.0, 1e-10},
      {"spatial loop, universal",
       spatial_loop_text("type: universal, axis: [0, 0, 1], axis2: [0, 1, 0]"), 0.0, 1e-10}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    const io::ModelFile file = io::parse_model_file(c.text, "loop.yaml", ".");
    for (unsigned seed = 1; seed <= 3; ++seed)
      EXPECT_LT(analytic_against_differences(file.model, seed, c.angle_step), c.tolerance);
  }
}

// Every bundled example with freedom left (the prescribed four-bar and slider-crank and the rod
// on its driven shaft have none): measured ≤ 1.4e-12.
TEST(ConstrainedLinearization, AnalyticDerivativesAgreeWithDifferencesOnEveryExampleWhileMoving) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator("examples/constraints"))
    files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  int compared = 0;
  for (const std::filesystem::path& path : files) {
    SCOPED_TRACE(path.string());
    const io::ModelFile file = io::read_model_file(path.string());
    try {
      analysis::linearize(file.model, analysis::initial_operating_point(file.model));
    } catch (const InvalidArgument&) {
      continue;  // no freedom
    }
    for (unsigned seed = 1; seed <= 3; ++seed) {
      EXPECT_LT(analytic_against_differences(file.model, seed), 1e-10);
    }
    ++compared;
  }
  EXPECT_GE(compared, 6);
}

TEST(ConstrainedLinearization, PrescribedInputsAreRefused) {
  // The driven four-bar: its crank's signal is an input that would move the closure.
  const io::ModelFile file = io::read_model_file("examples/constraints/four_bar.yaml");
  analysis::LinearizationOptions options;
  options.inputs = {"crank_angle"};
  EXPECT_THROW(
      analysis::linearize(file.model, analysis::initial_operating_point(file.model), options),
      InvalidArgument);
  // By default they are left out: Beer 18.3's rod on its driven shaft is refused for what it is,
  // a mechanism its wire leaves no freedom, not for its drive's signal.
  const io::ModelFile rod = io::read_model_file("examples/constraints/rod_on_rotating_shaft.yaml");
  try {
    analysis::linearize(rod.model, analysis::initial_operating_point(rod.model));
    FAIL() << "a mechanism without freedom linearized";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("no freedom"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace momenta
