// Identities every correct rigid-body dynamics implementation satisfies, checked on random trees
// with every joint type (fixed seeds): inverse of forward dynamics, mass matrix against RNEA,
// kinetic energy, Ṁ − 2C, gravity as the gradient of potential energy, hybrid dynamics, joint
// reactions against the momentum of each subtree, kinematics against finite differences, and
// the configuration-space exponential and logarithm.
//
// Tolerances: the algorithms are exact up to round-off, so algorithm-vs-algorithm checks use
// 1e-10 relative to the size of the quantities (n ≤ 24 bodies, O(1) masses, lengths and rates:
// accumulated round-off ~ n·10·eps·|x| ≈ 1e-13, so 1e-10 leaves margin yet catches any missing
// term, which would be O(1)). Finite-difference checks state their truncation and round-off.
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/energy.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta/dynamics/kinematics.hpp"
#include "momenta/dynamics/momentum.hpp"
#include "momenta/dynamics/point_kinematics.hpp"
#include "momenta/dynamics/reactions.hpp"
#include "momenta/dynamics/rnea.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics {
namespace {

using model::JointType;
using test::random_configuration;
using test::random_tree;
using test::random_vector;

struct Case {
  int bodies;
  unsigned seed;
  double armature = 0.0;  ///< kg·m² (kg): each joint's rotor inertia, test::random_tree's
};

class DynamicsProperties : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    model_ = std::make_unique<Model>(random_tree(GetParam().bodies, GetParam().seed,
                                                 test::all_joint_types(), Vec3(0, 0, -9.81),
                                                 GetParam().armature));
    rng_.seed(GetParam().seed + 1000);
  }
  const Model& m() const { return *model_; }
  std::unique_ptr<Model> model_;
  std::mt19937 rng_;
};

// Relative error of a against b, scaled by the larger of their norms (and 1).
double relative(const VecX& a, const VecX& b) {
  return (a - b).norm() / std::max({1.0, a.norm(), b.norm()});
}

TEST_P(DynamicsProperties, EveryJointTypeIsPresent) {
  std::vector<int> count(8, 0);
  for (const auto& j : m().joints()) ++count[static_cast<int>(j.type)];
  if (GetParam().bodies >= 8) {
    for (int t = 0; t < 8; ++t) EXPECT_GT(count[t], 0) << "joint type " << t;
  }
}

TEST_P(DynamicsProperties, RneaInvertsAba) {
  Data data(m());
  for (int trial = 0; trial < 5; ++trial) {
    const VecX q = random_configuration(m(), rng_);
    const VecX v = random_vector(m().nv(), rng_, 2.0);
    const VecX tau = random_vector(m().nv(), rng_, 5.0);
    std::vector<Vec6> f_ext(m().num_bodies());
    for (auto& f : f_ext) f = random_vector(6, rng_, 3.0);
    const VecX vdot = aba(m(), data, q, v, tau, f_ext);
    const VecX tau_back = rnea(m(), data, q, v, vdot, f_ext);
    EXPECT_LT(relative(tau_back, tau), 1e-10) << tau_back.transpose() << "\n" << tau.transpose();
  }
}

TEST_P(DynamicsProperties, MassMatrixColumnsAreRneaAndSolveMatchesAba) {
  Data data(m());
  const VecX q = random_configuration(m(), rng_);
  const MatX M = crba(m(), data, q);
  EXPECT_MATRIX_NEAR(M, M.transpose(), 1e-12 * M.norm());
  const VecX zero = VecX::Zero(m().nv());
  const VecX g = generalized_gravity(m(), data, q);
  for (int k = 0; k < m().nv(); ++k) {
    const VecX column = rnea(m(), data, q, zero, VecX::Unit(m().nv(), k)) - g;
    EXPECT_LT(relative(column, M.col(k)), 1e-10) << "column " << k;
  }
  // M v̇ + C v + g = τ: ABA's accelerations solve the CRBA system.
  const VecX v = random_vector(m().nv(), rng_, 2.0);
  const VecX tau = random_vector(m().nv(), rng_, 5.0);
  const VecX vdot = aba(m(), data, q, v, tau);
  const VecX nle = nonlinear_effects(m(), data, q, v);
  EXPECT_LT(relative(M * vdot + nle, tau), 1e-10);
  // Positive definite.
  EXPECT_EQ(Eigen::LLT<MatX>(M).info(), Eigen::Success);
}

TEST_P(DynamicsProperties, KineticEnergyIsHalfVMv) {
  Data data(m());
  for (int trial = 0; trial < 3; ++trial) {
    const VecX q = random_configuration(m(), rng_);
    const VecX v = random_vector(m().nv(), rng_, 2.0);
    const double T = kinetic_energy(m(), data, q, v);
    const MatX M = crba(m(), data, q);
    EXPECT_TRUE(test::relatively_near(T, 0.5 * v.dot(M * v), 1e-12));
  }
}

// Ṁ along the motion, by central differences: M(q ⊕ hv) − M(q ⊕ −hv) over 2h. Truncation
// h²/6 |d³M/dt³| ≈ 1e-10·|M|·|v|³ for h = 1e-5, round-off eps|M|/h ≈ 2e-11|M|.
MatX mass_matrix_rate(const Model& model, Data& data, const VecX& q, const VecX& v) {
  const double h = 1e-5;
  const MatX Mp = crba(model, data, model::integrate(model, q, v, h));
  const MatX Mm = crba(model, data, model::integrate(model, q, v, -h));
  return (Mp - Mm) / (2 * h);
}

// Power balance vᵀ(Ṁ − 2C)v = 0 with C v = nle − g (any joint type: this is dT/dt = vᵀτ).
TEST_P(DynamicsProperties, MdotMinusTwoCIsSkewAlongV) {
  Data data(m());
  const VecX q = random_configuration(m(), rng_);
  const VecX v = random_vector(m().nv(), rng_, 1.0);
  const MatX Mdot = mass_matrix_rate(m(), data, q, v);
  const VecX Cv = nonlinear_effects(m(), data, q, v) - generalized_gravity(m(), data, q);
  const double lhs = v.dot(Mdot * v);
  const double rhs = 2 * v.dot(Cv);
  // FD error above, times |v|² ≈ nv/3.
  EXPECT_NEAR(lhs, rhs, 1e-7 * std::max(1.0, std::abs(rhs)));
}

// The full matrix identity: Ṁ − 2C skew for the Christoffel C, obtained from RNEA by
// polarization (C(q, v) w = ¼ [c(v + w) − c(v − w)], exact for the quadratic c). Holds where v
// is q̇ (every joint but spherical and free, whose body-frame angular velocities are not
// coordinate rates), so this runs on trees of those types.
TEST(DynamicsPropertiesChristoffel, MdotMinusTwoCIsSkew) {
  const Model model =
      random_tree(12, 7,
                  {JointType::revolute, JointType::prismatic, JointType::cylindrical,
                   JointType::universal, JointType::planar, JointType::fixed});
  Data data(model);
  std::mt19937 rng(11);
  const VecX q = random_configuration(model, rng);
  const VecX v = random_vector(model.nv(), rng, 1.0);
  const int n = model.nv();
  const VecX g = generalized_gravity(model, data, q);
  const auto coriolis = [&](const VecX& w) {
    return VecX(nonlinear_effects(model, data, q, w) - g);
  };
  MatX C(n, n);
  for (int k = 0; k < n; ++k) {
    const VecX e = VecX::Unit(n, k);
    C.col(k) = 0.25 * (coriolis(v + e) - coriolis(v - e));
  }
  EXPECT_LT((C * v - coriolis(v)).norm(), 1e-10 * std::max(1.0, coriolis(v).norm()));
  const MatX Mdot = mass_matrix_rate(model, data, q, v);
  const MatX N = Mdot - 2 * C;
  EXPECT_MATRIX_NEAR(N + N.transpose(), MatX::Zero(n, n), 1e-7 * std::max(1.0, Mdot.norm()));
}

// g(q) = ∂V/∂q along each velocity coordinate: central differences of V(q ⊕ h e_k). Truncation
// h²/6 |V'''| ≈ 1e-11 |V| with h = 1e-5; round-off eps|V|/h ≈ 2e-11 |V| (V = O(10) J here).
TEST_P(DynamicsProperties, GravityIsGradientOfPotentialEnergy) {
  Data data(m());
  const VecX q = random_configuration(m(), rng_);
  const VecX g = generalized_gravity(m(), data, q);
  const double h = 1e-5;
  for (int k = 0; k < m().nv(); ++k) {
    const VecX e = VecX::Unit(m().nv(), k);
    const double Vp = potential_energy(m(), data, model::integrate(m(), q, e, h));
    const double Vm = potential_energy(m(), data, model::integrate(m(), q, e, -h));
    EXPECT_NEAR(g[k], (Vp - Vm) / (2 * h), 1e-8 * std::max(1.0, std::abs(g[k]))) << m().v_name(k);
  }
}

TEST_P(DynamicsProperties, HybridDynamicsAgreesWithAbaAndRnea) {
  Data data(m());
  const VecX q = random_configuration(m(), rng_);
  const VecX v = random_vector(m().nv(), rng_, 2.0);
  const VecX tau_in = random_vector(m().nv(), rng_, 5.0);
  const VecX vdot_in = random_vector(m().nv(), rng_, 5.0);
  std::vector<Vec6> f_ext(m().num_bodies());
  for (auto& f : f_ext) f = random_vector(6, rng_, 3.0);

  // Nothing prescribed: ABA.
  std::vector<char> none(m().num_joints(), 0);
  const VecX vdot_free = hybrid_dynamics(m(), data, none, q, v, vdot_in, tau_in, f_ext);
  EXPECT_LT(relative(vdot_free, aba(m(), data, q, v, tau_in, f_ext)), 1e-10);
  // Everything prescribed: RNEA.
  std::vector<char> all(m().num_joints(), 1);
  hybrid_dynamics(m(), data, all, q, v, vdot_in, tau_in, f_ext);
  EXPECT_EQ(data.vdot, vdot_in);
  const VecX tau_all = data.tau;
  EXPECT_LT(relative(tau_all, rnea(m(), data, q, v, vdot_in, f_ext)), 1e-10);
  // A random mix: the free joints get their τ, the prescribed their v̇, and together they
  // satisfy the equations of motion.
  std::vector<char> mix(m().num_joints());
  for (auto& x : mix) x = std::uniform_int_distribution<int>(0, 1)(rng_);
  hybrid_dynamics(m(), data, mix, q, v, vdot_in, tau_in, f_ext);
  const VecX vdot = data.vdot, tau = data.tau;
  for (const auto& j : m().joints()) {
    for (int k = 0; k < j.nv(); ++k) {
      const int i = j.v_index + k;
      if (mix[j.index]) {
        EXPECT_EQ(vdot[i], vdot_in[i]);
      } else {
        EXPECT_EQ(tau[i], tau_in[i]);
      }
    }
  }
  EXPECT_LT(relative(rnea(m(), data, q, v, vdot, f_ext), tau), 1e-10);
}

// Spatial momentum (in W about Wo) of the subtree rooted at body `root`, from the body
// velocities alone (not RNEA).
Vec6 subtree_momentum(const Model& model, const Data& data, int root) {
  Vec6 h = Vec6::Zero();
  for (int b = 1; b < model.num_bodies(); ++b) {
    int a = b;
    while (a > root) a = model.parent(a);
    if (a != root) continue;
    h += data.X_WB[b].act_force(model.spatial_inertia(b) * data.V_WB_B[b]);
  }
  return h;
}

// Newton–Euler of each subtree: the wrench the joint transmits into the subtree, plus gravity and
// the external wrenches on it, equals the rate of its momentum. The rate is a central difference
// along the motion, states at ±δ to second order (q ⊕ (±δv + ½δ²v̇), v ± δv̇), so its error is
// C δ²: measured 1e-6 |rate| at δ = 1e-4 (falling 100× per 10× δ), hence ≈ 1e-8 |rate| at
// δ = 1e-5, with round-off eps |h| / δ ≈ 1e-9. The 1e-6 tolerance catches any missing term.
TEST_P(DynamicsProperties, ReactionsBalanceTheMomentumRateOfEachSubtree) {
  Data data(m());
  const VecX q = random_configuration(m(), rng_);
  const VecX v = random_vector(m().nv(), rng_, 1.0);
  const VecX tau = random_vector(m().nv(), rng_, 5.0);
  std::vector<Vec6> f_ext(m().num_bodies());
  for (auto& f : f_ext) f = random_vector(6, rng_, 3.0);
  const VecX vdot = aba(m(), data, q, v, tau, f_ext);
  joint_reactions(m(), data, q, v, vdot, f_ext);
  std::vector<Vec6> F_W(m().num_bodies());
  std::vector<Transform> X_WB = data.X_WB;
  for (int b = 1; b < m().num_bodies(); ++b) F_W[b] = X_WB[b].act_force(data.F_B[b]);

  const double d = 1e-5;
  Data plus(m()), minus(m());
  forward_kinematics(m(), plus, model::integrate(m(), q, d * v + 0.5 * d * d * vdot, 1.0),
                     v + d * vdot);
  forward_kinematics(m(), minus, model::integrate(m(), q, -d * v + 0.5 * d * d * vdot, 1.0),
                     v - d * vdot);
  for (int b = 1; b < m().num_bodies(); ++b) {
    const Vec6 rate = (subtree_momentum(m(), plus, b) - subtree_momentum(m(), minus, b)) / (2 * d);
    Vec6 applied = F_W[b];
    for (int k = b; k < m().num_bodies(); ++k) {
      int a = k;
      while (a > b) a = m().parent(a);
      if (a != b) continue;
      const SpatialInertia& I = m().spatial_inertia(k);
      const Vec3 p_cm = X_WB[k].apply(I.center_of_mass());
      const Vec3 weight = I.mass * m().gravity();
      applied += spatial(p_cm.cross(weight), weight) + X_WB[k].act_force(f_ext[k]);
    }
    EXPECT_LT((applied - rate).norm(), 1e-6 * std::max(1.0, rate.norm())) << "body " << b;
  }
  // The components along each joint's motion subspace are its τ, less what accelerates the
  // joint's rotor (armature · v̇): the bodies feel the rest.
  for (const auto& j : m().joints()) {
    for (int k = 0; k < j.nv(); ++k) {
      EXPECT_NEAR(data.S[j.index].col(k).dot(data.F_B[j.child_index]),
                  tau[j.v_index + k] - j.armature * vdot[j.v_index + k],
                  1e-10 * std::max(1.0, tau.norm()));
    }
  }
}

// Velocities and accelerations of every body against central differences of poses and
// velocities along the motion (truncation h²/6 ≈ 2e-11 for h = 1e-5 times O(1) derivatives;
// round-off eps/h ≈ 2e-11).
TEST_P(DynamicsProperties, KinematicsMatchFiniteDifferences) {
  Data data(m()), plus(m()), minus(m());
  const VecX q = random_configuration(m(), rng_);
  const VecX v = random_vector(m().nv(), rng_, 1.0);
  const VecX vdot = random_vector(m().nv(), rng_, 1.0);
  forward_kinematics(m(), data, q, v, vdot);
  const double h = 1e-5;
  // Position-level: q ± h v.
  forward_kinematics(m(), plus, model::integrate(m(), q, v, h), v);
  forward_kinematics(m(), minus, model::integrate(m(), q, v, -h), v);
  for (int b = 1; b < m().num_bodies(); ++b) {
    const Vec6 V_W = body_velocity_in_world(data, b);
    const Vec3 v_fd = (plus.X_WB[b].p - minus.X_WB[b].p) / (2 * h);
    const Mat3 Rdot = (plus.X_WB[b].R - minus.X_WB[b].R) / (2 * h);
    const Mat3 W = Rdot * data.X_WB[b].R.transpose();  // [ω_W]×
    EXPECT_LT((v_fd - V_W.tail<3>()).norm(), 1e-8) << "body " << b;
    EXPECT_LT((Vec3(W(2, 1), W(0, 2), W(1, 0)) - V_W.head<3>()).norm(), 1e-8) << "body " << b;
  }
  // Velocity-level: (q, v) ± h (v, v̇), second-order state.
  forward_kinematics(m(), plus, model::integrate(m(), q, h * v + 0.5 * h * h * vdot, 1.0),
                     v + h * vdot);
  forward_kinematics(m(), minus, model::integrate(m(), q, -h * v + 0.5 * h * h * vdot, 1.0),
                     v - h * vdot);
  for (int b = 1; b < m().num_bodies(); ++b) {
    const Vec6 A_W = body_acceleration_in_world(data, b);
    const Vec6 fd = (body_velocity_in_world(plus, b) - body_velocity_in_world(minus, b)) / (2 * h);
    EXPECT_LT((fd - A_W).norm(), 1e-6) << "body " << b;
    // A body-fixed point: its acceleration splits into J v̇ + J̇ v.
    const Vec3 p_BoP_B(0.1, -0.2, 0.3);
    const PointKinematics k = point_kinematics(m(), data, b, p_BoP_B);
    const Vec3 p_fd = (plus.X_WB[b].apply(p_BoP_B) - minus.X_WB[b].apply(p_BoP_B)) / (2 * h);
    EXPECT_LT((p_fd - k.v_WP_W).norm(), 1e-8);
    const Vec3 a_fd = (point_kinematics(m(), plus, b, p_BoP_B).v_WP_W -
                       point_kinematics(m(), minus, b, p_BoP_B).v_WP_W) /
                      (2 * h);
    EXPECT_LT((a_fd - k.a_WP_W).norm(), 1e-6);
    MatX J(6, m().nv());
    frame_jacobian(m(), data, b, p_BoP_B, J);
    EXPECT_LT((J.bottomRows<3>() * vdot - k.from_vdot).norm(), 1e-10);
    EXPECT_LT((J.bottomRows<3>() * v - k.v_WP_W).norm(), 1e-10);
    EXPECT_LT((J.topRows<3>() * v - body_velocity_in_world(data, b).head<3>()).norm(), 1e-10);
  }
}

TEST_P(DynamicsProperties, IntegrateAndDifferenceAreInverse) {
  for (int trial = 0; trial < 5; ++trial) {
    const VecX q0 = random_configuration(m(), rng_);
    const VecX d = random_vector(m().nv(), rng_, 1.0);  // rotations below π
    const VecX q1 = model::integrate(m(), q0, d, 1.0);
    EXPECT_LT((model::difference(m(), q0, q1) - d).norm(), 1e-12);
    const VecX q2 = random_configuration(m(), rng_);
    const VecX back = model::integrate(m(), q0, model::difference(m(), q0, q2), 1.0);
    EXPECT_LT(model::difference(m(), q2, back).norm(), 1e-12);
    // Quaternions stay unit: the exponential map, not add-and-normalize.
    for (const auto& j : m().joints()) {
      const int k = j.type == JointType::spherical ? 0 : (j.type == JointType::free ? 3 : -1);
      if (k >= 0) {
        EXPECT_NEAR(q1.segment<4>(j.q_index + k).norm(), 1.0, 1e-15);
      }
    }
  }
}

// Momentum is conserved without gravity or external forces: its rate (central differences along
// the motion from ABA's accelerations) vanishes. Truncation C δ² measured ≤ 1.2e-5 at δ = 1e-4,
// so ≈ 1e-7 at δ = 1e-5; round-off eps |L| / δ ≈ 1e-10.
TEST_P(DynamicsProperties, MomentumOfAFloatingTreeIsConserved) {
  // Replace the root joint by a free joint: rebuild the same tree floating.
  const Model floating =
      random_tree(GetParam().bodies, GetParam().seed,
                  {JointType::free, JointType::free, JointType::prismatic, JointType::spherical,
                   JointType::cylindrical, JointType::universal, JointType::fixed,
                   JointType::planar, JointType::revolute},
                  Vec3::Zero());
  Data data(floating), plus(floating), minus(floating);
  const VecX q = random_configuration(floating, rng_);
  const VecX v = random_vector(floating.nv(), rng_, 1.0);
  const VecX vdot = aba(floating, data, q, v, VecX::Zero(floating.nv()));
  const double d = 1e-5;
  const Momentum mp = momentum(
      floating, plus, model::integrate(floating, q, d * v + 0.5 * d * d * vdot, 1.0), v + d * vdot);
  const Momentum mm =
      momentum(floating, minus, model::integrate(floating, q, -d * v + 0.5 * d * d * vdot, 1.0),
               v - d * vdot);
  EXPECT_LT((mp.linear - mm.linear).norm() / (2 * d), 1e-6);
  EXPECT_LT((mp.angular_about(Vec3(1, 2, 3)) - mm.angular_about(Vec3(1, 2, 3))).norm() / (2 * d),
            1e-6);
  // And the kinetic energy.
  const double Tp = kinetic_energy(floating, plus, v + d * vdot);
  const double Tm = kinetic_energy(floating, minus, v - d * vdot);
  EXPECT_LT(std::abs(Tp - Tm) / (2 * d), 1e-6);
}

INSTANTIATE_TEST_SUITE_P(RandomTrees, DynamicsProperties,
                         ::testing::Values(Case{1, 1}, Case{3, 2}, Case{8, 3}, Case{9, 4},
                                           Case{16, 5}, Case{24, 6}));

// The same properties with a rotor's reflected inertia (armature) on every joint, of the order of
// the bodies' own (0.01–0.1 kg·m²): ABA, CRBA, RNEA, hybrid dynamics and the kinetic energy each
// add it on their own, and must agree.
INSTANTIATE_TEST_SUITE_P(RandomTreesWithArmature, DynamicsProperties,
                         ::testing::Values(Case{3, 2, 0.02}, Case{9, 4, 0.05}, Case{16, 5, 0.03}));

}  // namespace
}  // namespace momenta::dynamics
