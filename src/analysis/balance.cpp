#include "balance.hpp"

#include <cmath>

namespace momenta::analysis::detail {

VecX balancing_scale(const MatX& A) {
  constexpr double kRadix = 2.0;
  const Eigen::Index n = A.rows();
  MatX M = A;
  VecX d = VecX::Ones(n);
  // Sweep until no row/column pair changes by more than 5 % (EISPACK balanc).
  for (bool changed = true; changed;) {
    changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      // Off-diagonal 1-norms of column i and row i.
      double c = M.col(i).cwiseAbs().sum() - std::abs(M(i, i));
      double r = M.row(i).cwiseAbs().sum() - std::abs(M(i, i));
      if (c == 0.0 || r == 0.0) continue;
      const double s = c + r;
      // The power of 2, f, that brings c·f and r/f closest.
      double f = 1.0;
      double g = r / kRadix;
      while (c < g && f < 1e150) {
        f *= kRadix;
        c *= kRadix * kRadix;
      }
      g = r * kRadix;
      while (c >= g && f > 1e-150) {
        f /= kRadix;
        c /= kRadix * kRadix;
      }
      if ((c + r) / f < 0.95 * s) {
        d[i] *= f;
        M.row(i) /= f;
        M.col(i) *= f;
        changed = true;
      }
    }
  }
  return d;
}

}  // namespace momenta::analysis::detail
