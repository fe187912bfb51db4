// Constrained forward dynamics (system/constraint_solver.hpp) against the unconstrained ABA of
// the same tree, on planar revolute chains closed to the ground by a pin (a `hinge` loop closure,
// three of whose five rows are redundant in the plane):
//   n = 3   a four-bar: crank 0.10 m, coupler 0.30 m, rocker 0.25 m, ground 0.30 m;
//   n = 30  thirty 0.1 m links hanging in a V between pins 2.6 m apart.
// Slender rods of 0.1 kg each, gravity −y, a consistent state with velocities
// from a fixed seed. Measured:
//   BM_Acceleration/n/closed   MultibodySystem::acceleration with the constraint (ABA, CRBA,
//                              Cholesky of M and of G M⁻¹ Gᵀ)
//   BM_Acceleration/n/tree     the same tree without it (ABA only)
//   BM_SimulatedSecond/n/...   one simulated second: 1000 RK4 steps of 1 ms through
//                              integrate::run, with the projection onto the constraints after
//                              every step in the closed case.
//
// Run: build-bench/bench/constraints_bench --benchmark_repetitions=5
//      --benchmark_report_aggregates_only=true

#include <cmath>
#include <random>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "momenta/integrate/run.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/multibody_system.hpp"

namespace {

using namespace momenta;

// The chain as a model file: links along their x axes, pins about z, the last link's tip pinned
// to (d, 0, 0) when `closed`.
std::string chain_text(const std::vector<double>& lengths, const std::vector<double>& q0_deg,
                       double d, bool closed) {
  std::string text = "name: closed chain\ngravity: [0, -9.81, 0]\nbodies:\n";
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    text += fmt::format(
        "  - {{name: link{}, shape: slender_rod, mass: 0.1, length: {}, position: [{}, 0, 0], "
        "euler: {{sequence: XYZ, angles_deg: [0, 90, 0]}}}}\n",
        i, lengths[i], lengths[i] / 2);
  }
  text += "joints:\n";
  for (std::size_t i = 0; i < lengths.size(); ++i) {
    text += fmt::format(
        "  - {{name: pin{}, type: revolute, parent: {}, child: link{}, axis: [0, 0, 1], "
        "in_parent: {{position: [{}, 0, 0]}}, q0_deg: {}}}\n",
        i, i == 0 ? "world" : fmt::format("link{}", i - 1), i, i == 0 ? 0.0 : lengths[i - 1],
        q0_deg[i]);
  }
  if (closed) {
    text += fmt::format(
        "constraints:\n  - {{name: ground, type: hinge, body_a: world, point_a: [{}, 0, 0], "
        "body_b: link{}, point_b: [{}, 0, 0]}}\n",
        d, lengths.size() - 1, lengths.back());
  }
  return text;
}

io::ModelFile chain(int n, bool closed) {
  if (n == 3) {
    return io::parse_model_file(chain_text({0.10, 0.30, 0.25}, {50, -14.73, -127.4}, 0.30, closed),
                                "four_bar.yaml", ".");
  }
  // A V: the first half going down at 30°, the second coming back up.
  const std::vector<double> lengths(static_cast<std::size_t>(n), 0.1);
  std::vector<double> q0(static_cast<std::size_t>(n), 0.0);
  q0[0] = -30;
  q0[static_cast<std::size_t>(n / 2)] = 60;
  const double d = n * 0.1 * std::cos(30 * 3.141592653589793 / 180);
  return io::parse_model_file(chain_text(lengths, q0, d, closed), "chain.yaml", ".");
}

// A model, its system and a consistent state with velocities from a fixed seed.
struct Setup {
  Setup(int n, bool closed) : file(chain(n, closed)), system(file.model) {
    state.q = file.model.initial_q();
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    state.v = VecX(file.model.nv());
    for (Eigen::Index i = 0; i < state.v.size(); ++i) state.v[i] = u(rng);
    system.make_consistent(0.0, state.q, state.v);
  }
  io::ModelFile file;
  system::MultibodySystem system;
  integrate::State state;
};

void label(benchmark::State& bench) {
  bench.SetLabel(fmt::format("n={} {}", bench.range(0), bench.range(1) ? "closed" : "tree"));
}

void BM_Acceleration(benchmark::State& bench) {
  Setup s(static_cast<int>(bench.range(0)), bench.range(1) != 0);
  VecX vdot(s.file.model.nv());
  for (auto _ : bench) {
    s.system.acceleration(0.0, s.state.q, s.state.v, vdot);
    benchmark::DoNotOptimize(vdot.data());
    benchmark::ClobberMemory();
  }
  label(bench);
}

void BM_SimulatedSecond(benchmark::State& bench) {
  Setup s(static_cast<int>(bench.range(0)), bench.range(1) != 0);
  integrate::RungeKutta4 rk4;
  for (auto _ : bench) {
    integrate::State state = s.state;
    integrate::run(s.system, rk4, state, {1.0, 1e-3, 1000}, [](const integrate::State&) {});
    benchmark::DoNotOptimize(state.v.data());
  }
  label(bench);
}

BENCHMARK(BM_Acceleration)->ArgsProduct({{3, 30}, {1, 0}});
BENCHMARK(BM_SimulatedSecond)->ArgsProduct({{3, 30}, {1, 0}})->Unit(benchmark::kMillisecond);

}  // namespace
