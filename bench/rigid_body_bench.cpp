// Free rigid body I = diag(1, 2, 3) kg·m², ω0 = (0.01, 2, 0.01) rad/s (a flip about the
// intermediate axis every 11 s), h = 1 ms — the setting of the peer figures in
// /work/shared/references.md (MuJoCo 2.2 RK4: 2270 ns per step, relative energy drift 1.7e-13,
// |H| drift 8.5e-14 after 1e6 steps).
//
//   BM_Step/<method>          ns per step (the benchmark's time), and as counters the relative
//                             drifts after 1e6 steps: energy_drift = (E − E0)/E0 at the end,
//                             energy_max = max |E − E0|/E0 over the run (the bounded O(hᵖ)
//                             oscillation of a symplectic method), H_norm_drift = (|H| − |H0|)/|H0|
//                             and H_W_drift = |H_W − H_W0|/|H0| (the spatial vector).
//   BM_LongRun/<method>       the same counters after 1e7 steps (10⁴ s; run on demand with
//                             --benchmark_filter=LongRun, about 10 s in all).
//   BM_ExactAccuracy          the exact solution at t = 1000 s against a Taylor integration in
//                             binary128 (34 digits): max error of R and ω (about 4 s).
//   BM_ExactEvaluate          one evaluation of FreeRigidBodySolution at an arbitrary time.
//
// Run: build/bench/rigid_body_bench --benchmark_repetitions=5 --benchmark_report_aggregates_only.

#include <benchmark/benchmark.h>

#include <cmath>
#include <functional>
#include <memory>

#include "momenta/rigid_body/free_rigid_body.hpp"
#include "momenta/rigid_body/rotation_integrators.hpp"
#include "momenta_test/rotation_reference.hpp"

namespace {

using namespace momenta;
using namespace momenta::rigid_body;

const Mat3 kInertia = Vec3(1.0, 2.0, 3.0).asDiagonal();
const Vec3 kOmega0(0.01, 2.0, 0.01);
constexpr double kStep = 1e-3;

enum Method { kStrang, kYoshida4, kSuzuki4, kLieGroup, kExactStepper };
const char* kNames[] = {"strang_axes", "yoshida4_axes", "suzuki4_axes", "lie_group_variational",
                        "exact_stepper"};

// A stepping function for one method, holding its integrator.
std::function<void(Mat3&, Vec3&, double)> make_stepper(int method) {
  switch (method) {
    case kStrang:
    case kYoshida4:
    case kSuzuki4: {
      const Composition c = method == kStrang     ? Composition::kStrang
                            : method == kYoshida4 ? Composition::kYoshida4
                                                  : Composition::kSuzuki4;
      auto integrator = std::make_shared<SplittingIntegrator>(kInertia, c);
      return [integrator](Mat3& R, Vec3& w, double h) { integrator->step(R, w, h); };
    }
    case kLieGroup: {
      auto integrator = std::make_shared<LieGroupVariational>(kInertia);
      return [integrator](Mat3& R, Vec3& w, double h) { integrator->step(R, w, h); };
    }
    default: {
      auto stepper = std::make_shared<ExactFreeRigidBodyStepper>(kInertia);
      return [stepper](Mat3& R, Vec3& w, double h) { stepper->step(R, w, h); };
    }
  }
}

// Runs n steps and records the drifts as counters.
void drift_counters(benchmark::State& state, int method, long n) {
  auto step = make_stepper(method);
  Mat3 R = Mat3::Identity();
  Vec3 w = kOmega0;
  const double E0 = 0.5 * w.dot(kInertia * w);
  const Vec3 H0 = kInertia * w;
  double energy_max = 0;
  for (long i = 1; i <= n; ++i) {
    step(R, w, kStep);
    if (i % 100 == 0) {
      energy_max = std::max(energy_max, std::abs(0.5 * w.dot(kInertia * w) - E0) / E0);
    }
  }
  const Vec3 H = R * kInertia * w;
  state.counters["energy_drift"] = (0.5 * w.dot(kInertia * w) - E0) / E0;
  state.counters["energy_max"] = energy_max;
  state.counters["H_norm_drift"] = (H.norm() - H0.norm()) / H0.norm();
  state.counters["H_W_drift"] = (H - H0).norm() / H0.norm();
}

void BM_Step(benchmark::State& state) {
  const int method = static_cast<int>(state.range(0));
  state.SetLabel(kNames[method]);
  auto step = make_stepper(method);
  Mat3 R = Mat3::Identity();
  Vec3 w = kOmega0;
  for (auto _ : state) {
    step(R, w, kStep);
    benchmark::DoNotOptimize(R.data());
    benchmark::DoNotOptimize(w.data());
  }
  drift_counters(state, method, 1'000'000);
}
BENCHMARK(BM_Step)->DenseRange(0, 4)->Unit(benchmark::kNanosecond);

void BM_LongRun(benchmark::State& state) {
  const int method = static_cast<int>(state.range(0));
  state.SetLabel(kNames[method]);
  for (auto _ : state) drift_counters(state, method, 10'000'000);
}
BENCHMARK(BM_LongRun)->DenseRange(0, 4)->Iterations(1)->Unit(benchmark::kSecond);

void BM_ExactEvaluate(benchmark::State& state) {
  const FreeRigidBodySolution solution(kInertia, Mat3::Identity(), kOmega0);
  Mat3 R;
  Vec3 w;
  double t = 0;
  for (auto _ : state) {
    solution.evaluate(t += 0.7317, R, w);
    benchmark::DoNotOptimize(R.data());
  }
}
BENCHMARK(BM_ExactEvaluate)->Unit(benchmark::kNanosecond);

void BM_ExactSetup(benchmark::State& state) {
  double m = 0;
  for (auto _ : state) {
    const FreeRigidBodySolution solution(kInertia, Mat3::Identity(), kOmega0);
    m += solution.parameter();
  }
  benchmark::DoNotOptimize(m);
}
BENCHMARK(BM_ExactSetup)->Unit(benchmark::kNanosecond);

void BM_ExactAccuracy(benchmark::State& state) {
  for (auto _ : state) {
    const RotationState s = FreeRigidBodySolution(kInertia, Mat3::Identity(), kOmega0)(1000.0);
    test::TaylorRotation<__float128> reference(kInertia, Mat3::Identity(), kOmega0,
                                               __float128(1.9259299443872359e-34));
    reference.advance_to(__float128(1000), __float128(0.25));
    state.counters["R_error"] = (s.R_WB - reference.R_double()).cwiseAbs().maxCoeff();
    state.counters["w_error"] = (s.w_WB_B - reference.w_double()).cwiseAbs().maxCoeff();
  }
}
BENCHMARK(BM_ExactAccuracy)->Iterations(1)->Unit(benchmark::kSecond);

}  // namespace
