#pragma once
// Cholesky factorization of a symmetric positive semi-definite matrix that keeps its rows in
// their given order and skips those that depend on earlier ones: the constraint solver's way of
// handling redundant rows (a planar loop closed by a 3-D hinge, a rolling disk whose axle is
// pivoted) — the later of two dependent rows carries no force.

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

#include "momenta/math/types.hpp"

namespace momenta::system::detail {

class OrderedCholesky {
 public:
  /// Sizes the workspace for m × m matrices.
  explicit OrderedCholesky(int m)
      : L_(MatX::Zero(m, m)), inverse_pivot_(VecX::Zero(m)), skipped_(m, 0), dependent_(m, 0) {}

  /// Factorizes A = L Lᵀ over the rows that are independent of the rows before them. Row j is
  /// dependent when its remaining pivot is at most `tolerance` times A_jj (the squared sine of
  /// its angle to the earlier rows, in A's metric), or A_jj ≤ 0. Reads A's lower triangle. No
  /// allocation.
  void factorize(const MatX& A, double tolerance) {
    factorize_rows(A, tolerance);
    for (int j = 0; j < static_cast<int>(A.rows()); ++j) dependent_[j] = skipped_[j];
  }

  /// The same for the rows `rows` (increasing) of an m × m system whose other rows and columns
  /// are zero (the rows of a constraint that exerts no force here): A is the system over `rows`
  /// alone, and the factorization is that of the whole system — the zero rows dependent, the
  /// same L on the others, solve_in_place taking b over `rows`.
  void factorize(Eigen::Ref<const MatX> A, double tolerance, std::span<const int> rows) {
    factorize_rows(A, tolerance);
    std::fill(dependent_.begin(), dependent_.end(), 1);
    for (int j = 0; j < static_cast<int>(A.rows()); ++j) dependent_[rows[j]] = skipped_[j];
  }

  /// Solves A x = b in place over the independent rows; x is 0 on the dependent ones. b has the
  /// size of the A last factorized.
  void solve_in_place(Eigen::Ref<VecX> b) const {
    const int m = static_cast<int>(b.size());
    for (int i = 0; i < m; ++i) {
      if (skipped_[i]) {
        b[i] = 0.0;
        continue;
      }
      double s = b[i];
      for (int k = 0; k < i; ++k) s -= L_(i, k) * b[k];
      b[i] = s * inverse_pivot_[i];
    }
    for (int i = m - 1; i >= 0; --i) {
      if (skipped_[i]) continue;
      double s = b[i];
      for (int k = i + 1; k < m; ++k) s -= L_(k, i) * b[k];
      b[i] = s * inverse_pivot_[i];
    }
  }

  int rank() const { return rank_; }
  /// Whether row `row` of the whole system depends on the rows before it.
  bool dependent(int row) const { return dependent_[row] != 0; }

 private:
  void factorize_rows(Eigen::Ref<const MatX> A, double tolerance) {
    const int m = static_cast<int>(A.rows());
    rank_ = 0;
    for (int j = 0; j < m; ++j) {
      double d = A(j, j);
      for (int k = 0; k < j; ++k) d -= L_(j, k) * L_(j, k);
      skipped_[j] = !(A(j, j) > 0.0) || d <= tolerance * A(j, j);
      if (skipped_[j]) {
        L_.col(j).head(m).setZero();
        continue;
      }
      ++rank_;
      const double pivot = std::sqrt(d);
      const double inverse = 1.0 / pivot;  // multiplied by below: one division per row
      L_(j, j) = pivot;
      inverse_pivot_[j] = inverse;
      for (int i = j + 1; i < m; ++i) {
        double s = A(i, j);
        for (int k = 0; k < j; ++k) s -= L_(i, k) * L_(j, k);
        L_(i, j) = s * inverse;
      }
    }
  }

  MatX L_;                       // over the rows factorized, in their order
  VecX inverse_pivot_;           // 1 / L_jj on the independent ones
  std::vector<char> skipped_;    // dependent, by the rows factorized
  std::vector<char> dependent_;  // dependent, by the rows of the whole system
  int rank_ = 0;
};

}  // namespace momenta::system::detail
