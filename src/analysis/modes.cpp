#include "momenta/analysis/modes.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include <fmt/format.h>
#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include "balance.hpp"
#include "momenta/common/error.hpp"

namespace momenta::analysis {
namespace {

// Throws unless X is a finite symmetric nq×nq matrix.
void check_symmetric(const MatX& X, const char* what, Eigen::Index nq) {
  if (X.rows() != nq || X.cols() != nq) {
    throw InvalidArgument(fmt::format("normal_modes: {} is {}×{} but must be {}×{} like M", what,
                                      X.rows(), X.cols(), nq, nq));
  }
  if (!X.allFinite()) throw InvalidArgument(fmt::format("normal_modes: {} is not finite", what));
  const double asymmetry = nq == 0 ? 0.0 : (X - X.transpose()).cwiseAbs().maxCoeff();
  const double scale = nq == 0 ? 0.0 : X.cwiseAbs().maxCoeff();
  if (asymmetry > 1e-12 * scale) {
    throw InvalidArgument(fmt::format(
        "normal_modes: {} is not symmetric: largest |X − Xᵀ| = {:.3g} against largest |X| = {:.3g}",
        what, asymmetry, scale));
  }
}

// Scales a complex vector to unit norm with its largest-magnitude entry real and positive, so a
// shape is unique up to the (rare) tie between equal-magnitude entries.
VecXc normalized_shape(const VecXc& v) {
  Eigen::Index largest = 0;
  v.cwiseAbs().maxCoeff(&largest);
  const Complex phase = v[largest] / std::abs(v[largest]);
  return v / (phase * v.norm());
}

}  // namespace

Modes modes(const MatX& A, std::vector<std::string> state_names) {
  if (A.rows() != A.cols()) {
    throw InvalidArgument(fmt::format("modes: A is {}×{} but must be square", A.rows(), A.cols()));
  }
  // Reuse StateSpace's checks of finiteness and names.
  const StateSpace system(A, MatX::Zero(A.rows(), 0), MatX::Zero(0, A.rows()), MatX(),
                          std::move(state_names));
  return modes(system);
}

Modes modes(const StateSpace& system) {
  Modes result;
  result.state_names = system.state_names();
  const Eigen::Index n = system.A().rows();
  if (n == 0) return result;

  // Balance (exact power-of-2 similarity D⁻¹ A D), then real Schur form → eigenvalues
  // (conjugate pairs exactly conjugate) and eigenvectors, mapped back by φ = D φ_balanced.
  const VecX scale = detail::balancing_scale(system.A());
  const MatX balanced = scale.cwiseInverse().asDiagonal() * system.A() * scale.asDiagonal();
  const Eigen::EigenSolver<MatX> solver(balanced, /*computeEigenvectors=*/true);
  if (solver.info() != Eigen::Success) {
    throw NumericalError(fmt::format(
        "modes: the eigenvalue iteration did not converge for the {}×{} matrix A", n, n));
  }
  const VecXc lambda = solver.eigenvalues();
  const Eigen::MatrixXcd vectors = scale.cast<Complex>().asDiagonal() * solver.eigenvectors();

  result.modes.reserve(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i) {
    Mode mode;
    mode.z = lambda[i];
    // A sampled system's z as the s it samples: z = e^(sT).
    const double T = system.sample_time();
    mode.eigenvalue =
        T > 0.0 ? std::log(std::abs(lambda[i]) > 1e-300 ? lambda[i] : Complex(1e-300, 0.0)) / T
                : lambda[i];
    const Complex s = mode.eigenvalue;
    mode.natural_frequency = std::abs(s);
    mode.damping_ratio = mode.natural_frequency > 0.0 ? -s.real() / mode.natural_frequency
                                                      : std::numeric_limits<double>::quiet_NaN();
    mode.damped_frequency = std::abs(s.imag());
    mode.shape = normalized_shape(vectors.col(i));
    result.modes.push_back(std::move(mode));
  }

  // Ascending ωn; among equal ωn the stable one first; a pair's Im > 0 member first.
  std::stable_sort(result.modes.begin(), result.modes.end(), [](const Mode& a, const Mode& b) {
    return std::make_tuple(a.natural_frequency, a.eigenvalue.real(), -a.eigenvalue.imag()) <
           std::make_tuple(b.natural_frequency, b.eigenvalue.real(), -b.eigenvalue.imag());
  });
  return result;
}

NormalModes normal_modes(const MatX& M, const MatX& K, std::vector<std::string> coordinate_names,
                         double squared_frequency_scale) {
  // Check M, K and the names.
  const Eigen::Index nq = M.rows();
  check_symmetric(M, "the mass matrix M", nq);
  check_symmetric(K, "the stiffness matrix K", nq);
  if (coordinate_names.empty()) {
    for (Eigen::Index i = 0; i < nq; ++i) coordinate_names.push_back(fmt::format("q{}", i + 1));
  } else if (coordinate_names.size() != static_cast<std::size_t>(nq)) {
    throw InvalidArgument(fmt::format("normal_modes: {} coordinate names for {} coordinates",
                                      coordinate_names.size(), nq));
  }
  NormalModes result;
  result.coordinate_names = std::move(coordinate_names);
  if (nq == 0) return result;
  if (Eigen::LLT<MatX>(M).info() != Eigen::Success) {
    throw InvalidArgument("normal_modes: the mass matrix M is not positive definite");
  }

  // K φ = ω² M φ via Cholesky M = L Lᵀ; Eigen returns ascending ω² and φᵀ M φ = 1.
  const Eigen::GeneralizedSelfAdjointEigenSolver<MatX> solver(
      K, M, Eigen::ComputeEigenvectors | Eigen::Ax_lBx);
  if (solver.info() != Eigen::Success) {
    throw NumericalError("normal_modes: the symmetric eigenvalue iteration did not converge");
  }
  const VecX& squared = solver.eigenvalues();
  // Eigenvalues below the round-off of the decomposition (relative to the largest, or to the
  // scale K's entries are round-off of) are zero: rigid-body modes must not come out as NaN
  // frequencies from −1e-17.
  const double round_off = 1e-12 * std::max(squared.cwiseAbs().maxCoeff(), squared_frequency_scale);
  for (Eigen::Index i = 0; i < nq; ++i) {
    NormalMode mode;
    mode.squared_frequency = std::abs(squared[i]) <= round_off ? 0.0 : squared[i];
    mode.natural_frequency = mode.squared_frequency >= 0.0
                                 ? std::sqrt(mode.squared_frequency)
                                 : std::numeric_limits<double>::quiet_NaN();
    mode.shape = solver.eigenvectors().col(i);
    Eigen::Index largest = 0;
    mode.shape.cwiseAbs().maxCoeff(&largest);
    if (mode.shape[largest] < 0.0) mode.shape = -mode.shape;
    result.modes.push_back(std::move(mode));
  }
  return result;
}

Modes damped_modes(const MatX& M, const MatX& C, const MatX& K,
                   std::vector<std::string> coordinate_names) {
  // The same checks as the undamped problem (C may be unsymmetric: gyroscopic coupling).
  const Eigen::Index nq = M.rows();
  check_symmetric(M, "the mass matrix M", nq);
  check_symmetric(K, "the stiffness matrix K", nq);
  if (C.rows() != nq || C.cols() != nq || !C.allFinite()) {
    throw InvalidArgument(fmt::format(
        "damped_modes: the damping matrix C is {}×{} (or not finite) but must be {}×{} like M",
        C.rows(), C.cols(), nq, nq));
  }
  const StateSpace system =
      second_order_state_space(M, C, K, MatX::Zero(nq, 0), MatX::Zero(0, nq), MatX::Zero(0, nq),
                               std::move(coordinate_names));
  return modes(system);
}

}  // namespace momenta::analysis
