// Sweeps (docs/sweeps.md): what a run costs beyond its integration, how the runs scale over
// threads, and the throughput of two classic jobs. Run from the source tree (it reads
// examples/):
//
//   build/bench/sweep_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
//
// - BM_QuarterCarStepResponse: one run of a 10 s quarter-car step response (RK4, h = 1 ms, the
//   model with two numbers changed, the five metrics of examples/sweeps/quarter_car_ride.yaml),
//   and BM_QuarterCarIntegrationOnly: the same integration with the model built once and no
//   metrics — their difference is the per-run overhead of a sweep.
// - BM_SweepThreads/N: 48 such runs (2 s each) on N threads through run_in_order; parallel
//   efficiency from 1 to 2 threads is T(1) / (2 T(2)).
// - BM_DoublePendulumRK4Steps: examples/double_pendulum.yaml, RK4 at 1 ms for 10 s through a
//   sweep run: items per second are steps per second on one core (MuJoCo's mj_step on the same
//   pendulum: bench/mujoco_comparison_bench.cpp).

#include <benchmark/benchmark.h>

#include "momenta/io/file_template.hpp"
#include "momenta/io/sweep_file.hpp"
#include "momenta/simulate/simulation.hpp"
#include "momenta/sweep/execution.hpp"

namespace {

using namespace momenta;

sweep::SweepSpec quarter_car(double duration) {
  sweep::SweepSpec spec = io::read_sweep_file("examples/sweeps/quarter_car_ride.yaml");
  spec.run.duration = duration;
  return spec;
}

class NullSink final : public simulate::RowSink {
 public:
  void begin(std::span<const std::string>) override {}
  void row(std::span<const double> values) override { benchmark::DoNotOptimize(values.data()); }
};

void BM_QuarterCarStepResponse(benchmark::State& state) {
  const sweep::SweepRunner runner(quarter_car(10.0));
  long run = 0;
  for (auto _ : state) {
    const sweep::RunOutcome o = runner.run(run++ % runner.run_count());
    if (!o.ok) state.SkipWithError(o.message.c_str());
    benchmark::DoNotOptimize(o.metrics.data());
  }
  state.SetItemsProcessed(state.iterations());
}

// A run of one 1 ms step: the model read with its numbers changed, checked, the simulation set
// up and its metrics taken — what every run costs beyond integrating.
void BM_QuarterCarRunSetUp(benchmark::State& state) {
  const sweep::SweepRunner runner(quarter_car(1e-3));
  long run = 0;
  for (auto _ : state)
    benchmark::DoNotOptimize(runner.run(run++ % runner.run_count()).metrics.data());
}

void BM_QuarterCarIntegrationOnly(benchmark::State& state) {
  const io::ModelFile file = io::read_model_file("examples/quarter_car.yaml");
  simulate::SimulationOptions options;
  options.duration = 10.0;
  options.step = 1e-3;
  options.integrator = "rk4";
  simulate::Simulation simulation(file.model, file.outputs, options);
  NullSink sink;
  for (auto _ : state) benchmark::DoNotOptimize(simulation.run(sink).t_end);
  state.SetItemsProcessed(state.iterations());
}

void BM_SweepThreads(benchmark::State& state) {
  const sweep::SweepRunner runner(quarter_car(2.0));
  std::vector<long> runs(static_cast<std::size_t>(runner.run_count()));
  for (std::size_t k = 0; k < runs.size(); ++k) runs[k] = static_cast<long>(k);
  for (auto _ : state) {
    sweep::run_in_order(runner, runs, static_cast<int>(state.range(0)),
                        [](sweep::RunOutcome&& o) { benchmark::DoNotOptimize(o.metrics.data()); });
  }
  state.SetItemsProcessed(state.iterations() * static_cast<long>(runs.size()));
}

void BM_DoublePendulumRK4Steps(benchmark::State& state) {
  sweep::SweepSpec spec;
  spec.file = "(benchmark)";
  spec.model = "examples/double_pendulum.yaml";
  spec.run.duration = 10.0;
  spec.run.step = 1e-3;
  spec.run.integrator = "rk4";
  spec.run.every = 10000;  // the metric needs the last row only
  spec.parameters.push_back({"joints.upper.q0_deg", "q0", std::vector<double>{90.0}});
  sweep::Metric final_angle;
  final_angle.kind = sweep::Metric::Kind::kFinal;
  final_angle.of = "theta2";
  spec.metrics.push_back(final_angle);
  const sweep::SweepRunner runner(spec);
  for (auto _ : state) benchmark::DoNotOptimize(runner.run(0).metrics.data());
  state.SetItemsProcessed(state.iterations() * 10000);  // steps
}

BENCHMARK(BM_QuarterCarStepResponse)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QuarterCarIntegrationOnly)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_QuarterCarRunSetUp)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SweepThreads)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_DoublePendulumRK4Steps)->Unit(benchmark::kMillisecond);

}  // namespace
