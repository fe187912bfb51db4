#pragma once
// Static equilibrium of a multibody model: the configuration q at rest (v = 0 on the free
// joints) where gravity, springs and constant inputs balance, r_f(q) = ID(q, 0, 0) − τ_elements
// = 0 on the free coordinates, with prescribed joints held at their signals and every signal at
// its value at time t.
//
// Newton's method on the tangent space, q ← q ⊕ α Δ with K Δ = −r (K = ∂r_f/∂δq from the same
// derivatives as linearize(), solved by a rank-revealing complete orthogonal decomposition so a
// singular K gives the least-squares, minimum-norm step), and a backtracking (Armijo) line search
// on ½‖r‖²: α = 1, ½, ¼, … until ‖r(q ⊕ αΔ)‖² ≤ (1 − 10⁻⁴ α) ‖r(q)‖² (Nocedal & Wright 2006,
// §3.1 and §11.2). A step turning any angle by more than 1 rad is first scaled down to 1 rad.
//
// With constraints (model/constraint.hpp) the guess is first made consistent, and Newton works
// in the independent coordinates of linearize() (linearize.hpp), re-chosen at every iterate: the
// residual is r = Tᵀ M_ff v̇_f, the generalized force along the independent velocities (T =
// ∂v_f/∂ζ; the constraint forces Gᵀλ drop out since G T = 0), zero exactly where the constrained
// accelerations at rest vanish.

#include <vector>

#include "momenta/analysis/linearize.hpp"
#include "momenta/analysis/modes.hpp"

namespace momenta::analysis {

struct EquilibriumOptions {
  /// Time at which the signals (inputs and prescribed motion) are evaluated, s.
  double t = 0.0;
  /// Converged when max |r_i| ≤ tolerance · F, F the model's force scale:
  /// L (m_total |g| + Σ k_linear L + Σ |applied force|) + Σ k_torsional + Σ |applied torque|
  /// (L = characteristic_length), or the generalized forces at the guess if larger; 1 if zero.
  double tolerance = 1e-10;
  /// Newton iterations before giving up.
  int max_iterations = 100;
};

/// A static equilibrium and its stability.
struct Equilibrium {
  /// The equilibrium: t, q (prescribed coordinates from their signals) and v = 0 on the free
  /// coordinates (a prescribed joint's rate as its signal gives it).
  OperatingPoint point;
  /// r_f at the point (nf: N on lengths, N·m on angles; with constraints one per independent
  /// velocity), max |r_i| ≤ tolerance · force_scale.
  VecX residual;
  /// F of EquilibriumOptions::tolerance.
  double force_scale = 0.0;
  /// Newton iterations taken.
  int iterations = 0;
  /// The linearization about the point (default inputs, configuration states as outputs).
  LinearModel linear;
  /// Eigenvalues of A with Re λ > 1e-6 · ρ(A) (ρ the largest |λ|): the equilibrium is unstable
  /// when there is any. A conservative system's stable equilibrium has every λ on the imaginary
  /// axis (Re λ within round-off of 0), so it is not reported as unstable.
  std::vector<Complex> unstable_eigenvalues;
  /// Rank of K = ∂r_f/∂δq at the point; below nf the equilibrium is not isolated (a free
  /// rotation about gravity's axis, a coordinate no force depends on).
  int stiffness_rank = 0;
  bool stable() const { return unstable_eigenvalues.empty(); }
};

/// Finds the static equilibrium nearest (by Newton's method) to the configuration `q_guess`
/// (size nq; its prescribed coordinates are replaced by their signals).
/// Throws InvalidArgument when no joint is free (all fixed or prescribed), when q_guess has the
/// wrong size or a non-unit quaternion; NumericalError when there is no equilibrium to be found:
/// the line search stalls with the residual still above tolerance (the forces cannot balance, e.g.
/// a constant push on a coordinate with no restoring force, or K singular along the residual) or
/// the iterations run out — the message names the largest residual coordinate and its value.
Equilibrium find_equilibrium(const model::Model& model, const VecX& q_guess,
                             const EquilibriumOptions& options = {});

}  // namespace momenta::analysis
