#pragma once
// Gain and phase margins of one input–output pair taken as the loop transfer function of a
// negative unity-feedback loop, L(s) = G(s) (Franklin, Powell & Emami-Naeini, Feedback Control
// of Dynamic Systems, §6.4; python-control's `margin` reads them the same way):
//
//   phase crossover ω_pc: ∠L(jω_pc) = −180° (mod 360°)   gain margin GM = 1 / |L(jω_pc)|
//   gain crossover  ω_gc: |L(jω_gc)| = 1                  phase margin PM = 180° + ∠L(jω_gc)
//
// searched over a frequency range: the crossings are bracketed on a logarithmic grid and each is
// located to 1e-12 relative in ω by Alefeld–Potra–Shi's TOMS 748 root finder on G(jω) evaluated
// from the state space. Where there are several, the margins reported are the smallest — the
// gain margin nearest 1 (smallest |GM in dB|), the phase margin nearest 0° (in (−180°, 180°]) —
// and every crossing is listed. A margin with no crossing in the range is infinite.

#include <cstddef>
#include <limits>
#include <vector>

#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis {

/// One crossing: where it is and the margin it gives.
struct Crossing {
  double frequency = 0.0;  ///< ω, rad/s
  double margin = 0.0;     ///< GM (a factor) at a phase crossover; PM (degrees) at a gain crossover
};

struct StabilityMargins {
  double gain_margin = std::numeric_limits<double>::infinity();       ///< factor; ∞ without one
  double gain_margin_db = std::numeric_limits<double>::infinity();    ///< 20 log₁₀ GM, dB
  double phase_crossover = std::numeric_limits<double>::quiet_NaN();  ///< ω_pc, rad/s
  double phase_margin_deg = std::numeric_limits<double>::infinity();  ///< degrees; ∞ without one
  double gain_crossover = std::numeric_limits<double>::quiet_NaN();   ///< ω_gc, rad/s
  std::vector<Crossing> phase_crossovers;  ///< every one in the range, ascending ω
  std::vector<Crossing> gain_crossovers;   ///< every one in the range, ascending ω
};

/// The margins of the pair (input, output) over [omega_min, omega_max] rad/s, bracketed on a
/// grid of `points` frequencies. Throws InvalidArgument on an index out of range or a bad range
/// (log_frequency_grid's rule); a crossing narrower than the grid's spacing is not seen.
StabilityMargins stability_margins(const StateSpace& system, std::size_t input, std::size_t output,
                                   double omega_min, double omega_max, std::size_t points = 2000);

}  // namespace momenta::analysis
