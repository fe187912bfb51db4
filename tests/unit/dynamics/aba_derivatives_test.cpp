// aba_derivatives against high-order finite differences of aba on the tangent space, and M⁻¹
// against crba.
#include "momenta/dynamics/aba_derivatives.hpp"

#include <limits>
#include <random>

#include <Eigen/Cholesky>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/rnea_derivatives.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tangent_differences.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics::aba_derivatives_test {
namespace {

double scale_of(const MatX& X) { return std::max(1.0, X.cwiseAbs().maxCoeff()); }

// Seeds 4–6 with a rotor's reflected inertia (armature) on every joint: M⁻¹ through the ABA's D.
TEST(AbaDerivatives, RandomTreesWithEveryJointTypeAndBodyForces) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(fmt::format("seed {}", seed));
    const Model m = test::random_tree(12, seed, test::all_joint_types(), Vec3(0, 0, -9.81),
                                      seed > 3 ? 0.03 : 0.0);
    std::mt19937 rng(seed + 200);
    const VecX q = test::random_configuration(m, rng);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    const VecX tau = test::random_vector(m.nv(), rng, 3.0);
    std::vector<Vec6> f_ext(m.num_bodies());
    for (Vec6& f : f_ext) f = test::random_vector(6, rng, 5.0);
    Data data(m), work(m);
    aba_derivatives(m, data, q, v, tau, f_ext);

    // h = 0.01: v̇ = M⁻¹(…) varies faster than τ, so the step that leaves RNEA's truncation at
    // 1e-12 leaves ABA's at 1e-9; at 0.01 truncation is ~1e-12 and round-off (κ(M) ε |v̇| / h,
    // κ up to ~1e3 here) ~1e-11 of the scale: measured 9e-13 to 3e-11 over these six trees.
    const MatX dq_reference = test::tangent_jacobian(
        m, q, [&](const VecX& qq) { return VecX(aba(m, work, qq, v, tau, f_ext)); }, 0.01);
    // 1e-10 relative, the bar.
    EXPECT_MATRIX_NEAR(data.dvdot_dq, dq_reference, 1e-10 * scale_of(dq_reference));
    // v̇ is quadratic in v: the exact differences leave round-off times κ(M).
    const MatX dv_reference = test::quadratic_jacobian(
        v, [&](const VecX& vv) { return VecX(aba(m, work, q, vv, tau, f_ext)); });
    EXPECT_MATRIX_NEAR(data.dvdot_dv, dv_reference, 1e-11 * scale_of(dv_reference));
    // M⁻¹ M = I, and ∂v̇/∂τ = M⁻¹ (v̇ is affine in τ).
    const MatX M = crba(m, work, q);
    EXPECT_MATRIX_NEAR(data.Minv * M, MatX::Identity(m.nv(), m.nv()), 1e-11);
    EXPECT_MATRIX_NEAR(data.vdot, aba(m, work, q, v, tau, f_ext), 1e-12);
  }
}

// M⁻¹ by the articulated-body recursion against the inverse of crba's M, and −M⁻¹ ∂τ by the
// running sums against a Cholesky solve of rnea_derivatives' ∂τ, on branched trees (each
// subtree's coordinates one range now that models are ordered depth first; the sums' buffers
// merged at branches) and on a chain, where the recursion writes every entry without zeroing
// first: the workspace and the results are filled with NaN before the second call, at a second
// state, so a stale or unwritten entry shows.
TEST(AbaDerivatives, InverseMassMatrixOverwritesItsWorkspace) {
  std::vector<Model> models;
  models.push_back(test::revolute_chain(9));
  for (unsigned seed = 11; seed <= 14; ++seed) models.push_back(test::random_tree(14, seed));
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t index = 0; index < models.size(); ++index) {
    SCOPED_TRACE(fmt::format("model {}", index));
    const Model& m = models[index];
    std::mt19937 rng(static_cast<unsigned>(index) + 300);
    Data data(m), work(m);
    const VecX q0 = test::random_configuration(m, rng);
    const VecX v0 = test::random_vector(m.nv(), rng, 2.0);
    const VecX tau0 = test::random_vector(m.nv(), rng, 3.0);
    aba_derivatives(m, data, q0, v0, tau0);

    for (MatX* X : {&data.Minv, &data.dvdot_dq, &data.dvdot_dv}) X->setConstant(nan);
    for (Mat6X* X : {&data.minv_U_W, &data.minv_F_W, &data.dtau_upper_q_W, &data.dtau_upper_v_W}) {
      X->setConstant(nan);
    }
    data.dtau_lower_W.setConstant(nan);
    for (std::size_t b = 1; b < data.minv_A_W.size(); ++b) data.minv_A_W[b].setConstant(nan);
    for (MatX& sums : data.minv_lower_sums) sums.setConstant(nan);
    for (MatX& sums : data.minv_upper_sums) sums.setConstant(nan);
    const VecX q = test::random_configuration(m, rng);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    const VecX tau = test::random_vector(m.nv(), rng, 3.0);
    aba_derivatives(m, data, q, v, tau);

    if (index == 0) {  // a chain hands one buffer of each running sum from joint to joint
      EXPECT_EQ(data.minv_lower_sums.size(), 1u);
      EXPECT_EQ(data.minv_upper_sums.size(), 1u);
    }
    ASSERT_TRUE(data.Minv.allFinite());
    EXPECT_EQ(data.Minv, data.Minv.transpose());  // mirrored, not computed twice
    const MatX M = crba(m, work, q);
    const Eigen::LLT<MatX> llt(M);
    const MatX Minv_reference = llt.solve(MatX::Identity(m.nv(), m.nv()));
    // Both inverses carry round-off of κ(M) ε relative to |M⁻¹| (κ ≤ 3.3e3 on these models,
    // κ ε ≤ 7e-13): measured ≤ 4e-14 for M⁻¹ and ≤ 1.1e-13 for the derivatives; held to 1e-12.
    EXPECT_MATRIX_NEAR(data.Minv, Minv_reference, 1e-12 * scale_of(Minv_reference));
    rnea_derivatives(m, work, q, v, data.vdot);
    const MatX dq_reference = -llt.solve(work.dtau_dq);
    const MatX dv_reference = -llt.solve(work.dtau_dv);
    EXPECT_MATRIX_NEAR(data.dvdot_dq, dq_reference, 1e-12 * scale_of(dq_reference));
    EXPECT_MATRIX_NEAR(data.dvdot_dv, dv_reference, 1e-12 * scale_of(dv_reference));
  }
}

}  // namespace
}  // namespace momenta::dynamics::aba_derivatives_test
