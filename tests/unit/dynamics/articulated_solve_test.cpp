// articulated_solve against M⁻¹ from crba and a dense Cholesky factor: every joint type, with and
// without prescribed joints (M_ff⁻¹ over the free coordinates), zero columns, wrong sizes.
#include "momenta/dynamics/articulated_solve.hpp"

#include <random>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "momenta/common/error.hpp"
#include "momenta/dynamics/aba.hpp"
#include "momenta/dynamics/crba.hpp"
#include "momenta/dynamics/hybrid_dynamics.hpp"
#include "momenta_test/multibody_models.hpp"
#include "momenta_test/tolerance.hpp"

namespace momenta::dynamics::articulated_solve_test {
namespace {

// Random generalized forces, five columns, the third all zero.
MatX random_columns(int nv, std::mt19937& rng) {
  MatX X(nv, 5);
  for (int k = 0; k < 5; ++k) X.col(k) = test::random_vector(nv, rng, 3.0);
  X.col(2).setZero();
  return X;
}

TEST(ArticulatedSolve, EqualsTheInverseMassMatrixOnRandomTreesOfEveryJointType) {
  for (unsigned seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE(fmt::format("seed {}", seed));
    const Model m = test::random_tree(14, seed);
    std::mt19937 rng(seed + 300);
    const VecX q = test::random_configuration(m, rng);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    const VecX tau = test::random_vector(m.nv(), rng, 3.0);
    Data data(m), work(m);
    aba(m, data, q, v, tau);
    const MatX X = random_columns(m.nv(), rng);
    MatX Y = X;
    articulated_solve(m, data, {}, Y);

    // Two independent references: the dense solve, and M Y = X. The solve's error is κ(M) ε
    // times |Y| (κ up to ~1e3 on these trees); the residual is round-off of |M| |Y| (measured
    // ≤ 2e-15 of it).
    const MatX M = crba(m, work, q);
    const MatX reference = M.llt().solve(X);
    const double scale = std::max(1.0, reference.cwiseAbs().maxCoeff());
    EXPECT_MATRIX_NEAR(Y, reference, 1e-11 * scale);
    EXPECT_MATRIX_NEAR(M * Y, X, 1e-13 * M.cwiseAbs().maxCoeff() * scale);
    EXPECT_TRUE(Y.col(2).isZero(0.0));  // a zero column is left alone, exactly
    // aba's results are untouched: the solve has its own workspace.
    EXPECT_MATRIX_NEAR(data.vdot, aba(m, work, q, v, tau), 0.0);
  }
}

TEST(ArticulatedSolve, HoldsPrescribedJointsAndSolvesTheFreeBlock) {
  for (unsigned seed = 1; seed <= 4; ++seed) {
    SCOPED_TRACE(fmt::format("seed {}", seed));
    const Model m = test::random_tree(14, seed);
    std::mt19937 rng(seed + 400);
    const VecX q = test::random_configuration(m, rng);
    const VecX v = test::random_vector(m.nv(), rng, 2.0);
    const VecX a = test::random_vector(m.nv(), rng, 3.0);
    std::vector<char> prescribed(m.num_joints(), 0);
    for (int j = 0; j < m.num_joints(); j += 3) prescribed[j] = 1;  // roots and inner joints
    Data data(m), work(m);
    hybrid_dynamics(m, data, prescribed, q, v, a, a);
    const MatX X = random_columns(m.nv(), rng);
    MatX Y = X;
    articulated_solve(m, data, prescribed, Y);

    // M_ff⁻¹ X_f over the free coordinates; zero on the held ones.
    std::vector<int> free;
    for (int j = 0; j < m.num_joints(); ++j) {
      if (prescribed[j]) continue;
      for (int k = 0; k < m.joint(j).nv(); ++k) free.push_back(m.joint(j).v_index + k);
    }
    const int nf = static_cast<int>(free.size());
    ASSERT_GT(nf, 0);
    ASSERT_LT(nf, m.nv());
    const MatX M = crba(m, work, q);
    MatX M_ff(nf, nf), X_f(nf, X.cols());
    for (int r = 0; r < nf; ++r) {
      X_f.row(r) = X.row(free[r]);
      for (int c = 0; c < nf; ++c) M_ff(r, c) = M(free[r], free[c]);
    }
    const MatX reference = M_ff.llt().solve(X_f);
    const double scale = std::max(1.0, reference.cwiseAbs().maxCoeff());
    MatX expected = MatX::Zero(m.nv(), X.cols());
    for (int r = 0; r < nf; ++r) expected.row(free[r]) = reference.row(r);
    EXPECT_MATRIX_NEAR(Y, expected, 1e-11 * scale);
  }
}

TEST(ArticulatedSolve, WrongSizesAreRefusedByName) {
  const Model m = test::random_tree(5, 2);
  const Model other = test::random_tree(7, 2);
  Data data(m), other_data(other);
  MatX X = MatX::Ones(m.nv() + 1, 2);
  EXPECT_THROW(articulated_solve(m, data, {}, X), InvalidArgument);
  MatX Y = MatX::Ones(m.nv(), 2);
  EXPECT_THROW(articulated_solve(m, other_data, {}, Y), InvalidArgument);
  const std::vector<char> mask(m.num_joints() + 1, 0);
  EXPECT_THROW(articulated_solve(m, data, mask, Y), InvalidArgument);
  try {
    articulated_solve(m, data, {}, X);
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find("articulated_solve"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace momenta::dynamics::articulated_solve_test
