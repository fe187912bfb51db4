#pragma once
// Nyquist's stability criterion on one input–output pair taken as the loop transfer function of a
// negative unity-feedback loop, L = G (Franklin, Powell & Emami-Naeini §6.3): Z = N + P, with
//
//   P  the open-loop poles in the unstable region — the open right half-plane, or outside the
//      unit circle for a system sampled every T s — counted among A's eigenvalues (so a mode the
//      pair cannot see is counted in P and, unmoved by the feedback, in Z);
//   N  the clockwise encirclements of −1 by L along the Nyquist contour: up the imaginary axis
//      and back around the right half-plane at a radius beyond every open- and closed-loop pole
//      (counter-clockwise round the unit circle when sampled), going round the poles on the
//      boundary on their unstable side at a small radius, so they count as stable;
//   Z  the closed-loop poles in the unstable region.
//
// N is counted from the curve itself, as a student reads the plot: the argument of 1 + L is
// followed along the contour, each step halved until it turns less than 1/16 of a turn and |1 + L|
// changes by less than a factor of 2, and N = −Δarg/(2π). The eigenvalues of the closed loop are
// not used: they are the tests' independent reference.

#include <cstddef>

#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis {

struct NyquistCount {
  int open_loop_unstable = 0;    ///< P
  int boundary_poles = 0;        ///< open-loop poles on the boundary, which the contour goes round
  int encirclements = 0;         ///< N, clockwise (negative: counter-clockwise)
  int closed_loop_unstable = 0;  ///< Z = N + P
  /// L passes through −1 on the contour: a closed-loop pole on the stability boundary (the loop
  /// is marginally stable); N and Z are then left 0.
  bool through_critical_point = false;
  double sample_time = 0.0;  ///< s; 0: the s-plane contour, T > 0: the unit circle
};

/// The Nyquist count of the pair (input, output). Throws InvalidArgument on an index out of range
/// or a loop that is not well posed (1 + D = 0); NumericalError if an eigenvalue iteration fails.
NyquistCount nyquist_count(const StateSpace& system, std::size_t input, std::size_t output);

}  // namespace momenta::analysis
