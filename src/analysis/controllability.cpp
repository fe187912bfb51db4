#include "momenta/analysis/controllability.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "momenta/analysis/matrix_equations.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

// The staircase: orthogonal changes of the state that gather what (A, B) reaches into the
// leading block. Returns the rank and the trailing (uncontrollable) block of the transformed A.
struct Staircase {
  Eigen::Index rank = 0;
  MatX uncontrollable;
};

Staircase staircase(const MatX& A_in, const MatX& B) {
  const Eigen::Index n = A_in.rows();
  const auto norm1 = [](const MatX& M) {
    return M.size() == 0 ? 0.0 : M.cwiseAbs().colwise().sum().maxCoeff();
  };
  const double tolerance = static_cast<double>(std::max<Eigen::Index>(n, 1)) *
                           std::numeric_limits<double>::epsilon() * std::max(norm1(A_in), norm1(B));
  MatX A = A_in;
  MatX block = B;  // what the last step reached, in the coordinates not yet gathered
  Eigen::Index done = 0;
  while (done < n) {
    const Eigen::Index left = n - done;
    if (block.cols() == 0) break;
    const Eigen::JacobiSVD<MatX> svd(block, Eigen::ComputeFullU);
    Eigen::Index reached = 0;
    for (Eigen::Index k = 0; k < svd.singularValues().size(); ++k) {
      if (svd.singularValues()[k] > tolerance) ++reached;
    }
    if (reached == 0) break;
    // x = U x̃ on the trailing coordinates: A ← diag(I, Uᵀ) A diag(I, U).
    const MatX& U = svd.matrixU();
    A.bottomRows(left) = U.transpose() * A.bottomRows(left);
    A.rightCols(left) = A.rightCols(left) * U;
    done += reached;
    if (done == n) break;
    // The next step reaches through the coupling of the new block into the rest.
    block = A.block(done, done - reached, n - done, reached);
  }
  return {done, A.bottomRightCorner(n - done, n - done)};
}

// Asymptotically stable with a margin: every pole's real part below −1e-9 |λ|max (inside the
// circle of radius 1 − 1e-9 when discrete), so that an undamped mode whose eigenvalues the QR
// iteration puts a round-off left of the axis does not count (its Gramian does not exist).
bool is_stable(const StateSpace& system) {
  if (system.state_count() == 0) return true;
  const Eigen::EigenSolver<MatX> eigen(system.A(), false);
  if (eigen.info() != Eigen::Success) {
    throw NumericalError("controllability: the eigenvalue iteration on A did not converge");
  }
  constexpr double kMargin = 1e-9;
  if (system.is_discrete()) return eigen.eigenvalues().cwiseAbs().maxCoeff() < 1.0 - kMargin;
  const double largest = std::max(1e-300, eigen.eigenvalues().cwiseAbs().maxCoeff());
  return eigen.eigenvalues().real().maxCoeff() < -kMargin * largest;
}

Reachability reachability(const StateSpace& system, const MatX& A, const MatX& B) {
  Reachability r;
  r.states = system.state_count();
  const Staircase s = staircase(A, B);
  r.rank = static_cast<std::size_t>(s.rank);
  if (s.uncontrollable.rows() > 0) {
    const Eigen::EigenSolver<MatX> hidden(s.uncontrollable, false);
    for (const Complex& z : hidden.eigenvalues()) r.hidden_poles.push_back(z);
    std::sort(r.hidden_poles.begin(), r.hidden_poles.end(), [](Complex a, Complex b) {
      return std::abs(a) != std::abs(b) ? std::abs(a) < std::abs(b) : a.imag() > b.imag();
    });
  }
  if (is_stable(system)) {
    const MatX BBt = B * B.transpose();
    try {
      r.gramian = system.is_discrete() ? solve_discrete_lyapunov(A, BBt)
                                       : solve_continuous_lyapunov(A, BBt);
    } catch (const NumericalError&) {
      return r;  // stable only to within round-off of the boundary: no Gramian
    }
    if (r.states == 0) {
      r.gramian_condition = 1.0;
    } else {
      const Eigen::JacobiSVD<MatX> svd(r.gramian);
      const double smallest = svd.singularValues().minCoeff();
      r.gramian_condition = smallest > 0.0 ? svd.singularValues().maxCoeff() / smallest
                                           : std::numeric_limits<double>::infinity();
    }
  }
  return r;
}

}  // namespace

Reachability controllability(const StateSpace& system) {
  return reachability(system, system.A(), system.B());
}

Reachability observability(const StateSpace& system) {
  return reachability(system, system.A().transpose(), system.C().transpose());
}

}  // namespace momenta::analysis
