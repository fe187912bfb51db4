#pragma once
// Characteristics of a step response, as control texts define them (Franklin, Powell &
// Emami-Naeini §3.4; MATLAB's stepinfo): rise time, settling time, overshoot, peak.

#include <cstddef>

#include "momenta/analysis/state_space.hpp"
#include "momenta/analysis/time_response.hpp"

namespace momenta::analysis {

/// Step response figures of one output. Times in s; NaN where not defined (a final value of 0 or
/// not finite, a response that has not risen or settled within the samples).
struct StepInfo {
  double final_value;    ///< y∞, the steady-state value the figures refer to.
  double rise_time;      ///< First time y reaches 90 % of y∞ minus first time it reaches 10 %.
  double settling_time;  ///< Time after which |y − y∞| stays within the band (2 % of |y∞|).
  double overshoot;      ///< max(0, (peak − y∞)/y∞) · 100, %, in the direction of y∞.
  double undershoot;     ///< max(0, −(most opposite excursion)/y∞) · 100, %.
  double peak;           ///< max |y|, in output units.
  double peak_time;      ///< Time of the peak sample.
};

/// Figures of output `output` of a sampled step response whose steady state is `final_value`
/// (typically amplitude × dc_gain). Crossing times are interpolated linearly between samples,
/// so they are accurate to O(h²) of the sample spacing h; peak and peak time are the sampled
/// ones. `settling_band` is the relative band (0.02 for 2 %).
/// Throws InvalidArgument on an output index out of range or a band outside (0, 1).
StepInfo step_info(const TimeResponse& response, std::size_t output, double final_value,
                   double settling_band = 0.02);

/// The figures of the system's own unit step response from `input`, y∞ = dc_gain(system, input,
/// output) (±inf for an integrating pair: figures NaN), computed on the analytic response, not
/// read off samples: y(t) = C Γ(t) b + D b with Γ(t) = ∫₀ᵗ e^{Aτ} dτ (Van Loan's exponential,
/// exact to round-off at any t), ẏ(t) = C e^{At} b. The samples of the automatic grid (or `grid`)
/// only bracket each event; each crossing time (10 %, 90 %, the settling band's edge) is then a
/// root of y(t) − level, and the peak and the extremes a root of ẏ(t), found by TOMS 748 to full
/// double precision. Peak time π/ω_d and overshoot e^{−ζπ/√(1−ζ²)} of a second-order system come
/// out to ~1e-15 relative. An event the grid does not bracket (a response faster than the
/// sampling) keeps its sampled value. Peak and extremes at the grid's end stay sampled.
StepInfo step_info(const StateSpace& system, std::size_t input, std::size_t output,
                   const TimeGrid& grid = {}, double settling_band = 0.02);

}  // namespace momenta::analysis
