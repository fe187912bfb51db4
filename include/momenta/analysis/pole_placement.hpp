#pragma once
// Pole placement: the state feedback u = −K x that puts the closed-loop poles, the eigenvalues of
// A − B K, where the designer wants them (Franklin, Powell & Emami-Naeini ch. 7).
//
// Method: Kautsky, Nichols & Van Dooren, "Robust pole assignment in linear state feedback",
// Int. J. Control 41(5), 1985 — method 0, as SciPy's place_poles(method="KNV0"). With
// B = [U₀ U₁] [Z; 0] (QR), each closed-loop eigenvector xⱼ must lie in
// Sⱼ = null(U₁ᵀ (A − λⱼ I)); with several inputs the freedom left is used to make the
// eigenvectors X as well conditioned as the method can (sweeps that turn each xⱼ towards the
// normal of the others), so the poles move little when the model is a little wrong. Then
// K = Z⁻¹ U₀ᵀ (A − X Λ X⁻¹). A single input leaves no freedom: K is the unique (Ackermann's)
// gain, found here without the controllability matrix's powers of A.

#include <vector>

#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis {

struct PolePlacement {
  MatX K;  ///< m×n, u = −K x.
  /// The eigenvalues of A − B K as computed (to compare with the request: the placement's
  /// accuracy), sorted as modes() sorts.
  VecXc closed_loop_poles;
  /// 2-norm condition number of the closed-loop eigenvector matrix X: how sensitive the placed
  /// poles are to errors in A, B and K (1 is ideal).
  double eigenvector_condition = 0.0;
  std::vector<std::string> state_names;
  std::vector<std::string> input_names;
};

/// The gain that places the poles `poles` (n of them, complex ones in conjugate pairs; in the
/// z-plane when the system is discrete: the same algebra). A pole may be repeated at most as
/// many times as B has independent columns.
/// Throws InvalidArgument on a wrong count, a non-finite or unpaired complex pole, a pole
/// repeated more than rank B times, or B without full column rank; NumericalError when (A, B)
/// is not controllable enough to place them (an eigenvector space is empty or X singular),
/// naming the pole.
PolePlacement place_poles(const StateSpace& system, const std::vector<Complex>& poles);

}  // namespace momenta::analysis
