#pragma once
// Step and impulse responses of a state-space system, sampled on a uniform time grid.
//
// The samples are exact (to round-off) for the linear model, not the output of an ODE
// integrator: over one step h the system is advanced by the zero-order-hold discretization
//
//     x(t + h) = Φ x(t) + Γ u,    exp([A B; 0 0] h) = [Φ Γ; 0 I]
//
// (C. F. Van Loan, "Computing integrals involving the matrix exponential", IEEE TAC 23(3), 1978),
// which is exact for a constant input; the matrix exponential is Eigen's scaling-and-squaring
// Padé (unsupported/Eigen/MatrixFunctions, Higham 2005). A step input is constant, and after an
// impulse the input is zero, so no discretization error enters at any sample.
//
// A sampled system (sample time T > 0) answers at its own samples t_k = k T by its recursion
// x[k+1] = A x[k] + B u[k]: the grid's `samples` fix the final time, else the final time
// (automatic: the continuous rule on s = ln z / T) is rounded down to whole samples; its impulse
// is the unit pulse u[0] = 1, so y[0] = D and x[1] = B.

#include <cstddef>
#include <string>
#include <vector>

#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis {

/// Where to sample a response. Zero fields are chosen automatically.
struct TimeGrid {
  /// Last sample time t_f, s; 0: automatic_final_time().
  double final_time = 0.0;
  /// Number of samples including t = 0 and t_f (≥ 2); 0: automatic, at least 501 and at least
  /// 20 per period of the fastest oscillating mode, at most 20001.
  std::size_t samples = 0;
};

/// The response of every output and state to one input.
struct TimeResponse {
  std::string input_name;
  std::vector<std::string> output_names;
  std::vector<std::string> state_names;
  /// The system's units (StateSpace::units): the input's, each output's and state's; empty where
  /// the system has none.
  std::string input_unit;
  std::vector<std::string> output_units, state_units;
  VecX time;     ///< Sample times t_k = k h, s (samples).
  MatX outputs;  ///< outputs(k, j): output j at t_k (samples × outputs).
  MatX states;   ///< states(k, i): state i at t_k (samples × states).
};

/// Zero-order-hold discretization over a step h: Φ = e^(A h), Γ = ∫₀ʰ e^(A τ) dτ B.
struct Discretization {
  MatX transition;  ///< Φ, n×n.
  MatX input;       ///< Γ, n×m.
};

/// Φ and Γ of ẋ = A x + B u over h > 0, from one exponential of the (n+m)×(n+m) augmented
/// matrix (Van Loan 1978). Throws InvalidArgument if h is not positive and finite,
/// NumericalError if the exponential is not finite (h times the growth rate too large).
Discretization zero_order_hold(const StateSpace& system, double h);

/// The same for bare matrices A (n×n) and B (n×m); throws InvalidArgument on mismatched sizes.
Discretization zero_order_hold(const MatX& A, const MatX& B, double h);

/// A horizon that shows the system's dynamics, from its poles λ:
///   - any unstable pole (Re λ > 0): 5 / max Re λ (the output grows by e⁵ ≈ 150);
///   - else 7 / min |Re λ| over the stable poles (the slowest mode decays to e⁻⁷ < 0.1 %),
///     and at least 5 periods 2π/|Im λ| of each undamped oscillating mode;
///   - else (all poles at the origin, or no states): 10 s.
/// Poles with |Re λ| ≤ 1e-9·|λ| count as undamped.
double automatic_final_time(const StateSpace& system);

/// Response to u_input(t) = amplitude for t ≥ 0 (0 before), from x(0) = 0:
///   y(t) = C ∫₀ᵗ e^(Aτ) dτ B u + D u. Other inputs are zero.
/// Throws InvalidArgument on an input index out of range, final_time not positive and finite, or
/// fewer than 2 samples; NumericalError if the response overflows.
TimeResponse step_response(const StateSpace& system, std::size_t input, const TimeGrid& grid = {},
                           double amplitude = 1.0);

/// Response to u_input(t) = δ(t) from x(0⁻) = 0: x(t) = e^(At) B, y(t) = C e^(At) B for t > 0
/// (the sample at t = 0 is the limit t → 0⁺; a feedthrough D δ(t) has no samples and is left
/// out). It is the time derivative of the step response. Throws as step_response does.
TimeResponse impulse_response(const StateSpace& system, std::size_t input,
                              const TimeGrid& grid = {});

}  // namespace momenta::analysis
