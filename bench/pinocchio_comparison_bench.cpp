// Side by side with Pinocchio's analytic derivatives (computeRNEADerivatives,
// computeABADerivatives; Carpentier & Mansard, RSS 2018) on the benchmark chains (n revolute
// links, 1 kg rods 0.1 m long, axes alternating z and y; random q, v, τ, v̇ from the seed of
// bench/chain_state.hpp). Pinocchio is not a Debian package: built only with
// -DMOMENTA_BENCH_PINOCCHIO=ON -DMOMENTA_PINOCCHIO_SOURCE=<a Pinocchio source checkout>, its
// algorithms used as the header code they are (cmake/PinocchioHeaders.cmake writes the three
// headers its own build would generate). Before timing, each chain's derivatives are checked
// against Pinocchio's (∂τ/∂q, ∂τ/∂v to 1e-12, ∂v̇/∂q, ∂v̇/∂v to 1e-9 of the largest entry: M⁻¹
// of the 128-link chain is ill-conditioned, and the two sides differ by 1e-10 there).

#include <cstdio>
#include <cstdlib>
#include <string>

#include <benchmark/benchmark.h>

#include "pinocchio/algorithm/aba-derivatives.hpp"
#include "pinocchio/algorithm/rnea-derivatives.hpp"
#include "pinocchio/multibody/data.hpp"
#include "pinocchio/multibody/model.hpp"

#include "chain_state.hpp"
#include "momenta/dynamics/aba_derivatives.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"

namespace {

// test::revolute_chain, built in Pinocchio.
pinocchio::Model pinocchio_chain(int n) {
  pinocchio::Model model;
  model.gravity.linear(Eigen::Vector3d(0, 0, -9.81));
  const double m = 1.0, L = 0.1, r = 0.01;
  const double Ixx = 0.5 * m * r * r, Iyy = m * (3 * r * r + L * L) / 12.0;
  pinocchio::JointIndex parent = 0;
  for (int k = 0; k < n; ++k) {
    pinocchio::SE3 placement = pinocchio::SE3::Identity();
    if (k > 0) placement.translation() = Eigen::Vector3d(L, 0, 0);
    const std::string name = "joint" + std::to_string(k);
    const pinocchio::JointIndex j =
        k % 2 == 0 ? model.addJoint(parent, pinocchio::JointModelRZ(), placement, name)
                   : model.addJoint(parent, pinocchio::JointModelRY(), placement, name);
    const Eigen::Matrix3d I = Eigen::Vector3d(Ixx, Iyy, Iyy).asDiagonal();
    model.appendBodyToJoint(j, pinocchio::Inertia(m, Eigen::Vector3d(L / 2, 0, 0), I),
                            pinocchio::SE3::Identity());
    parent = j;
  }
  return model;
}

struct Both {
  explicit Both(int n) : ours(n), model(pinocchio_chain(n)), data(model) {}
  momenta::bench::Chain ours;
  pinocchio::Model model;
  pinocchio::Data data;
};

double largest(const Eigen::MatrixXd& X) { return std::max(1.0, X.cwiseAbs().maxCoeff()); }

// Refuses to time two sides that compute different things.
void check_same(int n) {
  Both b(n);
  auto& c = b.ours;
  momenta::dynamics::rnea_derivatives(c.model, c.data, c.q, c.v, c.vdot);
  pinocchio::computeRNEADerivatives(b.model, b.data, c.q, c.v, c.vdot);
  const double rq =
      (c.data.dtau_dq - b.data.dtau_dq).cwiseAbs().maxCoeff() / largest(b.data.dtau_dq);
  const double rv =
      (c.data.dtau_dv - b.data.dtau_dv).cwiseAbs().maxCoeff() / largest(b.data.dtau_dv);
  momenta::dynamics::aba_derivatives(c.model, c.data, c.q, c.v, c.tau);
  pinocchio::computeABADerivatives(b.model, b.data, c.q, c.v, c.tau);
  const double aq =
      (c.data.dvdot_dq - b.data.ddq_dq).cwiseAbs().maxCoeff() / largest(b.data.ddq_dq);
  const double av =
      (c.data.dvdot_dv - b.data.ddq_dv).cwiseAbs().maxCoeff() / largest(b.data.ddq_dv);
  std::printf("n = %d: relative differences ∂τ/∂q %.2g, ∂τ/∂v %.2g, ∂v̇/∂q %.2g, ∂v̇/∂v %.2g\n", n,
              rq, rv, aq, av);
  if (!(rq < 1e-12 && rv < 1e-12 && aq < 1e-9 && av < 1e-9)) {
    std::fprintf(stderr, "momenta and Pinocchio disagree on the %d-link chain\n", n);
    std::exit(1);
  }
}

void BM_MomentaRneaDerivatives(benchmark::State& state) {
  Both b(static_cast<int>(state.range(0)));
  auto& c = b.ours;
  for (auto _ : state) {
    momenta::dynamics::rnea_derivatives(c.model, c.data, c.q, c.v, c.vdot);
    benchmark::DoNotOptimize(c.data.dtau_dq.data());
  }
}
void BM_PinocchioRneaDerivatives(benchmark::State& state) {
  Both b(static_cast<int>(state.range(0)));
  auto& c = b.ours;
  for (auto _ : state) {
    pinocchio::computeRNEADerivatives(b.model, b.data, c.q, c.v, c.vdot);
    benchmark::DoNotOptimize(b.data.dtau_dq.data());
  }
}
void BM_MomentaAbaDerivatives(benchmark::State& state) {
  Both b(static_cast<int>(state.range(0)));
  auto& c = b.ours;
  for (auto _ : state) {
    momenta::dynamics::aba_derivatives(c.model, c.data, c.q, c.v, c.tau);
    benchmark::DoNotOptimize(c.data.dvdot_dq.data());
  }
}
void BM_PinocchioAbaDerivatives(benchmark::State& state) {
  Both b(static_cast<int>(state.range(0)));
  auto& c = b.ours;
  for (auto _ : state) {
    pinocchio::computeABADerivatives(b.model, b.data, c.q, c.v, c.tau);
    benchmark::DoNotOptimize(b.data.ddq_dq.data());
  }
}

BENCHMARK(BM_MomentaRneaDerivatives)->Arg(7)->Arg(32)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PinocchioRneaDerivatives)->Arg(7)->Arg(32)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_MomentaAbaDerivatives)->Arg(7)->Arg(32)->Arg(128)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_PinocchioAbaDerivatives)->Arg(7)->Arg(32)->Arg(128)->Unit(benchmark::kMicrosecond);

}  // namespace

int main(int argc, char** argv) {
  for (const int n : {7, 32, 128}) check_same(n);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
