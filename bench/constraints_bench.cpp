// Constrained forward dynamics (system/constraint_solver.hpp) against the unconstrained ABA of
// the same tree, on three planar loops closed by a pin (a `hinge` loop closure, three of whose
// five rows are redundant in the plane):
//   four_bar      crank 0.10 m, coupler 0.30 m, rocker 0.25 m, ground 0.30 m (n = 3);
//   slider_crank  crank 0.05 m, rod 0.20 m, a 0.8 kg piston on a slider (n = 3);
//   loop_30       thirty 0.1 m links hanging in a V between pins 2.6 m apart (n = 30);
//   loop_120      the same with 120 links, 10.4 m apart (n = 120).
// Slender rods of 0.1 kg each (the slider-crank's as in examples/constraints/slider_crank.yaml,
// its crank free here), gravity −y, a consistent state with velocities from a fixed seed.
// Measured:
//   BM_Acceleration/<model>/closed  MultibodySystem::acceleration with the constraint: ABA's
//                                   first two passes, the rows, their leaves-to-root pass
//                                   (L Gᵀ and G v̇₀), the Cholesky of G M⁻¹ Gᵀ, ABA's third pass
//                                   with the row forces (the default method)
//   BM_Acceleration/<model>/dense   the same by CRBA and a dense Cholesky of M (the check), in
//                                   the accelerations and the projection alike
//   BM_Acceleration/<model>/tree    the same tree without the constraint (ABA only)
//   BM_SimulatedSecond/<model>/...  one simulated second: 1000 RK4 steps of 1 ms through
//                                   integrate::run, with the projection onto the constraints after
//                                   every step in the closed cases.
//   BM_Linearize/<model>            analysis::linearize of the closed model at its moving
//                                   consistent state (independent coordinates, A and the reduced
//                                   mass, stiffness and damping; no inputs, the states as outputs).
//
// Run: build-bench/bench/constraints_bench --benchmark_repetitions=5
//      --benchmark_report_aggregates_only=true

#include <random>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "momenta/analysis/linearize.hpp"
#include "momenta/integrate/run.hpp"
#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/closed_chains.hpp"

namespace {

using namespace momenta;

const char* const kModels[] = {"four_bar", "slider_crank", "loop_30", "loop_120"};
const char* const kVariants[] = {"closed", "dense", "tree"};

std::string slider_crank_text(bool closed) {
  std::string text = R"(name: slider-crank
gravity: [0, -9.81, 0]
bodies:
  - {name: crank, shape: slender_rod, mass: 0.5, length: 0.05, position: [0.025, 0, 0],
     euler: {sequence: XYZ, angles_deg: [0, 90, 0]}}
  - {name: rod, shape: slender_rod, mass: 1.0, length: 0.20, position: [0.10, 0, 0],
     euler: {sequence: XYZ, angles_deg: [0, 90, 0]}}
  - {name: piston, shape: box, mass: 0.8, size: [0.04, 0.04, 0.04]}
joints:
  - {name: main_bearing, type: revolute, parent: world, child: crank, axis: [0, 0, 1], q0: 0.6}
  - {name: crank_pin, type: revolute, parent: crank, child: rod, axis: [0, 0, 1],
     in_parent: {position: [0.05, 0, 0]}}
  - {name: cylinder, type: slider, parent: world, child: piston, axis: [1, 0, 0], q0: 0.24}
)";
  if (closed) {
    text +=
        "constraints:\n  - {name: wrist_pin, type: hinge, body_a: piston, body_b: rod, "
        "point_b: [0.20, 0, 0]}\n";
  }
  return text;
}

io::ModelFile model_file(int model, bool closed) {
  if (model == 0) return io::parse_model_file(test::four_bar_text(closed), "four_bar.yaml", ".");
  if (model == 1) return io::parse_model_file(slider_crank_text(closed), "slider_crank.yaml", ".");
  const int links = model == 2 ? 30 : 120;
  return io::parse_model_file(test::v_loop_text(links, closed), fmt::format("loop_{}.yaml", links),
                              ".");
}

// A model, its system and a consistent state with velocities from a fixed seed (the tree takes
// the closed model's state).
struct Setup {
  Setup(int model, int variant)
      : closed_file(model_file(model, true)),
        file(model_file(model, variant != 2)),
        system(file.model) {
    system::MultibodySystem closed_system(closed_file.model);
    state.q = closed_file.model.initial_q();
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    state.v = VecX(closed_file.model.nv());
    for (Eigen::Index i = 0; i < state.v.size(); ++i) state.v[i] = u(rng);
    closed_system.make_consistent(0.0, state.q, state.v);
    if (variant == 1)
      system.constraints()->set_acceleration_method(system::AccelerationMethod::dense);
  }
  io::ModelFile closed_file, file;
  system::MultibodySystem system;
  integrate::State state;
};

void label(benchmark::State& bench) {
  bench.SetLabel(fmt::format("{} {}", kModels[bench.range(0)], kVariants[bench.range(1)]));
}

void BM_Acceleration(benchmark::State& bench) {
  Setup s(static_cast<int>(bench.range(0)), static_cast<int>(bench.range(1)));
  VecX vdot(s.file.model.nv());
  for (auto _ : bench) {
    s.system.acceleration(0.0, s.state.q, s.state.v, vdot);
    benchmark::DoNotOptimize(vdot.data());
    benchmark::ClobberMemory();
  }
  label(bench);
}

void BM_SimulatedSecond(benchmark::State& bench) {
  Setup s(static_cast<int>(bench.range(0)), static_cast<int>(bench.range(1)));
  integrate::RungeKutta4 rk4;
  for (auto _ : bench) {
    integrate::State state = s.state;
    integrate::run(s.system, rk4, state, {1.0, 1e-3, 1000}, [](const integrate::State&) {});
    benchmark::DoNotOptimize(state.v.data());
  }
  label(bench);
}

void BM_Linearize(benchmark::State& bench) {
  Setup s(static_cast<int>(bench.range(0)), 0);
  const analysis::OperatingPoint point{0.0, s.state.q, s.state.v};
  for (auto _ : bench) {
    benchmark::DoNotOptimize(analysis::linearize(s.file.model, point).system.A().data());
  }
  bench.SetLabel(kModels[bench.range(0)]);
}

BENCHMARK(BM_Acceleration)->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2}});
BENCHMARK(BM_SimulatedSecond)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Linearize)->DenseRange(0, 2)->Unit(benchmark::kMicrosecond);

}  // namespace
