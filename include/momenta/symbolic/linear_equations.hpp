#pragma once
// The equations of motion linearized in symbols about an operating point (q0, v0, u0), in the
// second-order form a textbook writes,
//
//     M δq̈ + D δq̇ + K δq = B0 δu + B1 δu̇ + B2 δü,
//
// over the free coordinates (δq = q − q0), with M = M(q0), D = ∂b/∂v, K = ∂(M v̇0 + b)/∂q,
// B0 = −∂b/∂u, B1 = −∂b/∂u̇, B2 = −∂b/∂ü at the point, b = C v + g − Q the bias of
// symbolic/equations.hpp and v̇0 the motion's acceleration there (zero at an equilibrium). Inputs
// u: every signal that scales a load, then every prescribing signal (its rate and acceleration
// give B1 and B2: a road profile enters a quarter car through the tyre's spring and damper).
// Where B1 = B2 = 0 the first-order form ẋ = A x + B u, x = [δq; δq̇], A = [0 I; −M⁻¹K −M⁻¹D],
// B = [0; M⁻¹ B0], is given too (up to four free coordinates: M⁻¹ in symbols grows fast).
//
// The transfer function from input i to a free coordinate k (or its rate) is
// G(s) = s^d e_kᵀ (s² M + s D + K)⁻¹ (B0 + s B1 + s² B2) e_i, d = 0 or 1, written as a ratio of
// polynomials in s with their coefficients collected: 1/(m s + b) for the cruise control.
// Parameters stay the symbols (or numbers) of the equations; the operating point's numbers are
// put in exactly where they are integers (q0 = 0 gives sin 0 = 0, cos 0 = 1).

#include <complex>
#include <memory>
#include <string>
#include <vector>

#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"
#include "momenta/symbolic/equations.hpp"

namespace momenta::symbolic {

/// Which matrix of the linearization.
enum class LinearMatrix { M, D, K, B0, B1, B2, A, B };

/// The linearization (see the file comment). Copies share the expressions.
class LinearEquations {
 public:
  ~LinearEquations();
  LinearEquations(const LinearEquations&);
  LinearEquations& operator=(const LinearEquations&);

  /// The free coordinates' names (the rows of M, D, K, B*), and the inputs' (B's columns).
  const std::vector<std::string>& coordinate_names() const;
  const std::vector<std::string>& input_names() const;

  /// True when an input's rate or acceleration enters (B1 or B2 nonzero): no A, B then.
  bool has_input_rates() const;
  /// True when A and B are given (no input rates, at most four free coordinates).
  bool has_state_space() const;
  /// Rows and columns of a matrix (A: 2n × 2n, B: 2n × inputs; B* n × inputs; others n × n).
  int rows(LinearMatrix which) const;
  int columns(LinearMatrix which) const;
  /// Entry (r, c) printed in `format` (text or latex). Throws InvalidArgument out of range or for
  /// A, B without has_state_space().
  std::string entry(LinearMatrix which, int r, int c, Format format) const;

  /// G(s) from input `input` to free coordinate `coordinate` (rate = false) or its rate, as
  /// "numerator/denominator" in `format`. Throws InvalidArgument for an index out of range.
  std::string transfer_function(int input, int coordinate, bool rate, Format format) const;
  /// The same evaluated at a complex s with every parameter at its model value: for checks
  /// against the numeric linearization.
  std::complex<double> transfer_function_at(int input, int coordinate, bool rate,
                                            std::complex<double> s) const;

  struct Impl;

 private:
  friend LinearEquations linearize_equations(const Equations&, const model::Model&, double,
                                             const VecX&, const VecX&);
  explicit LinearEquations(std::shared_ptr<const Impl> impl);
  std::shared_ptr<const Impl> impl_;
};

/// Linearizes `equations` (derived from `model`) about q0, v0 (model sizes; prescribed
/// coordinates as given) at time t, the signals' values, rates and accelerations taken there.
/// Throws InvalidArgument when a free joint has nq ≠ nv (a ball or free joint: its quaternion has
/// no δq of its own here; use `momenta linearize`), for a constrained model (its linearization
/// lives in independent coordinates chosen at the operating point: `momenta linearize`, which
/// does that numerically), or on a size mismatch.
LinearEquations linearize_equations(const Equations& equations, const model::Model& model, double t,
                                    const VecX& q0, const VecX& v0);

}  // namespace momenta::symbolic
