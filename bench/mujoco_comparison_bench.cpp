// Side by side with MuJoCo 2.2 (libmujoco-dev) on the same serial chains as dynamics_bench:
// n revolute links (1 kg, 0.1 m rods of radius 0.01 m, axes alternating z and y), random q, v,
// τ from a fixed seed. Built only with -DMOMENTA_BENCH_MUJOCO=ON; run once to get both sides
// (and their ratios) from one process on one machine. Before timing, each chain's results are
// checked against MuJoCo's (mass matrix, inverse and forward dynamics to 1e-9 relative), so the
// two sides compute the same thing.
//
// MuJoCo sides: forward dynamics = mj_forward (contacts and the constraint solver disabled) and
// the minimal pipeline mj_kinematics, mj_comPos, mj_crb, mj_factorM, mj_comVel, mj_rne, mj_solveM;
// inverse dynamics = mj_kinematics, mj_comPos, mj_comVel, mj_rne(flg_acc = 1); mass matrix =
// mj_kinematics, mj_comPos, mj_crb, mj_fullM (dense, as momenta's).
//
// The tumbling free body of the peer figures (I = diag(1, 2, 3) kg·m², ω0 = (0.01, 2, 0.01)
// rad/s, h = 1 ms, 10⁶ steps): MuJoCo's mj_step with its RK4 integrator against momenta's
// integrators on the same body as a model (system::MultibodySystem): ns per step, and as
// counters the relative energy and |H| drift at the end of the 10⁶ steps.

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <random>
#include <string>

#include <benchmark/benchmark.h>
#include <fmt/format.h>
#include <mujoco/mujoco.h>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/integrate/integrator.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta/system/rigid_body_integrator.hpp"
#include "momenta_test/multibody_models.hpp"

namespace {

using namespace momenta;

// The same chain as test::revolute_chain, as URDF: its links and joints are listed flat, so
// MuJoCo's XML reader (whose element depth is limited to about 100) takes n = 128, which nested
// MJCF bodies cannot reach. Contacts and the constraint solver are disabled after loading.
std::string chain_urdf(int n) {
  const double m = 1.0, L = 0.1, r = 0.01;
  const double Ixx = 0.5 * m * r * r, Iyy = m * (3 * r * r + L * L) / 12.0;
  std::string xml = "<robot name='chain'><link name='base'/>";
  for (int k = 0; k < n; ++k) {
    xml += fmt::format(
        "<link name='link{0}'><inertial><origin xyz='{1} 0 0'/><mass value='{2}'/>"
        "<inertia ixx='{3:.17g}' iyy='{4:.17g}' izz='{4:.17g}' ixy='0' ixz='0' iyz='0'/>"
        "</inertial></link>"
        "<joint name='joint{0}' type='continuous'><parent link='{5}'/><child link='link{0}'/>"
        "<origin xyz='{6} 0 0'/><axis xyz='{7}'/></joint>",
        k, L / 2, m, Ixx, Iyy, k == 0 ? std::string("base") : fmt::format("link{}", k - 1),
        k == 0 ? 0.0 : L, k % 2 == 0 ? "0 0 1" : "0 1 0");
  }
  return xml + "</robot>";
}

struct Pair {
  explicit Pair(int n) : model(test::revolute_chain(n)), data(model) {
    std::mt19937 rng(42);
    q = test::random_vector(n, rng, 3.14);
    v = test::random_vector(n, rng, 1.0);
    tau = test::random_vector(n, rng, 1.0);
    vdot = test::random_vector(n, rng, 1.0);
    const std::string xml = chain_urdf(n);
    mjVFS vfs;
    mj_defaultVFS(&vfs);
    mj_makeEmptyFileVFS(&vfs, "chain.urdf", static_cast<int>(xml.size()));
    std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "chain.urdf")], xml.data(), xml.size());
    char error[1000] = "";
    m = mj_loadXML("chain.urdf", &vfs, error, sizeof(error));
    mj_deleteVFS(&vfs);
    if (!m) {
      std::fprintf(stderr, "MuJoCo could not load the chain: %s\n", error);
      std::exit(1);
    }
    m->opt.disableflags |= mjDSBL_CONTACT | mjDSBL_CONSTRAINT;
    m->opt.gravity[0] = m->opt.gravity[1] = 0.0;
    m->opt.gravity[2] = -9.81;
    if (m->nv != n) {
      std::fprintf(stderr, "MuJoCo built %d degrees of freedom for a chain of %d\n", m->nv, n);
      std::exit(1);
    }
    d = mj_makeData(m);
    for (int i = 0; i < n; ++i) {
      d->qpos[i] = q[i];
      d->qvel[i] = v[i];
      d->qfrc_applied[i] = tau[i];
    }
    dense_M.resize(n, n);
    check(n);
  }
  ~Pair() {
    mj_deleteData(d);
    mj_deleteModel(m);
  }

  // Both sides must agree before their times mean anything.
  void check(int n) {
    const auto fail = [&](const char* what, double error) {
      std::fprintf(stderr, "n = %d: momenta and MuJoCo differ in %s by %g\n", n, what, error);
      std::exit(1);
    };
    mj_forward(m, d);
    const VecX qacc = Eigen::Map<const VecX>(d->qacc, n);
    const VecX ours = dynamics::aba(model, data, q, v, tau);
    if ((ours - qacc).norm() > 1e-9 * (1 + qacc.norm()))
      fail("forward dynamics", (ours - qacc).norm());
    mj_fullM(m, dense_M.data(), d->qM);
    const MatX M = dynamics::crba(model, data, q);
    if ((M - dense_M).norm() > 1e-9 * M.norm()) fail("the mass matrix", (M - dense_M).norm());
    for (int i = 0; i < n; ++i) d->qacc[i] = vdot[i];
    VecX rne(n);
    mj_rne(m, d, 1, rne.data());
    const VecX id = dynamics::rnea(model, data, q, v, vdot);
    if ((id - rne).norm() > 1e-9 * (1 + rne.norm())) fail("inverse dynamics", (id - rne).norm());
  }

  model::Model model;
  dynamics::Data data;
  VecX q, v, tau, vdot;
  mjModel* m = nullptr;
  mjData* d = nullptr;
  MatX dense_M;
};

void BM_Momenta_Aba(benchmark::State& state) {
  Pair p(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynamics::aba(p.model, p.data, p.q, p.v, p.tau).data());
    benchmark::ClobberMemory();
  }
}

void BM_MuJoCo_Forward(benchmark::State& state) {
  Pair p(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    mj_forward(p.m, p.d);
    benchmark::DoNotOptimize(p.d->qacc);
    benchmark::ClobberMemory();
  }
}

void BM_MuJoCo_ForwardMinimal(benchmark::State& state) {
  Pair p(static_cast<int>(state.range(0)));
  const int n = p.m->nv;
  VecX rhs(n);
  for (auto _ : state) {
    mj_kinematics(p.m, p.d);
    mj_comPos(p.m, p.d);
    mj_crb(p.m, p.d);
    mj_factorM(p.m, p.d);
    mj_comVel(p.m, p.d);
    mj_rne(p.m, p.d, 0, p.d->qfrc_bias);
    for (int i = 0; i < n; ++i) rhs[i] = p.d->qfrc_applied[i] - p.d->qfrc_bias[i];
    mj_solveM(p.m, p.d, p.d->qacc, rhs.data(), 1);
    benchmark::DoNotOptimize(p.d->qacc);
    benchmark::ClobberMemory();
  }
}

void BM_Momenta_Rnea(benchmark::State& state) {
  Pair p(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynamics::rnea(p.model, p.data, p.q, p.v, p.vdot).data());
    benchmark::ClobberMemory();
  }
}

void BM_MuJoCo_Rne(benchmark::State& state) {
  Pair p(static_cast<int>(state.range(0)));
  for (int i = 0; i < p.m->nv; ++i) p.d->qacc[i] = p.vdot[i];
  VecX out(p.m->nv);
  for (auto _ : state) {
    mj_kinematics(p.m, p.d);
    mj_comPos(p.m, p.d);
    mj_comVel(p.m, p.d);
    mj_rne(p.m, p.d, 1, out.data());
    benchmark::DoNotOptimize(out.data());
    benchmark::ClobberMemory();
  }
}

void BM_Momenta_Crba(benchmark::State& state) {
  Pair p(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynamics::crba(p.model, p.data, p.q).data());
    benchmark::ClobberMemory();
  }
}

void BM_MuJoCo_Crb(benchmark::State& state) {
  Pair p(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    mj_kinematics(p.m, p.d);
    mj_comPos(p.m, p.d);
    mj_crb(p.m, p.d);
    mj_fullM(p.m, p.dense_M.data(), p.d->qM);
    benchmark::DoNotOptimize(p.dense_M.data());
    benchmark::ClobberMemory();
  }
}

// --- the tumbling free body, 10⁶ steps of 1 ms --------------------------------------------------

constexpr long kFreeBodySteps = 1'000'000;
const Vec3 kMoments(1.0, 2.0, 3.0);

// Relative energy and |H| drift of a body-frame angular velocity against the initial one.
void report_drift(benchmark::State& state, const Vec3& w, const Vec3& w0) {
  const auto energy = [](const Vec3& x) { return 0.5 * x.dot(kMoments.cwiseProduct(x)); };
  state.counters["energy_drift"] = (energy(w) - energy(w0)) / energy(w0);
  state.counters["H_norm_drift"] =
      (kMoments.cwiseProduct(w).norm() - kMoments.cwiseProduct(w0).norm()) /
      kMoments.cwiseProduct(w0).norm();
}

void BM_MuJoCo_FreeBodyRK4(benchmark::State& state) {
  const char* xml =
      "<mujoco><option timestep='0.001' integrator='RK4' gravity='0 0 0'/>"
      "<worldbody><body name='racket'><freejoint/>"
      "<inertial pos='0 0 0' mass='1' diaginertia='1 2 3'/></body></worldbody></mujoco>";
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "racket.xml", static_cast<int>(std::strlen(xml)));
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "racket.xml")], xml, std::strlen(xml));
  char error[1000] = "";
  mjModel* m = mj_loadXML("racket.xml", &vfs, error, sizeof(error));
  mj_deleteVFS(&vfs);
  if (!m) {
    std::fprintf(stderr, "MuJoCo could not load the free body: %s\n", error);
    std::exit(1);
  }
  mjData* d = mj_makeData(m);
  // A free joint's angular velocity (qvel[3..5]) is in the body frame, as momenta's w_WB_B.
  const Vec3 w0(0.01, 2.0, 0.01);
  for (int k = 0; k < 3; ++k) d->qvel[3 + k] = w0[k];
  for (auto _ : state) {
    mj_step(m, d);
    benchmark::DoNotOptimize(d->qpos);
  }
  report_drift(state, Vec3(d->qvel[3], d->qvel[4], d->qvel[5]), w0);
  mj_deleteData(d);
  mj_deleteModel(m);
}

const char* kFreeBodyIntegrators[] = {"splitting", "splitting4", "lie_group", "exact", "rk4"};

void BM_Momenta_FreeBody(benchmark::State& state) {
  const char* name = kFreeBodyIntegrators[state.range(0)];
  state.SetLabel(name);
  static const model::Model model = test::tumbling_free_body();
  system::MultibodySystem system(model);
  std::unique_ptr<integrate::Integrator> integrator = system::make_rigid_body_integrator(name);
  if (!integrator) integrator = integrate::make_integrator(name);
  integrate::State s{0.0, model.initial_q(), model.initial_v()};
  integrator->initialize(system, s);
  for (auto _ : state) {
    integrator->step(system, s, 1e-3);
    benchmark::DoNotOptimize(s.q.data());
  }
  report_drift(state, s.v.head<3>(), model.initial_v().head<3>());
}

// The double pendulum of examples/double_pendulum.yaml (two 1 kg point masses on 1 m rods, upper
// rod horizontal, from rest), RK4 at h = 1 ms: one step, the peer figure of a sweep's cost
// (docs/sweeps.md; bench/sweep_bench.cpp runs the same model through momenta sweep). MuJoCo needs
// a positive inertia: 1e-9 kg·m², nothing against the 1 kg·m² the masses carry about the pivots.
void BM_MuJoCo_DoublePendulumRK4(benchmark::State& state) {
  const char* xml =
      "<mujoco><option timestep='0.001' integrator='RK4' gravity='0 0 -9.81'/><worldbody>"
      "<body name='mass1'><joint name='upper' type='hinge' axis='0 1 0'/>"
      "<inertial pos='0 0 -1' mass='1' diaginertia='1e-9 1e-9 1e-9'/>"
      "<body name='mass2' pos='0 0 -1'><joint name='lower' type='hinge' axis='0 1 0'/>"
      "<inertial pos='0 0 -1' mass='1' diaginertia='1e-9 1e-9 1e-9'/></body></body>"
      "</worldbody></mujoco>";
  mjVFS vfs;
  mj_defaultVFS(&vfs);
  mj_makeEmptyFileVFS(&vfs, "pendulum.xml", static_cast<int>(std::strlen(xml)));
  std::memcpy(vfs.filedata[mj_findFileVFS(&vfs, "pendulum.xml")], xml, std::strlen(xml));
  char error[1000] = "";
  mjModel* m = mj_loadXML("pendulum.xml", &vfs, error, sizeof(error));
  mj_deleteVFS(&vfs);
  if (!m) {
    std::fprintf(stderr, "MuJoCo could not load the double pendulum: %s\n", error);
    std::exit(1);
  }
  mjData* d = mj_makeData(m);
  d->qpos[0] = M_PI / 2;
  for (auto _ : state) {
    mj_step(m, d);
    benchmark::DoNotOptimize(d->qpos);
  }
  mj_deleteData(d);
  mj_deleteModel(m);
}

void BM_Momenta_DoublePendulumRK4(benchmark::State& state) {
  static const io::ModelFile file = io::read_model_file("examples/double_pendulum.yaml");
  system::MultibodySystem system(file.model);
  std::unique_ptr<integrate::Integrator> integrator = integrate::make_integrator("rk4");
  integrate::State s{0.0, file.model.initial_q(), file.model.initial_v()};
  integrator->initialize(system, s);
  for (auto _ : state) {
    integrator->step(system, s, 1e-3);
    benchmark::DoNotOptimize(s.q.data());
  }
}

BENCHMARK(BM_MuJoCo_DoublePendulumRK4)->Iterations(1000000)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_Momenta_DoublePendulumRK4)->Iterations(1000000)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_MuJoCo_FreeBodyRK4)->Iterations(kFreeBodySteps)->Unit(benchmark::kNanosecond);
BENCHMARK(BM_Momenta_FreeBody)
    ->DenseRange(0, 4)
    ->Iterations(kFreeBodySteps)
    ->Unit(benchmark::kNanosecond);

BENCHMARK(BM_Momenta_Aba)->Arg(7)->Arg(32)->Arg(128);
BENCHMARK(BM_MuJoCo_Forward)->Arg(7)->Arg(32)->Arg(128);
BENCHMARK(BM_MuJoCo_ForwardMinimal)->Arg(7)->Arg(32)->Arg(128);
BENCHMARK(BM_Momenta_Rnea)->Arg(7)->Arg(32)->Arg(128);
BENCHMARK(BM_MuJoCo_Rne)->Arg(7)->Arg(32)->Arg(128);
BENCHMARK(BM_Momenta_Crba)->Arg(7)->Arg(32)->Arg(128);
BENCHMARK(BM_MuJoCo_Crb)->Arg(7)->Arg(32)->Arg(128);

}  // namespace
