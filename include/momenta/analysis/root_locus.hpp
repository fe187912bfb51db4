#pragma once
// The root locus of one input–output pair: where the closed-loop poles go as the gain k of the
// negative feedback u = r − k y grows from 0 (Evans; Franklin, Powell & Emami-Naeini ch. 5). The
// closed-loop poles are the roots of 1 + k G(s) = 0, G = K N(s)/D(s) the pair's transfer
// function (transfer_function.hpp): at k = 0 the open-loop poles, as k → ∞ the zeros and, for
// the rest, the asymptotes.
//
// Besides the branches on a grid of gains, the locus's landmarks, each exact rather than read off
// the grid:
//   - break-away and break-in points: where branches meet, dk/ds = 0 with k(s) = −D(s)/(K N(s)),
//     i.e. Σ 1/(s − pⱼ) = Σ 1/(s − zᵢ) — the roots of N′D − N D′ polished by Newton on that
//     sum; kept where k is real and positive;
//   - imaginary-axis crossings: s = jω with k = −D(jω)/(K N(jω)) real and positive, from the real
//     roots of Im[D(jω) · conj N(jω)] (a polynomial in ω, Routh's criterion's crossings): the
//     gains at which the loop turns unstable or stable;
//   - the asymptotes: centroid (Σp − Σz)/(n − m) and angles (2l + 1)·180°/(n − m).
// A sampled system's locus lies in the z-plane (poles z, the characteristic equation 1 + k G(z) =
// 0), where the stability boundary is the unit circle: its landmarks are the same but for the
// crossings, which are those of the unit circle, z = e^{jθ}, from the roots on it of
// z^n Im-part polynomial z^{n−m} D(z) N̄ʳ(z) − D̄ʳ(z) N(z) (ʳ: coefficients reversed, so that on
// the circle N̄ʳ(z) = z^m conj N(z)), with z = ±1 always tried.
// For the landmarks a pole's or zero's real or imaginary part within 1e-7 of the largest |p|, |z|
// of zero is taken as zero: a multiple pole comes out of the eigenvalue iteration about √ε apart
// (a double integrator's as ±1e-9j), which would draw crossings at gains near 0.

#include <vector>

#include "momenta/analysis/state_space.hpp"
#include "momenta/analysis/transfer_function.hpp"

namespace momenta::analysis {

/// A point of the locus with the gain that puts a closed-loop pole there.
struct LocusPoint {
  Complex s;    ///< 1/s; z (dimensionless) on a sampled system's locus.
  double gain;  ///< k > 0.
};

struct RootLocus {
  std::string input_name;
  std::string output_name;
  TransferFunction open_loop;  ///< G(s), after cancellation: the locus's poles and zeros.
  VecX gains;                  ///< k at each row of `poles`, as given.
  /// poles(i, j): branch j at gains[i]; each branch continued from the previous gain by nearest
  /// neighbour, so a column traces one pole (gains × n).
  Eigen::MatrixXcd poles;
  std::vector<LocusPoint> breakaway;  ///< Break-away and break-in points, by gain.
  /// Crossings of the stability boundary, by gain: of the imaginary axis at s = jω, ω ≥ 0, or
  /// for a sampled system of the unit circle at z = e^{jθ}, 0 ≤ θ ≤ π (one of each conjugate
  /// pair).
  std::vector<LocusPoint> crossings;
  double sample_time = 0.0;  ///< s; 0: the s-plane, T > 0: the z-plane of a system sampled at T.
  double asymptote_centroid = 0.0;           ///< 1/s; 0 when n = m.
  std::vector<double> asymptote_angles_deg;  ///< n − m of them, in [0°, 360°).
};

/// The root locus of the pair (input, output) over `gains` (each finite and ≥ 0). The
/// closed-loop poles at each gain are the eigenvalues of A − k B (1 + k D)⁻¹ C (the state space
/// itself, not the polynomial; with the pair's cancelled modes, which do not move).
/// Throws InvalidArgument on an index out of range, a bad gain, or a gain at
/// which 1 + k D = 0 (the loop is not well posed); NumericalError if an eigenvalue iteration
/// fails.
RootLocus root_locus(const StateSpace& system, std::size_t input, std::size_t output,
                     const VecX& gains);

/// `points` gains spaced logarithmically from k_min to k_max (0 < k_min < k_max), with 0 first.
VecX log_gain_grid(double k_min, double k_max, std::size_t points);

}  // namespace momenta::analysis
