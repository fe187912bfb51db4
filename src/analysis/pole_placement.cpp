#include "momenta/analysis/pole_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "momenta/common/error.hpp"
#include "momenta/common/number_text.hpp"

namespace momenta::analysis {
namespace {

using MatXc = Eigen::MatrixXcd;

// The requested poles, each complex one followed by its conjugate.
std::vector<Complex> paired(std::vector<Complex> poles, Eigen::Index n, Eigen::Index m) {
  if (static_cast<Eigen::Index>(poles.size()) != n) {
    throw InvalidArgument(
        fmt::format("place_poles: {} poles given for {} states", poles.size(), n));
  }
  double scale = 1.0;
  for (const Complex& p : poles) {
    if (!std::isfinite(p.real()) || !std::isfinite(p.imag())) {
      throw InvalidArgument("place_poles: a pole is not finite");
    }
    scale = std::max(scale, std::abs(p));
  }
  std::vector<Complex> out;
  std::vector<bool> used(poles.size(), false);
  for (std::size_t i = 0; i < poles.size(); ++i) {
    if (used[i]) continue;
    used[i] = true;
    if (std::abs(poles[i].imag()) <= 1e-12 * scale) {
      out.emplace_back(poles[i].real(), 0.0);
      continue;
    }
    std::size_t partner = poles.size();
    for (std::size_t j = i + 1; j < poles.size(); ++j) {
      if (!used[j] && std::abs(poles[j] - std::conj(poles[i])) <= 1e-12 * scale) {
        partner = j;
        break;
      }
    }
    if (partner == poles.size()) {
      throw InvalidArgument(fmt::format(
          "place_poles: the pole {} has no conjugate among the poles given: a real system's "
          "complex poles come in pairs",
          complex_text(poles[i])));
    }
    used[partner] = true;
    const Complex upper(poles[i].real(), std::abs(poles[i].imag()));
    out.push_back(upper);
    out.push_back(std::conj(upper));
  }
  for (const Complex& p : out) {
    const auto repeats = std::count_if(
        out.begin(), out.end(), [&](const Complex& q) { return std::abs(q - p) <= 1e-12 * scale; });
    if (repeats > m) {
      throw InvalidArgument(fmt::format(
          "place_poles: the pole {} is asked for {} times, but {} input{} can place a pole at "
          "most {} times",
          complex_text(p), repeats, m, m == 1 ? "" : "s", m));
    }
  }
  return out;
}

// An orthonormal basis (columns) of the null space of M, by SVD.
MatXc null_space(const MatXc& M, double scale) {
  const Eigen::JacobiSVD<MatXc> svd(M, Eigen::ComputeFullV);
  const Eigen::Index n = M.cols();
  Eigen::Index rank = 0;
  for (Eigen::Index k = 0; k < svd.singularValues().size(); ++k) {
    if (svd.singularValues()[k] > 1e-10 * scale) ++rank;
  }
  return svd.matrixV().rightCols(n - rank);
}

double condition(const MatXc& X) {
  const Eigen::JacobiSVD<MatXc> svd(X);
  const double smallest = svd.singularValues().minCoeff();
  return smallest > 0.0 ? svd.singularValues().maxCoeff() / smallest
                        : std::numeric_limits<double>::infinity();
}

}  // namespace

PolePlacement place_poles(const StateSpace& system, const std::vector<Complex>& requested) {
  const MatX& A = system.A();
  const MatX& B = system.B();
  const Eigen::Index n = A.rows();
  const Eigen::Index m = B.cols();
  if (m == 0) throw InvalidArgument("place_poles: the system has no inputs to feed back into");
  const std::vector<Complex> poles = paired(requested, n, m);

  // B = U [Z; 0].
  const Eigen::HouseholderQR<MatX> qr(B);
  const MatX U = qr.householderQ();
  const MatX Z = qr.matrixQR().topRows(m).triangularView<Eigen::Upper>();
  const double scale = std::max({1.0, A.cwiseAbs().maxCoeff(), B.cwiseAbs().maxCoeff()});
  if (Eigen::FullPivLU<MatX>(Z).rank() < m ||
      Z.diagonal().cwiseAbs().minCoeff() <= 1e-12 * B.cwiseAbs().maxCoeff()) {
    throw InvalidArgument(
        "place_poles: B's columns are not independent: two inputs act the same way; drop one");
  }
  const MatX U0 = U.leftCols(m);
  const MatX U1 = U.rightCols(n - m);

  // Each eigenvector's space Sⱼ, and a first X from it.
  std::vector<MatXc> spaces;
  MatXc X(n, n);
  for (std::size_t j = 0; j < poles.size(); ++j) {
    MatXc shifted = A.cast<Complex>();
    shifted.diagonal().array() -= poles[j];
    const MatXc S = n > m ? null_space(U1.transpose().cast<Complex>() * shifted, scale)
                          : MatXc(MatXc::Identity(n, n));
    if (S.cols() == 0) {
      throw NumericalError(fmt::format(
          "place_poles: no closed-loop eigenvector for the pole {}: (A, B) is not controllable",
          complex_text(poles[j])));
    }
    spaces.push_back(S);
    // Start from the space's vectors in turn, so a repeated pole gets a different one each time.
    const auto earlier = std::count_if(poles.begin(), poles.begin() + static_cast<long>(j),
                                       [&](const Complex& p) { return p == poles[j]; });
    X.col(static_cast<Eigen::Index>(j)) = S.col(static_cast<Eigen::Index>(earlier) % S.cols());
  }

  // KNV method 0: turn each xⱼ (within Sⱼ) towards the normal of the other columns.
  if (m > 1) {
    for (int sweep = 0; sweep < 50; ++sweep) {
      for (Eigen::Index j = 0; j < n; ++j) {
        if (poles[static_cast<std::size_t>(j)].imag() < 0.0) continue;  // set with its partner
        MatXc others(n, n - 1);
        for (Eigen::Index k = 0, c = 0; k < n; ++k) {
          if (k != j) others.col(c++) = X.col(k);
        }
        const Eigen::HouseholderQR<MatXc> q(others);
        const Eigen::VectorXcd normal = MatXc(q.householderQ()).col(n - 1);
        const MatXc& S = spaces[static_cast<std::size_t>(j)];
        const Eigen::VectorXcd projected = S * (S.adjoint() * normal);
        if (projected.norm() <= 1e-12) continue;
        X.col(j) = projected.normalized();
        if (poles[static_cast<std::size_t>(j)].imag() > 0.0 && j + 1 < n) {
          X.col(j + 1) = X.col(j).conjugate();
        }
      }
    }
  }
  const Eigen::FullPivLU<MatXc> lu(X);
  if (!lu.isInvertible()) {
    throw NumericalError(
        "place_poles: the closed-loop eigenvectors are dependent: (A, B) is not controllable "
        "enough to place these poles");
  }
  Eigen::VectorXcd lambda(n);
  for (Eigen::Index j = 0; j < n; ++j) lambda[j] = poles[static_cast<std::size_t>(j)];
  const MatX closed = (X * lambda.asDiagonal() * lu.inverse()).real();

  PolePlacement result;
  result.K = Z.triangularView<Eigen::Upper>().solve(U0.transpose() * (A - closed));
  const Modes placed = modes(MatX(A - B * result.K));
  result.closed_loop_poles.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    result.closed_loop_poles[i] = placed.modes[static_cast<std::size_t>(i)].eigenvalue;
  }
  result.eigenvector_condition = condition(X);
  result.state_names = system.state_names();
  result.input_names = system.input_names();
  return result;
}

}  // namespace momenta::analysis
