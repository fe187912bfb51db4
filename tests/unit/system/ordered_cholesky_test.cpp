// OrderedCholesky (src/system/ordered_cholesky.hpp), the constraint solver's factorization of
// G M⁻¹ Gᵀ that skips rows depending on earlier ones: factorized over the rows that exert a
// force alone, it is the factorization of the whole system — the same rank, the same rows named
// dependent (the zero rows among them, whatever an earlier factorization left), the same
// solution to the last bit — and its solution solves the system.

#include "system/ordered_cholesky.hpp"

#include <array>
#include <random>

#include <gtest/gtest.h>

namespace momenta::system::detail {
namespace {

constexpr double kTolerance = 1e-10;  // the constraint solver's kDependentRow

// A 5 × 5 system whose rows 1 and 3 are zero, with the 3 × 3 block of the others: B Bᵀ for a
// random B (rank 3), or, with `dependent_last`, with row 4 a combination of rows 0 and 2.
struct System {
  MatX whole = MatX::Zero(5, 5);
  MatX active = MatX::Zero(3, 3);
  std::array<int, 3> rows{0, 2, 4};
};

System make_system(bool dependent_last) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MatX B(3, 4);
  for (Eigen::Index i = 0; i < B.size(); ++i) B.data()[i] = u(rng);
  if (dependent_last) B.row(2) = 0.3 * B.row(0) - 1.7 * B.row(1);
  System s;
  s.active = B * B.transpose();
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) s.whole(s.rows[i], s.rows[k]) = s.active(i, k);
  return s;
}

TEST(OrderedCholesky, OverTheNonzeroRowsItIsTheFactorizationOfTheWholeSystem) {
  for (const bool dependent_last : {false, true}) {
    const System s = make_system(dependent_last);
    OrderedCholesky whole(5), compact(5);
    whole.factorize(s.whole, kTolerance);
    compact.factorize(MatX::Identity(5, 5), kTolerance);  // every row independent, before
    compact.factorize(s.active, kTolerance, s.rows);
    EXPECT_EQ(compact.rank(), whole.rank());
    EXPECT_EQ(whole.rank(), dependent_last ? 2 : 3);
    for (int row = 0; row < 5; ++row) {
      EXPECT_EQ(compact.dependent(row), whole.dependent(row)) << "row " << row;
    }
    EXPECT_TRUE(compact.dependent(1));
    EXPECT_TRUE(compact.dependent(3));
    EXPECT_EQ(compact.dependent(4), dependent_last);

    const VecX b_whole = (VecX(5) << 0.4, -2.0, -1.1, 5.0, 0.9).finished();
    VecX x_whole = b_whole;
    whole.solve_in_place(x_whole);
    VecX x_compact(3);
    for (int i = 0; i < 3; ++i) x_compact[i] = b_whole[s.rows[i]];
    compact.solve_in_place(x_compact);
    for (int i = 0; i < 3; ++i) EXPECT_EQ(x_compact[i], x_whole[s.rows[i]]) << "row " << s.rows[i];
    EXPECT_EQ(x_whole[1], 0.0);
    EXPECT_EQ(x_whole[3], 0.0);
  }
}

TEST(OrderedCholesky, ItsSolutionSolvesTheIndependentRows) {
  // Full rank: A x = b to round-off. Cholesky is backward stable: the residual is a few ε |A| |x|
  // (ε = 2.2e-16); 1e-13 |A| |x| allows for the 3 × 3 sums.
  const System full = make_system(false);
  OrderedCholesky cholesky(3);
  cholesky.factorize(full.active, kTolerance);
  const VecX b = (VecX(3) << 1.0, -0.5, 2.0).finished();
  VecX x = b;
  cholesky.solve_in_place(x);
  EXPECT_LT((full.active * x - b).norm(), 1e-13 * full.active.norm() * x.norm());
  // Row 2 dependent: x_2 = 0, and rows 0 and 1 hold to round-off (row 2 only where b is
  // consistent with them).
  const System dependent = make_system(true);
  cholesky.factorize(dependent.active, kTolerance);
  x = b;
  cholesky.solve_in_place(x);
  EXPECT_EQ(x[2], 0.0);
  const VecX residual = dependent.active * x - b;
  EXPECT_LT(residual.head(2).norm(), 1e-13 * dependent.active.norm() * x.norm());
}

// A box's four corner contacts on a plane: their normal rows over its z, roll and pitch (rank 3;
// the fourth depends on the other three), and a load they carry consistently. Ordered, the
// dependent row carries nothing; least_norm_in_place over those rows gives the least-norm
// solution of all — Eigen's complete orthogonal decomposition's — still solving the system.
TEST(OrderedCholesky, LeastNormSharesWhatRedundantRowsCarry) {
  const double a = 0.2, b = 0.1;  // half length and width
  MatX G(4, 3);                   // rows: corners (∓a, ∓b); columns: z, roll, pitch
  for (int k = 0; k < 4; ++k) {
    const double x = (k & 1) ? a : -a, y = (k & 2) ? b : -b;
    G.row(k) << 1.0, y, -x;
  }
  const Mat3 M_inv = Vec3(1.0 / 2.0, 1.0 / 0.0083, 1.0 / 0.0283).asDiagonal();
  const MatX A = G * M_inv * G.transpose();
  const VecX rhs = A * (VecX(4) << 4.0, 5.5, 4.5, 5.0).finished();  // consistent
  OrderedCholesky cholesky(4);
  cholesky.factorize(A, kTolerance);
  ASSERT_EQ(cholesky.rank(), 3);
  ASSERT_TRUE(cholesky.dependent(3));
  VecX x = rhs;
  cholesky.solve_in_place(x);
  EXPECT_EQ(x[3], 0.0);
  const std::array<char, 4> all{1, 1, 1, 1};
  cholesky.least_norm_in_place(x, all);
  const VecX least = A.completeOrthogonalDecomposition().solve(rhs);
  EXPECT_LT((x - least).norm(), 1e-12 * least.norm())
      << x.transpose() << " against " << least.transpose();
  EXPECT_LT((A * x - rhs).norm(), 1e-13 * A.norm() * x.norm());
  // Rows left out keep the ordered solution.
  VecX ordered = rhs;
  cholesky.solve_in_place(ordered);
  VecX kept = ordered;
  const std::array<char, 4> none{1, 1, 1, 0};
  cholesky.least_norm_in_place(kept, none);
  EXPECT_EQ(kept, ordered);
}

}  // namespace
}  // namespace momenta::system::detail
