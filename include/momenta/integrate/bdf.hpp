#pragma once
// Variable-order, variable-step backward differentiation formulas (BDF, orders 1–5) for stiff
// models: SUNDIALS CVODE (Hindmarsh et al., ACM TOMS 31, 2005; Byrne & Hindmarsh's fixed-leading-
// coefficient Nordsieck form) with a modified Newton iteration on a dense difference-quotient
// Jacobian that CVODE keeps across steps (refreshed every 20 steps or when Newton converges
// slowly).
//
// What CVODE integrates. The first-order system y = (δ, v) of size 2 nv, δ the local coordinates
// of the configuration about a base point q_b (q = q_b ⊕ δ), δ̇ = dexp⁻¹_δ(v), v̇ = a(t, q, v) —
// the same chart the Runge–Kutta methods use, so quaternions advance by the exponential map and
// stay unit. On models whose coordinates are all vectors (no ball or free joint) q_b ⊕ δ is
// q_b + δ and the chart is never changed; otherwise the base moves to the current configuration
// (a restart) once a local coordinate exceeds 1 (rad), well inside the chart's domain |δ| < π.
//
// Error weights mirror dopri5's: component i of δ against atol + rtol·s_i(q) (s from
// SecondOrderSystem::configuration_scale: |q_i| on vector coordinates, 1 rad on rotations), of v
// against atol + rtol·|v_i|, in the root-mean-square norm over all 2 nv components.
//
// Output. A call of step() integrates to state.t + h_max and returns the state there from CVODE's
// interpolating polynomial: CVODE chooses its own steps (it is not limited by h_max), and the rows
// land on the requested times. A step never straddles an input discontinuity
// (SecondOrderSystem::next_discontinuity): CVODE stops on it and restarts there (the BDF history
// across a jump would cut it to first order).
//
// Projection. When the caller hands back a state other than the one step() returned (the
// projection of a constrained model onto its constraints, or an edit), the difference is measured
// in the error weights: within the tolerance CVODE continues from its own history (the projected
// state is what is reported); beyond it CVODE restarts from the given state. The constraint drift
// of the integrated solution is so held to the tolerance without restarting every step.
//
// Statistics: steps and rejected steps (error-test and Newton failures) summed over restarts;
// evaluations count every call of SecondOrderSystem::acceleration, those of the difference-quotient
// Jacobians included.

#include <memory>

#include "momenta/integrate/integrator.hpp"

namespace momenta::integrate {

class Bdf final : public Integrator {
 public:
  /// Throws InvalidArgument when a tolerance is not positive and finite or asks for more than
  /// double precision holds (as dopri5).
  explicit Bdf(const Tolerances& tolerances = {});
  ~Bdf() override;

  std::string_view name() const override { return "bdf"; }
  int order() const override { return 5; }  ///< the highest order it uses
  bool adaptive() const override { return true; }
  void initialize(SecondOrderSystem& system, const State& state) override;
  /// Integrates to state.t + h_max (see the file comment) and returns h_max. Throws
  /// NumericalError naming the time, CVODE's reason and a hint when it cannot continue (the error
  /// test or Newton's method failing repeatedly at the smallest step), and rethrows what the
  /// system throws.
  double step(SecondOrderSystem& system, State& state, double h_max) override;

  /// Restarts since initialize(): chart changes, projections beyond the tolerance, input
  /// discontinuities.
  long restarts() const { return restarts_; }

 private:
  struct Solver;  // CVODE's memory and the workspace of its callbacks
  std::unique_ptr<Solver> solver_;
  Tolerances tolerances_;
  long restarts_ = 0;
};

}  // namespace momenta::integrate
