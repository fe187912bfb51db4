#pragma once
// Modes of linear systems: the eigenvalues of ẋ = A x with their natural frequencies, damping
// ratios and shapes; the normal modes of the undamped M q̈ + K q = 0 (generalized symmetric
// eigenproblem K φ = ω² M φ); and the modes of M q̈ + C q̇ + K q = 0 through its first-order
// companion form.
//
// Conventions (as MATLAB's damp and every control text): for an eigenvalue λ,
//   natural frequency ωn = |λ| (rad/s), damping ratio ζ = −Re λ / |λ|, damped frequency |Im λ|.
// A stable real pole has ζ = 1, an unstable real pole ζ = −1, a pole at the origin has ωn = 0 and
// an undefined ζ (NaN; a rigid-body mode).

#include <complex>
#include <string>
#include <vector>

#include "momenta/analysis/state_space.hpp"
#include "momenta/math/types.hpp"

namespace momenta::analysis {

using Complex = std::complex<double>;
using VecXc = Eigen::VectorXcd;

/// One eigenvalue of A with its mode shape.
struct Mode {
  /// λ, 1/s. Of a sampled system (sample time T): the equivalent s = ln(z)/T of A's eigenvalue z
  /// (principal logarithm; a deadbeat z = 0 as ln(10⁻³⁰⁰)/T), so that ωn and ζ mean what they
  /// mean for a continuous one.
  Complex eigenvalue;
  /// A sampled system's eigenvalue z of A itself; equal to `eigenvalue` for a continuous one.
  Complex z;
  double natural_frequency;  ///< ωn = |λ|, rad/s.
  double damping_ratio;      ///< ζ = −Re λ/|λ|; NaN when λ = 0.
  double damped_frequency;   ///< |Im λ|, rad/s: the frequency at which the mode oscillates.
  /// Right eigenvector, A φ = λ φ, of unit 2-norm, scaled by a unit complex number so that its
  /// largest-magnitude entry is real and positive. Entry i belongs to state_names[i].
  VecXc shape;
};

/// Every mode of a system, with the names of the entries of the shapes.
struct Modes {
  /// Sorted by natural frequency ascending; a complex-conjugate pair is adjacent, the member with
  /// Im λ > 0 first; real eigenvalues of equal |λ|, the stable one first.
  std::vector<Mode> modes;
  std::vector<std::string> state_names;  ///< Names of the entries of each shape.
};

/// Modes of ẋ = A x (the poles of the system), n of them, each with its shape over the states.
/// Computed by Eigen's real Schur decomposition (EigenSolver) after an exact power-of-2
/// balancing of the states (Parlett & Reinsch 1969). Throws NumericalError if the
/// eigenvalue iteration does not converge.
Modes modes(const StateSpace& system);

/// Modes of a square matrix A (n×n); state_names default to x1..xn. Throws InvalidArgument if A
/// is not square or its names do not match, NumericalError as above.
Modes modes(const MatX& A, std::vector<std::string> state_names = {});

/// One undamped normal mode of M q̈ + K q = 0: K φ = ω² M φ.
struct NormalMode {
  /// ω², rad²/s². Negative for a statically unstable (divergent) mode, which grows like
  /// exp(√(−ω²) t); zero for a rigid-body mode.
  double squared_frequency;
  /// ω = √(ω²), rad/s; NaN for a divergent mode. Values of ω² within the round-off of the
  /// eigenproblem of zero (|ω²| ≤ 1e-12 · the largest |ω²|) are reported as 0.
  double natural_frequency;
  VecX shape;  ///< φ, mass-normalized: φᵀ M φ = 1; sign chosen so its largest entry is positive.
};

/// Normal modes of the undamped system, frequencies ascending.
struct NormalModes {
  std::vector<NormalMode> modes;
  std::vector<std::string> coordinate_names;  ///< Names of the entries of each shape.
};

/// Normal modes of M q̈ + K q = 0 (nq coordinates): the generalized symmetric eigenproblem
/// K φ = ω² M φ, solved by Cholesky of M and a symmetric eigen-decomposition (Eigen's
/// GeneralizedSelfAdjointEigenSolver), so ω² are real and the shapes M-orthonormal
/// (Φᵀ M Φ = I, Φᵀ K Φ = diag ω²). Frequencies ascending.
/// An ω² with |ω²| ≤ 1e-12 · max(largest |ω²|, squared_frequency_scale) is reported as 0 (a
/// rigid-body mode, not −1e-17 and a NaN frequency): the scale, 1/s², is what the caller knows
/// K's entries to be round-off of (undamped_modes passes the generalized forces at the point
/// over the mass); 0: the largest |ω²| alone.
/// Throws InvalidArgument if M or K is not square and nq×nq, not symmetric (to 1e-12 of its
/// largest entry), or M is not positive definite.
NormalModes normal_modes(const MatX& M, const MatX& K,
                         std::vector<std::string> coordinate_names = {},
                         double squared_frequency_scale = 0.0);

/// Modes of M q̈ + C q̇ + K q = 0 through the companion form x = [q; q̇],
/// A = [0 I; −M⁻¹K −M⁻¹C] (second_order_state_space). 2·nq modes; the shapes run over
/// q (first nq entries, named after the coordinates) and q̇ (named "<coordinate>_dot").
/// Throws as normal_modes does (C need not be symmetric: gyroscopic terms are allowed).
Modes damped_modes(const MatX& M, const MatX& C, const MatX& K,
                   std::vector<std::string> coordinate_names = {});

}  // namespace momenta::analysis
