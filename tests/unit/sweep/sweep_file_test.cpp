// Sweep files (io/sweep_file.hpp) and what the runner checks before any run
// (sweep/runner.hpp): every mistake is refused at its line, before a run starts.

#include <cmath>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/io/sweep_file.hpp"
#include "momenta/sweep/runner.hpp"

namespace momenta::sweep {
namespace {

// Writes `text` as a sweep file in examples/sweeps/ (so ../quarter_car.yaml resolves), reads it
// and makes its runner; returns the message of what was thrown ("" when nothing was).
std::string refusal(const std::string& text) {
  // One file per test: CTest runs the tests of this file side by side.
  const std::filesystem::path path =
      std::string("examples/sweeps/test_refusal_") +
      ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".sweep.yaml";
  std::ofstream(path) << text;
  std::string message;
  try {
    const SweepRunner runner(io::read_sweep_file(path));
  } catch (const Error& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

const std::string kHead =
    "model: ../quarter_car.yaml\n"   // line 1
    "simulation: {duration: 0.2}\n"  // line 2
    "parameters:\n";                 // line 3
const std::string kMetrics = "metrics:\n  - max: body_y\n";

TEST(SweepFile, AnUnknownPathIsRefusedAtItsLineWithASuggestion) {
  const std::string m =
      refusal(kHead + "  - {path: forces.suspenson.stiffness, values: [1, 2]}\n" + kMetrics);
  EXPECT_NE(m.find("Suggestion.sweep.yaml:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'suspension'"), std::string::npos) << m;
}

TEST(SweepFile, ARangeThatMakesAMassNegativeIsRefusedBeforeAnyRun) {
  const std::string m = refusal(
      kHead + "  - path: bodies.body.mass\n    range: {from: -10, to: 400, count: 5}\n" + kMetrics);
  EXPECT_NE(m.find("AnyRun.sweep.yaml:4:"), std::string::npos) << m;
  EXPECT_NE(m.find("smallest value (-10)"), std::string::npos) << m;
  EXPECT_NE(m.find("mass"), std::string::npos) << m;
}

TEST(SweepFile, ADistributionWithANegativeSigmaIsRefusedAtItsLine) {
  const std::string m = refusal(kHead +
                                "  - path: bodies.body.mass\n"
                                "    distribution: {type: normal, mean: 375, sd: -5}\n" +
                                kMetrics + "samples: 10\nseed: 1\n");
  EXPECT_NE(m.find("AtItsLine.sweep.yaml:5:"), std::string::npos) << m;
  EXPECT_NE(m.find("standard deviation must be positive"), std::string::npos) << m;
}

TEST(SweepFile, MetricsAreCheckedAgainstTheJobAndTheRecordedColumns) {
  const std::string param = "  - {path: bodies.body.mass, values: [300, 400]}\n";
  std::string m = refusal(kHead + param + "metrics:\n  - max: body_yy\n");
  EXPECT_NE(m.find(":6:"), std::string::npos) << m;
  EXPECT_NE(m.find("did you mean 'body_y'"), std::string::npos) << m;
  m = refusal(kHead + param + "metrics:\n  - poles\n");
  EXPECT_NE(m.find("not a figure of this sweep's job"), std::string::npos) << m;
  m = refusal(kHead + param + "metrics:\n  - maximum: body_y\n");
  EXPECT_NE(m.find("unknown metric 'maximum'"), std::string::npos) << m;
  m = refusal(kHead + param + "metrics:\n  - {max_audit_drift: enrgy}\n");
  EXPECT_NE(m.find("did you mean 'energy'"), std::string::npos) << m;
}

TEST(SweepFile, DesignsAndValuesThatDoNotFitAreRefused) {
  EXPECT_NE(refusal(kHead + "  - {path: bodies.body.mass, range: {from: 1, to: 2, count: 1}}\n" +
                    kMetrics)
                .find("count ≥ 2"),
            std::string::npos);
  EXPECT_NE(
      refusal(kHead +
              "  - {path: bodies.body.mass, range: {from: 0, to: 2, count: 3, spacing: log}}\n" +
              kMetrics)
          .find("log range"),
      std::string::npos);
  EXPECT_NE(
      refusal(kHead + "  - {path: bodies.body.mass, values: [1, 2]}\n" + kMetrics + "seed: 3\n")
          .find("belongs to a sampled design"),
      std::string::npos);
  EXPECT_NE(
      refusal(kHead +
              "  - {path: bodies.body.mass, distribution: {type: uniform, low: 1, high: 2}}\n" +
              kMetrics)
          .find("missing"),
      std::string::npos);  // samples and seed
  EXPECT_NE(refusal(kHead +
                    "  - {path: bodies.body.mass, values: [1, 2]}\n  - {path: bodies.wheel.mass, "
                    "values: [1, 2, 3]}\n" +
                    kMetrics + "design: zip\n")
                .find("one length"),
            std::string::npos);
  EXPECT_EQ(refusal(kHead + "  - {path: bodies.body.mass, values: [300, 400]}\n" + kMetrics), "");
}

TEST(SweepFile, ARunThatFailsIsRecordedAndTheOthersGoOn) {
  // A damping of 1e95 N·s/m makes the explicit integrator's state blow up at once.
  const std::filesystem::path path = "examples/sweeps/test_failure.sweep.yaml";
  std::ofstream(path) << kHead << "  - {path: forces.suspension.damping, values: [9800, 1e95]}\n"
                      << kMetrics;
  const SweepRunner runner(io::read_sweep_file(path));
  std::filesystem::remove(path);
  const RunOutcome good = runner.run(0);
  const RunOutcome bad = runner.run(1);
  EXPECT_TRUE(good.ok) << good.message;
  EXPECT_TRUE(std::isfinite(good.metrics[0]));
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.message.find("t = "), std::string::npos) << bad.message;  // names the time
  EXPECT_TRUE(std::isnan(bad.metrics[0]));
}

}  // namespace
}  // namespace momenta::sweep
