// Linear-systems analysis: frequency response (Hessenberg vs a dense LU per frequency), step
// response (Van Loan discretization + recurrence), and zeros (deflation + QZ), on random
// stable systems of n states; and find_equilibrium on a hanging chain of n links.

#include <complex>
#include <random>

#include <benchmark/benchmark.h>

#include "momenta/analysis/equilibrium.hpp"
#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"
#include "momenta/model/model_builder.hpp"

namespace {

using momenta::MatX;
using momenta::analysis::StateSpace;

StateSpace random_system(int n) {
  std::mt19937 generator(42);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  MatX A(n, n), B(n, 1), C(1, n);
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) A(i, j) = uniform(generator);
    B(j, 0) = uniform(generator);
    C(0, j) = uniform(generator);
  }
  A -= 1.5 * std::sqrt(static_cast<double>(n)) * MatX::Identity(n, n);
  return StateSpace(A, B, C, MatX());
}

// 1000 frequencies, one Hessenberg reduction then O(n²) per frequency.
void BM_FrequencyResponse(benchmark::State& state) {
  const StateSpace system = random_system(static_cast<int>(state.range(0)));
  const momenta::VecX w = momenta::analysis::log_frequency_grid(1e-2, 1e3, 1000);
  for (auto _ : state) {
    benchmark::DoNotOptimize(momenta::analysis::frequency_response(system, 0, 0, w));
  }
}
BENCHMARK(BM_FrequencyResponse)->Arg(8)->Arg(32)->Arg(96)->Unit(benchmark::kMicrosecond);

// The same 1000 frequencies by a dense complex LU each: the O(n³) baseline.
void BM_FrequencyResponseDenseLu(benchmark::State& state) {
  const StateSpace system = random_system(static_cast<int>(state.range(0)));
  const momenta::VecX w = momenta::analysis::log_frequency_grid(1e-2, 1e3, 1000);
  for (auto _ : state) {
    for (Eigen::Index k = 0; k < w.size(); ++k) {
      benchmark::DoNotOptimize(
          momenta::analysis::evaluate(system, 0, 0, std::complex<double>(0.0, w[k])));
    }
  }
}
BENCHMARK(BM_FrequencyResponseDenseLu)->Arg(8)->Arg(32)->Arg(96)->Unit(benchmark::kMicrosecond);

// Step response on 2001 samples.
void BM_StepResponse(benchmark::State& state) {
  const StateSpace system = random_system(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(momenta::analysis::step_response(system, 0, {10.0, 2001}));
  }
}
BENCHMARK(BM_StepResponse)->Arg(8)->Arg(32)->Arg(96)->Unit(benchmark::kMicrosecond);

// Poles, zeros, gain and cancellation of one pair.
void BM_TransferFunction(benchmark::State& state) {
  const StateSpace system = random_system(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(momenta::analysis::transfer_function(system, 0, 0));
  }
}
BENCHMARK(BM_TransferFunction)->Arg(8)->Arg(32)->Arg(96)->Unit(benchmark::kMicrosecond);

// n links of 1 kg, 0.1 m along x, every axis y, gravity −ẑ: the chain hangs straight down at
// q = (π/2, 0, …, 0); the search starts 0.3 rad off at the root and ±0.1 rad at every other joint.
void BM_FindEquilibrium(benchmark::State& state) {
  using namespace momenta;
  const int n = static_cast<int>(state.range(0));
  model::ModelBuilder builder;
  builder.set_gravity(Vec3(0, 0, -9.81));
  for (int k = 0; k < n; ++k) {
    const std::string name = "link" + std::to_string(k);
    builder.add_body(
        name, inertia::MassProperties(1.0, Vec3(0.05, 0, 0),
                                      Vec3(5e-5, 8.4e-4, 8.4e-4).asDiagonal().toDenseMatrix()));
    model::Joint j;
    j.name = "joint" + std::to_string(k);
    j.type = model::JointType::revolute;
    j.parent = k == 0 ? "world" : "link" + std::to_string(k - 1);
    j.child = name;
    j.X_PJ = Transform::translation(k == 0 ? Vec3::Zero() : Vec3(0.1, 0, 0));
    j.axis = Vec3::UnitY();
    builder.add_joint(j);
  }
  const model::Model model = builder.build();
  VecX guess(n);
  for (int k = 0; k < n; ++k) guess[k] = k == 0 ? 1.5707963267948966 + 0.3 : (k % 2 ? 0.1 : -0.1);
  for (auto _ : state) {
    const analysis::Equilibrium e = analysis::find_equilibrium(model, guess);
    benchmark::DoNotOptimize(e.point.q.data());
    state.counters["iterations"] = e.iterations;
  }
}
BENCHMARK(BM_FindEquilibrium)->Arg(7)->Arg(32)->Unit(benchmark::kMicrosecond);

}  // namespace
