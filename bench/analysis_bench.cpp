// Linear-systems analysis: frequency response (Hessenberg vs a dense LU per frequency), step
// response (Van Loan discretization + recurrence), and zeros (deflation + QZ), on random
// stable systems of n states.

#include <complex>
#include <random>

#include <benchmark/benchmark.h>

#include "momenta/analysis/frequency_response.hpp"
#include "momenta/analysis/time_response.hpp"
#include "momenta/analysis/transfer_function.hpp"

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

}  // namespace
