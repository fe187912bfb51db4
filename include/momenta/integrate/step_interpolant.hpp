#pragma once
// The state anywhere inside the step an integrator has just taken, for locating events: the
// method's own dense output where it has one (dopri5), else cubic Hermite interpolation between
// the step's ends in local coordinates about its start — q(t) = q0 ⊕ δ(t) with δ(t0) = 0,
// δ̇(t0) = v0, δ(t1) = q1 ⊖ q0, δ̇(t1) = dexp⁻¹_δ(v1); v(t) from v0, v1 and the accelerations at
// both ends. The interpolant is third order (error O(h⁴)) and matches the ends exactly.

#include "momenta/integrate/integrator.hpp"

namespace momenta::integrate {

class StepInterpolant {
 public:
  /// Sizes the workspace (allocates; once per run).
  void resize(int nq, int nv);

  /// Takes the step from `start` to `end` that `integrator` has just taken on `system` (`end` as
  /// the run holds it, after any projection). Without a dense output it evaluates the
  /// accelerations at both ends (two evaluations of the system). No allocation.
  void set(SecondOrderSystem& system, const Integrator& integrator, const State& start,
           const State& end);

  /// The state at t in [start.t, end.t] (`out` sized like the state). The ends give the
  /// states set() was handed exactly. No allocation.
  void evaluate(const SecondOrderSystem& system, double t, State& out);

 private:
  const Integrator* integrator_ = nullptr;
  State start_, end_;
  VecX a0_, a1_;         // accelerations at the ends (Hermite only)
  VecX delta1_, rate1_;  // q1 ⊖ q0 and dexp⁻¹_δ1(v1)
  VecX delta_;           // scratch
};

}  // namespace momenta::integrate
