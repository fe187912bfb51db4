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

}  // namespace
}  // namespace momenta::system::detail
