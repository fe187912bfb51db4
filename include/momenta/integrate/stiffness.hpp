#pragma once
// Is an explicit method held by stability rather than accuracy? The linearization's eigenvalues
// against the method's stability region (Hairer & Wanner, Solving ODEs II, §IV.2), for a check
// before a fixed-step run. (During a dopri5 run, Hairer's estimate of h|λ| inside its steps does
// the same: IntegratorStatistics::stability_limited_steps.)

#include <complex>
#include <string_view>

#include <Eigen/Core>

#include "momenta/integrate/integrator.hpp"

namespace momenta::integrate {

/// The eigenvalues (1/s) of the linearization of the first-order system (δ̇, v̇) =
/// (dexp⁻¹_δ v, a(t, q ⊕ δ, v)) at `state` (δ = 0), its Jacobian by forward differences with the
/// probe √ε·max(1, |x|): 2 nv + 1 evaluations of the acceleration. Size 2 nv. Allocates.
Eigen::VectorXcd linearization_eigenvalues(SecondOrderSystem& system, const State& state);

/// |R(z)| of an explicit Runge–Kutta method's stability function — rk4: Σ_{k≤4} z^k/k!;
/// dopri5's fifth-order solution: Σ_{k≤5} z^k/k! + z⁶/600 — or NaN for another method.
double amplification(std::string_view integrator, std::complex<double> z);

/// The mode (Re λ ≤ 0: decaying or oscillating; a growing mode grows whatever the method) whose
/// amplification at step h is largest, and whether fixed steps of h keep it bounded.
struct StepStability {
  bool stable = true;
  std::complex<double> eigenvalue{0.0, 0.0};  ///< 1/s: the worst mode
  double largest_stable_step = 0.0;           ///< s: the largest h with |R(h λ)| ≤ 1 for it
};

/// Checks h against every eigenvalue with Re λ ≤ 0 (relative round-off 1e-9 |λ| allowed). For a
/// method amplification() does not know, `stable` is true and nothing else is set.
StepStability check_step_stability(std::string_view integrator, const Eigen::VectorXcd& eigenvalues,
                                   double h);

}  // namespace momenta::integrate
