#pragma once
// The linear–quadratic regulator: the state feedback u = −K x that minimizes
//
//     J = ∫₀^∞ (xᵀ Q x + uᵀ R u + 2 xᵀ N u) dt          (continuous system), or
//     J = Σₖ (xₖᵀ Q xₖ + uₖᵀ R uₖ + 2 xₖᵀ N uₖ)         (discrete system, sample time T),
//
// K = R⁻¹ (Bᵀ S + Nᵀ), or K = (R + Bᵀ S B)⁻¹ (Bᵀ S A + Nᵀ) when discrete, with S the stabilizing
// solution of the algebraic Riccati equation (matrix_equations.hpp). The minimum cost from x₀ is
// x₀ᵀ S x₀. As MATLAB's lqr / dlqr and python-control's lqr / dlqr. For a linearization the
// state is the deviation from the operating point: u = u₀ − K (x − x₀).

#include <string>
#include <vector>

#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis {

struct LqrDesign {
  MatX K;  ///< m×n gain, u = −K x (rows: inputs, columns: states).
  MatX S;  ///< n×n Riccati solution; the optimal cost from x₀ is x₀ᵀ S x₀.
  /// Eigenvalues of A − B K: in the left half-plane (1/s), or inside the unit circle when the
  /// system is discrete. Sorted as modes() sorts (by magnitude, conjugate pairs together).
  VecXc closed_loop_poles;
  std::vector<std::string> state_names;
  std::vector<std::string> input_names;
  double sample_time = 0.0;  ///< 0: continuous design; else the discrete system's period, s.
};

/// The LQR design for `system` (continuous or discrete by its sample time). Q n×n symmetric
/// positive semidefinite, R m×m symmetric positive definite, N n×m (empty: none), with
/// [Q N; Nᵀ R] positive semidefinite.
/// Throws InvalidArgument on a size, a non-finite entry, or a weight that is not (semi)definite,
/// naming it; NumericalError when no feedback stabilizes the system (solve_*_riccati's reasons).
LqrDesign lqr(const StateSpace& system, const MatX& Q, const MatX& R, const MatX& N = MatX());

}  // namespace momenta::analysis
