// One full simulation step of a Model: MultibodySystem (signals, force elements, ABA) advanced
// by RK4 (4 evaluations) or symplectic Euler (1 evaluation), h = 1 ms, on
//   free_body  a free rigid body I = diag(1, 2, 3) kg·m², 1 kg, ω0 = (0.01, 2, 0.01) rad/s, no
//              gravity (the setting of bench/rigid_body_bench.cpp; peer figure MuJoCo 2.2 RK4:
//              2270 ns per step, /work/shared/references.md);
//   chain7     the 7-link revolute chain of bench/dynamics_bench.cpp (1 kg, 0.1 m rods, axes
//              alternating z and y, gravity), random q, v from a fixed seed.
// BM_Acceleration is one MultibodySystem::acceleration alone, for the step's overhead over it.
//
// Run: build/bench/simulation_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only.

#include <random>

#include <benchmark/benchmark.h>

#include "momenta/integrate/runge_kutta.hpp"
#include "momenta/integrate/symplectic_euler.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/multibody_models.hpp"

namespace {

using namespace momenta;

enum Case { kFreeBody, kChain7 };

model::Model free_body() {
  model::ModelBuilder b;
  b.set_gravity(Vec3::Zero());
  b.add_body("body", inertia::MassProperties(1.0, Vec3::Zero(),
                                             Vec3(1.0, 2.0, 3.0).asDiagonal().toDenseMatrix()));
  model::Joint j;
  j.name = "float";
  j.type = model::JointType::free;
  j.parent = "world";
  j.child = "body";
  j.v0 = (VecX(6) << 0.01, 2.0, 0.01, 0.0, 0.0, 0.0).finished();
  b.add_joint(j);
  return b.build();
}

// A model, its system and a starting state.
struct Setup {
  explicit Setup(int which)
      : model(which == kFreeBody ? free_body() : test::revolute_chain(7)), system(model) {
    state.q = model.initial_q();
    state.v = model.initial_v();
    if (which == kChain7) {
      std::mt19937 rng(42);
      state.q = test::random_vector(model.nq(), rng, 3.14);
      state.v = test::random_vector(model.nv(), rng, 1.0);
    }
  }
  model::Model model;
  system::MultibodySystem system;
  integrate::State state;
};

template <class Integrator>
void BM_Step(benchmark::State& bench) {
  Setup s(static_cast<int>(bench.range(0)));
  Integrator integrator;
  integrator.initialize(s.system, s.state);
  for (auto _ : bench) {
    integrator.step(s.system, s.state, 1e-3);
    benchmark::DoNotOptimize(s.state.v.data());
    benchmark::ClobberMemory();
  }
  bench.SetLabel(bench.range(0) == kFreeBody ? "free_body" : "chain7");
}

void BM_Acceleration(benchmark::State& bench) {
  Setup s(static_cast<int>(bench.range(0)));
  VecX vdot(s.model.nv());
  for (auto _ : bench) {
    s.system.acceleration(0.0, s.state.q, s.state.v, vdot);
    benchmark::DoNotOptimize(vdot.data());
    benchmark::ClobberMemory();
  }
  bench.SetLabel(bench.range(0) == kFreeBody ? "free_body" : "chain7");
}

BENCHMARK_TEMPLATE(BM_Step, integrate::RungeKutta4)->Arg(kFreeBody)->Arg(kChain7);
BENCHMARK_TEMPLATE(BM_Step, integrate::SymplecticEuler)->Arg(kFreeBody)->Arg(kChain7);
BENCHMARK(BM_Acceleration)->Arg(kFreeBody)->Arg(kChain7);

}  // namespace
