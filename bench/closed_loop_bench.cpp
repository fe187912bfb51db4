// The closed loop's cost beside the open plant (issue 59's aim: at most 1.2×): one RK4 step,
// h = 1 ms, of the inverted pendulum on a cart (examples/cart_pendulum_lqr.yaml, 2 joints — the
// smallest plant, where a controller's share is largest), as
//   open      the plant alone (MultibodySystem), its force held at 0.5 N (an input acting, as the
//             controller's does),
//   lqr       closed by the file's state feedback u = −K x (ClosedLoopSystem, no states),
//   pid       closed by a filtered PID on the tilt (two controller states integrated with it),
//   sampled   closed by the state feedback sampled at 100 Hz (a sample every 10 steps).
// Every run restarts from 10° each simulated 2 s (2000 steps, the restart amortized): a loop left
// to settle decays into subnormal numbers, whose arithmetic is many times slower and would be
// measured instead of the loop.
// Run: build/bench/closed_loop_bench --benchmark_repetitions=10
//      --benchmark_report_aggregates_only=true (from anywhere: examples/ is found by path).

#include <fstream>
#include <iterator>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/closed_loop_system.hpp"

#ifndef MOMENTA_SOURCE_DIR
#error "MOMENTA_SOURCE_DIR must name the source tree (for examples/)"
#endif

namespace {

using namespace momenta;

// The example with its controllers section replaced by `controllers`.
io::ModelFile pendulum_with(const std::string& controllers) {
  const std::string path = fmt::format("{}/examples/cart_pendulum_lqr.yaml", MOMENTA_SOURCE_DIR);
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!controllers.empty()) {
    const auto from = text.find("controllers:"), to = text.find("bodies:");
    text.replace(from, to - from, controllers);
  }
  return io::parse_model_file(text, path, MOMENTA_SOURCE_DIR);
}

constexpr const char* kPid = R"(controllers:
  - name: tilt_pid
    type: pid
    measure: tilt.angle
    kp: -40
    ki: -20
    kd: -4
    derivative_filter: 0.02
    drives: force

)";

constexpr const char* kSampled = R"(controllers:
  - name: balance
    type: state_feedback
    measure: [x.position, tilt.angle, x.position_rate, tilt.angle_rate]
    gain: [-1.0, -18.70145874371149, -1.656513311485028, -3.460604945318623]
    sample_time: 0.01
    drives: force

)";

void BM_OpenPlant(benchmark::State& bench) {
  const io::ModelFile file = pendulum_with("");
  system::MultibodySystem plant(file.model);
  plant.set_driven_value(*file.model.find_signal("force"), 0.5);
  integrate::State state{0.0, file.model.initial_q(), file.model.initial_v()};
  integrate::RungeKutta4 rk4;
  rk4.initialize(plant, state);
  for (auto _ : bench) {
    if (state.t >= 2.0) {
      state = {0.0, file.model.initial_q(), file.model.initial_v()};
      rk4.initialize(plant, state);
    }
    rk4.step(plant, state, 1e-3);
    benchmark::DoNotOptimize(state.v.data());
    benchmark::ClobberMemory();
  }
}

// Steps as integrate::run takes them: each ended by the projection, which takes the samples.
void closed(benchmark::State& bench, const io::ModelFile& file) {
  system::MultibodySystem plant(file.model);
  system::ClosedLoopSystem loop(plant);
  integrate::State state = loop.start(0.0, file.model.initial_q(), file.model.initial_v());
  integrate::RungeKutta4 rk4;
  rk4.initialize(loop, state);
  for (auto _ : bench) {
    if (state.t >= 2.0) {
      state = loop.start(0.0, file.model.initial_q(), file.model.initial_v());
      rk4.initialize(loop, state);
    }
    rk4.step(loop, state, 1e-3);
    if (loop.project(state.t, state.q, state.v)) rk4.state_changed();
    benchmark::DoNotOptimize(state.v.data());
    benchmark::ClobberMemory();
  }
}

void BM_ClosedLqr(benchmark::State& bench) { closed(bench, pendulum_with("")); }
void BM_ClosedPid(benchmark::State& bench) { closed(bench, pendulum_with(kPid)); }
void BM_ClosedSampled(benchmark::State& bench) { closed(bench, pendulum_with(kSampled)); }

}  // namespace

BENCHMARK(BM_OpenPlant);
BENCHMARK(BM_ClosedLqr);
BENCHMARK(BM_ClosedPid);
BENCHMARK(BM_ClosedSampled);
