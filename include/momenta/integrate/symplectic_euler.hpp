#pragma once
// Semi-implicit (symplectic) Euler: v₁ = v₀ + h a(t₀, q₀, v₀); q₁ = q₀ ⊕ h v₁.
// First order; symplectic for separable conservative systems (energy error bounded, no drift),
// one evaluation per step. Rotations advance by the exponential map.

#include "momenta/integrate/integrator.hpp"

namespace momenta::integrate {

class SymplecticEuler final : public Integrator {
 public:
  std::string_view name() const override { return "symplectic_euler"; }
  int order() const override { return 1; }
  void initialize(SecondOrderSystem& system, const State& state) override;
  double step(SecondOrderSystem& system, State& state, double h) override;

 private:
  VecX vdot_, dq_, q_next_;
};

}  // namespace momenta::integrate
