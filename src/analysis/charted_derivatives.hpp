#pragma once
// Internal to momenta::analysis: the motion of a constrained model in the independent coordinates
// of a chart (constraint_chart.hpp), differentiated analytically — what linearize() puts in A and
// find_equilibrium() takes its stiffness from.

#include "constraint_chart.hpp"
#include "model_residual.hpp"
#include "momenta/analysis/linearize.hpp"
#include "momenta/math/types.hpp"

namespace momenta::analysis::detail {

/// [∂ξ̇/∂ξ ∂ξ̇/∂ζ; ∂ζ̇/∂ξ ∂ζ̇/∂ζ] at the consistent point p, on the chart's configuration states ξ
/// and velocity states ζ (linearize.hpp, "Models with constraints"): the chart's maps from its
/// rows' Jacobian G and their derivatives (dynamics/constraint_derivatives.hpp), the
/// accelerations' from the derivatives of the constrained equations r_f(q, v, v̇) − G_fᵀ λ = 0,
/// G v̇ + k = 0 (r_f: ModelResidual; docs/constraints.md, "The derivatives"). Exact to round-off.
/// Throws NumericalError when the reduced mass Tᵀ M T is not positive definite.
MatX charted_state_matrix(ModelResidual& residual, ConstraintChart& chart, const OperatingPoint& p);

}  // namespace momenta::analysis::detail
