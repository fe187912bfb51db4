// Closed loops side by side with Pinocchio (3.7): what a constrained forward dynamics costs over
// the same tree's ABA, on both sides, for the planar loops of constraints_bench.cpp:
//   four_bar  crank 0.10 m, coupler 0.30 m, rocker 0.25 m, ground 0.30 m (n = 3);
//   loop_30   thirty 0.1 m links hanging in a V between pins 2.6 m apart (n = 30).
// momenta closes each loop with its `hinge` (five rows, three of them redundant in the plane; the
// ordered Cholesky of G M⁻¹ Gᵀ drops them); Pinocchio with a 3-D point contact between the same
// two frames (three rows, the one across the plane identically zero: its solvers need a proximal
// damping μ to pass it — 1e-9 for constraintDynamics; 1e-4 for constrainedABA, whose 1/μ terms
// lose digits below that (measured on the four-bar: 1.8e-11 at 1e-3, 1.6e-11 at 1e-4, 1.2e-9 at
// 1e-6, 1.8e-5 at 1e-9) — to an accuracy of 1e-12 in at most 10 iterations). In a planar state
// both describe the same motion, and the benchmark refuses to time them unless their
// accelerations agree (1e-9 relative).
//   BM_Momenta/<model>/tree          aba on the tree
//   BM_Momenta/<model>/closed        MultibodySystem::acceleration with the loop closed
//   BM_Pinocchio/<model>/tree        pinocchio::aba on the tree
//   BM_Pinocchio/<model>/dense       pinocchio::constraintDynamics (sparse LDLᵀ of the KKT matrix,
//                                    Carpentier, Budhiraja & Mansard, RSS 2021)
//   BM_Pinocchio/<model>/articulated pinocchio::constrainedABA (Sathya & Carpentier 2024)
// Built with the Pinocchio comparison (-DMOMENTA_BENCH_PINOCCHIO=ON).

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>

#include <benchmark/benchmark.h>

#include "pinocchio/algorithm/aba.hpp"
#include "pinocchio/algorithm/constrained-dynamics.hpp"
#include "pinocchio/algorithm/pv.hpp"
#include "pinocchio/multibody/data.hpp"
#include "pinocchio/multibody/model.hpp"

#include "momenta/dynamics/aba.hpp"
#include "momenta/io/model_file.hpp"
#include "momenta/system/multibody_system.hpp"
#include "momenta_test/closed_chains.hpp"

namespace {

using namespace momenta;

using ConstraintModels = PINOCCHIO_STD_VECTOR_WITH_EIGEN_ALLOCATOR(pinocchio::RigidConstraintModel);
using ConstraintDatas = PINOCCHIO_STD_VECTOR_WITH_EIGEN_ALLOCATOR(pinocchio::RigidConstraintData);

const char* const kModels[] = {"four_bar", "loop_30"};

io::ModelFile model_file(int model, bool closed) {
  if (model == 0) return io::parse_model_file(test::four_bar_text(closed), "four_bar.yaml", ".");
  return io::parse_model_file(test::v_loop_text(30, closed), "loop_30.yaml", ".");
}

pinocchio::SE3 se3(const Transform& X) { return pinocchio::SE3(X.R, X.p); }

// The tree of a momenta model of revolute joints, joint j carrying body j + 1 in both.
pinocchio::Model pinocchio_tree(const model::Model& m) {
  pinocchio::Model p;
  p.gravity.linear(m.gravity());
  for (int j = 0; j < m.num_joints(); ++j) {
    const model::JointConstants& c = m.joint_constants()[j];
    if (c.type != model::JointType::revolute) {
      std::fprintf(stderr, "pinocchio_tree: revolute joints only\n");
      std::exit(1);
    }
    const std::string name = "joint" + std::to_string(j);
    // Pinocchio's fastest joint where the axis is a coordinate axis (all of them here).
    const auto id = c.axis == Vec3::UnitZ()
                        ? p.addJoint(c.parent, pinocchio::JointModelRZ(), se3(c.X_PJ), name)
                    : c.axis == Vec3::UnitY()
                        ? p.addJoint(c.parent, pinocchio::JointModelRY(), se3(c.X_PJ), name)
                    : c.axis == Vec3::UnitX()
                        ? p.addJoint(c.parent, pinocchio::JointModelRX(), se3(c.X_PJ), name)
                        : p.addJoint(c.parent, pinocchio::JointModelRevoluteUnaligned(c.axis),
                                     se3(c.X_PJ), name);
    // momenta's inertia about the body origin, Pinocchio's about the centre of mass.
    const SpatialInertia& I = m.spatial_inertia(c.child);
    const Vec3 com = I.center_of_mass();
    const Mat3 I_com =
        I.I_O - I.mass * (com.squaredNorm() * Mat3::Identity() - com * com.transpose());
    p.appendBodyToJoint(id, pinocchio::Inertia(I.mass, com, I_com), se3(c.X_JC));
  }
  return p;
}

// The loop's hinge as a point contact between its two frames.
ConstraintModels pinocchio_loop(const model::Model& m, const pinocchio::Model& p) {
  const auto& loop = std::get<model::LoopClosure>(m.constraints().at(0));
  ConstraintModels out;
  out.emplace_back(pinocchio::CONTACT_3D, p, loop.b.body_index, se3(loop.b.X_BF), loop.a.body_index,
                   se3(loop.a.X_BF), pinocchio::LOCAL);
  return out;
}

struct Setup {
  explicit Setup(int which)
      : closed(model_file(which, true)),
        tree(model_file(which, false)),
        system(closed.model),
        data(tree.model),
        p_model(pinocchio_tree(tree.model)),
        p_data(p_model),
        contacts(pinocchio_loop(closed.model, p_model)),
        dense_settings(1e-12, 1e-9, 10),
        articulated_settings(1e-12, 1e-4, 10) {
    q = closed.model.initial_q();
    std::mt19937 rng(42);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    v = VecX(closed.model.nv());
    for (Eigen::Index i = 0; i < v.size(); ++i) v[i] = u(rng);
    system.make_consistent(0.0, q, v);
    tau = VecX::Zero(closed.model.nv());
    vdot = VecX::Zero(closed.model.nv());
    for (const auto& c : contacts) contact_data.emplace_back(c);
  }
  io::ModelFile closed, tree;
  system::MultibodySystem system;
  dynamics::Data data;
  pinocchio::Model p_model;
  pinocchio::Data p_data;
  ConstraintModels contacts;
  ConstraintDatas contact_data;
  pinocchio::ProximalSettings dense_settings, articulated_settings;
  VecX q, v, tau, vdot;
};

double relative(const VecX& x, const VecX& reference) {
  return (x - reference).cwiseAbs().maxCoeff() / std::max(1.0, reference.cwiseAbs().maxCoeff());
}

// Refuses to time two sides that compute different things.
void check_same(int which) {
  Setup s(which);
  const VecX tree = dynamics::aba(s.tree.model, s.data, s.q, s.v, s.tau);
  const VecX p_tree = pinocchio::aba(s.p_model, s.p_data, s.q, s.v, s.tau);
  s.system.acceleration(0.0, s.q, s.v, s.vdot);
  pinocchio::initConstraintDynamics(s.p_model, s.p_data, s.contacts);
  const VecX dense = pinocchio::constraintDynamics(s.p_model, s.p_data, s.q, s.v, s.tau, s.contacts,
                                                   s.contact_data, s.dense_settings);
  pinocchio::initPvSolver(s.p_model, s.p_data, s.contacts);
  const VecX articulated = pinocchio::constrainedABA(
      s.p_model, s.p_data, s.q, s.v, s.tau, s.contacts, s.contact_data, s.articulated_settings);
  const double d_tree = relative(p_tree, tree), d_dense = relative(dense, s.vdot),
               d_articulated = relative(articulated, s.vdot);
  std::printf(
      "%s: relative differences from momenta: tree %.2g, constraintDynamics %.2g, "
      "constrainedABA %.2g\n",
      kModels[which], d_tree, d_dense, d_articulated);
  if (!(d_tree < 1e-12 && d_dense < 1e-9 && d_articulated < 1e-9)) {
    std::fprintf(stderr, "momenta and Pinocchio disagree on %s\n", kModels[which]);
    std::exit(1);
  }
}

void BM_Momenta(benchmark::State& bench) {
  Setup s(static_cast<int>(bench.range(0)));
  const bool closed = bench.range(1) == 1;
  for (auto _ : bench) {
    if (closed) {
      s.system.acceleration(0.0, s.q, s.v, s.vdot);
      benchmark::DoNotOptimize(s.vdot.data());
    } else {
      benchmark::DoNotOptimize(dynamics::aba(s.tree.model, s.data, s.q, s.v, s.tau).data());
    }
    benchmark::ClobberMemory();
  }
  bench.SetLabel(std::string(kModels[bench.range(0)]) + (closed ? " closed" : " tree"));
}

void BM_Pinocchio(benchmark::State& bench) {
  Setup s(static_cast<int>(bench.range(0)));
  const int method = static_cast<int>(bench.range(1));
  if (method == 1) pinocchio::initConstraintDynamics(s.p_model, s.p_data, s.contacts);
  if (method == 2) pinocchio::initPvSolver(s.p_model, s.p_data, s.contacts);
  for (auto _ : bench) {
    if (method == 0) {
      benchmark::DoNotOptimize(pinocchio::aba(s.p_model, s.p_data, s.q, s.v, s.tau).data());
    } else if (method == 1) {
      benchmark::DoNotOptimize(pinocchio::constraintDynamics(s.p_model, s.p_data, s.q, s.v, s.tau,
                                                             s.contacts, s.contact_data,
                                                             s.dense_settings)
                                   .data());
    } else {
      benchmark::DoNotOptimize(pinocchio::constrainedABA(s.p_model, s.p_data, s.q, s.v, s.tau,
                                                         s.contacts, s.contact_data,
                                                         s.articulated_settings)
                                   .data());
    }
    benchmark::ClobberMemory();
  }
  const char* const methods[] = {" tree", " dense", " articulated"};
  bench.SetLabel(std::string(kModels[bench.range(0)]) + methods[method]);
}

BENCHMARK(BM_Momenta)->ArgsProduct({{0, 1}, {0, 1}});
BENCHMARK(BM_Pinocchio)->ArgsProduct({{0, 1}, {0, 1, 2}});

}  // namespace

int main(int argc, char** argv) {
  for (const int which : {0, 1}) check_same(which);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
}
