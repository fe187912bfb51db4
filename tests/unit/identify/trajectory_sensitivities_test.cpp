// The sensitivities of sampled outputs to model-file numbers: against the closed form of the
// cruise-control car's speed, and against central differences of whole runs on the quarter car
// (springs, a damper, the road's height — a prescribed motion's own number) and the damped
// pendulum (its release angle: an initial state). And the channels a run can sample.

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/identify/trajectory_sensitivities.hpp"
#include "momenta/io/file_template.hpp"

namespace momenta::identify {
namespace {

using ::testing::HasSubstr;

// Models from a file's numbers at `paths`.
struct FileFamily {
  io::ModelTemplate file;
  std::vector<std::string> paths;
  model::Model operator()(const VecX& p) const {
    std::vector<io::NumberOverride> overrides;
    for (std::size_t i = 0; i < paths.size(); ++i)
      overrides.push_back({paths[i], p[Eigen::Index(i)]});
    return file.with(overrides).model;
  }
};

SensitivityOptions tight() {
  SensitivityOptions options;
  options.tolerances = {1e-11, 1e-14};
  return options;
}

// v(t) = (u/b)(1 − e^(−bt/m)) for the 500 N step from rest: its derivatives in m and b, with ∂a/∂p
// by forward differences (the default) and by central ones.
TEST(TrajectorySensitivities, CruiseControlSpeedMatchesTheClosedForm) {
  const FileFamily family{io::ModelTemplate("examples/cruise_control.yaml"),
                          {"bodies.car.mass", "joints.road.damping"}};
  const ChannelSet channels(family.file.nominal().model, family.file.nominal().outputs, {"speed"});
  const VecX times = VecX::LinSpaced(121, 0.0, 60.0);
  VecX p(2);
  p << 1000.0, 50.0;
  // Sizes: v up to 9.5 m/s, ∂v/∂m up to 3.7e-3 m/s per kg, ∂v/∂b up to 0.12 m/s per N·s/m; the
  // run's tolerance 1e-11. ∂a/∂m (a ∝ 1/m) carries the differences' truncation: h/m = 1e-7 of its
  // size forward (3.7e-10 here), h²/m² = 1e-8 central (3.7e-11); ∂a/∂b (linear in b) none.
  for (const auto& [mode, bound_m] : {std::pair{SensitivityOptions::Differences::forward, 5e-10},
                                      std::pair{SensitivityOptions::Differences::central, 5e-11}}) {
    SCOPED_TRACE(mode == SensitivityOptions::Differences::forward ? "forward" : "central");
    SensitivityOptions options = tight();
    options.dynamics = mode;
    const SampledOutputs out = sample_outputs(std::cref(family), p, channels, times, true, options);
    const double m = 1000.0, b = 50.0, u = 500.0;
    double worst_value = 0.0, worst_m = 0.0, worst_b = 0.0;
    for (Eigen::Index k = 0; k < times.size(); ++k) {
      const double t = times[k], e = std::exp(-b * t / m);
      worst_value = std::max(worst_value, std::abs(out.values(k, 0) - u / b * (1.0 - e)));
      worst_m = std::max(worst_m, std::abs(out.sensitivities(k, 0) - (-u * t / (m * m) * e)));
      worst_b = std::max(worst_b, std::abs(out.sensitivities(k, 1) -
                                           (-u / (b * b) * (1.0 - e) + u * t / (b * m) * e)));
    }
    EXPECT_LT(worst_value, 1e-9);
    EXPECT_LT(worst_m, bound_m);
    EXPECT_LT(worst_b, 1e-10);
  }
}

// ∂y/∂p_i by central differences of whole runs (h = 1e-4 relative, error ~1e-8 of the size).
MatX differences_of_runs(const FileFamily& family, const ChannelSet& channels, const VecX& times,
                         const VecX& p) {
  const Eigen::Index rows = times.size() * static_cast<Eigen::Index>(channels.names().size());
  MatX d(rows, p.size());
  for (Eigen::Index i = 0; i < p.size(); ++i) {
    const double h = 1e-4 * std::max(std::abs(p[i]), 1e-3);
    VecX plus = p, minus = p;
    plus[i] += h;
    minus[i] -= h;
    const MatX y_plus =
        sample_outputs(std::cref(family), plus, channels, times, false, tight()).values;
    const MatX y_minus =
        sample_outputs(std::cref(family), minus, channels, times, false, tight()).values;
    const MatX diff = (y_plus - y_minus) / (2.0 * h);
    for (Eigen::Index k = 0; k < times.size(); ++k)
      for (Eigen::Index c = 0; c < diff.cols(); ++c) d(k * diff.cols() + c, i) = diff(k, c);
  }
  return d;
}

void expect_columns_match(const MatX& sensitivities, const MatX& reference, double relative) {
  for (Eigen::Index i = 0; i < reference.cols(); ++i) {
    SCOPED_TRACE("parameter " + std::to_string(i));
    const double size = reference.col(i).cwiseAbs().maxCoeff();
    ASSERT_GT(size, 0.0);
    EXPECT_LT((sensitivities.col(i) - reference.col(i)).cwiseAbs().maxCoeff(), relative * size);
  }
}

TEST(TrajectorySensitivities, QuarterCarMatchesDifferencesOfWholeRuns) {
  const FileFamily family{io::ModelTemplate("examples/quarter_car.yaml"),
                          {"forces.suspension.stiffness", "forces.suspension.damping",
                           "bodies.wheel.mass", "inputs.road.final"}};
  // An output column (body_y, a spring's tension) and a coordinate's rate.
  const ChannelSet channels(family.file.nominal().model, family.file.nominal().outputs,
                            {"body_y", "suspension_force", "wheel_travel.position_rate"});
  const VecX times = VecX::LinSpaced(201, 0.0, 0.8);
  VecX p(4);
  p << 130000.0, 9800.0, 20.0, 0.05;
  const SampledOutputs out = sample_outputs(std::cref(family), p, channels, times, true, tight());
  expect_columns_match(out.sensitivities, differences_of_runs(family, channels, times, p), 1e-6);
}

TEST(TrajectorySensitivities, PendulumReleaseAngleAndDampingMatchDifferencesOfWholeRuns) {
  const FileFamily family{io::ModelTemplate("examples/identification/damped_pendulum.yaml"),
                          {"joints.pivot.damping", "joints.pivot.q0_deg"}};
  const ChannelSet channels(family.file.nominal().model, family.file.nominal().outputs,
                            {"theta", "pivot.angle_rate"});
  const VecX times = VecX::LinSpaced(101, 0.0, 10.0);
  VecX p(2);
  p << 0.2, 30.0;
  const SampledOutputs out = sample_outputs(std::cref(family), p, channels, times, true, tight());
  expect_columns_match(out.sensitivities, differences_of_runs(family, channels, times, p), 1e-6);
  // At t = 0 the angle moves with the release angle alone: π/180 rad per degree.
  EXPECT_NEAR(out.sensitivities(0, 1), M_PI / 180.0, 1e-10);
  EXPECT_NEAR(out.sensitivities(0, 0), 0.0, 1e-14);
}

TEST(TrajectorySensitivities, ChannelsAreOutputsOrCoordinatesWithSuggestions) {
  const io::ModelFile file = io::ModelTemplate("examples/quarter_car.yaml").nominal();
  const ChannelSet channels(file.model, file.outputs, {"body_y", "body_travel.position"});
  EXPECT_EQ(channels.units(), (std::vector<std::string>{"m", "m"}));
  try {
    ChannelSet(file.model, file.outputs, {"body_yy"});
    FAIL() << "an unknown channel was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(e.what(), HasSubstr("did you mean 'body_y'"));
  }
  try {
    ChannelSet(file.model, file.outputs, {"road.position"});
    FAIL() << "a prescribed coordinate was accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(e.what(), HasSubstr("prescribed"));
  }
}

TEST(TrajectorySensitivities, RefuseModelsOutsideTheirScope) {
  const io::ModelFile top = io::ModelTemplate("examples/heavy_top.yaml").nominal();
  EXPECT_THROW(ChannelSet(top.model, top.outputs, {}), InvalidArgument);
  const io::ModelFile four_bar = io::ModelTemplate("examples/constraints/four_bar.yaml").nominal();
  EXPECT_THROW(ChannelSet(four_bar.model, four_bar.outputs, {}), InvalidArgument);
}

// A run past its budget of steps stops, named: the cruise car with a damper of 10⁸ N·s/m has a
// time constant of 10 µs, which dopri5 (explicit) resolves with ~10⁵ steps a second of it — the
// budget of 500 stops it within the first 5 ms of the minute, with or without sensitivities. At
// the file's 50 N·s/m the same budget is plenty (the minute takes 143 steps).
TEST(TrajectorySensitivities, ARunPastItsBudgetOfStepsStops) {
  const FileFamily family{io::ModelTemplate("examples/cruise_control.yaml"),
                          {"bodies.car.mass", "joints.road.damping"}};
  const ChannelSet channels(family.file.nominal().model, family.file.nominal().outputs, {"speed"});
  const VecX times = VecX::LinSpaced(121, 0.0, 60.0);
  SensitivityOptions options;
  options.max_steps = 500;
  VecX p(2);
  p << 1000.0, 50.0;
  EXPECT_LT(sample_outputs(std::cref(family), p, channels, times, true, options).steps, 200);
  p[1] = 1e8;
  for (const bool sensitivities : {false, true}) {
    try {
      sample_outputs(std::cref(family), p, channels, times, sensitivities, options);
      FAIL() << "a run of 10⁸ N·s/m finished within 500 steps";
    } catch (const NumericalError& e) {
      EXPECT_THAT(e.what(), HasSubstr("the run took more than 500 steps by t = "));
      EXPECT_THAT(e.what(), HasSubstr(" s of 60 s: the model is far stiffer or faster"));
    }
  }
}

TEST(TrajectorySensitivities, SampleTimesMustBeEvenlySpaced) {
  VecX times(4);
  times << 0.0, 0.1, 0.25, 0.3;
  try {
    even_spacing(times, "log.csv");
    FAIL() << "uneven times were accepted";
  } catch (const InvalidArgument& e) {
    EXPECT_THAT(e.what(), HasSubstr("log.csv: sample 3 is at t = 0.25 s, not 0.2 s"));
  }
}

}  // namespace
}  // namespace momenta::identify
