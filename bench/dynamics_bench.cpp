// Multibody dynamics on serial chains of n revolute links (1 kg, 0.1 m rods, axes alternating z
// and y), random q, v, τ from a fixed seed: forward dynamics (ABA), inverse dynamics (RNEA) and
// the mass matrix (CRBA), n = 7, 32, 128. Targets: ABA 1.30/6.34/25.7 µs, RNEA 0.47/2.22/8.72 µs,
// CRBA 0.46/3.07/24.0 µs.

#include <benchmark/benchmark.h>

#include "chain_state.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/rnea.hpp"

namespace {

using namespace momenta;

using bench::Chain;

void BM_Aba(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynamics::aba(c.model, c.data, c.q, c.v, c.tau).data());
    benchmark::ClobberMemory();
  }
}

void BM_Rnea(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynamics::rnea(c.model, c.data, c.q, c.v, c.vdot).data());
    benchmark::ClobberMemory();
  }
}

void BM_Crba(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynamics::crba(c.model, c.data, c.q).data());
    benchmark::ClobberMemory();
  }
}

BENCHMARK(BM_Aba)->Arg(7)->Arg(32)->Arg(128);
BENCHMARK(BM_Rnea)->Arg(7)->Arg(32)->Arg(128);
BENCHMARK(BM_Crba)->Arg(7)->Arg(32)->Arg(128);

}  // namespace
