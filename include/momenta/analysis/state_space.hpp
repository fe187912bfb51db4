#pragma once
// A linear time-invariant system in state-space form, continuous or sampled,
//
//     ẋ = A x + B u,              y = C x + D u          (continuous, sample time 0), or
//     x[k+1] = A x[k] + B u[k],   y[k] = C x[k] + D u[k] (discrete, sample time T > 0, t = k T),
//
// with n states, m inputs and p outputs, each named. The continuous form is what the
// linearization of a model produces; the discrete one is what c2d (discretize.hpp) makes of it.
// Units are whatever the states, inputs and outputs carry (SI); time is in seconds.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "momenta/math/types.hpp"

namespace momenta::analysis {

/// ẋ = A x + B u, y = C x + D u, or its sampled form. Immutable once built; the constructor
/// checks every dimension.
class StateSpace {
 public:
  /// The SI unit of each state, input and output ("m", "rad/s", "N"; "" where none is known), or
  /// an empty list where none of them is known (a system built from matrices).
  struct Units {
    std::vector<std::string> states, inputs, outputs;
  };

  /// Builds the system and checks it.
  ///   A: n×n, B: n×m, C: p×n, D: p×m. An empty D (0×0) stands for the zero p×m matrix.
  ///   state_names (n), input_names (m), output_names (p): an empty list is filled with
  ///   "x1".."xn", "u1".."um", "y1".."yp". Names must be non-empty and unique within their list.
  ///   sample_time: 0 for a continuous system, else the discrete system's sample period T (s).
  /// Throws InvalidArgument naming the matrix and both sizes when dimensions disagree, the entry
  /// when one is not finite, the name when a list has the wrong length or a duplicate, and a
  /// sample time that is negative or not finite.
  StateSpace(MatX A, MatX B, MatX C, MatX D, std::vector<std::string> state_names = {},
             std::vector<std::string> input_names = {}, std::vector<std::string> output_names = {},
             double sample_time = 0.0);

  const MatX& A() const { return A_; }
  const MatX& B() const { return B_; }
  const MatX& C() const { return C_; }
  const MatX& D() const { return D_; }

  std::size_t state_count() const { return static_cast<std::size_t>(A_.rows()); }
  std::size_t input_count() const { return static_cast<std::size_t>(B_.cols()); }
  std::size_t output_count() const { return static_cast<std::size_t>(C_.rows()); }

  /// 0 for a continuous system, else the sample period T in seconds.
  double sample_time() const { return sample_time_; }
  bool is_discrete() const { return sample_time_ > 0.0; }

  const std::vector<std::string>& state_names() const { return state_names_; }
  const std::vector<std::string>& input_names() const { return input_names_; }
  const std::vector<std::string>& output_names() const { return output_names_; }

  const Units& units() const { return units_; }
  /// The same system with these units; each list empty or one per state, input, output (else
  /// InvalidArgument naming the list).
  StateSpace with_units(Units units) const;

  /// Index of the input called `name`. Throws InvalidArgument listing the inputs, with a
  /// "did you mean" suggestion, when there is none.
  std::size_t input_index(std::string_view name) const;
  /// Index of the output called `name`; throws as input_index does.
  std::size_t output_index(std::string_view name) const;
  /// Index of the state called `name`; throws as input_index does.
  std::size_t state_index(std::string_view name) const;

  /// The single-input single-output system from input `input` to output `output` (same A and
  /// states; B, C, D reduced to one column / row). Throws InvalidArgument on an index out of
  /// range.
  StateSpace siso(std::size_t input, std::size_t output) const;
  /// The same, by names; throws as input_index / output_index do.
  StateSpace siso(std::string_view input, std::string_view output) const;

  /// True when the system has one input and one output.
  bool is_siso() const { return input_count() == 1 && output_count() == 1; }

 private:
  MatX A_, B_, C_, D_;
  std::vector<std::string> state_names_, input_names_, output_names_;
  double sample_time_ = 0.0;
  Units units_;
};

/// The state-space form of the second-order system M q̈ + C_damping q̇ + K q = F u with outputs
/// y = Cq q + Cv q̇ (nq coordinates, m inputs): state x = [q; q̇], A = [0 I; −M⁻¹K −M⁻¹C],
/// B = [0; M⁻¹F], C = [Cq Cv], D = 0. State names are the coordinate names (default q1..qnq)
/// followed by the same names with "_dot". M must be symmetric positive definite (Cholesky); M⁻¹ is
/// applied by solving, never formed. Cq and Cv are p×nq (both given, zero where unused). Throws
/// InvalidArgument on mismatched sizes or a mass matrix that is not positive definite.
StateSpace second_order_state_space(const MatX& M, const MatX& C_damping, const MatX& K,
                                    const MatX& F, const MatX& Cq, const MatX& Cv,
                                    std::vector<std::string> coordinate_names = {},
                                    std::vector<std::string> input_names = {},
                                    std::vector<std::string> output_names = {});

}  // namespace momenta::analysis
