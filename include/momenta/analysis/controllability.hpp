#pragma once
// Controllability and observability of a state-space system: can the inputs move every state,
// and do the outputs show every state?
//
// The rank is found by the orthogonal staircase reduction (Rosenbrock; Varga, "Computation of
// irreducible generalized state-space realizations", Kybernetika 26, 1990; MATLAB's ctrbf): each
// step compresses the part of the state the inputs reach so far with an SVD, never forming the
// ill-conditioned matrix [B AB A²B …]. What is left is the uncontrollable part, whose
// eigenvalues are the modes no input moves. A singular value counts as nonzero above
//     n · ε · max(‖A‖₁, ‖B‖₁)     (ε: the double's machine epsilon),
// so the answer depends on how the states are scaled, as any numerical rank does.
// Observability is controllability of the dual (Aᵀ, Cᵀ).
//
// The Gramian is given for a stable system (continuous: every pole in the open left half-plane;
// discrete: inside the unit circle), from the Lyapunov equation A W + W Aᵀ + B Bᵀ = 0
// (continuous) or A W Aᵀ − W + B Bᵀ = 0 (discrete); its condition number says how much harder
// the weakest direction is to reach (or see) than the strongest.

#include <cstddef>
#include <optional>
#include <vector>

#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis {

/// What the inputs reach (controllability) or the outputs see (observability).
struct Reachability {
  std::size_t rank = 0;    ///< Dimension of the controllable (observable) subspace.
  std::size_t states = 0;  ///< n.
  /// Eigenvalues of the part the inputs do not move (the outputs do not see): n − rank of them.
  std::vector<Complex> hidden_poles;
  /// The Gramian (n×n) when the system is stable; empty otherwise.
  MatX gramian;
  /// Its 2-norm condition number (∞ when singular); nullopt when the system is not stable.
  std::optional<double> gramian_condition;

  bool complete() const { return rank == states; }
};

/// Controllability of (A, B). Throws NumericalError if an SVD or eigenvalue iteration fails.
Reachability controllability(const StateSpace& system);

/// Observability of (A, C), as controllability of (Aᵀ, Cᵀ).
Reachability observability(const StateSpace& system);

}  // namespace momenta::analysis
