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
      : L_(MatX::Zero(m, m)),
        inverse_pivot_(VecX::Zero(m)),
        skipped_(m, 0),
        dependent_(m, 0),
        Z_(MatX::Zero(m, m)),
        ZtZ_(MatX::Zero(m, m)),
        alpha_(VecX::Zero(m)) {}

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

  /// Makes x, a solution solve_in_place gave, the one of least norm among those that leave the
  /// rows in `minimized` (a flag per row factorized) free to share what they carry: adds the
  /// combination of null vectors — one per dependent row j in `minimized`, e_j − c_j, c_j the
  /// earlier independent rows' share of row j (L_IIᵀ c_j = L_jIᵀ) — that takes most from ‖x‖.
  /// A x is unchanged where the rows are exactly dependent (to round-off). A row that exerts no
  /// force (no share) keeps its 0. No allocation.
  void least_norm_in_place(Eigen::Ref<VecX> x, std::span<const char> minimized) {
    const int m = static_cast<int>(x.size());
    int d = 0;
    for (int j = 0; j < m; ++j) {
      if (!skipped_[j] || !minimized[j]) continue;
      auto z = Z_.col(d);
      z.head(m).setZero();
      bool shared = false;
      for (int i = j - 1; i >= 0; --i) {  // back substitution: z_I = −c_j
        if (skipped_[i]) continue;
        double s = L_(j, i);
        for (int k = i + 1; k < j; ++k) s += L_(k, i) * z[k];
        z[i] = -s * inverse_pivot_[i];
        shared = shared || z[i] != 0.0;
      }
      if (!shared) continue;
      z[j] = 1.0;
      ++d;
    }
    if (d == 0) return;
    // (Zᵀ Z) α = −Zᵀ x by Cholesky in place (Zᵀ Z is positive definite: each z_j has its own
    // e_j), then x += Z α.
    for (int a = 0; a < d; ++a) {
      alpha_[a] = -Z_.col(a).head(m).dot(x);
      for (int b = 0; b <= a; ++b) ZtZ_(a, b) = Z_.col(a).head(m).dot(Z_.col(b).head(m));
    }
    for (int a = 0; a < d; ++a) {
      for (int k = 0; k < a; ++k) {
        double s = ZtZ_(a, k);
        for (int l = 0; l < k; ++l) s -= ZtZ_(a, l) * ZtZ_(k, l);
        ZtZ_(a, k) = s / ZtZ_(k, k);
      }
      double diagonal = ZtZ_(a, a);
      for (int l = 0; l < a; ++l) diagonal -= ZtZ_(a, l) * ZtZ_(a, l);
      ZtZ_(a, a) = std::sqrt(diagonal);
    }
    for (int a = 0; a < d; ++a) {
      double s = alpha_[a];
      for (int k = 0; k < a; ++k) s -= ZtZ_(a, k) * alpha_[k];
      alpha_[a] = s / ZtZ_(a, a);
    }
    for (int a = d - 1; a >= 0; --a) {
      double s = alpha_[a];
      for (int k = a + 1; k < d; ++k) s -= ZtZ_(k, a) * alpha_[k];
      alpha_[a] = s / ZtZ_(a, a);
    }
    for (int a = 0; a < d; ++a) x += alpha_[a] * Z_.col(a).head(m);
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
  MatX Z_;      // least_norm_in_place: the null vectors, a column each
  MatX ZtZ_;    // their Gram matrix, then its Cholesky factor (lower)
  VecX alpha_;  // −Zᵀ x, then the combination
};

}  // namespace momenta::system::detail
