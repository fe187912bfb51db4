#pragma once
// Cholesky factorization of a symmetric positive semi-definite matrix that keeps its rows in
// their given order and skips those that depend on earlier ones: the constraint solver's way of
// handling redundant rows (a planar loop closed by a 3-D hinge, a rolling disk whose axle is
// pivoted) — the later of two dependent rows carries no force.

#include <vector>

#include "momenta/math/types.hpp"

namespace momenta::system::detail {

class OrderedCholesky {
 public:
  /// Sizes the workspace for m × m matrices.
  explicit OrderedCholesky(int m) : L_(MatX::Zero(m, m)), dependent_(m, 0) {}

  /// Factorizes A = L Lᵀ over the rows that are independent of the rows before them. Row j is
  /// dependent when its remaining pivot is at most `tolerance` times A_jj (the squared sine of
  /// its angle to the earlier rows, in A's metric), or A_jj ≤ 0. Reads A's lower triangle. No
  /// allocation.
  void factorize(const MatX& A, double tolerance) {
    const int m = static_cast<int>(A.rows());
    rank_ = 0;
    for (int j = 0; j < m; ++j) {
      double d = A(j, j);
      for (int k = 0; k < j; ++k) d -= L_(j, k) * L_(j, k);
      dependent_[j] = !(A(j, j) > 0.0) || d <= tolerance * A(j, j);
      if (dependent_[j]) {
        L_.col(j).setZero();
        continue;
      }
      ++rank_;
      const double pivot = std::sqrt(d);
      L_(j, j) = pivot;
      for (int i = j + 1; i < m; ++i) {
        double s = A(i, j);
        for (int k = 0; k < j; ++k) s -= L_(i, k) * L_(j, k);
        L_(i, j) = s / pivot;
      }
    }
  }

  /// Solves A x = b in place over the independent rows; x is 0 on the dependent ones.
  void solve_in_place(VecX& b) const {
    const int m = static_cast<int>(b.size());
    for (int i = 0; i < m; ++i) {
      if (dependent_[i]) {
        b[i] = 0.0;
        continue;
      }
      double s = b[i];
      for (int k = 0; k < i; ++k) s -= L_(i, k) * b[k];
      b[i] = s / L_(i, i);
    }
    for (int i = m - 1; i >= 0; --i) {
      if (dependent_[i]) continue;
      double s = b[i];
      for (int k = i + 1; k < m; ++k) s -= L_(k, i) * b[k];
      b[i] = s / L_(i, i);
    }
  }

  int rank() const { return rank_; }
  bool dependent(int row) const { return dependent_[row] != 0; }

 private:
  MatX L_;
  std::vector<char> dependent_;
  int rank_ = 0;
};

}  // namespace momenta::system::detail
