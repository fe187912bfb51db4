// The operating point a linear analysis is taken about (analysis/operating_point.hpp), the rule
// the command line, the report and Python share: `auto` on the bundled examples chooses as the
// header says — the heavy top's steady precession (its nutation, validated against a simulated
// top in top_examples_test), the sleeping top's permanent rotation (Euler–Poisson), the rolling
// coin's steady motion, the double pendulum's static equilibrium (it starts horizontal), the
// pendulum's initial state at rest, the rotor's steady motion — each the analysis the named
// choice gives, and a mode's shape mapped onto the joints as the kind moves them.

#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/operating_point.hpp"
#include "momenta/common/error.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta {
namespace {

using analysis::LinearAnalysisKind;
using analysis::OperatingPointChoice;

model::Model example(const std::string& name) {
  return io::read_model_file(test::source_dir() + "/examples/" + name + ".yaml").model;
}

analysis::LinearAnalysis about(const model::Model& model, OperatingPointChoice choice) {
  return analysis::linear_analysis_about(model, choice);
}

// The eigenvalues of the panel's A, sorted by imaginary part then real part.
std::vector<std::complex<double>> poles(const analysis::LinearAnalysis& r) {
  std::vector<std::complex<double>> p;
  for (const analysis::Mode& m : analysis::modes(r.linear.system).modes) p.push_back(m.eigenvalue);
  std::sort(p.begin(), p.end(), [](auto a, auto b) {
    return a.imag() != b.imag() ? a.imag() < b.imag() : a.real() < b.real();
  });
  return p;
}

TEST(OperatingPoint, NamesAreTheFrontEndsWords) {
  EXPECT_EQ(analysis::operating_point_choice("auto"), OperatingPointChoice::automatic);
  EXPECT_EQ(analysis::operating_point_choice("steady"), OperatingPointChoice::steady);
  EXPECT_FALSE(analysis::operating_point_choice("state.json").has_value());
  EXPECT_STREQ(analysis::operating_point_choice_name(OperatingPointChoice::automatic), "auto");
}

// The heavy top: auto on a top in steady precession is that precession — stable, the
// nutation ±i ω_n with ω_n² = [(I₃ω₃ − 2 I₁ φ̇ cos θ)² + I₁² φ̇² sin² θ]/I₁² (Routh), computed here
// from the top's own I₁, I₃, spin and precession — not the upright top at rest.
TEST(OperatingPoint, AutoOnAPrecessingTopIsItsSteadyPrecession) {
  const model::Model top = example("heavy_top");
  const analysis::LinearAnalysis r = about(top, OperatingPointChoice::automatic);
  ASSERT_EQ(r.kind, LinearAnalysisKind::steady_precession) << r.about;
  ASSERT_TRUE(r.precession.has_value());
  const analysis::SteadyPrecession& p = *r.precession;
  const double c = std::cos(p.tilt), s = std::sin(p.tilt), phi = p.precession;
  const double wn =
      std::sqrt(std::pow(p.I3 * p.spin - 2 * p.I1 * phi * c, 2) + std::pow(p.I1 * phi * s, 2)) /
      p.I1;
  const auto lambda = poles(r);
  ASSERT_EQ(lambda.size(), 2u);
  EXPECT_NEAR(lambda[1].imag(), wn, 1e-12 * wn);
  EXPECT_NEAR(lambda[0].imag(), -wn, 1e-12 * wn);
  EXPECT_EQ(lambda[1].real(), 0.0);
  EXPECT_NE(r.about.find("steady precession of the symmetric top 'top'"), std::string::npos)
      << r.about;
  EXPECT_NE(r.about.find("slow root"), std::string::npos) << r.about;
  // The same as asked for by name; the nutation tilts the top about the line of nodes, across
  // the vertical and its axis: a unit rotation in the ball joint's tangent, no spin about e.
  const analysis::LinearAnalysis steady = about(top, OperatingPointChoice::steady);
  EXPECT_EQ(steady.kind, r.kind);
  EXPECT_EQ(poles(steady), lambda);
  const Vec3 tilt = r.shape_to_tangent.col(0).head<3>();
  EXPECT_NEAR(tilt.norm(), 1.0, 1e-15);
  EXPECT_NEAR(tilt.dot(p.axis_B), 0.0, 1e-15);
  // Asked for the initial state, the top is linearized where it is, and moving.
  const analysis::LinearAnalysis initial = about(top, OperatingPointChoice::initial);
  EXPECT_EQ(initial.kind, LinearAnalysisKind::joint_coordinates);
  EXPECT_GT(initial.largest_speed, 1.0);
}

// The sleeping top: Euler–Poisson's permanent rotation about the vertical, above the critical
// spin (182.63 rad/s at 300): stable, the eigenvalues steady_motion_modes gives.
TEST(OperatingPoint, AutoOnASleepingTopIsItsPermanentRotation) {
  const model::Model top = example("sleeping_top");
  const analysis::LinearAnalysis r = about(top, OperatingPointChoice::automatic);
  ASSERT_EQ(r.kind, LinearAnalysisKind::spinning_body) << r.about;
  ASSERT_TRUE(r.spinning_modes.has_value());
  EXPECT_TRUE(r.spinning_modes->stable);
  const analysis::SteadyMotionModes direct = analysis::steady_motion_modes(
      analysis::spinning_body(top, analysis::initial_operating_point(top)));
  EXPECT_MATRIX_NEAR(r.linear.system.A(), direct.A, 0.0);
  // Every pole of the panel is one of the body's (or a conserved quantity's zero).
  for (const auto& z : poles(r)) {
    if (std::abs(z) < 1e-9) continue;
    double nearest = INFINITY;
    for (const auto& w : direct.eigenvalues) {
      nearest = std::min({nearest, std::abs(z - w), std::abs(z - std::conj(w))});
    }
    EXPECT_LT(nearest, 1e-9 * std::abs(z)) << z;
  }
  // A mode's tilt is across the vertical (the spin about it moves nothing).
  EXPECT_NEAR((r.shape_to_tangent.block<3, 3>(0, 3) * r.spinning_body->up_B).norm(), 0.0, 1e-15);
}

TEST(OperatingPoint, AutoOnARollingCoinIsItsSteadyMotion) {
  const model::Model coin = example("constraints/rolling_coin");
  const analysis::LinearAnalysis r = about(coin, OperatingPointChoice::automatic);
  ASSERT_EQ(r.kind, LinearAnalysisKind::rolling_steady) << r.about;
  const analysis::LinearAnalysis steady = about(coin, OperatingPointChoice::steady);
  EXPECT_EQ(poles(r), poles(steady));
  EXPECT_FALSE(r.has_channels());
}

// The double pendulum starts with its upper rod horizontal, at rest: not an equilibrium. auto
// moves to the static equilibrium found from it — hanging straight down, ω² = (2 ∓ √2) g/L — and
// says why.
TEST(OperatingPoint, AutoOffAStateInMotionIsTheStaticEquilibrium) {
  const model::Model pendulum = example("double_pendulum");
  const analysis::LinearAnalysis r = about(pendulum, OperatingPointChoice::automatic);
  ASSERT_EQ(r.kind, LinearAnalysisKind::joint_coordinates);
  ASSERT_TRUE(r.equilibrium.has_value());
  EXPECT_EQ(r.about.rfind("the static equilibrium found from the initial state (the initial "
                          "state is not one: its largest acceleration is",
                          0),
            0u)
      << r.about;
  std::vector<double> omega;
  for (const auto& z : poles(r))
    if (z.imag() > 0) omega.push_back(z.imag());
  ASSERT_EQ(omega.size(), 2u);
  std::sort(omega.begin(), omega.end());
  EXPECT_NEAR(omega[0], std::sqrt((2 - std::sqrt(2.0)) * 9.81), 1e-6);
  EXPECT_NEAR(omega[1], std::sqrt((2 + std::sqrt(2.0)) * 9.81), 1e-6);
  EXPECT_EQ(poles(about(pendulum, OperatingPointChoice::equilibrium)), poles(r));
  // A pendulum released at rest off its equilibrium keeps its initial state when asked for it.
  const analysis::LinearAnalysis initial = about(pendulum, OperatingPointChoice::initial);
  EXPECT_EQ(initial.about, "the initial state");
  EXPECT_GT(initial.largest_acceleration, 1.0);
}

TEST(OperatingPoint, AutoAtRestIsTheInitialStateAndOnARotorItsSteadyMotion) {
  const model::Model quarter_car = example("quarter_car");
  const analysis::LinearAnalysis at_rest = about(quarter_car, OperatingPointChoice::automatic);
  EXPECT_EQ(at_rest.about, "the initial state");
  EXPECT_TRUE(at_rest.has_channels());
  const model::Model rotor = example("rotor_on_bearings");
  const analysis::LinearAnalysis r = about(rotor, OperatingPointChoice::automatic);
  ASSERT_EQ(r.kind, LinearAnalysisKind::joint_steady) << r.about;
  EXPECT_EQ(r.about.rfind("the steady motion: spin.angle turning at", 0), 0u) << r.about;
  EXPECT_EQ(poles(r), poles(about(rotor, OperatingPointChoice::steady)));
}

TEST(OperatingPoint, StatesAndChoicesThatDoNotApplyAreRefused) {
  const model::Model pendulum = example("pendulum");
  EXPECT_THROW(about(pendulum, OperatingPointChoice::steady), InvalidArgument);  // nothing turns
  EXPECT_THROW(about(pendulum, OperatingPointChoice::given), InvalidArgument);   // no state
  analysis::OperatingPoint point = analysis::initial_operating_point(pendulum);
  const analysis::LinearAnalysis r =
      analysis::linear_analysis_about(pendulum, OperatingPointChoice::given, {}, point, "s.json");
  EXPECT_EQ(r.about, "s.json");
}

}  // namespace
}  // namespace momenta
