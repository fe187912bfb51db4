// Integrators on a model: the free rigid body of the peer figures (/work/shared/references.md),
// I = diag(1, 2, 3) kg·m², ω0 = (0.01, 2, 0.01) rad/s, as a one-body model on a free joint
// (system::MultibodySystem), h = 1 ms, 1e6 steps (1000 s, 45 periods of ω, 90 flips). Every
// integrator the model can be run with: the structure-preserving ones
// (system::make_rigid_body_integrator) and the generic ones (integrate::make_integrator).
//
//   BM_ModelStep/<integrator>   ns per step over exactly 1e6 steps from the initial state
//                               (--benchmark_repetitions=3, quote the median), and as counters
//                               at the end of those steps: energy_drift = (E − E0)/E0,
//                               H_norm_drift = (|H| − |H0|)/|H0|, H_W_drift = |H_W − H_W0|/|H0|
//                               (H_W = R_WB I ω, the spatial angular momentum) and the phase
//                               error against the exact solution (FreeRigidBodySolution):
//                               R_error = max |R − R_exact|, w_error = max |ω − ω_exact| (rad/s).
//   BM_ModelEnergyMax/<integrator>  max over the run of |E − E0|/E0 (sampled every 100 steps;
//                               the bounded oscillation of a symplectic method), run once.
//   BM_CompositionPhase/<0|1>   Yoshida's and Suzuki's fourth-order compositions (library level)
//                               at h = 10 ms for 1000 s: attitude and ω error against the exact
//                               solution; the time shown is for the 10⁵ steps. The choice behind
//                               splitting4.
//
// Run: build/bench/rigid_body_model_bench --benchmark_repetitions=3
//      --benchmark_report_aggregates_only=true

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <string_view>

#include "momenta/integrate/integrator.hpp"
#include "momenta/model/model_builder.hpp"
#include "momenta/rigid_body/free_rigid_body.hpp"
#include "momenta/rigid_body/rotation_integrators.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta/system/rigid_body_integrator.hpp"
#include "momenta_test/multibody_models.hpp"

namespace {

using namespace momenta;

const Vec3 kMoments(1.0, 2.0, 3.0);
const Vec3 kOmega0(0.01, 2.0, 0.01);
constexpr double kStep = 1e-3;
constexpr long kSteps = 1'000'000;

const char* kNames[] = {"splitting", "splitting4", "lie_group",       "exact",
                        "rk4",       "dopri5",     "symplectic_euler"};

const model::Model& racket() {
  static const model::Model model = test::tumbling_free_body();
  return model;
}

std::unique_ptr<integrate::Integrator> make(std::string_view name) {
  if (auto integrator = system::make_rigid_body_integrator(name)) return integrator;
  return integrate::make_integrator(name);
}

Mat3 attitude(const integrate::State& s) {
  return Quat(s.q[3], s.q[4], s.q[5], s.q[6]).normalized().toRotationMatrix();
}
double energy(const integrate::State& s) {
  const Vec3 w = s.v.head<3>();
  return 0.5 * w.dot(kMoments.cwiseProduct(w));
}

void BM_ModelStep(benchmark::State& bench) {
  const std::string_view name = kNames[bench.range(0)];
  bench.SetLabel(std::string(name));
  const model::Model& model = racket();
  system::MultibodySystem system(model);
  auto integrator = make(name);
  integrate::State s{0.0, model.initial_q(), model.initial_v()};
  integrator->initialize(system, s);
  // The time reached: the steps taken, summed with compensation (a plain sum, even in long
  // double, is off by ~1e-12 s after 1e6 steps of 1 ms, 2e-12 rad of phase at 2 rad/s).
  long double t = 0, t_low = 0;
  for (auto _ : bench) {
    const long double taken = integrator->step(system, s, kStep);
    const long double sum = t + taken;
    t_low += (t - sum) + taken;
    t = sum;
    benchmark::DoNotOptimize(s.q.data());
  }
  t += t_low;
  // Drifts and phase error at the end of the timed run (1e6 steps from the initial state).
  const integrate::State start{0.0, model.initial_q(), model.initial_v()};
  const Vec3 w = s.v.head<3>(), H0 = kMoments.cwiseProduct(kOmega0);
  const Vec3 H_W = attitude(s) * kMoments.cwiseProduct(w);
  rigid_body::RotationState exact;
  rigid_body::FreeRigidBodySolution(Mat3(kMoments.asDiagonal()), Mat3::Identity(), kOmega0)
      .evaluate(t, exact.R_WB, exact.w_WB_B);
  bench.counters["t_end"] = static_cast<double>(t);
  bench.counters["energy_drift"] = (energy(s) - energy(start)) / energy(start);
  bench.counters["H_norm_drift"] = (H_W.norm() - H0.norm()) / H0.norm();
  bench.counters["H_W_drift"] = (H_W - H0).norm() / H0.norm();
  bench.counters["R_error"] = (attitude(s) - exact.R_WB).cwiseAbs().maxCoeff();
  bench.counters["w_error"] = (w - exact.w_WB_B).cwiseAbs().maxCoeff();
}
BENCHMARK(BM_ModelStep)->DenseRange(0, 6)->Iterations(kSteps)->Unit(benchmark::kNanosecond);

void BM_ModelEnergyMax(benchmark::State& bench) {
  const std::string_view name = kNames[bench.range(0)];
  bench.SetLabel(std::string(name));
  const model::Model& model = racket();
  for (auto _ : bench) {
    system::MultibodySystem system(model);
    auto integrator = make(name);
    integrate::State s{0.0, model.initial_q(), model.initial_v()};
    integrator->initialize(system, s);
    const double E0 = energy(s);
    double worst = 0;
    for (long i = 1; i <= kSteps; ++i) {
      integrator->step(system, s, kStep);
      if (i % 100 == 0) worst = std::max(worst, std::abs(energy(s) - E0) / E0);
    }
    bench.counters["energy_max"] = worst;
  }
}
BENCHMARK(BM_ModelEnergyMax)->DenseRange(0, 6)->Iterations(1)->Unit(benchmark::kSecond);

// Why splitting4 is Suzuki's composition: the attitude error of the two fourth-order
// compositions (library level) after 1000 s at h = 10 ms, against the exact solution, and their
// time per step.
void BM_CompositionPhase(benchmark::State& bench) {
  const bool suzuki = bench.range(0) == 1;
  bench.SetLabel(suzuki ? "suzuki4" : "yoshida4");
  const Mat3 I = kMoments.asDiagonal();
  const double h = 0.01;
  const long steps = 100'000;
  for (auto _ : bench) {
    rigid_body::SplittingIntegrator integrator(
        I, suzuki ? rigid_body::Composition::kSuzuki4 : rigid_body::Composition::kYoshida4);
    Mat3 R = Mat3::Identity();
    Vec3 w = kOmega0;
    for (long i = 0; i < steps; ++i) integrator.step(R, w, h);
    rigid_body::RotationState exact;
    rigid_body::FreeRigidBodySolution(I, Mat3::Identity(), kOmega0)
        .evaluate(static_cast<long double>(h) * steps, exact.R_WB, exact.w_WB_B);
    bench.counters["R_error"] = (R - exact.R_WB).cwiseAbs().maxCoeff();
    bench.counters["w_error"] = (w - exact.w_WB_B).cwiseAbs().maxCoeff();
  }
}
BENCHMARK(BM_CompositionPhase)->DenseRange(0, 1)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
