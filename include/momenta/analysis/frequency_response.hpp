#pragma once
// Frequency response (Bode data) of one input–output pair: G(jω) over angular frequencies ω in
// rad/s (divide by 2π for Hz) — H(e^{jωT}) for a system sampled every T s, up to the Nyquist
// frequency π/T (beyond it refused: it repeats) — its magnitude in absolute units and in dB, and
// its phase in degrees, unwrapped.
//
// G(jω) = C (jωI − A)⁻¹ B + D is evaluated from the state space, never from polynomial
// coefficients: A is reduced once to Hessenberg form A = Q H Qᵀ (orthogonal, backward stable),
// and each frequency then costs one O(n²) Hessenberg solve (jωI − H) y = Qᵀ B with partial
// pivoting (Laub, "Efficient multivariable frequency response computations", IEEE TAC 26(2),
// 1981).

#include <complex>
#include <cstddef>
#include <string>

#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis {

/// Bode data of one pair, one entry per frequency.
struct FrequencyResponse {
  std::string input_name;
  std::string output_name;
  VecX frequency;             ///< ω, rad/s, as given (ascending on a log grid).
  Eigen::VectorXcd response;  ///< G(jω).
  VecX magnitude;             ///< |G(jω)|, output units per input unit.
  VecX magnitude_db;          ///< 20 log₁₀ |G(jω)|, dB (−inf where G = 0).
  /// arg G(jω), degrees, continuous along the grid: steps between neighbours are kept within
  /// ±180° by adding multiples of 360°. The branch is fixed at the first frequency by the
  /// factored form, arg K + Σ arg(jω − z) − Σ arg(jω − p) with each term in (−180°, 180°] and
  /// arg K = 0° for K > 0, −180° for K < 0; so 1/(s+1) starts near 0°, 1/s² sits at −180°,
  /// a lightly damped pair of poles drops by 180° across its resonance. On a grid too coarse to
  /// resolve a resonance (a phase change over 180° between neighbours) the unwrapped phase can
  /// be off by 360° beyond it.
  VecX phase_deg;
};

/// Where a system's response at ω rad/s is evaluated: s = jω, or z = e^{jωT} when it is sampled
/// every T s.
std::complex<double> frequency_point(const StateSpace& system, double omega);

/// `points` angular frequencies from omega_min to omega_max (rad/s), equally spaced in log ω,
/// both ends included. Throws InvalidArgument unless 0 < omega_min < omega_max (finite) and
/// points ≥ 2.
VecX log_frequency_grid(double omega_min, double omega_max, std::size_t points);

/// Bode data of the pair (input, output) at the given angular frequencies (rad/s, ≥ 0, finite;
/// ascending for the unwrapping to mean anything). At a frequency that is exactly an imaginary
/// pole the response is not finite.
/// Throws InvalidArgument on an index out of range or a negative / non-finite frequency.
FrequencyResponse frequency_response(const StateSpace& system, std::size_t input,
                                     std::size_t output, const VecX& frequencies);

/// The same on log_frequency_grid(omega_min, omega_max, points).
FrequencyResponse frequency_response(const StateSpace& system, std::size_t input,
                                     std::size_t output, double omega_min, double omega_max,
                                     std::size_t points = 200);

}  // namespace momenta::analysis
