// Symbolic equations of motion (symbolic/equations.hpp) of the planar n-link pendulum — the
// problem SymPy mechanics is measured on (pydy PR#360: 4.5 s to derive and 82 s to generate code
// for n = 10): n uniform links of 1 kg and 1 m on revolute joints about z, gravity −y.
//   BM_Derive/n      derive_equations with every parameter a symbol (m, I, c, l, g per link)
//   BM_GenerateC/n   generate_code(cpp) of the derived equations (M and b)
//   BM_GeneratedForwardDynamics/n   the generated C++ (momenta equations --cpp, compiled in):
//                    M(q) and b(q, v), then v̇ = −M⁻¹ b by Cholesky (Eigen, fixed size)
//   BM_Aba/n         the numeric engine's forward dynamics on the same model and state
//   BM_GeneratedBias/n, BM_Rnea/n    b(q, v) alone against RNEA's τ(q, v, v̇)
// The models are bench/models/chain<n>.yaml.
//
// Run: build-bench/bench/equations_bench --benchmark_repetitions=5
//      --benchmark_report_aggregates_only=true

#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <Eigen/Cholesky>

#include "chain10.hpp"
#include "chain2.hpp"
#include "chain20.hpp"
#include "chain5.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/symbolic/equations.hpp"

namespace {

using namespace momenta;

model::Model n_link_pendulum(int n) {
  return io::read_model_file(fmt::format("{}/chain{}.yaml", MOMENTA_BENCH_MODELS, n)).model;
}

symbolic::EquationOptions every_symbol() {
  symbolic::EquationOptions o;
  o.all_symbols = true;
  return o;
}

void BM_Derive(benchmark::State& state) {
  const model::Model model = n_link_pendulum(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(symbolic::derive_equations(model, every_symbol()));
}

void BM_GenerateC(benchmark::State& state) {
  const model::Model model = n_link_pendulum(static_cast<int>(state.range(0)));
  const symbolic::Equations e = symbolic::derive_equations(model, every_symbol());
  for (auto _ : state) {
    std::string code = e.generate_code(symbolic::Format::cpp, "chain");
    benchmark::DoNotOptimize(code);
  }
}

void BM_Rnea(benchmark::State& state) {
  const model::Model model = n_link_pendulum(static_cast<int>(state.range(0)));
  dynamics::Data data(model);
  const VecX q = VecX::Constant(model.nq(), 0.3), v = VecX::Constant(model.nv(), 0.2),
             a = VecX::Constant(model.nv(), 0.1);
  for (auto _ : state) benchmark::DoNotOptimize(dynamics::rnea(model, data, q, v, a).data());
}

void BM_Aba(benchmark::State& state) {
  const model::Model model = n_link_pendulum(static_cast<int>(state.range(0)));
  dynamics::Data data(model);
  const VecX q = VecX::Constant(model.nq(), 0.3), v = VecX::Constant(model.nv(), 0.2),
             tau = VecX::Zero(model.nv());
  for (auto _ : state) benchmark::DoNotOptimize(dynamics::aba(model, data, q, v, tau).data());
}

// The generated functions of one chain, for the templates below.
template <int N>
struct Generated {
  void (*mass_matrix)(const double*, double*);
  void (*bias)(const double*, const double*, const double*, const double*, double*);
};

template <int N>
void generated_forward_dynamics(benchmark::State& state, Generated<N> g) {
  using Vec = Eigen::Matrix<double, N, 1>;
  const Vec q = Vec::Constant(0.3), v = Vec::Constant(0.2), no_vdot = Vec::Zero();
  Eigen::Matrix<double, N, N> M;  // symmetric: its row-major entries are its column-major ones
  Vec b, vdot;
  for (auto _ : state) {
    g.mass_matrix(q.data(), M.data());
    g.bias(q.data(), v.data(), no_vdot.data(), nullptr, b.data());
    vdot = M.llt().solve(-b);
    benchmark::DoNotOptimize(vdot.data());
  }
}

template <int N>
void generated_bias(benchmark::State& state, Generated<N> g) {
  using Vec = Eigen::Matrix<double, N, 1>;
  const Vec q = Vec::Constant(0.3), v = Vec::Constant(0.2), vdot = Vec::Constant(0.1);
  Vec b;
  for (auto _ : state) {
    g.bias(q.data(), v.data(), vdot.data(), nullptr, b.data());
    benchmark::DoNotOptimize(b.data());
  }
}

#define MOMENTA_GENERATED_BENCHMARKS(n)                                                     \
  BENCHMARK_CAPTURE(generated_forward_dynamics, n,                                          \
                    Generated<n>{chain##n::mass_matrix, chain##n::bias})                    \
      ->Name("BM_GeneratedForwardDynamics/" #n);                                            \
  BENCHMARK_CAPTURE(generated_bias, n, Generated<n>{chain##n::mass_matrix, chain##n::bias}) \
      ->Name("BM_GeneratedBias/" #n);

MOMENTA_GENERATED_BENCHMARKS(2)
MOMENTA_GENERATED_BENCHMARKS(5)
MOMENTA_GENERATED_BENCHMARKS(10)
MOMENTA_GENERATED_BENCHMARKS(20)

BENCHMARK(BM_Aba)->Arg(2)->Arg(5)->Arg(10)->Arg(20);
BENCHMARK(BM_Derive)->Arg(2)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GenerateC)->Arg(2)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Rnea)->Arg(2)->Arg(5)->Arg(10)->Arg(20);

}  // namespace

BENCHMARK_MAIN();
