#pragma once
// Internal to momenta::analysis: what linearize() shares between its tree path (linearize.cpp)
// and its constrained path (linearize_constrained.cpp) — the inputs and outputs by name, the
// difference steps, and the assembly of C, D and the folded inputs.

#include <string>
#include <vector>

#include "momenta/analysis/linearize.hpp"
#include "momenta/math/types.hpp"
#include "momenta/model/model.hpp"
#include "momenta/system/multibody_system.hpp"

namespace momenta::analysis::detail {

// Automatic steps: angles in rad, lengths as a fraction of the characteristic length (both near
// ε^(1/5), the best step of a Richardson-extrapolated central difference).
inline constexpr double kRelativeStep = 1e-3;
// Steps of the exact differences (velocity, prescribed rate and acceleration, in their units):
// any step is exact for a quadratic, and a large one keeps round-off (ε·|r|/h) small.
inline constexpr double kExactStep = 1.0;

/// One input: the signal perturbed and the name it goes by.
struct Input {
  std::string name;
  int signal = -1;
  bool prescribed = false;  // drives a prescribed joint (value by Richardson; rate, acceleration)
  // A controller drives it: it commands the coordinate's acceleration. Left unfolded: the closed
  // loop makes the coordinate and its rate states (linearize_closed_loop.cpp).
  bool commanded = false;
};

/// The inputs named (signals, or prescribed coordinates standing for their signals); every
/// signal something reads when `names` is empty. Throws InvalidArgument on an unknown or
/// repeated name, or a signal that acts on nothing.
std::vector<Input> resolve_inputs(const model::Model& model, const std::vector<std::string>& names);

/// The name of velocity coordinate i's configuration tangent ("hinge.angle", "base.rx").
std::string tangent_name(const model::Model& model, int i);

/// An output row: a state read directly, or a column of the OutputSet by finite differences.
struct OutputRow {
  std::string name;
  int state = -1;   // ≥ 0: C row = e_state
  int column = -1;  // ≥ 0: column of the OutputSet
};

/// Resolves the output names against the output columns, the states (the first
/// `configuration_states` of `state_names` are the configuration ones, the default outputs when
/// there are no columns) and any joint coordinate; `specs` receives options.output_specs and the
/// coordinate outputs synthesized.
std::vector<OutputRow> resolve_outputs(const model::Model& model,
                                       const std::vector<std::string>& state_names,
                                       int configuration_states,
                                       const LinearizationOptions& options,
                                       std::vector<model::OutputSpec>& specs);

/// The configuration steps of the differences: angles in rad, lengths relative to the model's
/// characteristic length (or absolute when length_step > 0).
struct DifferenceSteps {
  const model::Model& model;
  double angle_step;   // rad
  double length;       // characteristic length, m
  double length_step;  // m, or 0: relative to the length and the coordinate

  DifferenceSteps(const model::Model& model, const LinearizationOptions& options);
  double of_length(double value) const;
  /// The step of velocity coordinate i's configuration at q0: an angle or a length.
  double configuration(int i, const VecX& q0) const;
};

/// ∂g/∂(configuration states), ∂g/∂(velocity states) and ∂g/∂u by the input signal's value, rate
/// and acceleration, g = [the state equations' rows; the output columns].
struct Jacobians {
  MatX dq, dv, du0, du1, du2;
};

/// Throws NumericalError naming the first non-finite entry of a derivative.
void check_derivative_finite(const MatX& X, const char* what);
void check_jacobians_finite(const Jacobians& J);

/// Output rows: a state directly (reading `state_values` at the point), or row
/// `rows_before_outputs` + column of the Jacobians. Sets the feedthroughs and output values of
/// `result`; returns C.
MatX output_matrix(LinearModel& result, const std::vector<OutputRow>& rows, const Jacobians& J,
                   const VecX& g0, int rows_before_outputs, const VecX& state_values);

/// Folds each prescribed input's rate and acceleration into its position (linearize.hpp), but a
/// commanded one's (left to the closed loop):
/// w = x − E₁ u − E₂ u̇, E₂ = B₂, E₁ = A E₂ + B₁; B = B₀ + A E₁, D = D₀ + C E₁. Throws when an
/// output feels a rate or acceleration that no state shift absorbs (an improper transfer).
void fold_input_rates(LinearModel& result, const MatX& A, const MatX& C,
                      const std::vector<Input>& inputs,
                      const std::vector<std::string>& output_names, MatX& B, MatX& D);

/// Each commanded input's coordinate p and its rate ṗ appended to the states of result.system,
/// its acceleration a the input (linearize.hpp): from the unfolded columns, ẋ = A x + B₀ p + B₁ ṗ
/// + B₂ a, d/dt [p; ṗ] = [ṗ; a], y = C x + D₀ p + D₁ ṗ + D₂ a. Nothing without commanded inputs.
/// Throws InvalidArgument where a prescribed-motion input's rates also enter (folded states).
void add_commanded_states(const model::Model& model, const std::vector<Input>& inputs,
                          LinearModel& result);

/// T = ∂δ̇/∂δ (free × free coordinates) from δ̇ = J_r(δ)⁻¹ ω at δ = 0 and velocities v0: −½[ω]×
/// on a ball or free joint's rotation tangent, zero elsewhere (and at rest). Exact: central
/// differences of a step on which J_r(δ)⁻¹ ω is linear but for an even part.
MatX rotation_rate_jacobian(const model::Model& model, const std::vector<int>& free,
                            const VecX& v0);

/// Sets the plant's driven inputs to options.driven_values (nothing when it is empty).
void set_driven_values(const model::Model& model, const LinearizationOptions& options,
                       system::MultibodySystem& system);
/// Whether signal s scales an applied load or drives a prescribed joint.
bool signal_has_effect(const model::Model& model, int s);

/// linearize() for a model with controllers and options.close_loops: the plant's linearization
/// closed by the controllers' linear laws (linearize_closed_loop.cpp).
LinearModel linearize_closed_loop(const model::Model& model, const OperatingPoint& point,
                                  const LinearizationOptions& options);

/// linearize() for a model with constraints (linearize_constrained.cpp).
LinearModel linearize_constrained(const model::Model& model, const OperatingPoint& point,
                                  const LinearizationOptions& options);

}  // namespace momenta::analysis::detail
