// aba_derivatives against high-order finite differences of aba on the tangent space, and M⁻¹
// against crba.
#include "momenta/dynamics/aba_derivatives.hpp"

#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tangent_differences.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics::aba_derivatives_test {
namespace {

double scale_of(const MatX& X) { return std::max(1.0, X.cwiseAbs().maxCoeff()); }

TEST(AbaDerivatives, RandomTreesWithEveryJointTypeAndBodyForces) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(fmt::format("seed {}", seed));
    const Model m = test::random_tree(12, seed);
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
    // κ up to ~1e3 here) ~1e-11 of the scale: measured 4e-12 to 3e-11 over these six trees.
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

}  // namespace
}  // namespace momenta::dynamics::aba_derivatives_test
