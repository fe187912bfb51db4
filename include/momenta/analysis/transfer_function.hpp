#pragma once
// The transfer function of one input–output pair of a state-space system, in zero-pole-gain form
//
//     G(s) = C (sI − A)⁻¹ B + D = K ∏(s − zᵢ) / ∏(s − pⱼ),
//
// computed from the state space without ever forming polynomial coefficients (whose roots are
// ill-conditioned). Poles are the eigenvalues of A. Zeros are the finite generalized eigenvalues
// of the Rosenbrock system pencil
//
//     P(s) = [sI − A  −B]          det P(s) = det(sI − A) · G(s) = K ∏(s − zᵢ),
//            [  C      D],
//
// after the orthogonal deflation of its infinite eigenvalues of Emami-Naeini & Van Dooren,
// "Computation of zeros of linear multivariable systems", Automatica 18(4), 1982 (SISO case):
// each step turns the state coordinates so that the output reads one state, drops that state
// and makes its derivative the new output. A relative degree r costs r steps; what remains is a
// regular pencil with a single infinite eigenvalue, solved by QZ (Eigen's GeneralizedEigenSolver).
// Solving the raw pencil by QZ instead would split the r-fold infinite eigenvalue into spurious
// finite "zeros" of size ~ε^(−1/r)·‖A‖.

#include <complex>
#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/analysis/modes.hpp"
#include "momenta/analysis/state_space.hpp"

namespace momenta::analysis {

/// Default relative tolerance under which a pole and a zero cancel (see transfer_function()).
inline constexpr double kDefaultCancellationTolerance = 1e-6;

/// G(s) = gain · ∏(s − zeros) / ∏(s − poles) of one input–output pair.
struct TransferFunction {
  std::string input_name;
  std::string output_name;
  /// K: the leading coefficient, lim s→∞ s^(r) G(s) with r = poles.size() − zeros.size() the
  /// relative degree (K = D when r = 0; K = C A^(r−1) B otherwise). 0 when G ≡ 0.
  double gain = 0.0;
  /// Zeros left after cancellation, sorted like the poles. Conjugate pairs adjacent.
  std::vector<Complex> zeros;
  /// Poles left after cancellation, sorted by |p| ascending, then Re ascending, then Im
  /// descending (as modes()).
  std::vector<Complex> poles;
  /// The poles removed with an equal zero (uncontrollable or unobservable modes of this pair, in
  /// exact arithmetic); each stands for one pole and one zero.
  std::vector<Complex> cancelled;
  /// G(0) — G(1) for a sampled system, its steady gain: finite when no pole at the origin (at
  /// z = 1) remains; ±infinity (the sign of G on the real axis just above it) when one does.
  double dc_gain = 0.0;

  /// Relative degree r = number of poles − number of zeros.
  int relative_degree() const { return static_cast<int>(poles.size() - zeros.size()); }
  /// True when G(s) ≡ 0 (no path from the input to the output).
  bool is_zero() const { return gain == 0.0; }
  /// K ∏(s − z)/∏(s − p) from the factors (for plotting or checks; evaluate() on the state
  /// space is the stabler way to get G(s)).
  Complex operator()(Complex s) const;
};

/// Zero-pole-gain transfer function from input `input` to output `output`.
/// Every eigenvalue of A is a pole and every finite eigenvalue of the Rosenbrock pencil a zero
/// (its invariant zeros); then pole–zero pairs closer than
///     |p − z| ≤ cancellation_tolerance · max(|p|, |z|, ρ(A))        (ρ: largest |pole|)
/// are cancelled (greedily, each zero with its nearest remaining pole) and listed in
/// `cancelled`, so that what is reported is the minimal (controllable and observable) transfer
/// function. The test is relative, so it does not depend on the time unit. Pass 0 to keep
/// every pole and zero.
/// A nonzero D is taken as given (exactly): any D ≠ 0 makes G biproper. For a sampled system
/// the same algebra gives H(z): its poles and zeros in the z-plane.
/// Throws InvalidArgument on an index out of range or a negative tolerance, NumericalError if
/// an eigenvalue iteration fails.
TransferFunction transfer_function(const StateSpace& system, std::size_t input, std::size_t output,
                                   double cancellation_tolerance = kDefaultCancellationTolerance);
/// The same by names; throws InvalidArgument with a suggestion on an unknown name.
TransferFunction transfer_function(const StateSpace& system, std::string_view input,
                                   std::string_view output,
                                   double cancellation_tolerance = kDefaultCancellationTolerance);

/// G(s) = C (sI − A)⁻¹ B + D of every pair (p×m complex), by an LU solve of (sI − A) X = B (no
/// inverse, no polynomials). At a pole the result is not finite.
Eigen::MatrixXcd evaluate(const StateSpace& system, Complex s);

/// G(s) of one pair, as above. Throws InvalidArgument on an index out of range.
Complex evaluate(const StateSpace& system, std::size_t input, std::size_t output, Complex s);

/// Static gain G(0) = D − C A⁻¹ B of one pair (G(1) = D + C (I − A)⁻¹ B when sampled) (the steady
/// output per unit constant input of a stable system); ±infinity when the pair has an uncancelled
/// pole at the origin. Same as transfer_function(...).dc_gain.
double dc_gain(const StateSpace& system, std::size_t input, std::size_t output);

}  // namespace momenta::analysis
