// Steady motions of a spinning body (analysis/steady_motion.hpp) against the closed forms: the
// sleeping top's stability threshold I₃²ω₃² > 4 I₁ m g l and its two precession frequencies
// (I₃ω₃ ± √(I₃²ω₃² − 4 I₁ m g l))/(2 I₁) seen from space (Goldstein §5.7; Beer & Johnston §18.10),
// for several I₃/I₁ — not only 1/4 — and its growth rate below the threshold; a free body's spin
// about each principal axis (Euler; the intermediate-axis growth rate n √((I₂−I₁)(I₃−I₂)/(I₁I₃))).

#include "momenta/analysis/steady_motion.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta_test/hand_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::analysis {
namespace {

using model::JointType;

constexpr double kG = 9.81;

// A top symmetric about its z axis on a ball at its tip: mass m, centre of mass l above the tip,
// moments I₁ (transverse) and I₃ (axial) about the tip; upright, spinning at ω₃.
model::Model upright_top(double m, double l, double I1, double I3) {
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -kG));
  b.add_body("top", inertia::MassProperties::from_inertia_about(
                        m, Vec3(0, 0, l), Vec3(I1, I1, I3).asDiagonal(), Vec3::Zero()));
  b.add_joint(momenta::test::make_joint("tip", JointType::spherical, "world", "top"));
  return b.build();
}

OperatingPoint spinning(const model::Model& model, const Vec3& w_B) {
  VecX q = model.initial_q();
  return {0.0, q, VecX(w_B)};
}

TEST(SteadyMotion, SleepingTopThresholdAndPrecessionFrequencies) {
  const double m = 1.0, l = 0.1, I1 = 0.05, mgl = m * kG * l;
  for (const double ratio : {0.25, 0.5, 1.0, 1.5}) {
    const double I3 = ratio * I1;
    const model::Model top = upright_top(m, l, I1, I3);
    const double critical = 2 * std::sqrt(I1 * mgl) / I3;
    for (const double factor : {0.7, 1.3, 3.0}) {
      const double w3 = factor * critical;
      const SteadyMotionModes r =
          steady_motion_modes(spinning_body(top, spinning(top, Vec3(0, 0, w3))));
      EXPECT_LT(r.residual, 1e-15);
      const double D = I3 * I3 * w3 * w3 - 4 * I1 * mgl;
      EXPECT_EQ(r.stable, D > 0) << "I3/I1 = " << ratio << ", ω3 = " << factor << " ω_c\n"
                                 << r.verdict;
      if (D > 0) {
        // Two oscillations seen from space, both turning with the spin.
        ASSERT_EQ(r.space_frequencies.size(), 2u) << r.verdict;
        const double slow = (I3 * w3 - std::sqrt(D)) / (2 * I1),
                     fast = (I3 * w3 + std::sqrt(D)) / (2 * I1);
        const double a = std::min(r.space_frequencies[0], r.space_frequencies[1]);
        const double b = std::max(r.space_frequencies[0], r.space_frequencies[1]);
        // Eigenvalues of a 6×6 of O(ω₃) entries: 1e-10 relative.
        EXPECT_REL_NEAR(a, slow, 1e-10) << "I3/I1 = " << ratio << ", factor " << factor;
        EXPECT_REL_NEAR(b, fast, 1e-10) << "I3/I1 = " << ratio << ", factor " << factor;
        EXPECT_EQ(r.whirl[0], "forward");
        EXPECT_EQ(r.whirl[1], "forward");
        EXPECT_NE(r.verdict.find("gyroscopically stabilized"), std::string::npos) << r.verdict;
      } else {
        EXPECT_REL_NEAR(r.growth_rate, std::sqrt(-D) / (2 * I1), 1e-10) << "I3/I1 = " << ratio;
        EXPECT_NE(r.verdict.find("below the critical"), std::string::npos) << r.verdict;
      }
    }
  }
}

TEST(SteadyMotion, HangingSpinningBodyIsStableAtAnySpeed) {
  // The centre of mass below the ball: stable without spin, and with it.
  const model::Model top = upright_top(1.0, -0.1, 0.05, 0.02);
  for (const double w3 : {0.0, 5.0, 300.0}) {
    const SteadyMotionModes r =
        steady_motion_modes(spinning_body(top, spinning(top, Vec3(0, 0, w3))));
    EXPECT_TRUE(r.stable) << w3;
  }
}

model::Model free_body(const Vec3& moments) {
  model::ModelBuilder b;
  b.set_gravity(Vec3(0, 0, -kG));
  b.add_body("racket", inertia::MassProperties(0.3, Vec3::Zero(), moments.asDiagonal()));
  b.add_joint(momenta::test::make_joint("free", JointType::free, "world", "racket"));
  return b.build();
}

TEST(SteadyMotion, FreeBodyAxisRules) {
  const Vec3 I(1.0, 2.0, 3.0);
  const model::Model racket = free_body(I);
  const double n = 4.0;
  const auto at = [&](const Vec3& w) {
    VecX v = VecX::Zero(6);
    v.head<3>() = w;
    return steady_motion_modes(spinning_body(racket, {0.0, racket.initial_q(), v}));
  };
  // Intermediate axis: grows like e^(σt), σ = n √((I₂−I₁)(I₃−I₂)/(I₁I₃)).
  const SteadyMotionModes middle = at(Vec3(0, n, 0));
  EXPECT_FALSE(middle.stable);
  EXPECT_REL_NEAR(middle.growth_rate, n * std::sqrt((I[1] - I[0]) * (I[2] - I[1]) / (I[0] * I[2])),
                  1e-12);
  EXPECT_NE(middle.verdict.find("intermediate"), std::string::npos) << middle.verdict;
  // Major axis: the wobble at n √((I₃−I₁)(I₃−I₂)/(I₁I₂)) seen from the body; stable with
  // dissipation too.
  const SteadyMotionModes major = at(Vec3(0, 0, n));
  EXPECT_TRUE(major.stable);
  ASSERT_EQ(major.eigenvalues.size(), 1u);
  EXPECT_REL_NEAR(major.eigenvalues[0].imag(),
                  n * std::sqrt((I[2] - I[0]) * (I[2] - I[1]) / (I[0] * I[1])), 1e-12);
  EXPECT_NE(major.verdict.find("major-axis rule"), std::string::npos) << major.verdict;
  // Minor axis: stable, but not once the body dissipates energy.
  const SteadyMotionModes minor = at(Vec3(n, 0, 0));
  EXPECT_TRUE(minor.stable);
  EXPECT_NE(minor.verdict.find("drifts to its major axis"), std::string::npos) << minor.verdict;
}

TEST(SteadyMotion, ASymmetricFreeBodyWobblesAtTheEulerFrequency) {
  // I₁ = I₂ = A, spin n about the symmetry axis: seen from the body the axis wobbles at
  // n (C − A)/A; seen from space the axis cones at C n / A (the body's H / A).
  const double A = 2.0, C = 3.0, n = 5.0;
  const model::Model disk = free_body(Vec3(A, A, C));
  VecX v = VecX::Zero(6);
  v[2] = n;
  const SteadyMotionModes r = steady_motion_modes(spinning_body(disk, {0.0, disk.initial_q(), v}));
  ASSERT_EQ(r.eigenvalues.size(), 1u);
  EXPECT_REL_NEAR(std::abs(r.eigenvalues[0].imag()), n * (C - A) / A, 1e-12);
  ASSERT_EQ(r.space_frequencies.size(), 1u);
  EXPECT_REL_NEAR(r.space_frequencies[0], C * n / A, 1e-12);
  EXPECT_EQ(r.whirl[0], "forward");
}

// Campbell diagrams of spinning tops: the whirls seen from space against the spin speed Ω, and
// the critical speeds where one crosses the 1× line. From I₁σ² − I₃Ωσ + m g l = 0 with σ = Ω:
// Ω_c² = m g l/(I₃ − I₁) — for a hanging top (l < 0) with I₁ > I₃, and for an upright flat top
// (I₃ > I₁, above its critical spin); an upright top with I₁ > I₃ has none.
TEST(SteadyMotion, CampbellDiagramCriticalSpeedsOfSpinningTops) {
  const double m = 1.0, I1 = 0.05;
  const auto critical_speeds = [&](double l, double I3, double from, double to) {
    const model::Model top = upright_top(m, l, I1, I3);
    const SpinningBody body = spinning_body(top, spinning(top, Vec3(0, 0, 1.0)));
    return campbell_diagram(body, from, to, 60);
  };
  const CampbellDiagram hanging = critical_speeds(-0.1, 0.02, 1.0, 20.0);
  ASSERT_EQ(hanging.critical_speeds.size(), 1u);
  EXPECT_REL_NEAR(hanging.critical_speeds[0].speed, std::sqrt(m * kG * 0.1 / (I1 - 0.02)), 1e-10);
  EXPECT_EQ(hanging.critical_speeds[0].whirl, "forward");
  // Each point: one backward and one forward whirl, the roots of I₁σ² ∓ I₃Ωσ − m g |l| = 0.
  const CampbellPoint& p = hanging.points[10];
  ASSERT_EQ(p.frequencies.size(), 2u);
  EXPECT_EQ(p.whirl[0], "backward");
  const double root = std::sqrt(0.02 * 0.02 * p.speed * p.speed + 4 * I1 * m * kG * 0.1);
  EXPECT_REL_NEAR(p.frequencies[0], (root - 0.02 * p.speed) / (2 * I1), 1e-10);
  EXPECT_REL_NEAR(p.frequencies[1], (root + 0.02 * p.speed) / (2 * I1), 1e-10);
  const CampbellDiagram flat = critical_speeds(0.1, 1.5 * I1, 6.0, 30.0);
  ASSERT_EQ(flat.critical_speeds.size(), 1u);
  EXPECT_REL_NEAR(flat.critical_speeds[0].speed, std::sqrt(m * kG * 0.1 / (0.5 * I1)), 1e-10);
  EXPECT_TRUE(critical_speeds(0.1, 0.5 * I1, 30.0, 300.0).critical_speeds.empty());
  EXPECT_THROW(critical_speeds(0.1, 0.5 * I1, 30.0, 10.0), InvalidArgument);
}

TEST(SteadyMotion, NotSteadyOrNotApplicableIsNamed) {
  // A tilted top spinning about its own axis is not steady in these variables.
  const model::Model top = upright_top(1.0, 0.1, 0.05, 0.02);
  OperatingPoint p = spinning(top, Vec3(0, 0, 100));
  p.q << std::cos(0.1), std::sin(0.1), 0, 0;  // 0.2 rad about x
  try {
    steady_motion_modes(spinning_body(top, p));
    FAIL() << "a tilted spinning top passed as steady";
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("not in a steady motion"), std::string::npos) << e.what();
  }
  model::ModelBuilder b;
  b.add_body("bob", inertia::MassProperties(1.0, Vec3(0, 0, -1), Mat3::Zero()));
  b.add_joint(momenta::test::make_joint("pin", JointType::revolute, "world", "bob"));
  EXPECT_THROW(spinning_body(b.build(), {0.0, VecX::Zero(1), VecX::Zero(1)}), InvalidArgument);
}

}  // namespace
}  // namespace momenta::analysis
