#pragma once
// An L-stable, stiffly accurate singly diagonally implicit Runge–Kutta method of order 3 with a
// fixed step (Alexander, SIAM J. Numer. Anal. 14, 1977; Hairer & Wanner, Solving ODEs II, §IV.6,
// eq. 6.18): for stiff models at a step chosen for the motion, not for the stiffness — real-time-
// like runs, or rows at a fixed rate.
//
// Why this method. It is stable for every h λ in the left half-plane (A-stable) and damps a mode
// the step cannot resolve to nothing in one step (L-stable: R(−∞) = 0), oscillatory (a stiff
// spring) or not (a stiff damper). Generalized-α, the second-order workhorse of multibody codes,
// is A-stable but not L-stable on overdamped modes: on examples/stiff_spring_damper.yaml at
// h = 10 ms it was 240 % off the closed form (ρ∞ = 0.5; 37 % at ρ∞ = 0.8), where this method is
// within 7e-5 (docs/integrators.md).
//
// Tableau (γ = 0.43586652150845900, the root of x³ − 3x² + 3x/2 − 1/6 in (1/6, 1/2)):
//   c = (γ, (1 + γ)/2, 1);  a21 = (1 − γ)/2;  a31 = b1 = −(6γ² − 16γ + 1)/4,
//   a32 = b2 = (6γ² − 20γ + 5)/4, b3 = γ (the last stage is the solution).
//
// On the configuration manifold the stages live in local coordinates about the step's start,
// q = q_n ⊕ δ, δ̇ = dexp⁻¹_δ(v) (as the explicit Runge–Kutta methods, runge_kutta.hpp). Each stage
// Z = ψ + h γ f(Z) is solved by a simplified Newton iteration whose matrix, reduced to the
// velocities, is S = I − h γ ∂a/∂v − (h γ)² ∂a/∂q: a finite-difference Jacobian of a(t, q, v)
// (2 nv + 1 evaluations) kept across steps, renewed before a step when Newton's method contracted
// slower than θ = 0.1 in the last one (or failed), S refactored when h or the Jacobian changes.
// The iteration stops when the estimated distance to the solution, η |ΔZ| with η = θ/(1 − θ) from
// its contraction θ (Hairer & Wanner §IV.8), is below 0.1 of 1e-12 + 1e-10·|x| on every
// coordinate (the `newton` tolerances): far below the truncation error of any step worth taking,
// so the solution is the method's, not Newton's.
//
// Statistics: evaluations count every call of SecondOrderSystem::acceleration, the Jacobians'
// included; rejected_steps counts steps retried with a fresh Jacobian.

#include <Eigen/LU>

#include "momenta/integrate/acceleration_jacobian.hpp"
#include "momenta/integrate/integrator.hpp"

namespace momenta::integrate {

class Sdirk3 final : public Integrator {
 public:
  /// `newton`: the convergence test of Newton's method (not an error control; file comment).
  /// Throws InvalidArgument when they are not positive and finite.
  explicit Sdirk3(const Tolerances& newton = {1e-10, 1e-12});

  std::string_view name() const override { return "sdirk3"; }
  int order() const override { return 3; }
  void initialize(SecondOrderSystem& system, const State& state) override;
  /// One step of exactly h. Throws NumericalError naming the time when Newton's method does not
  /// converge even with a fresh Jacobian (the step is far too large for the model's nonlinearity).
  double step(SecondOrderSystem& system, State& state, double h) override;

  /// Jacobians of a(t, q, v) evaluated since initialize().
  long jacobians() const { return jacobians_; }

 private:
  bool solve_stages(SecondOrderSystem& system, const State& start, double h);
  bool solve_stage(SecondOrderSystem& system, const State& start, double h, int i);
  void update_jacobian(SecondOrderSystem& system, const State& at);
  void factor(double h);

  Tolerances tolerances_;
  VecX kq_[3], kv_[3];      // stage slopes of δ and v
  VecX psi_delta_, psi_v_;  // the stage's known part ψ
  VecX z_delta_, z_v_;      // the stage value Z being solved for
  VecX q_, delta_rate_, a_, r_delta_, r_v_, rhs_, dv_, scale_;
  JacobianWorkspace probes_;  // the Jacobian's
  MatX dadq_, dadv_, iteration_matrix_;
  Eigen::PartialPivLU<MatX> lu_;
  double factored_h_ = 0.0;           // h of the factored S; 0: none
  double eta_ = 1.0;                  // Newton's convergence-rate estimate, carried between stages
  double slowest_contraction_ = 0.0;  // the largest θ of the last step
  double non_finite_at_ = 0.0;        // the stage time of a non-finite acceleration, else NaN
  bool jacobian_fresh_ = false;
  long jacobians_ = 0;
};

}  // namespace momenta::integrate
