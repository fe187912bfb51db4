// Derivatives of the dynamics on the benchmark chains (test::revolute_chain, n = 7, 32, 128),
// random state from a fixed seed: analytic ∂RNEA and ∂ABA (rnea_derivatives, aba_derivatives)
// against the finite differences linearize used before them (central differences of ABA with one
// Richardson extrapolation on q, 4 evaluations a column, and exact central ones on v, 2 a
// column), and linearize itself on the 32-link chain.

#include <benchmark/benchmark.h>

#include "chain_state.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/aba_derivatives.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"

namespace {

using namespace momenta;

using bench::Chain;

void BM_RneaDerivatives(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    dynamics::rnea_derivatives(c.model, c.data, c.q, c.v, c.vdot);
    benchmark::DoNotOptimize(c.data.dtau_dq.data());
    benchmark::ClobberMemory();
  }
}

void BM_AbaDerivatives(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    dynamics::aba_derivatives(c.model, c.data, c.q, c.v, c.tau);
    benchmark::DoNotOptimize(c.data.dvdot_dq.data());
    benchmark::ClobberMemory();
  }
}

// ∂v̇/∂q and ∂v̇/∂v as linearize took them before: Richardson on q (h, h/2), exact on v.
void BM_AbaDerivativesByDifferences(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  const int n = c.model.nv();
  MatX dq(n, n), dv(n, n);
  VecX q = c.q, v = c.v, plus(n), minus(n), coarse(n);
  for (auto _ : state) {
    for (int k = 0; k < n; ++k) {
      const auto central = [&](double h) {
        q[k] = c.q[k] + h;
        plus = dynamics::aba(c.model, c.data, q, c.v, c.tau);
        q[k] = c.q[k] - h;
        minus = dynamics::aba(c.model, c.data, q, c.v, c.tau);
        q[k] = c.q[k];
        return VecX((plus - minus) / (2 * h));
      };
      coarse = central(1e-3);
      dq.col(k) = (4 * central(5e-4) - coarse) / 3;
      v[k] = c.v[k] + 1;
      plus = dynamics::aba(c.model, c.data, c.q, v, c.tau);
      v[k] = c.v[k] - 1;
      minus = dynamics::aba(c.model, c.data, c.q, v, c.tau);
      v[k] = c.v[k];
      dv.col(k) = (plus - minus) / 2;
    }
    benchmark::DoNotOptimize(dq.data());
    benchmark::DoNotOptimize(dv.data());
  }
}

// The whole linearization (state space, mass, stiffness, damping; no inputs, every angle an
// output) of the chain at a moving state.
void BM_Linearize(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  const analysis::OperatingPoint point{0.0, c.q, c.v};
  for (auto _ : state) {
    benchmark::DoNotOptimize(analysis::linearize(c.model, point).system.A().data());
  }
}

BENCHMARK(BM_RneaDerivatives)->Arg(7)->Arg(32)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AbaDerivatives)->Arg(7)->Arg(32)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AbaDerivativesByDifferences)->Arg(7)->Arg(32)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Linearize)->Arg(7)->Arg(32)->Unit(benchmark::kMicrosecond);

}  // namespace
