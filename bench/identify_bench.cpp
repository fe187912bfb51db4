// Identification of inertia on the benchmark chains of n revolute links (1 kg, 0.1 m rods, axes
// alternating z and y), random q, v, v̇ from a fixed seed: the regressor Y(q, v, v̇) beside RNEA
// on the same chain and state (the ratio is the regressor's price: its nv × 10n entries against
// RNEA's nv), the base parameters (a model's one-off QR), and an estimate from 500 samples of the
// two-link arm.

#include <random>

#include <benchmark/benchmark.h>

#include "chain_state.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/identify/inertia_estimate.hpp"
#include "momenta/identify/inertial_regressor.hpp"
#include "momenta_test/two_link_arm.hpp"

namespace {

using namespace momenta;

using bench::Chain;

void BM_RneaBesideRegressor(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynamics::rnea(c.model, c.data, c.q, c.v, c.vdot).data());
    benchmark::ClobberMemory();
  }
}

void BM_InertialRegressor(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  identify::InertialRegressor regressor(c.model);
  for (auto _ : state) {
    benchmark::DoNotOptimize(regressor.compute(c.q, c.v, c.vdot).data());
    benchmark::ClobberMemory();
  }
}

void BM_BaseParameters(benchmark::State& state) {
  Chain c(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(identify::base_parameters(c.model).rank());
}

void BM_EstimateInertiaTwoLinkArm500Samples(benchmark::State& state) {
  const test::TwoLinkArm arm;
  const model::Model model = arm.model();
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> u(-2, 2);
  identify::InertiaSamples s{MatX(500, 2), MatX(500, 2), MatX(500, 2), MatX(500, 2), {}};
  for (int i = 0; i < 500; ++i) {
    const Eigen::Vector2d q(u(rng), u(rng)), v(u(rng), u(rng)), a(u(rng), u(rng));
    s.q.row(i) = q, s.v.row(i) = v, s.vdot.row(i) = a;
    s.tau.row(i) = arm.torque(q, v, a) + Eigen::Vector2d(0.01 * u(rng), 0.01 * u(rng));
  }
  const identify::BaseParameters base = identify::base_parameters(model);
  for (auto _ : state)
    benchmark::DoNotOptimize(identify::estimate_inertia(model, s, base).beta.data());
}

BENCHMARK(BM_RneaBesideRegressor)->Arg(7)->Arg(32);
BENCHMARK(BM_InertialRegressor)->Arg(7)->Arg(32);
BENCHMARK(BM_BaseParameters)->Arg(7)->Arg(32)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EstimateInertiaTwoLinkArm500Samples)->Unit(benchmark::kMillisecond);

}  // namespace
