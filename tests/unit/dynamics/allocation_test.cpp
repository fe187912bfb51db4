// The algorithms must not allocate once Data exists: counts heap allocations (malloc and operator
// new) around them, on a random tree with every joint type.
#include <random>

#include <gtest/gtest.h>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/aba_derivatives.hpp"
#include "momenta/dynamics/articulated_solve.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/energy.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/point_kinematics.hpp"
#include "momenta/dynamics/reactions.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"
#include "momenta_test/allocation_counter.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

// The counter sees Eigen's own heap (aligned_malloc calls malloc, not operator new), so a dynamic
// temporary inside an algorithm would count: an expression that nests a negated block, or a sum
// with a product assigned without noalias(), makes one.
TEST(DynamicsAllocation, CounterSeesEigenTemporaries) {
  if (!test::allocation_count_includes_malloc()) {
    GTEST_SKIP() << "under the sanitizers only operator new is counted";
  }
  volatile int size = 64;
  const long before = test::allocation_count();
  const VecX x = VecX::Ones(size);
  EXPECT_EQ(test::allocation_count() - before, 1);
  EXPECT_EQ(x.sum(), 64.0);
}

TEST(DynamicsAllocation, AlgorithmsDoNotAllocate) {
  const Model m = test::random_tree(16, 9);
  Data data(m);
  std::mt19937 rng(1);
  const VecX q = test::random_configuration(m, rng);
  const VecX v = test::random_vector(m.nv(), rng);
  const VecX a = test::random_vector(m.nv(), rng);
  std::vector<Vec6> f_ext(m.num_bodies(), Vec6::Ones());
  std::vector<char> mask(m.num_joints(), 0);
  mask[1] = mask[4] = 1;
  MatX J(6, m.nv()), X = MatX::Ones(m.nv(), 3);
  VecX q_out(m.nq()), d(m.nv()), qdot(m.nq());
  const long before = test::allocation_count();
  forward_kinematics(m, data, q);
  forward_kinematics(m, data, q, v);
  forward_kinematics(m, data, q, v, a);
  rnea(m, data, q, v, a);
  rnea(m, data, q, v, a, f_ext);
  nonlinear_effects(m, data, q, v);
  generalized_gravity(m, data, q);
  crba(m, data, q);
  aba(m, data, q, v, a);
  aba(m, data, q, v, a, f_ext);
  hybrid_dynamics(m, data, mask, q, v, a, a, f_ext);
  hybrid_dynamics(m, data, q, v, a, a);
  joint_reactions(m, data, q, v, a, f_ext);
  joint_reaction(m, data, 3, ReactionFrame::world);
  kinetic_energy(m, data, q, v);
  potential_energy(m, data, q);
  momentum(m, data, q, v);
  center_of_mass(m, data, q);
  point_kinematics(m, data, q, v, a, 5, Vec3(1, 2, 3));
  frame_jacobian(m, data, 5, Vec3(1, 2, 3), J);
  model::integrate(m, q, v, 0.1, q_out);
  model::difference(m, q, q_out, d);
  model::configuration_rate(m, q, v, qdot);
  rnea_derivatives(m, data, q, v, a, f_ext);
  aba_derivatives(m, data, q, v, a, f_ext);
  aba(m, data, q, v, a);
  articulated_solve(m, data, {}, X);
  hybrid_dynamics(m, data, mask, q, v, a, a);
  articulated_solve(m, data, mask, X);
  EXPECT_EQ(test::allocation_count() - before, 0);

  // Inputs that are parts of larger vectors (a stacked state [q; v], a mapped buffer) bind to
  // the algorithms' Eigen::Ref parameters without a copy.
  VecX state(m.nq() + m.nv());
  state << q, v;
  const Eigen::Map<const VecX> mapped(a.data(), a.size());
  const long before_views = test::allocation_count();
  aba(m, data, state.head(m.nq()), state.tail(m.nv()), mapped);
  rnea(m, data, state.head(m.nq()), state.tail(m.nv()), mapped);
  crba(m, data, state.head(m.nq()));
  hybrid_dynamics(m, data, state.head(m.nq()), state.tail(m.nv()), mapped, mapped);
  kinetic_energy(m, data, state.head(m.nq()), state.tail(m.nv()));
  EXPECT_EQ(test::allocation_count() - before_views, 0);
  EXPECT_MATRIX_NEAR(aba(m, data, state.head(m.nq()), state.tail(m.nv()), mapped),
                     aba(m, data, q, v, a), 0.0);
}

// aba_derivatives' products with M⁻¹ are running sums in Data's buffers, not Eigen's blocked
// products (which take workspace from the heap at these sizes): none at 64 coordinates either.
TEST(DynamicsAllocation, AbaDerivativesOfALongChainDoNotAllocate) {
  const Model m = test::revolute_chain(64);
  Data data(m);
  std::mt19937 rng(2);
  const VecX q = test::random_configuration(m, rng);
  const VecX v = test::random_vector(m.nv(), rng);
  const VecX tau = test::random_vector(m.nv(), rng);
  const long before = test::allocation_count();
  aba_derivatives(m, data, q, v, tau);
  EXPECT_EQ(test::allocation_count() - before, 0);
  EXPECT_TRUE(data.dvdot_dq.allFinite());
}

}  // namespace
}  // namespace momenta::dynamics
