// Grey-box fits of the examples' logs (examples/identification/make_grey_box_logs.py: SciPy on
// the textbooks' equations, seeded noise): the parameters the logs were made with lie inside the
// fits' 95 % intervals, the residuals are white and as large as the noise put in.

#include <cmath>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "momenta/identify/grey_box.hpp"
#include "momenta/identify/identification_file.hpp"

namespace momenta::identify {
namespace {

const std::filesystem::path kExamples = "examples/identification";

GreyBoxEstimate fit_example(const std::string& file) {
  const GreyBoxProblem problem = read_identification_file(kExamples / file);
  return fit_grey_box(problem);
}

// The truth lies inside the 95 % interval, which is tight (its half-width a small fraction of the
// value): a fit that cannot fail by returning huge intervals.
void expect_recovered(const GreyBoxEstimate& e, int i, double truth, double largest_relative_se) {
  SCOPED_TRACE(e.names[std::size_t(i)]);
  EXPECT_LE(e.lower95[i], truth);
  EXPECT_GE(e.upper95[i], truth);
  EXPECT_LT(e.standard_error[i] / std::abs(e.value[i]), largest_relative_se);
  EXPECT_GT(e.standard_error[i], 0.0);
}

TEST(GreyBoxExamples, CruiseControlMassAndDragFromASpeedLogUnderAKnownForce) {
  const GreyBoxEstimate e = fit_example("cruise_control_identify.yaml");
  ASSERT_TRUE(e.converged) << e.termination;
  EXPECT_TRUE(e.identifiable);
  expect_recovered(e, 0, 1000.0, 0.02);  // m, kg
  expect_recovered(e, 1, 50.0, 0.02);    // b, N·s/m
  ASSERT_EQ(e.channels.size(), 1u);
  // σ estimated from the residuals: the 0.05 m/s put in, to its sampling spread (241 samples:
  // relative SD 1/√(2·239) ≈ 4.6 %, so ±15 % is over three of them).
  EXPECT_NEAR(e.channels[0].noise, 0.05, 0.15 * 0.05);
  EXPECT_GT(e.channels[0].whiteness_p, 0.01);
}

TEST(GreyBoxExamples, QuarterCarSpringAndDamperFromTheBodyResponseToAKerb) {
  const GreyBoxEstimate e = fit_example("quarter_car_identify.yaml");
  ASSERT_TRUE(e.converged) << e.termination;
  EXPECT_TRUE(e.identifiable);
  expect_recovered(e, 0, 130000.0, 0.02);  // ks, N/m
  expect_recovered(e, 1, 9800.0, 0.02);    // b, N·s/m
}

TEST(GreyBoxExamples, PendulumDampingAndReleaseAngleFromAFreeDecay) {
  const GreyBoxEstimate e = fit_example("damped_pendulum_identify.yaml");
  ASSERT_TRUE(e.converged) << e.termination;
  EXPECT_TRUE(e.identifiable);
  expect_recovered(e, 0, 0.05, 0.02);  // c, N·m·s/rad
  expect_recovered(e, 1, 28.5, 0.02);  // θ0, deg
}

// Two releases: the damping shared, each release angle estimated for its own test (61.2° the
// larger swing, whose period the small-angle formula would get 7 % wrong).
TEST(GreyBoxExamples, PendulumDampingFromTwoReleasesEachWithItsOwnAngle) {
  const GreyBoxEstimate e = fit_example("damped_pendulum_releases_identify.yaml");
  ASSERT_TRUE(e.converged) << e.termination;
  EXPECT_TRUE(e.identifiable);
  expect_recovered(e, 0, 0.05, 0.01);  // c, N·m·s/rad: both tests tighten it
  expect_recovered(e, 1, 28.5, 0.01);  // θ0 of the first, deg
  expect_recovered(e, 2, 61.2, 0.01);  // θ0 of the second, deg
  for (const FittedChannel& c : e.channels) {
    EXPECT_NEAR(c.rms, c.noise, 0.1 * c.noise) << c.experiment;
    EXPECT_GT(c.whiteness_p, 0.01) << c.experiment;
  }
}

// Sixteen noisy samples: the cost is far from quadratic, both intervals are the profile
// likelihood's, lopsided (b's longer below its estimate, as a 1/b-shaped cost's is), and they
// hold the truth.
TEST(GreyBoxExamples, ShortNoisyDriveGivesProfileIntervalsThatHoldTheTruth) {
  const GreyBoxEstimate e = fit_example("cruise_control_short_identify.yaml");
  ASSERT_TRUE(e.converged) << e.termination;
  EXPECT_EQ(e.profiled, (std::vector<bool>{true, true}));
  ASSERT_EQ(e.interval_notes.size(), 2u);
  EXPECT_NE(e.interval_notes[1].find("b: ["), std::string::npos) << e.interval_notes[1];
  const double truth[] = {1000.0, 50.0};
  for (int i = 0; i < 2; ++i) {
    SCOPED_TRACE(e.names[std::size_t(i)]);
    EXPECT_GT(e.not_quadratic[i], kNotQuadratic);
    EXPECT_LE(e.lower95[i], truth[i]);
    EXPECT_GE(e.upper95[i], truth[i]);
    EXPECT_TRUE(e.lower_bounded[std::size_t(i)] && e.upper_bounded[std::size_t(i)]);
  }
  EXPECT_GT(e.value[1] - e.lower95[1], 1.5 * (e.upper95[1] - e.value[1]));
}

// A shaker-table Bode test (magnitude and phase from Franklin's transfer function, with 0.2 dB
// and 1° of noise) fitted by the linearization: ks, b and the body's mass within their intervals,
// the residuals as large as the noise and white.
TEST(GreyBoxExamples, QuarterCarSpringDamperAndBodyFromAShakerTableBodeTest) {
  const GreyBoxEstimate e = fit_example("quarter_car_shaker_identify.yaml");
  ASSERT_TRUE(e.converged) << e.termination;
  EXPECT_TRUE(e.identifiable);
  expect_recovered(e, 0, 130000.0, 0.02);  // ks, N/m
  expect_recovered(e, 1, 9800.0, 0.02);    // b, N·s/m
  expect_recovered(e, 2, 375.0, 0.02);     // m2, kg
  ASSERT_EQ(e.channels.size(), 2u);
  EXPECT_EQ(e.channels[0].abscissa, "frequency");
  EXPECT_EQ(e.channels[0].unit, "dB");
  EXPECT_EQ(e.channels[1].unit, "deg");
  // 40 frequencies: the RMS of N(0, σ) samples spreads by σ/√80 ≈ 11 %; within 30 %.
  EXPECT_NEAR(e.channels[0].rms, 0.2, 0.3 * 0.2);
  EXPECT_NEAR(e.channels[1].rms, 1.0, 0.3 * 1.0);
  for (const FittedChannel& c : e.channels) EXPECT_GT(c.whiteness_p, 0.01) << c.channel;
  EXPECT_EQ(e.evaluations, 0);  // no runs: linearizations alone
  EXPECT_GT(e.linearizations, 0);
}

}  // namespace
}  // namespace momenta::identify
