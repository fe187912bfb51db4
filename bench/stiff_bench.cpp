// Stiff and non-stiff models under every general integrator, each at the setting that reaches
// about the same accuracy (docs/integrators.md, "Stiff models"):
//
//   governor     examples/flyball_governor.yaml (IFToMM A05), 10 s; error: the largest |s − s_ref|
//                of the slider at 13 times against the independent Radau solution
//                (scripts/reference/flyball_governor.py); aim 1e-6 m
//   spring       examples/stiff_spring_damper.yaml, 1 s; error: the largest |x − x_exact| against
//                the closed form at every 10 ms row
//   pendulum     examples/double_pendulum.yaml (not stiff), 10 s; error: the largest |θ − θ_ref|
//                of both angles at every 10 ms row, θ_ref from dopri5 at rtol 1e-13 (computed
//                once, here)
//
// Each iteration is one whole run through integrate::run on system::MultibodySystem (rows every
// 10 ms, no output written). Counters: steps, evaluations (calls of the acceleration, Jacobians
// included), error. Run:
//   build/bench/stiff_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only=true

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "momenta/integrate/run.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/integrators.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/flyball_governor_reference.hpp"

#ifndef MOMENTA_SOURCE_DIR
#error "MOMENTA_SOURCE_DIR must name the source tree (for examples/)"
#endif

namespace {

using namespace momenta;

constexpr double kRow = 0.01;  // s: rows every 10 ms

io::ModelFile example(const char* name) {
  return io::read_model_file(fmt::format("{}/examples/{}.yaml", MOMENTA_SOURCE_DIR, name));
}

// One run to t_end; observe(state) at every row, the states on the 10 ms grid (adaptive methods
// land on it, fixed steps divide it).
integrate::IntegratorStatistics run_once(
    const model::Model& model, const std::string& integrator, double step,
    integrate::Tolerances tolerances, double t_end,
    const std::function<void(const integrate::State&)>& observe) {
  system::MultibodySystem system(model);
  auto method = system::make_integrator(integrator, tolerances);
  integrate::State state{0.0, model.initial_q(), model.initial_v()};
  const double h = method->adaptive() ? kRow : step;
  integrate::run(system, *method, state, {t_end, h, 1}, [&](const integrate::State& s) {
    if (std::abs(s.t - kRow * std::round(s.t / kRow)) < 1e-9) observe(s);
  });
  return method->statistics();
}

// The benchmark loop: one whole run per iteration; row_error(state, row) is the error of the
// row-th row on the 10 ms grid (0 where none is measured); the largest is reported.
void measure(benchmark::State& bench, const model::Model& model, const std::string& integrator,
             double step, integrate::Tolerances tolerances, double t_end,
             const std::function<double(const integrate::State&, std::size_t)>& row_error) {
  integrate::IntegratorStatistics stats;
  double error = 0.0;
  for (auto _ : bench) {
    error = 0.0;
    std::size_t row = 0;
    stats = run_once(model, integrator, step, tolerances, t_end, [&](const integrate::State& x) {
      error = std::max(error, row_error(x, row++));
    });
  }
  bench.counters["steps"] = static_cast<double>(stats.steps);
  bench.counters["evaluations"] = static_cast<double>(stats.evaluations);
  bench.counters["error"] = error;
}

void governor(benchmark::State& bench, std::string integrator, double step, double rtol) {
  const io::ModelFile file = example("flyball_governor");
  const int s = file.model.joint(file.model.joint_index("s")).q_index;
  measure(bench, file.model, integrator, step, {rtol, 1e-10}, 10.0,
          [&](const integrate::State& x, std::size_t) {
            for (const test::GovernorReference& r : test::kFlyballGovernor) {
              if (std::abs(x.t - r.t) < 1e-9) return std::abs(x.q[s] - r.s);
            }
            return 0.0;
          });
}

void spring(benchmark::State& bench, std::string integrator, double step, double rtol,
            double atol) {
  const io::ModelFile file = example("stiff_spring_damper");
  const double m = 1.0, k = 8e5, c = 4e4, x0 = 0.01, d = std::sqrt(c * c - 4 * m * k);
  const double l1 = (-c + d) / (2 * m), l2 = (-c - d) / (2 * m);
  measure(bench, file.model, integrator, step, {rtol, atol}, 1.0,
          [&](const integrate::State& x, std::size_t) {
            const double exact =
                x0 * (l2 * std::exp(l1 * x.t) - l1 * std::exp(l2 * x.t)) / (l2 - l1);
            return std::abs(x.q[0] - exact);
          });
}

// θ1, θ2 every 10 ms from dopri5 at rtol 1e-13.
const std::vector<VecX>& pendulum_reference(const model::Model& model) {
  static const std::vector<VecX> rows = [&] {
    std::vector<VecX> out;
    run_once(model, "dopri5", kRow, {1e-13, 1e-15}, 10.0,
             [&](const integrate::State& x) { out.push_back(x.q); });
    return out;
  }();
  return rows;
}

void pendulum(benchmark::State& bench, std::string integrator, double step, double rtol) {
  const io::ModelFile file = example("double_pendulum");
  const std::vector<VecX>& reference = pendulum_reference(file.model);
  measure(bench, file.model, integrator, step, {rtol, 1e-12}, 10.0,
          [&](const integrate::State& x, std::size_t row) {
            return row < reference.size() ? (x.q - reference[row]).cwiseAbs().maxCoeff() : 0.0;
          });
}

// The settings each method needs for about 1e-6 (measured; docs/integrators.md).
const int registered = [] {
  const auto add = [](const std::string& name, auto function) {
    benchmark::RegisterBenchmark(name.c_str(), function)->Unit(benchmark::kMillisecond);
  };
  add("governor/dopri5/rtol=1e-3", [](benchmark::State& b) { governor(b, "dopri5", 0, 1e-3); });
  add("governor/rk4/h=2e-4", [](benchmark::State& b) { governor(b, "rk4", 2e-4, 1e-8); });
  add("governor/bdf/rtol=1e-8", [](benchmark::State& b) { governor(b, "bdf", 0, 1e-8); });
  add("governor/sdirk3/h=4e-3", [](benchmark::State& b) { governor(b, "sdirk3", 4e-3, 1e-8); });
  add("spring/dopri5/rtol=1e-6", [](benchmark::State& b) { spring(b, "dopri5", 0, 1e-6, 1e-8); });
  add("spring/rk4/h=5e-5", [](benchmark::State& b) { spring(b, "rk4", 5e-5, 1e-8, 1e-10); });
  add("spring/bdf/rtol=1e-6", [](benchmark::State& b) { spring(b, "bdf", 0, 1e-6, 1e-8); });
  add("spring/bdf/rtol=1e-8", [](benchmark::State& b) { spring(b, "bdf", 0, 1e-8, 1e-10); });
  add("spring/sdirk3/h=1e-2", [](benchmark::State& b) { spring(b, "sdirk3", 1e-2, 1e-8, 1e-10); });
  add("pendulum/dopri5/rtol=1e-7", [](benchmark::State& b) { pendulum(b, "dopri5", 0, 1e-7); });
  add("pendulum/rk4/h=5e-4", [](benchmark::State& b) { pendulum(b, "rk4", 5e-4, 1e-8); });
  add("pendulum/bdf/rtol=1e-10", [](benchmark::State& b) { pendulum(b, "bdf", 0, 1e-10); });
  add("pendulum/sdirk3/h=5e-4", [](benchmark::State& b) { pendulum(b, "sdirk3", 5e-4, 1e-8); });
  return 0;
}();

}  // namespace
