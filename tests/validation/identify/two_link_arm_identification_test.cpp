// A two-link arm's base inertial parameters from torques the textbook's closed form gives (an
// independent route: Spong's equations, not momenta's dynamics), with seeded Gaussian noise.
#include <random>

#include <gtest/gtest.h>

#include "momenta/identify/inertia_estimate.hpp"
#include "momenta_test/two_link_arm.hpp"

namespace momenta::identify {
namespace {

// N samples of an exciting motion (angles over the circle, rates to 2 rad/s, accelerations to
// 5 rad/s²) and the closed form's torques plus noise of σ (N·m) on each joint.
InertiaSamples closed_form_samples(const test::TwoLinkArm& arm, int N, double sigma,
                                   std::mt19937& rng) {
  std::uniform_real_distribution<double> angle(-M_PI, M_PI), rate(-2, 2), acc(-5, 5);
  std::normal_distribution<double> noise(0.0, sigma);
  InertiaSamples s{MatX(N, 2), MatX(N, 2), MatX(N, 2), MatX(N, 2), {}};
  for (int i = 0; i < N; ++i) {
    const Eigen::Vector2d q(angle(rng), angle(rng)), v(rate(rng), rate(rng)), a(acc(rng), acc(rng));
    s.q.row(i) = q;
    s.v.row(i) = v;
    s.vdot.row(i) = a;
    s.tau.row(i) = arm.torque(q, v, a) + Eigen::Vector2d(noise(rng), noise(rng));
  }
  return s;
}

// β in the textbook's terms, in base_parameters' order (see base_parameters_test).
VecX textbook_beta(const test::TwoLinkArm& a) {
  return (VecX(6) << 0.0, -(a.m1 * a.lc1 + a.m2 * a.l1),
          a.I1 + a.m1 * a.lc1 * a.lc1 + a.m2 * a.l1 * a.l1, 0.0, -a.m2 * a.lc2,
          a.I2 + a.m2 * a.lc2 * a.lc2)
      .finished();
}

// Exact torques: the estimate is the textbook's β to round-off of the stacked solve.
TEST(InertiaEstimate, FromExactTorquesIsTheClosedFormsBeta) {
  const test::TwoLinkArm arm;
  const Model model = arm.model();
  std::mt19937 rng(11);
  const InertiaSamples samples = closed_form_samples(arm, 40, 0.0, rng);
  const InertiaEstimate e = estimate_inertia(model, samples, base_parameters(model));
  EXPECT_LT((e.beta - textbook_beta(arm)).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_LT(e.residual_rms.maxCoeff(), 1e-11);
  // The fitted efforts are the measured ones (the report's red line on the grey).
  EXPECT_LT((e.fitted - samples.tau).cwiseAbs().maxCoeff(), 1e-11);
  // Every figure finite, the correlations too (standard errors at round-off, or zero).
  EXPECT_TRUE(e.correlation.allFinite() && e.standard_error.allFinite() && e.lower.allFinite());
  EXPECT_TRUE(e.whiteness_p.allFinite() && e.excitation.allFinite());
  for (const PhysicalConsistency& c : e.consistency) EXPECT_TRUE(c.consistent()) << c.verdict();
}

// σ = 0.02 N·m on 200 samples: each estimate within 4 standard errors of the truth (a test that
// fails by chance once in ~16 000; the intervals' calibration is the coverage test's), the noise
// each joint had found to 10 % (200 draws: its estimate's spread is ~5 %), and the residuals
// that size.
TEST(InertiaEstimate, RecoversTheTwoLinkArmsBaseParametersFromNoisyTorques) {
  const test::TwoLinkArm arm;
  const Model model = arm.model();
  std::mt19937 rng(12);
  const double sigma = 0.02;
  const InertiaEstimate e =
      estimate_inertia(model, closed_form_samples(arm, 200, sigma, rng), base_parameters(model));
  const VecX truth = textbook_beta(arm);
  for (int k = 0; k < 6; ++k) {
    EXPECT_LT(std::abs(e.beta[k] - truth[k]), 4 * e.standard_error[k])
        << e.base.describe(model, k) << ": " << e.beta[k] << " ± " << e.standard_error[k];
    EXPECT_LT(e.standard_error[k], 0.01);
    EXPECT_LE(e.lower[k], e.beta[k]);
    EXPECT_GE(e.upper[k], e.beta[k]);
  }
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(e.noise[j], sigma, 0.1 * sigma);
    EXPECT_NEAR(e.residual_rms[j], sigma, 0.1 * sigma);
  }
  EXPECT_EQ(e.degrees_of_freedom, 400 - 6);
  EXPECT_NEAR(e.correlation(0, 0), 1.0, 1e-14);
  for (const PhysicalConsistency& c : e.consistency) EXPECT_TRUE(c.consistent()) << c.verdict();
}

// The 95 % intervals are honest: over 1000 noise draws of a 60-sample experiment, the six
// intervals hold the truth 93–97 % of the time (6000 intervals: the binomial spread about 95 %
// is 0.28 %; the draws of one experiment's six are correlated, so ±2 % leaves ~3σ or more).
TEST(InertiaEstimate, TheNinetyFivePercentIntervalsHoldTheTruth93To97PercentOfDraws) {
  const test::TwoLinkArm arm;
  const Model model = arm.model();
  const BaseParameters base = base_parameters(model);
  const VecX truth = textbook_beta(arm);
  std::mt19937 rng(13);
  int held = 0, total = 0;
  for (int draw = 0; draw < 1000; ++draw) {
    const InertiaEstimate e =
        estimate_inertia(model, closed_form_samples(arm, 60, 0.05, rng), base);
    for (int k = 0; k < 6; ++k, ++total) held += e.lower[k] <= truth[k] && truth[k] <= e.upper[k];
  }
  const double coverage = double(held) / total;
  EXPECT_GE(coverage, 0.93);
  EXPECT_LE(coverage, 0.97);
  RecordProperty("coverage", std::to_string(coverage));
  std::printf("95 %% intervals held the truth in %.2f %% of %d\n", 100 * coverage, total);
}

// A CAD guess as the prior (two_link_arm.yaml's): its links' moments about x and z, which the
// joints never feel, would break the triangle inequality beside the estimated moment about y
// (0.02 + 0.13 < 0.156 kg·m² for the upper link); the completion chooses them so that each link
// can exist, and the completed π still gives the estimate's β exactly.
TEST(InertiaEstimate, CompletesEachBodySoThatItCanExist) {
  const test::TwoLinkArm arm;
  test::TwoLinkArm cad = arm;
  cad.m1 = 2.2, cad.lc1 = 0.33, cad.I1 = 0.13, cad.m2 = 1.2, cad.lc2 = 0.42, cad.I2 = 0.05;
  const Model model = cad.model();
  std::mt19937 rng(15);
  const InertiaEstimate e =
      estimate_inertia(model, closed_form_samples(arm, 200, 0.02, rng), base_parameters(model));
  for (const PhysicalConsistency& c : e.consistency) EXPECT_TRUE(c.consistent()) << c.verdict();
  EXPECT_LT((e.base.base_of(e.parameters) - e.beta).cwiseAbs().maxCoeff(), 1e-12);
  // The lower link's regrouped mass stays the model's.
  EXPECT_EQ(e.parameters[10], 1.2);
}

// No choice of what the joints never feel rescues links whose regrouped mass (from the model) is
// wrong: with lower.m = 0.5 kg instead of 1.5, the lower link's estimated first moment and moment
// about the elbow need m c² = 0.6²/0.5 = 0.72 kg·m² > I_yy = 0.3 kg·m², and the upper link,
// credited 0.8 · 1 kg of first moment and 0.64 · 1 kg·m² of moment the lower mass should carry,
// has I_yy = 1.325 − 0.32 = 1.005 kg·m² about the shoulder against m₁ c² = 2 · 0.75² = 1.125: both
// negative about their centres (the upper by −0.12 kg·m²).
TEST(InertiaEstimate, SaysWhenNoBodyHasTheEstimate) {
  const test::TwoLinkArm arm;
  test::TwoLinkArm prior = arm;
  prior.m2 = 0.5;
  const Model model = prior.model();
  std::mt19937 rng(16);
  const InertiaEstimate e =
      estimate_inertia(model, closed_form_samples(arm, 200, 0.02, rng), base_parameters(model));
  for (const PhysicalConsistency& c : e.consistency) {
    EXPECT_TRUE(c.positive_mass);
    EXPECT_FALSE(c.positive_moments) << c.verdict();
  }
  EXPECT_NEAR(e.consistency[0].principal_moments[0], 1.005 - 1.125, 0.005);
}

// 10 s at 50 Hz of a sum-of-sines motion (the bundled log's), efforts from the closed form plus
// viscous joint friction b θ̇ (which the regressor has no column for) and noise σ.
InertiaSamples logged_samples(const test::TwoLinkArm& arm, double friction, double sigma,
                              std::mt19937& rng) {
  const double terms[2][3][3] = {{{1.2, 0.9, 0.0}, {0.5, 2.3, 1.0}, {0.25, 4.1, 2.0}},
                                 {{1.0, 1.3, 0.5}, {0.6, 2.9, 2.5}, {0.3, 5.2, 0.3}}};
  std::normal_distribution<double> noise(0.0, sigma);
  const int N = 501;
  InertiaSamples s{MatX(N, 2), MatX(N, 2), MatX(N, 2), MatX(N, 2), {}};
  for (int i = 0; i < N; ++i) {
    const double t = 0.02 * i;
    Eigen::Vector2d q = Eigen::Vector2d::Zero(), v = q, a = q;
    for (int k = 0; k < 2; ++k) {
      for (const auto& [amplitude, w, phase] : terms[k]) {
        q[k] += amplitude * std::sin(w * t + phase);
        v[k] += amplitude * w * std::cos(w * t + phase);
        a[k] -= amplitude * w * w * std::sin(w * t + phase);
      }
    }
    s.q.row(i) = q, s.v.row(i) = v, s.vdot.row(i) = a;
    s.tau.row(i) = arm.torque(q, v, a) + friction * v + Eigen::Vector2d(noise(rng), noise(rng));
  }
  return s;
}

// White noise leaves white residuals (Ljung–Box p above 0.01: a 1 % chance per effort for a
// seed, fixed here); the same log with viscous friction of 0.3 N·m·s/rad, which the model lacks,
// leaves residuals that follow the rates — correlated, p below 1e-6 — while the RMS alone (about
// 0.3 N·m against σ = 0.02) could be taken for noisy sensors.
TEST(InertiaEstimate, ResidualsThatAreNotWhiteShowAMissingFriction) {
  const test::TwoLinkArm arm;
  const Model model = arm.model();
  const BaseParameters base = base_parameters(model);
  std::mt19937 rng(17);
  const InertiaEstimate right = estimate_inertia(model, logged_samples(arm, 0.0, 0.02, rng), base);
  const InertiaEstimate wrong = estimate_inertia(model, logged_samples(arm, 0.3, 0.02, rng), base);
  EXPECT_EQ(right.whiteness_lags, 20);
  for (int j = 0; j < 2; ++j) {
    EXPECT_GT(right.whiteness_p[j], kWhitenessLevel) << j;
    EXPECT_LT(wrong.whiteness_p[j], 1e-6) << j;
  }
}

// An arm moved slowly (rates and accelerations 1/100 of the others') is weighed, not
// accelerated: gravity decides the first moments, but the moments of inertia enter only through
// M v̇ and the velocity terms, 10⁻² and 10⁻⁴ of what they were — the scaled regressor's
// condition number grows more than tenfold, past kPoorExcitation (11 → 1000 for seed 1), and the
// least-determined combination is the links' moments about their joints (upper.I_yy + 0.64·lower.m,
// lower.I_yy).
TEST(InertiaEstimate, SaysWhatTheDataBarelyDetermines) {
  const test::TwoLinkArm arm;
  const Model model = arm.model();
  const BaseParameters base = base_parameters(model);
  std::mt19937 rng(18);
  InertiaSamples slow = closed_form_samples(arm, 200, 0.0, rng);
  slow.v *= 0.01;
  slow.vdot *= 0.01;
  for (Eigen::Index i = 0; i < slow.q.rows(); ++i) {
    slow.tau.row(i) = arm.torque(slow.q.row(i), slow.v.row(i), slow.vdot.row(i));
  }
  const InertiaEstimate moving =
      estimate_inertia(model, closed_form_samples(arm, 200, 0.0, rng), base);
  const InertiaEstimate weighed = estimate_inertia(model, slow, base);
  EXPECT_NEAR(moving.excitation[0], 1.0, 1e-15);
  EXPECT_GT(weighed.condition_number, 10 * moving.condition_number)
      << moving.condition_number << " " << weighed.condition_number;
  EXPECT_LT(moving.condition_number, kPoorExcitation);
  EXPECT_GT(weighed.condition_number, kPoorExcitation);
  const VecX& v = weighed.least_determined;
  EXPECT_GT(std::hypot(v[2], v[5]), 0.99) << v.transpose();
  EXPECT_NEAR(v.norm(), 1.0, 1e-12);
}

TEST(InertiaEstimate, SaysWhatIsWrongWithTheData) {
  const test::TwoLinkArm arm;
  const Model model = arm.model();
  const BaseParameters base = base_parameters(model);
  std::mt19937 rng(14);
  InertiaSamples s = closed_form_samples(arm, 20, 0.01, rng);
  s.tau(7, 1) = std::nan("");
  try {
    estimate_inertia(model, s, base);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_STREQ(e.what(),
                 "estimate_inertia: tau row 7 column 1 is nan: measured data must be finite");
  }
  const InertiaSamples two = closed_form_samples(arm, 3, 0.01, rng);
  try {
    estimate_inertia(model, two, base);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("3 samples × 2 joint coordinates give 6 equations for 6 "
                                         "base parameters; at least 4 samples are needed"),
              std::string::npos)
        << e.what();
  }
  // An arm weighed at rest in one pose: two equations, repeated, for six parameters.
  InertiaSamples still = closed_form_samples(arm, 30, 0.01, rng);
  for (int i = 0; i < 30; ++i) {
    still.q.row(i) = still.q.row(0);
    still.v.row(i).setZero();
    still.vdot.row(i).setZero();
  }
  try {
    estimate_inertia(model, still, base);
    FAIL();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("the samples excite only 2 of the 6 base parameters"),
              std::string::npos)
        << e.what();
  }
  s.q = MatX(20, 3);
  EXPECT_THROW(estimate_inertia(model, s, base), InvalidArgument);
}

}  // namespace
}  // namespace momenta::identify
