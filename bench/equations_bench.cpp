// Symbolic equations of motion (symbolic/equations.hpp) of the planar n-link pendulum — the
// problem SymPy mechanics is measured on (pydy PR#360: 4.5 s to derive and 82 s to generate code
// for n = 10): n uniform links of 1 kg and 1 m on revolute joints about z, gravity −y.
//   BM_Derive/n      derive_equations with every parameter a symbol (m, I, c, l, g per link)
//   BM_GenerateC/n   generate_code(cpp) of the derived equations (M and b)
//   BM_Evaluate...   evaluating the equations is the generated code's job (compiled by the user):
//                    the numeric engine's RNEA is the reference, BM_Rnea/n
//
// Run: build-bench/bench/equations_bench --benchmark_repetitions=5
//      --benchmark_report_aggregates_only=true

#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include "momenta/dynamics/data.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/symbolic/equations.hpp"

namespace {

using namespace momenta;

model::Model n_link_pendulum(int n) {
  std::string text = "name: pendulum chain\ngravity: [0, -9.81, 0]\nbodies:\n";
  for (int i = 0; i < n; ++i)
    text += fmt::format(
        "  - {{name: link{}, mass: 1, com: [0.5, 0, 0], inertia: [0.001, "
        "0.0833, 0.0833]}}\n",
        i);
  text += "joints:\n";
  for (int i = 0; i < n; ++i) {
    text += fmt::format(
        "  - {{name: j{}, type: revolute, parent: {}, child: link{}, axis: [0, 0, 1], "
        "in_parent: {{position: [{}, 0, 0]}}}}\n",
        i, i == 0 ? std::string("world") : fmt::format("link{}", i - 1), i, i == 0 ? 0 : 1);
  }
  return io::parse_model_file(text, "chain.yaml", ".").model;
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

BENCHMARK(BM_Derive)->Arg(2)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GenerateC)->Arg(2)->Arg(5)->Arg(10)->Arg(20)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Rnea)->Arg(2)->Arg(5)->Arg(10)->Arg(20);

}  // namespace

BENCHMARK_MAIN();
