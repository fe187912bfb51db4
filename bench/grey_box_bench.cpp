// Grey-box fits to the same optimum with the Jacobian from the sensitivity equations (momenta's
// way) and from forward differences of whole runs (the obvious alternative): wall time, runs,
// evaluations of the dynamics and iterations (docs/identification.md, "Speed"). Two problems:
// the quarter car's ks and b from its bundled kerb log (examples/identification), and a 7-link
// arm's seven joint dampings from its seven angles over 3 s at 100 Hz (bench/models/
// seven_link_arm.yaml; the log made here by a run at the true 0.3 N·m·s/rad plus 1 mrad of
// seeded noise, the fit started at 0.5).

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "momenta/identify/grey_box.hpp"
#include "momenta/identify/identification_file.hpp"
#include "momenta/io/file_template.hpp"

#ifndef MOMENTA_SOURCE_DIR
#error "MOMENTA_SOURCE_DIR must name the source tree (for examples/)"
#endif

namespace momenta::identify {
namespace {

using Jacobian = GreyBoxSettings::Jacobian;

GreyBoxProblem quarter_car() {
  return read_identification_file(std::filesystem::path(MOMENTA_SOURCE_DIR) / "examples" /
                                  "identification" / "quarter_car_identify.yaml");
}

GreyBoxProblem seven_link_arm() {
  const std::filesystem::path model =
      std::filesystem::path(MOMENTA_SOURCE_DIR) / "bench" / "models" / "seven_link_arm.yaml";
  const io::ModelTemplate file(model);
  std::vector<std::string> angles;
  for (int j = 0; j < 7; ++j) angles.push_back(fmt::format("a{}", j));
  const ChannelSet channels(file.nominal().model, file.nominal().outputs, angles);
  const VecX times = VecX::LinSpaced(301, 0.0, 3.0);
  const auto nominal = [&](const VecX&) { return file.nominal().model; };
  const MatX truth = sample_outputs(nominal, VecX(), channels, times, false).values;

  GreyBoxProblem problem;
  problem.name = "seven link arm";
  problem.model = model;
  GreyBoxExperiment swing;
  swing.name = "swing";
  swing.data.source = "swing (made in the benchmark)";
  swing.data.columns = {"time"};
  swing.data.values.resize(times.size(), 8);
  swing.data.values.col(0) = times;
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1e-3);
  for (int j = 0; j < 7; ++j) {
    swing.data.columns.push_back(angles[std::size_t(j)]);
    for (Eigen::Index k = 0; k < times.size(); ++k)
      swing.data.values(k, j + 1) = truth(k, j) + noise(rng);
    swing.outputs.push_back({angles[std::size_t(j)], angles[std::size_t(j)], 1e-3});
    GreyBoxParameter p;
    p.path = fmt::format("joints.j{}.damping", j);
    p.name = fmt::format("c{}", j);
    p.guess = 0.5;
    problem.parameters.push_back(p);
  }
  problem.experiments = {std::move(swing)};
  return problem;
}

void fit(benchmark::State& state, GreyBoxProblem (*make)(), Jacobian jacobian) {
  GreyBoxProblem problem = make();
  problem.settings.jacobian = jacobian;
  // The fit alone: the check of each Fisher interval for a profile (2 runs per parameter, the
  // same whichever Jacobian) is statistics after the optimum, not the work compared here.
  problem.settings.profile = GreyBoxSettings::Profile::never;
  GreyBoxEstimate e;
  for (auto _ : state) {
    e = fit_grey_box(problem);
    benchmark::DoNotOptimize(e.value.data());
  }
  state.counters["runs"] = double(e.simulations + e.sensitivity_simulations);
  state.counters["evaluations"] = double(e.evaluations);
  state.counters["iterations"] = e.iterations;
  state.counters["cost"] = e.final_cost;
  state.counters["p0"] = e.value[0];
  if (!e.converged) state.SkipWithError(e.termination.c_str());
}

BENCHMARK_CAPTURE(fit, quarter_car_sensitivities, quarter_car, Jacobian::sensitivities)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(5)
    ->ReportAggregatesOnly(false);
BENCHMARK_CAPTURE(fit, quarter_car_run_differences, quarter_car, Jacobian::run_differences)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(5);
BENCHMARK_CAPTURE(fit, seven_link_arm_sensitivities, seven_link_arm, Jacobian::sensitivities)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(5);
BENCHMARK_CAPTURE(fit, seven_link_arm_run_differences, seven_link_arm, Jacobian::run_differences)
    ->Unit(benchmark::kMillisecond)
    ->Iterations(1)
    ->Repetitions(5);

}  // namespace
}  // namespace momenta::identify
